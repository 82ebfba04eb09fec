#pragma once
/// The panel of the leg library beside the linkage: the legs editor (the platform, and each
/// leg's type — which joint is actuated — and working mode; legs added and removed with the
/// platform) above the generic workspace and singularity map. The lengths, guide angles,
/// strokes and points are the design panel's fields (only those the legs use are shown), and
/// the attachment points are dragged in the linkage view. Every edit is one undoable step of
/// the document; one that cannot be assembled is refused with the document's message (the
/// leg and why) in the status bar, and the design stays as it was.

#include "kinds/kindpanel.h"
#include "kinds/planarparallel/planarparallel.h"

#include <array>

class QComboBox;
class QGroupBox;
class QLabel;
class QPushButton;

namespace pkm {

class Document;
class WorkspacePanel;

class PlanarParallelPanel : public KindPanel
{
    Q_OBJECT

public:
    explicit PlanarParallelPanel(Document *document, QWidget *parent = nullptr);

    void setDesign(const MechanismPtr &mechanism, const QString &title) override;
    void setPose(const Pose &pose) override;
    /// Presenting: the map alone; the legs are edited in the working layout.
    void setPresenting(bool on) override;

    WorkspacePanel *mapPanel() const { return m_map; }
    QComboBox *platformBox() const { return m_platform; }
    /// Leg `leg`'s (0, 1, 2) type and working-mode choosers.
    QComboBox *typeBox(int leg) const { return m_types[std::size_t(leg)]; }
    QComboBox *workingBox(int leg) const { return m_working[std::size_t(leg)]; }
    QPushButton *addLegButton() const { return m_add; }
    QPushButton *removeLegButton() const { return m_remove; }

    /// The editor's requests, also what its choosers do: the design gets this platform (and
    /// with it its number of legs) and these leg types, holding the platform where it is.
    bool restructure(PlatformType platform, const std::array<LegType, 3> &types);
    bool setWorking(int leg, int working);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void showDesign();
    std::array<LegType, 3> types() const;
    /// The document's answer: a refusal goes to the status bar and the choosers show the
    /// design that stays.
    bool answer(const Result<bool> &result);

    Document *m_document = nullptr;
    std::shared_ptr<const PlanarParallel> m_mechanism;
    Pose m_pose;
    QGroupBox *m_box = nullptr;
    QLabel *m_platformLabel = nullptr;
    QComboBox *m_platform = nullptr;
    QPushButton *m_add = nullptr;
    QPushButton *m_remove = nullptr;
    std::array<QLabel *, 3> m_legLabels {};
    std::array<QComboBox *, 3> m_types {};
    std::array<QComboBox *, 3> m_working {};
    WorkspacePanel *m_map = nullptr;
};

} // namespace pkm
