#include "kinds/oxglide/oxglidepanel.h"

#include "document/document.h"
#include "flowlayout.h"
#include "formworkspaceview.h"
#include "kinds/oxglide/oxglide.h"
#include "quantityformat.h"
#include "kinds/workspacepanel.h"

#include <QButtonGroup>
#include <QEvent>
#include <QHideEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTabWidget>
#include <QVBoxLayout>

#include <cmath>

namespace pkm {

namespace {
constexpr int tickMilliseconds = 30;
constexpr int ticksPerPhase = 50; ///< 1.5 s per phase

QString mmText(double value)
{
    return formatQuantity(value, units::millimetre, 2);
}

/// Whole sentences for each form (not "the %1 form": the name's case changes in Russian and
/// Serbian with its place in the sentence).
bool isX(int form)
{
    return form == oxglide::formX;
}

const OxGlide *oxglideOf(const MechanismPtr &mechanism)
{
    return dynamic_cast<const OxGlide *>(mechanism.get());
}
} // namespace

OxGlidePanel::OxGlidePanel(Document *document, QWidget *parent)
    : KindPanel(parent)
    , m_document(document)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);

    // The form's label and buttons as one, and Animate crossing beside them where there is
    // room, else under them: one row held the panel to 740 px in Russian, and presentation
    // mode's linkage to a third of a 1280×720 projector.
    auto *bar = new QWidget(this);
    auto *flow = new FlowLayout(bar);
    flow->setContentsMargins(0, 0, 0, 0);
    auto *forms = new QWidget(bar);
    auto *row = new QHBoxLayout(forms);
    row->setContentsMargins(0, 0, 0, 0);
    auto *formLabel = new QLabel(this);
    m_formLabel = formLabel;
    m_formO = new QPushButton(this);
    m_formX = new QPushButton(this);
    auto *group = new QButtonGroup(this);
    for (QPushButton *button : {m_formO, m_formX}) {
        button->setCheckable(true);
        group->addButton(button);
    }
    m_formO->setObjectName(QStringLiteral("formO"));
    m_formX->setObjectName(QStringLiteral("formX"));
    m_cross = new QPushButton(this);
    m_cross->setObjectName(QStringLiteral("animateCrossing"));
    formLabel->setBuddy(m_formO);
    row->addWidget(formLabel);
    row->addWidget(m_formO);
    row->addWidget(m_formX);
    flow->addWidget(forms);
    flow->addWidget(m_cross);
    layout->addWidget(bar);

    m_banner = new QLabel(this);
    m_banner->setWordWrap(true);
    m_banner->setObjectName(QStringLiteral("crossingBanner"));
    m_banner->setStyleSheet(QStringLiteral("QLabel { background: #fff4e5; border: 1px solid #e0a040; padding: 6px; }"));
    m_banner->hide();
    layout->addWidget(m_banner);
    auto *leaveRow = new QHBoxLayout;
    m_leaveOther = new QPushButton(this);
    m_leaveSame = new QPushButton(this);
    m_leaveOther->setObjectName(QStringLiteral("leaveOther"));
    m_leaveSame->setObjectName(QStringLiteral("leaveSame"));
    leaveRow->addWidget(m_leaveOther);
    leaveRow->addWidget(m_leaveSame);
    leaveRow->addStretch(1);
    layout->addLayout(leaveRow);
    m_leaveOther->hide();
    m_leaveSame->hide();

    m_tabs = new QTabWidget(this);
    m_formView = new FormWorkspaceView(this);
    m_mapPanel = new WorkspacePanel(this);
    m_tabs->addTab(m_formView, QString());
    m_tabs->addTab(m_mapPanel, QString());
    layout->addWidget(m_tabs, 1);

    connect(m_formO, &QPushButton::clicked, this, [this] { requestForm(oxglide::formO); });
    connect(m_formX, &QPushButton::clicked, this, [this] { requestForm(oxglide::formX); });
    connect(m_cross, &QPushButton::clicked, this, &OxGlidePanel::toggleCrossing);
    connect(m_leaveOther, &QPushButton::clicked, this, [this] { leave(true); });
    connect(m_leaveSame, &QPushButton::clicked, this, [this] { leave(false); });
    connect(m_formView, &FormWorkspaceView::pointClicked, this, &OxGlidePanel::pointClicked);
    connect(m_mapPanel, &WorkspacePanel::pointClicked, this, &OxGlidePanel::pointClicked);
    m_timer.setInterval(tickMilliseconds);
    connect(&m_timer, &QTimer::timeout, this, &OxGlidePanel::tick);
    retranslate();
}

void OxGlidePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void OxGlidePanel::hideEvent(QHideEvent *event)
{
    // Not a minimised window (spontaneous): the panel made way for another kind's design. An
    // animation or banner left running would greet the next O-X glide opened as if still true.
    if (!event->spontaneous()) {
        m_timer.stop();
        m_phase = Phase::Idle;
        showCrossButton();
        m_leaveOther->hide();
        m_leaveSame->hide();
        showBanner({});
    }
    QWidget::hideEvent(event);
}

