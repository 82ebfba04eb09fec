#pragma once
/// The main window: the linkage view, the joint-variable sliders, the design panel, live values
/// and plots, all reading one Document and asking it for every change.

#include "mechanism.h"

#include <QMainWindow>

class QLabel;
class QMenu;
class QSplitter;
class QStackedWidget;
class QTabWidget;

namespace pkm {

class DesignPanel;
class Document;
class LinkageView;
class ModeBar;
class PJointPlots;
class ValuesTable;
class VariablePanel;
class WorkspacePanel;
class OxGlidePanel;
class View3DPanel;

class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    Document *document() const { return m_document; }
    LinkageView *linkageView() const { return m_view; }
    VariablePanel *variablePanel() const { return m_variables; }
    DesignPanel *designPanel() const { return m_designPanel; }
    ValuesTable *valuesTable() const { return m_values; }
    PJointPlots *pjointPlots() const { return m_pjointPlots; }
    ModeBar *modeBar() const { return m_modeBar; }
    WorkspacePanel *workspacePanel() const { return m_workspacePanel; }
    OxGlidePanel *oxglidePanel() const { return m_oxglidePanel; }
    View3DPanel *view3d() const { return m_view3d; }
    /// The tabs over the linkage: "2D" and "3D".
    QTabWidget *viewTabs() const { return m_viewTabs; }
    /// The last message the status bar showed (tests read it after it times out).
    QString lastStatus() const { return m_lastStatus; }

    /// Whether a remembered window geometry was restored at construction.
    bool restoredGeometry() const { return m_restoredGeometry; }

    /// Opens a preset id or a design file; on failure says why and keeps the current design.
    bool openDesign(const QString &presetOrPath);

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void createActions();
    void createDocks();
    void onDesignChanged();
    void onPoseChanged();
    void keepMechanismInView();
    void updateModes();
    /// Gives the 3D view the current pose when it is shown; refits it for a new mechanism.
    void update3d(bool designChanged);
    void switchMode(int index);
    void showStatus(const QString &message, bool error = false);
    void openFile();
    void saveFileAs();
    void about();
    void restoreLayout();

    Document *m_document = nullptr;
    LinkageView *m_view = nullptr;
    VariablePanel *m_variables = nullptr;
    ModeBar *m_modeBar = nullptr;
    std::vector<ModeAlternative> m_alternatives; ///< the other modes at the current pose
    DesignPanel *m_designPanel = nullptr;
    ValuesTable *m_values = nullptr;
    PJointPlots *m_pjointPlots = nullptr;
    WorkspacePanel *m_workspacePanel = nullptr;
    OxGlidePanel *m_oxglidePanel = nullptr;
    View3DPanel *m_view3d = nullptr;
    QTabWidget *m_viewTabs = nullptr;
    Eigen::AlignedBox3d m_view3dExtent; ///< of the model last fitted in the 3D view
    QStackedWidget *m_plots = nullptr;
    QSplitter *m_splitter = nullptr;
    QLabel *m_poseLabel = nullptr;
    QLabel *m_singularityLabel = nullptr;
    QString m_lastStatus;
    bool m_statusIsError = false;
    bool m_restoredGeometry = false;
};

} // namespace pkm
