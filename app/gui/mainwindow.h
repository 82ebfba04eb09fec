#pragma once
/// The main window: the linkage view, the joint-variable sliders, the design panel, live values
/// and plots, all reading one Document and asking it for every change.

#include "capabilityshapes.h"
#include "export/animation.h"
#include "mechanism.h"
#include "scenestyle.h"

#include <QDeadlineTimer>
#include <QMainWindow>
#include <QMessageBox>
#include <QPointer>

#include <functional>
#include <string>
#include <utility>
#include <vector>

class QAction;
class QCustomPlot;
class QDockWidget;
class QLabel;
class QToolBar;
class QMenu;
class QShortcut;
class QSplitter;
class QStackedWidget;
class QTabWidget;

namespace pkm {

class DesignPanel;
class GuideWindow;
class EquationsPanel;
class DesignSession;
class Document;
class KindPanel;
class LinkageView;
class ModeBar;
class ValuesTable;
class MobilityPanel;
class VariablePanel;
class PlayBar;
class Player;
class SweepPlotsPanel;
class WorkspacePanel;
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
    /// The Mobility dock's panel (tabified with the values).
    MobilityPanel *mobilityPanel() const { return m_mobility; }
    /// The Equations dock's panel (tabified with the values).
    EquationsPanel *equationsPanel() const { return m_equations; }
    ModeBar *modeBar() const { return m_modeBar; }
    /// The generic panel of a planar kind without a panel of its own (the workspace map).
    WorkspacePanel *workspacePanel() const { return m_workspacePanel; }
    /// The generic panel of a kind with one input and no panel of its own (its sweep plots).
    SweepPlotsPanel *sweepPanel() const { return m_sweepPanel; }
    /// The panel beside the linkage now, or nullptr when the design has none.
    KindPanel *currentPanel() const { return m_currentPanel; }
    /// The panel of type `Panel` that a kind's module made (kindmodule.h), or nullptr.
    template <typename Panel>
    Panel *kindPanel() const
    {
        for (const auto &[kind, panel] : m_kindPanels) {
            if (auto *found = qobject_cast<Panel *>(panel))
                return found;
        }
        return nullptr;
    }
    View3DPanel *view3d() const { return m_view3d; }
    /// The tabs over the linkage: "2D" and "3D".
    QTabWidget *viewTabs() const { return m_viewTabs; }
    /// The last message the status bar showed (tests read it after it times out).
    QString lastStatus() const { return m_lastStatus; }

    /// Whether a remembered window geometry was restored at construction.
    bool restoredGeometry() const { return m_restoredGeometry; }

    /// Opens a preset id or a design file; on failure says why and keeps the current design.
    bool openDesign(const QString &presetOrPath);
    /// The file, unsaved changes, recent files and autosave of the document.
    DesignSession *session() const { return m_session; }
    /// Asks whether to save unsaved changes: true when the caller may go on (saved, discarded,
    /// or nothing to save), false when the user cancelled or the save failed.
    bool maybeSave();
    /// Saves to the document's file, or asks for one; false if not saved.
    bool saveFile();
    /// Offers the designs of sessions that ended without closing (at start-up).
    void offerRecovery();
    /// How the window asks questions; tests replace it to answer without a dialog. Gets the
    /// title, the text and the buttons; returns the button chosen.
    using Question = std::function<QMessageBox::StandardButton(const QString &, const QString &,
                                                               QMessageBox::StandardButtons)>;
    void setQuestion(Question question) { m_question = std::move(question); }
    /// Draws the animation of the current design from its current pose off the GUI thread and
    /// writes the GIF to `path`; the status bar says when it is done.
    /// `beside`: what the frames show beside the view (AnimationDialog::besideChoice()).
    void exportAnimationTo(const QString &path, AnimationSettings settings, const QString &beside = {});

    /// The Play controls and the player behind them (mainwindowplay.cpp).
    PlayBar *playBar() const { return m_playBar; }
    Player *player() const { return m_player; }
    /// Starts (with the Play bar's settings) or stops Play.
    void setPlaying(bool play);
    /// View ▸ Presentation Mode: full screen, high contrast, the docks hidden, text at the
    /// presentation's size (mainwindowpresentation.cpp).
    void setPresentationMode(bool on);
    bool isPresenting() const { return m_presenting; }
    /// Text at `factor` × its normal size (textscale.h), everywhere in the window.
    void setTextScale(double factor);
    /// The bookmark shown last (index into Document::bookmarks()), or -1.
    int currentBookmark() const { return m_currentBookmark; }