void OxGlidePanel::retranslate()
{
    m_formLabel->setText(tr("Form:"));
    m_formO->setText(tr("O — extended"));
    m_formX->setText(tr("X — crossed"));
    m_formO->setToolTip(tr("Work in the extended form: the rods splay outwards from the platform."));
    m_formX->setToolTip(tr("Work in the crossed form: the slider pairs pass each other and the rods cross."));
    m_cross->setToolTip(tr("Raise the platform towards the O↔X crossing (y = l, x_CD − x_AB = s) and stop short of "
                           "the singular pose there."));
    showCrossButton();
    showLeaveButtons();
    m_tabs->setTabText(m_tabs->indexOf(m_formView), tr("Workspace O / X"));
    m_tabs->setTabText(m_tabs->indexOf(m_mapPanel), tr("Singularity map"));
    if (m_bannerText)
        m_banner->setText(m_bannerText());
    showForms();
}

void OxGlidePanel::showCrossButton()
{
    const bool moving = m_phase == Phase::Rising || m_phase == Phase::Descending;
    m_cross->setText(moving ? tr("Stop") : tr("Animate crossing"));
}

void OxGlidePanel::showLeaveButtons()
{
    if (!oxglideOf(m_mechanism))
        return;
    const bool x = isX(currentForm());
    m_leaveOther->setText(x ? tr("Leave in the extended (O) form") : tr("Leave in the crossed (X) form"));
    m_leaveSame->setText(x ? tr("Go back in the crossed (X) form") : tr("Go back in the extended (O) form"));
}

void OxGlidePanel::showBanner(const TextMaker &text)
{
    m_bannerText = text;
    if (!text) {
        m_banner->hide();
        return;
    }
    m_banner->setText(text());
    m_banner->show();
}

QPushButton *OxGlidePanel::formButton(int form) const
{
    return form == oxglide::formX ? m_formX : m_formO;
}

int OxGlidePanel::currentForm() const
{
    const OxGlide *glide = oxglideOf(m_mechanism);
    return glide ? glide->design().form : oxglide::formO;
}

double OxGlidePanel::stopHeight() const
{
    const OxGlide *glide = oxglideOf(m_mechanism);
    const double l = glide ? glide->design().rod : 0.0;
    return l * std::sqrt(1.0 - stopMargin * stopMargin);
}

void OxGlidePanel::setDesign(const MechanismPtr &mechanism, const QString &title)
{
    m_mechanism = mechanism;
    const OxGlide *glide = oxglideOf(mechanism);
    if (!glide)
        return;
    if (!m_switching && m_phase != Phase::Idle)
        stopAnimation([] { return tr("The crossing stopped: the design changed."); });
    showFormButtons();
    m_mapPanel->setDesign(mechanism, title);
    showForms();
}

void OxGlidePanel::showForms()
{
    const OxGlide *glide = oxglideOf(m_mechanism);
    if (!glide)
        return;
    // fig. 5: the X form's region (light) under the O form's (dark)
    OxGlideDesign o = glide->design(), x = glide->design();
    o.form = oxglide::formO;
    x.form = oxglide::formX;
    auto designO = OxGlide::create(o), designX = OxGlide::create(x);
    if (!designO || !designX)
        return;
    std::vector<FormRegion> forms = {
        {tr("X — crossed"), *designX, QColor(0xb5, 0xcd, 0xe8), oxglide::exactArea(x, oxglide::formX)},
        {tr("O — extended"), *designO, QColor(0x2b, 0x5c, 0x8f), oxglide::exactArea(o, oxglide::formO)},
    };
    std::vector<SingularCurve> crossing;
    for (const SingularCurve &curve : glide->singularCurves()) {
        if (curve.type == SingularCurve::Type::Inverse)
            crossing.push_back(curve);
    }
    m_formView->setForms(tr("Workspaces of the O and X forms (fig. 5)"), forms, crossing,
                         tr("O↔X crossing y = l: singular"));
}

void OxGlidePanel::showFormButtons()
{
    const int form = currentForm();
    m_formO->setChecked(form == oxglide::formO);
    m_formX->setChecked(form == oxglide::formX);
}

void OxGlidePanel::setPresenting(bool on)
{
    m_mapPanel->setPresenting(on);
}

void OxGlidePanel::setPose(const Pose &pose)
{
    if (pose.outputs.size() >= 2)
        m_formView->setPose(pose.outputs.head<2>());
    m_mapPanel->setPose(pose);
    if (m_phase != Phase::Idle && m_phase != Phase::AtCrossing && !m_expected.outputs.isApprox(pose.outputs))
        stopAnimation([] { return tr("The crossing stopped: the pose was moved."); });
}

