// The four-bar's own panel (docs/mathematics.md, section 4): the link lengths with sliders and
// spin boxes, Grashof's class, the transmission angle now and over the motion, and why α stops;
// the gauge is drawn in fourbargauge.cpp, the plots are FourBarPlots.
#include "kinds/fourbar/fourbarpanel.h"

#include "document/designfile.h"
#include "document/document.h"
#include "fitscrollarea.h"
#include "gridreflow.h"
#include "kinds/fourbar/fourbar.h"
#include "kinds/fourbar/fourbarplots.h"
#include "plotfont.h"
#include "quantityformat.h"
#include "symboltext.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace pkm {

namespace {

constexpr double labelPoints = 11.5;
/// α samples for the transmission angle over the motion (as designWarnings()).
constexpr int motionSamples = 720;

const FourBar *fourbarOf(const MechanismPtr &mechanism)
{
    return dynamic_cast<const FourBar *>(mechanism.get());
}

QString lengthText(double mm)
{
    return QLocale().toString(mm, 'g', 6);
}

QString degreeText(double radians, int decimals = 1)
{
    return formatQuantity(radians, units::angle, decimals);
}

/// Whole degrees of the transmission limits (40°, 140°) in the locale's digits.
QString limitText(double degrees)
{
    return QLocale().toString(degrees, 'f', 0);
}

/// Grashof's class as the panel names it, capitalised.
QString grashofTitle(fourbar::Grashof g)
{
    switch (g) {
    case fourbar::Grashof::CrankRocker: return FourBarPanel::tr("Crank-rocker");
    case fourbar::Grashof::RockerCrank: return FourBarPanel::tr("Rocker-crank");
    case fourbar::Grashof::DoubleCrank: return FourBarPanel::tr("Double-crank");
    case fourbar::Grashof::DoubleRocker: return FourBarPanel::tr("Double-rocker");
    case fourbar::Grashof::TripleRocker: return FourBarPanel::tr("Triple-rocker");
    case fourbar::Grashof::ChangePoint: return FourBarPanel::tr("Change-point");
    }
    return {};
}

/// The acute transmission angle min(|γ|, 180° − |γ|) is below the limit.
bool isPoor(double gammaDegrees)
{
    const double g = std::abs(gammaDegrees);
    return std::min(g, 180.0 - g) < FourBar::poorTransmission;
}

/// A spin box that tells a step (arrows, wheel: merged into one undo step) from a typed value.
class LengthSpinBox : public NumberSpinBox
{
public:
    using NumberSpinBox::NumberSpinBox;
    bool stepping() const { return m_stepping; }
    void stepBy(int steps) override
    {
        m_stepping = true;
        QDoubleSpinBox::stepBy(steps);
        m_stepping = false;
    }

private:
    bool m_stepping = false;
};

} // namespace