    /// Help ▸ User Guide (F1): the guide's window, made at the first call (mainwindowhelp.cpp).
    void showGuide();
    /// The guide's window once shown, else nullptr.
    GuideWindow *guideWindow() const;

    /// View ▸ Velocity and Force Shapes: the actuators' polygons and ellipses at the platform
    /// point in the 2D view (mainwindowcapability.cpp); `on` also where they cannot be drawn
    /// (the action stays checked, the status bar says why).
    void setCapabilityShapes(bool on);
    bool showsCapabilityShapes() const;
    /// Why the current design has no shapes to draw (empty when it has).
    QString capabilityShapesUnavailable() const;

    /// Switches the program to the language `code` (language.h) and remembers it.
    void setLanguage(const QString &code);

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void createActions();
    /// Sets the action's text (and tooltip) to the translation of `source` now and after every
    /// change of language.
    QAction *translated(QAction *action, const char *source, const char *toolTip = nullptr);
    void createUndoActions();
    /// The Play toolbar and the Bookmarks menu (mainwindowplay.cpp); Play's actions go into `viewMenu`.
    void createPlayControls(QMenu *viewMenu);
    void createPresentationActions(QMenu *viewMenu);
    /// The Velocity and Force Shapes toggle, in `viewMenu` and on the toolbar.
    void createCapabilityActions(QMenu *viewMenu);
    /// The actuators and the shapes' scales of a new design.
    void updateCapabilityDesign();
    /// Edit ▸ Requirements…: what the actuators must deliver, mapped as the specification region.
    void createRequirementsAction(QMenu *editMenu);
    void editRequirements();
    /// The document's requirements to every workspace map.
    void showRequirements();
    /// The 2D view's scene of `pose`: the mechanism's, with the shapes when they are on.
    Scene viewScene(const Pose &pose) const;
    /// Help ▸ User Guide and What's This (mainwindowhelp.cpp), at the top of `help`.
    void createHelpActions(QMenu *help);
    /// The What's This text of every panel, in the current language.
    void updateWhatsThis();
    /// Keeps the status bar's message whole: the pose read-out steps aside when both do not fit.
    void watchStatusBar();
    void fitStatusMessage();
    /// The linkage view's style at the current text size (and contrast, when presenting).
    void applySceneStyle();
    /// The sliders large in presentation mode, as usual otherwise (new sliders included).
    void styleSliders();
    /// In presentation mode one plot per page of the panel's tabs, the chosen one in front;
    /// every plot otherwise (and on the panels not shown).
    void applyPresentationPlots();
    /// View ▸ Presentation Plot: enabled where a page has several plots; with `entries` (as it
    /// opens) the current panel's plots by title, the one shown checked.
    void fillPresentationPlotMenu(bool entries);
    void addBookmark();
    void goToBookmark(int index);
    /// The next (+1) or previous (−1) bookmark, round the list.
    void stepBookmark(int step);
    void updateBookmarksMenu();
    /// "θ = 30.0°   d = 183.1 mm": the pose as the status bar shows it.
    QString poseSummary() const;
    /// The symbols a message about the current mechanism may name ("x_AB", "θ_min", "det J_q"):
    /// its variables, parameters and reported quantities, which the status bar lowers.
    QStringList shownSymbols() const;
    void fillPresetsMenu();
    void retranslate();
    void createDocks();
    void onDesignChanged();
    void onPoseChanged();
    void updateModes();
    /// Gives the 3D view the current pose when it is shown; refits it for a new mechanism.
    void update3d(bool designChanged);
    void switchMode(int index);
    void showStatus(const QString &message, bool error = false);
    void openFile();
    bool saveFileAs();
    void updateTitle();
    void exportAnimationDialog();
    /// File ▸ Export Drawing (DXF)…: the current design and pose as a DXF file (dxfwriter.h).
    void exportDrawing();
    /// File ▸ Export Parameter Sheet…: the current design and pose as a PDF, JSON or CSV
    /// parameter sheet (sheet.h), the same file as `pkm sheet`.
    void exportParameterSheet();
    /// File ▸ Save 2D View Picture…: the current design and pose as PNG, SVG or PDF
    /// (viewpicture.h), as `pkm render` draws it.
    void saveViewPicture();
    void updateRecentMenu();
    /// Opens a preset or file from a menu: asks about unsaved changes first.
    void openFromMenu(const QString &presetOrPath);
    void about();
    /// Help ▸ Source Documents: the four documents the mechanisms come from, with full references.
    void sourceDocuments();
    void restoreLayout();

