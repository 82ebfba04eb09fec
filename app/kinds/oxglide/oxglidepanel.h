#pragma once
/// The right-hand panel for the O-X glide: the form selector (O extended, X crossed), the
/// animated crossing between the forms, the workspaces of both forms as in the document's
/// fig. 5 with their areas, and the det J / κ map of the current form.
///
/// The crossing raises the platform towards y = l, where x_CD − x_AB = s: the rods are
/// perpendicular to the guides and parallel, and the platform can swing. The animation stops
/// short of that pose and explains it; the user then chooses the form to leave in.

#include "kinds/kindpanel.h"
#include "kinds/oxglide/oxglide.h"

#include <QTimer>

#include <functional>

class QLabel;
class QPushButton;
class QTabWidget;

namespace pkm {

class Document;
class FormWorkspaceView;
class WorkspacePanel;

class OxGlidePanel : public KindPanel
{
    Q_OBJECT

public:
    explicit OxGlidePanel(Document *document, QWidget *parent = nullptr);

    /// A new design (`title` names it in the map's comparison list).
    void setDesign(const MechanismPtr &mechanism, const QString &title) override;
    void setPose(const Pose &pose) override;
    /// Presenting: the map tab without its comparison row.
    void setPresenting(bool on) override;

    FormWorkspaceView *formView() const { return m_formView; }
    WorkspacePanel *mapPanel() const { return m_mapPanel; }
    QTabWidget *tabs() const { return m_tabs; }
    /// The form selector's button of form +1 (O) or −1 (X).
    QPushButton *formButton(int form) const;
    QPushButton *crossingButton() const { return m_cross; }
    QPushButton *leaveOtherButton() const { return m_leaveOther; }
    QPushButton *leaveSameButton() const { return m_leaveSame; }
    QLabel *banner() const { return m_banner; }

    enum class Phase { Idle, Rising, AtCrossing, Descending };
    Phase phase() const { return m_phase; }
    /// The height at which the crossing stops: the rods' margin from the singular pose is
    /// `stopMargin` there.
    double stopHeight() const;
    static constexpr double stopMargin = oxglide::crossingStopMargin; ///< w/l: rods ≈ 87° to the guides

    /// Switches to form +1 (O) or −1 (X) at the current platform position (undoable); the
    /// status bar says why when that form cannot reach it.
    void requestForm(int form);
    /// Starts (or stops) the crossing animation.
    void toggleCrossing();

protected:
    /// A new language: every text again, the banner and the workspace plot's titles included.
    void changeEvent(QEvent *event) override;
    /// Another kind's design took the window's place: the crossing and its banner are over.
    void hideEvent(QHideEvent *event) override;

private:
    /// Makes the banner's text in the current language.
    using TextMaker = std::function<QString()>;
    void retranslate();
    void tick();
    /// `message` (none: the banner hides) is shown in the banner and the status bar.
    void stopAnimation(const TextMaker &message = {}, bool error = false);
    void showBanner(const TextMaker &text);
    void leave(bool otherForm);
    void showFormButtons();
    void showCrossButton();
    void showLeaveButtons();
    /// The workspaces of both forms (fig. 5) in the form view.
    void showForms();
    int currentForm() const;

    Document *m_document = nullptr;
    MechanismPtr m_mechanism;
    QLabel *m_formLabel = nullptr;
    QPushButton *m_formO = nullptr;
    QPushButton *m_formX = nullptr;
    QPushButton *m_cross = nullptr;
    QPushButton *m_leaveOther = nullptr;
    QPushButton *m_leaveSame = nullptr;
    QLabel *m_banner = nullptr;
    TextMaker m_bannerText; ///< the banner's text, or null while it is hidden
    QTabWidget *m_tabs = nullptr;
    FormWorkspaceView *m_formView = nullptr;
    WorkspacePanel *m_mapPanel = nullptr;
    QTimer m_timer;
    Phase m_phase = Phase::Idle;
    double m_startHeight = 0.0; ///< where the crossing began; the descent returns there
    double m_target = 0.0;      ///< the height the current phase moves to
    double m_step = 0.0;        ///< mm per tick
    Pose m_expected;            ///< the pose the animation set last: another one means the user moved
    bool m_switching = false;   ///< our own form switch is replacing the design
};

} // namespace pkm