FourBarPanel::FourBarPanel(Document *document, QWidget *parent)
    : KindPanel(parent)
    , m_document(document)
{
    setObjectName(QStringLiteral("fourbarPanel"));
    const QFont labelFont = fontOf(font(), labelPoints);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(6);

    // The lengths and the texts: hidden in presentation mode, which shows the plots alone.
    m_details = new QWidget(this);
    auto *details = new QVBoxLayout(m_details);
    details->setContentsMargins(0, 0, 0, 0);
    details->setSpacing(6);
    layout->addWidget(m_details);

    // -- link lengths: two per row --------------------------------------------------------------
    auto *links = new QGroupBox(this);
    m_linksGroup = links;
    links->setFont(labelFont);
    auto *grid = new QGridLayout(links);
    grid->setContentsMargins(8, 4, 8, 6);
    grid->setHorizontalSpacing(8);
    grid->setVerticalSpacing(4);
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        const QString name = QString::fromLatin1(linkNames[i]);
        LinkRow &row = m_rows[i];
        auto *label = new QLabel(links);
        label->setWordWrap(true); // "AB crank" on two lines where the panel is narrow
        row.label = label;
        row.slider = new QSlider(Qt::Horizontal, links);
        row.slider->setObjectName(QStringLiteral("length_") + name);
        row.slider->setMinimumWidth(45);
        auto *spin = new LengthSpinBox(links);
        row.spinBox = spin;
        spin->setObjectName(QStringLiteral("lengthSpin_") + name);
        spin->setDecimals(2);
        spin->setRange(0.0, 1e5); // 0 is refused by the core with its message
        spin->setSingleStep(1.0);
        spin->setKeyboardTracking(false);
        label->setBuddy(spin);

        connect(row.slider, &QSlider::sliderPressed, this, [this, i] {
            m_dragging = int(i);
            m_dragCommitted = false;
        });
        connect(row.slider, &QSlider::sliderReleased, this, [this] {
            m_dragging = -1;
            showLengths(true); // the ranges wait for the end of the drag
        });
        connect(row.slider, &QSlider::valueChanged, this, [this, i, name](int value) {
            if (m_updating)
                return;
            const bool dragging = m_dragging == int(i);
            // a drag is one undo step: its first change opens it, the rest merge; a key or wheel
            // step merges into the previous change of the same link, as in the design panel
            const bool continuous = dragging ? m_dragCommitted : true;
            if (requestLength(name, double(value) / sliderScale, continuous) && dragging)
                m_dragCommitted = true;
        });
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, spin, name](double value) {
            if (!m_updating)
                requestLength(name, value, spin->stepping());
        });
    }
    std::vector<std::vector<QWidget *>> rows;
    for (const LinkRow &row : m_rows)
        rows.push_back({row.label, row.slider, row.spinBox});
    m_linksReflow = new GridReflow(links, grid, std::move(rows), 1, 18); // two to a line where they fit
    details->addWidget(links);

    m_linkMessage = new QLabel(this);
    m_linkMessage->setObjectName(QStringLiteral("linkMessage"));
    m_linkMessage->setWordWrap(true);
    m_linkMessage->setFont(labelFont);
    m_linkMessage->setStyleSheet(
        QStringLiteral("QLabel { color: #b3261e; background: #fde7e5; border: 1px solid #e0a0a0; padding: 5px; }"));
    m_linkMessage->hide();
    details->addWidget(m_linkMessage);

    // -- the design in words and the transmission angle ----------------------------------------
    auto *infoBox = new QWidget;
    auto *info = new QGridLayout(infoBox);
    info->setContentsMargins(0, 0, 0, 0);
    auto *wordsBox = new QWidget(infoBox);
    auto *words = new QVBoxLayout(wordsBox);
    words->setContentsMargins(0, 0, 0, 0);
    words->setSpacing(4);
    m_grashof = new QLabel(this);
    m_grashof->setObjectName(QStringLiteral("grashofLabel"));
    m_range = new QLabel(this);
    m_range->setObjectName(QStringLiteral("rangeLabel"));
    m_limit = new QLabel(this);
    m_limit->setObjectName(QStringLiteral("limitLabel"));
    m_limit->setStyleSheet(QStringLiteral("QLabel { background: #fff4e5; border: 1px solid #e0a040; padding: 4px; }"));
    m_limit->hide();
    for (QLabel *label : {m_grashof, m_range, m_limit}) {
        label->setWordWrap(true);
        label->setFont(labelFont);
        label->setTextFormat(Qt::RichText);
        words->addWidget(label);
    }
    words->addStretch(1);
    // The words beside the gauge (3 : 2), or above it where a small window has no room
    QGroupBox *transmission = createTransmissionGroup(labelFont);
    m_infoReflow = new GridReflow(infoBox, info, {{wordsBox}, {transmission}}, 0, 12, {3, 2});
    details->addWidget(new FitScrollArea(infoBox, this)); // scrolls where a small window cuts it

    // -- plots ----------------------------------------------------------------------------------
    m_plots = new FourBarPlots(this);
    layout->addWidget(m_plots, 1);
    connect(m_plots, &FourBarPlots::alphaRequested, this, [this](double alpha) {
        if (!m_document)
            return;
        if (auto moved = m_document->setVariable(FourBar::variableAlpha, alpha); !moved)
            emit statusMessage(QString::fromStdString(moved.failure().message), true);
    });
    retranslate();
}

void FourBarPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void FourBarPanel::retranslate()
{
    m_linksGroup->setTitle(tr("Link lengths"));
    const std::array<QString, 4> titles = {tr("AB crank"), tr("BC coupler"), tr("CD rocker"), tr("AD ground")};
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        m_rows[i].label->setText(titles[i]);
        QDoubleSpinBox *spin = m_rows[i].spinBox;
        spin->setSuffix(QLatin1Char(' ') + unitText(units::millimetre));
        // Wide enough for "888.88 mm" whole (its hint is for the range's 100000.00 mm), so
        // that two to a line are only placed where the lengths are not cut; a metre or more
        // at the narrowest only (room for more took the Serbian docks' tabs' last pixels)
        const QFontMetrics metrics(spin->font());
        const auto text = [&](double v) { return metrics.horizontalAdvance(spin->textFromValue(v) + spin->suffix()); };
        spin->setMinimumWidth(spin->sizeHint().width() - text(spin->maximum()) + text(888.88));
    }
    for (GridReflow *reflow : {m_linksReflow, m_infoReflow}) {
        if (reflow)
            reflow->refit();
    }
    m_transmissionGroup->setTitle(tr("Transmission angle γ at C"));
    m_transmissionGroup->setToolTip(tr("The crank drives the rocker well when γ stays between %1° and %2°.")
                                        .arg(limitText(FourBar::poorTransmission),
                                            limitText(180.0 - FourBar::poorTransmission)));
    // The reason for a refused length came from the core in the old language: ask again.
    if (!m_linkFailure.isEmpty() && m_mechanism) {
        if (auto again = designfile::setDisplayParameter(m_mechanism, m_refusedLink, m_refusedValue); !again)
            m_linkFailure = QString::fromStdString(again.failure().message);
    }
    showLinkMessage();
    if (!fourbarOf(m_mechanism))
        return;
    showLengths(m_dragging < 0);
    showDesignInfo();
    showPose(m_pose);
}

QSlider *FourBarPanel::lengthSlider(const QString &link) const
{
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (link == QLatin1String(linkNames[i]))
            return m_rows[i].slider;
    return nullptr;
}

QDoubleSpinBox *FourBarPanel::lengthSpinBox(const QString &link) const
{
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (link == QLatin1String(linkNames[i]))
            return m_rows[i].spinBox;
    return nullptr;
}

bool FourBarPanel::requestLength(const QString &link, double value, bool continuous)
{
    if (!m_document || !fourbarOf(m_mechanism))
        return false;
    auto changed = m_document->setParameter(link, value, continuous);
    if (changed)
        return true;
    m_linkFailure = QString::fromStdString(changed.failure().message);
    m_refusedLink = link;
    m_refusedValue = value;
    showLinkMessage();
    showLengths(false); // the controls go back to the design
    emit statusMessage(m_linkFailure, true);
    return false;
}

void FourBarPanel::showLinkMessage()
{
    if (m_linkFailure.isEmpty()) {
        m_linkMessage->hide();
        return;
    }
    m_linkMessage->setText(m_linkFailure + QLatin1Char(' ') + tr("The last valid design is kept."));
    m_linkMessage->show();
}

void FourBarPanel::setDesign(const MechanismPtr &mechanism, const QString &)
{
    const FourBar *fourbar = fourbarOf(mechanism);
    if (!fourbar)
        return;
    m_mechanism = mechanism;
    m_linkFailure.clear(); // a design that arrives is valid
    m_linkMessage->hide();
    showLengths(m_dragging < 0);
    showDesignInfo();
    const Pose pose = m_document ? m_document->pose() : fourbar->homePose();
    m_plots->setDesign(mechanism, pose);
    setPose(pose);
}

void FourBarPanel::showLengths(bool ranges)
{
    const FourBar *fourbar = fourbarOf(m_mechanism);
    if (!fourbar)
        return;
    const FourBarDesign &d = fourbar->design();
    const std::array<double, 4> lengths = {d.crank, d.coupler, d.rocker, d.ground};
    // 1 mm … three times the longest link, in steps of 50 mm: room to grow every link
    const double longest = *std::max_element(lengths.begin(), lengths.end());
    const double top = std::max(100.0, std::ceil(3.0 * longest / 50.0) * 50.0);
    m_updating = true;
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        const QSignalBlocker blockSlider(m_rows[i].slider), blockSpin(m_rows[i].spinBox);
        if (ranges || int(i) != m_dragging) {
            m_rows[i].slider->setRange(sliderScale, int(std::lround(top * sliderScale)));
            m_rows[i].slider->setPageStep(10 * sliderScale);
            m_rows[i].slider->setSingleStep(sliderScale);
        }
        m_rows[i].slider->setValue(int(std::lround(lengths[i] * sliderScale)));
        m_rows[i].spinBox->setValue(lengths[i]);
        for (QWidget *w : std::initializer_list<QWidget *> {m_rows[i].slider, m_rows[i].spinBox}) {
            const auto &infos = fourbar->parameterInfo();
            const auto info = std::find_if(
                infos.begin(), infos.end(), [&](const ParameterInfo &p) { return p.name == linkNames[i]; });
            if (info != infos.end())
                w->setToolTip(tr("%1: %2").arg(QLatin1String(linkNames[i]), coreLabel(info->label)));
        }
    }
    m_updating = false;
}