    Document *m_document = nullptr;
    DesignSession *m_session = nullptr;
    QMenu *m_recentMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_presetsMenu = nullptr;
    QMenu *m_languageMenu = nullptr;
    QToolBar *m_toolBar = nullptr;
    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
    QAction *m_undoButton = nullptr;
    QAction *m_redoButton = nullptr;
    QDockWidget *m_designDock = nullptr;
    QDockWidget *m_valuesDock = nullptr;
    QDockWidget *m_mobilityDock = nullptr;
    QDockWidget *m_equationsDock = nullptr;
    QDockWidget *m_toleranceDock = nullptr;
    struct TranslatedAction {
        QPointer<QAction> action;
        const char *source = nullptr;
        const char *toolTip = nullptr;
    };
    QList<TranslatedAction> m_translatedActions;
    Question m_question;
    LinkageView *m_view = nullptr;
    VariablePanel *m_variables = nullptr;
    ModeBar *m_modeBar = nullptr;
    std::vector<ModeAlternative> m_alternatives; ///< the other modes at the current pose
    DesignPanel *m_designPanel = nullptr;
    ValuesTable *m_values = nullptr;
    MobilityPanel *m_mobility = nullptr;
    EquationsPanel *m_equations = nullptr;
    /// The panels the kinds' modules made, by kind id.
    std::vector<std::pair<std::string, KindPanel *>> m_kindPanels;
    WorkspacePanel *m_workspacePanel = nullptr;
    SweepPlotsPanel *m_sweepPanel = nullptr;
    KindPanel *m_currentPanel = nullptr;
    View3DPanel *m_view3d = nullptr;
    QTabWidget *m_viewTabs = nullptr;
    Eigen::AlignedBox3d m_view3dExtent; ///< of the model last fitted in the 3D view
    QStackedWidget *m_plots = nullptr;
    QSplitter *m_splitter = nullptr;
    QLabel *m_statusText = nullptr; // the status message, wrapped (watchStatusBar)
    QLabel *m_poseLabel = nullptr;
    QLabel *m_singularityLabel = nullptr;
    QString m_lastStatus;
    bool m_statusIsError = false;
    /// Until when a message stays while the pose moves on: Play's "turned back: …", which the
    /// next step's pose would otherwise clear before anyone read it.
    QDeadlineTimer m_statusHeldUntil;
    bool m_restoredGeometry = false;
    PlayBar *m_playBar = nullptr;
    Player *m_player = nullptr;
    QToolBar *m_playToolBar = nullptr;
    QAction *m_playAction = nullptr;
    QMenu *m_bookmarksMenu = nullptr;
    QAction *m_addBookmarkAction = nullptr;
    QAction *m_previousBookmarkAction = nullptr;
    QAction *m_nextBookmarkAction = nullptr;
    QAction *m_removeBookmarkAction = nullptr;
    int m_currentBookmark = -1;
    QFont m_baseFont;       ///< the application's font at 100 %
    SceneStyle m_baseStyle; ///< the linkage view's style at 100 %
    QAction *m_presentationAction = nullptr;
    QAction *m_capabilityAction = nullptr;
    QAction *m_requirementsAction = nullptr;
    capability::Actuators m_actuators;
    capability::ShapeScales m_shapeScales;
    QMenu *m_textSizeMenu = nullptr;
    QMenu *m_presentationPlotMenu = nullptr;
    QPointer<QCustomPlot> m_presentationPlot; ///< the plot presentation mode shows, when chosen
    QShortcut *m_leavePresentation = nullptr;
    bool m_presenting = false;
    QPointer<GuideWindow> m_guide;
    QByteArray m_stateBeforePresentation;
    QByteArray m_splitterBeforePresentation;
    bool m_maximizedBeforePresentation = false;
    QRect m_geometryBeforePresentation; ///< the window's own place and size, given back on leaving
    /// The shown docks' sizes: restoreState() shares a dock area out anew when the window's
    /// size or the docks' least sizes differ from when it was saved.
    QList<QPair<QPointer<QDockWidget>, QSize>> m_docksBeforePresentation;
};

} // namespace pkm