void OxGlidePanel::requestForm(int form)
{
    showFormButtons(); // the buttons show the design's form until the switch happens
    if (form == currentForm())
        return;
    const std::vector<ModeAlternative> alternatives = m_document->modeAlternatives();
    for (const ModeAlternative &alternative : alternatives) {
        const auto mode = alternative.changes.find("mode");
        if (mode == alternative.changes.end() || int(mode->second) != form)
            continue;
        if (auto switched = m_document->switchMode(alternative); !switched) {
            emit statusMessage(QString::fromStdString(switched.failure().message), true);
            return;
        }
        emit statusMessage(isX(form) ? tr("Switched to the crossed (X) form at the same platform position.")
                                     : tr("Switched to the extended (O) form at the same platform position."),
                           false);
        showFormButtons();
        return;
    }
    // The other form does not reach this platform position: say why, as the solver does.
    for (const ModeAlternative &neighbour : m_document->modeNeighbours()) {
        const Pose &pose = m_document->pose();
        auto solved = neighbour.mechanism->solveInverse(pose.outputs, &pose);
        if (!solved) {
            emit statusMessage(QString::fromStdString(solved.failure().message), true);
            return;
        }
    }
    emit statusMessage(isX(form) ? tr("The crossed (X) form is not available at this pose.")
                                 : tr("The extended (O) form is not available at this pose."),
                       true);
}

void OxGlidePanel::toggleCrossing()
{
    if (m_phase == Phase::Rising || m_phase == Phase::Descending) {
        stopAnimation([] { return tr("Crossing stopped."); });
        return;
    }
    const Pose &pose = m_document->pose();
    if (!oxglideOf(m_mechanism) || pose.outputs.size() < 2)
        return;
    m_startHeight = pose.outputs[1];
    m_target = stopHeight();
    m_leaveOther->hide();
    m_leaveSame->hide();
    if (m_startHeight >= m_target) {
        // already at the crossing: only the choice is left
        m_startHeight = m_mechanism->homePose().outputs[1];
    }
    m_step = std::max(1e-3, (m_target - m_startHeight) / ticksPerPhase);
    m_phase = Phase::Rising;
    m_expected = pose;
    showCrossButton();
    showBanner([] { return tr("Raising the platform towards the O↔X crossing at y = l…"); });
    m_timer.start();
}

void OxGlidePanel::tick()
{
    const Pose &pose = m_document->pose();
    const double y = pose.outputs[1];
    const bool rising = m_phase == Phase::Rising;
    const double next = rising ? std::min(m_target, y + m_step) : std::max(m_target, y - m_step);
    Coordinates outputs = pose.outputs;
    outputs[1] = next;
    m_expected.outputs = outputs;
    auto moved = m_document->moveOutputsTo(outputs);
    if (!moved) {
        const QString message = QString::fromStdString(moved.failure().message);
        stopAnimation([message] { return message; }, true);
        return;
    }
    m_expected = *moved;
    if (std::abs(next - m_target) > 1e-9)
        return;
    m_timer.stop();
    if (rising) {
        const double l = oxglideOf(m_mechanism)->design().rod;
        const double angle = std::atan2(next, std::sqrt(std::max(0.0, l * l - next * next))) * 180.0 / std::numbers::pi;
        m_phase = Phase::AtCrossing;
        showCrossButton();
        showBanner([l, next, angle] {
            return tr("<b>Stopped %1 short of the singular pose.</b> At y = l = %2 the slider pairs stand at "
                      "x_CD − x_AB = s: the rods are perpendicular to the guides and parallel to each other, so the "
                      "platform can swing sideways while the sliders hold still (a combined singularity), and it may "
                      "leave in either form. Here the rods are at %3° to the guides. Passing needs the platform guided "
                      "through that point: choose the form to leave in.")
                .arg(mmText(l - next), mmText(l), QLocale().toString(angle, 'f', 1));
        });
        showLeaveButtons();
        m_leaveOther->show();
        m_leaveSame->show();
        emit statusMessage(tr("The crossing stopped %1 below y = l, short of the singular pose x_CD − x_AB = s.")
                               .arg(mmText(l - next)),
                           false);
    } else {
        m_phase = Phase::Idle;
        showCrossButton();
        const int form = currentForm();
        showBanner([next, form] {
            return (isX(form) ? tr("The platform is back at y = %1, in the crossed (X) form.")
                              : tr("The platform is back at y = %1, in the extended (O) form."))
                .arg(mmText(next));
        });
    }
}

void OxGlidePanel::leave(bool otherForm)
{
    if (m_phase != Phase::AtCrossing)
        return;
    m_leaveOther->hide();
    m_leaveSame->hide();
    if (otherForm) {
        m_switching = true;
        requestForm(-currentForm());
        m_switching = false;
    }
    m_phase = Phase::Descending;
    m_target = m_startHeight;
    m_step = std::max(1e-3, (m_document->pose().outputs[1] - m_target) / ticksPerPhase);
    m_expected = m_document->pose();
    showCrossButton();
    const int form = currentForm();
    showBanner([form] {
        return isX(form) ? tr("Lowering the platform in the crossed (X) form…")
                         : tr("Lowering the platform in the extended (O) form…");
    });
    m_timer.start();
}

void OxGlidePanel::stopAnimation(const TextMaker &message, bool error)
{
    m_timer.stop();
    m_phase = Phase::Idle;
    showCrossButton();
    m_leaveOther->hide();
    m_leaveSame->hide();
    showBanner(message);
    if (message)
        emit statusMessage(message(), error);
}

} // namespace pkm