void FourBarPanel::showDesignInfo()
{
    const FourBar *fourbar = fourbarOf(m_mechanism);
    const FourBarDesign &d = fourbar->design();

    // Grashof: s + l against p + q
    std::array<std::pair<double, const char *>, 4> links = {
        std::pair {d.crank, "AB"}, std::pair {d.coupler, "BC"}, std::pair {d.rocker, "CD"}, std::pair {d.ground, "AD"}};
    std::stable_sort(links.begin(), links.end(), [](const auto &x, const auto &y) { return x.first < y.first; });
    const auto &s = links[0], &l = links[3], &p = links[1], &q = links[2];
    const fourbar::Grashof g = FourBar::grashof(d);
    const QString relation = g == fourbar::Grashof::ChangePoint ? QStringLiteral("=")
        : g == fourbar::Grashof::TripleRocker                   ? QStringLiteral(">")
                                                                : QStringLiteral("<");
    QString meaning;
    switch (g) {
    case fourbar::Grashof::CrankRocker:
        meaning = tr("the crank AB, the shortest link, turns fully; the rocker CD swings.");
        break;
    case fourbar::Grashof::RockerCrank:
        meaning = tr("the rocker CD, the shortest link, could turn fully; the crank AB only swings.");
        break;
    case fourbar::Grashof::DoubleCrank:
        meaning = tr("the ground AD is the shortest link: the crank and the rocker both turn fully (drag link).");
        break;
    case fourbar::Grashof::DoubleRocker:
        meaning = tr("the coupler BC is the shortest link: the crank and the rocker only swing.");
        break;
    case fourbar::Grashof::TripleRocker:
        meaning = tr("non-Grashof: no link turns fully.");
        break;
    case fourbar::Grashof::ChangePoint:
        meaning = tr("the links can fold flat in line, where the open and crossed branches meet.");
        break;
    }
    const QString name = grashofTitle(g);
    const QString mm = unitText(units::millimetre);
    auto sum = [&mm](const std::pair<double, const char *> &a, const std::pair<double, const char *> &b) {
        // unbreakable pieces: the label wraps between the sums or before a sum's total (on a
        // narrow projector screen), never inside a term
        const QChar nbsp(0x00A0);
        return QStringLiteral("%1 + %2 = %3 + %4 =")
                   .arg(QLatin1String(a.second), QLatin1String(b.second), lengthText(a.first), lengthText(b.first))
                   .replace(QLatin1Char(' '), nbsp)
            + QLatin1Char(' ') + QStringLiteral("%1 %2").arg(lengthText(a.first + b.first), mm).replace(QLatin1Char(' '), nbsp);
    };
    m_grashof->setText(tr("<b>%1</b>: s + l = %2 %3 p + q = %4; %5")
                           .arg(name, sum(s, l), relation.toHtmlEscaped(), sum(p, q), meaning));

    // the ranges of α and δ
    const Interval alpha = fourbar->variableRange(FourBar::variableAlpha);
    const Interval delta = fourbar->variableRange(FourBar::variableDelta);
    const QString alphaText = fourbar->crankTurnsFully()
        ? tr("<b>α</b>: the crank turns fully, %1 … %2").arg(degreeText(alpha.min, 0), degreeText(alpha.max, 0))
        : tr("<b>α</b> assembles from %1 to %2 only: at the ends the coupler and the rocker are in line (dead "
             "points)")
              .arg(degreeText(alpha.min, 2), degreeText(alpha.max, 2));
    m_range->setText((d.branch == fourbar::crossed ? tr("%1. <b>δ</b> swings over %2 … %3 (crossed branch).")
                                                   : tr("%1. <b>δ</b> swings over %2 … %3 (open branch)."))
                         .arg(alphaText, degreeText(delta.min), degreeText(delta.max)));
    m_infoReflow->refit(); // the words' longest word: beside the gauge or above it

    // |γ| over the motion
    double lo = 180.0, hi = 0.0;
    for (int i = 0; i <= motionSamples; ++i) {
        Coordinates inputs(1);
        inputs << alpha.min + (alpha.max - alpha.min) * i / motionSamples;
        const auto pose = fourbar->solveDirect(inputs);
        if (!pose)
            continue;
        const double gamma = std::abs(fourbar::angles(d, pose->inputs[0], pose->outputs[0]).gamma) / units::degree;
        lo = std::min(lo, gamma);
        hi = std::max(hi, gamma);
    }
    m_gammaMin = lo;
    m_gammaMax = hi;
    const bool poorSomewhere = isPoor(lo) || isPoor(hi);
    m_transmissionRange->setText(poorSomewhere
            ? tr("<span style='color:#b3261e'>over the motion %1° … %2°: enters the poor band</span>")
                  .arg(QLocale().toString(lo, 'f', 1), QLocale().toString(hi, 'f', 1))
            : tr("over the motion %1° … %2°: inside %3° … %4°")
                  .arg(QLocale().toString(lo, 'f', 1), QLocale().toString(hi, 'f', 1),
                      limitText(FourBar::poorTransmission), limitText(180.0 - FourBar::poorTransmission)));
}

void FourBarPanel::setPresenting(bool on)
{
    m_details->setVisible(!on);
}

void FourBarPanel::setPose(const Pose &pose)
{
    const FourBar *fourbar = fourbarOf(m_mechanism);
    if (!fourbar || pose.inputs.size() != 1 || pose.outputs.size() != 1)
        return;
    m_pose = pose;
    m_plots->setPose(pose);
    showPose(pose);
}

void FourBarPanel::showPose(const Pose &pose)
{
    const FourBar *fourbar = fourbarOf(m_mechanism);
    if (!fourbar || pose.inputs.size() != 1 || pose.outputs.size() != 1)
        return;
    const double gamma = fourbar::angles(fourbar->design(), pose.inputs[0], pose.outputs[0]).gamma / units::degree;
    m_poor = isPoor(gamma);
    const QString value
        = QStringLiteral("γ = %1°").arg(QLocale().toString(gamma, 'f', 1).replace(QLatin1Char('-'), QChar(0x2212)));
    if (m_poor) {
        m_transmission->setText(
            tr("%1 — poor: %2")
                .arg(value,
                    std::abs(gamma) < 90.0 ? tr("below %1°").arg(limitText(FourBar::poorTransmission))
                                           : tr("above %1°").arg(limitText(180.0 - FourBar::poorTransmission))));
        m_transmission->setStyleSheet(QStringLiteral("QLabel { color: #b3261e; }"));
    } else {
        m_transmission->setText(value);
        m_transmission->setStyleSheet(QString());
    }
    m_transmission->setProperty("warning", m_poor);
    m_gauge->setValues(std::abs(gamma), m_gammaMin, m_gammaMax);
    showLimit(pose);
}

void FourBarPanel::showLimit(const Pose &pose)
{
    const FourBar *fourbar = fourbarOf(m_mechanism);
    m_limitText.clear();
    if (!fourbar->crankTurnsFully()) {
        const Interval range = fourbar->variableRange(FourBar::variableAlpha);
        const double alpha = pose.inputs[0];
        const double tolerance = 1e-9 * std::max({1.0, std::abs(range.min), std::abs(range.max)});
        const bool atMax = alpha >= range.max - tolerance, atMin = alpha <= range.min + tolerance;
        if (atMax || atMin) {
            const QString reason = QString::fromStdString(fourbar->rangeLimitReason(FourBar::variableAlpha, atMax));
            m_limitText = atMax ? tr("α stops at its upper limit: %1.").arg(reason)
                                : tr("α stops at its lower limit: %1.").arg(reason);
        }
    }
    m_limit->setText(m_limitText.toHtmlEscaped());
    m_limit->setVisible(!m_limitText.isEmpty());
    m_infoReflow->refit();
}

} // namespace pkm
