#include "variablepanel.h"
#include "wraplabel.h"

#include "quantityformat.h"
#include "symboltext.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QResizeEvent>
#include <QSlider>

#include <cmath>

namespace pkm {

VariablePanel::VariablePanel(QWidget *parent)
    : QWidget(parent)
{
    m_grid = new QGridLayout(this);
    m_grid->setColumnStretch(2, 1);
    m_grid->setHorizontalSpacing(10);
}

void VariablePanel::setMechanism(const MechanismPtr &mechanism)
{
    // A design of the same kind may have other variables (a leg library's third leg, a crank
    // retyped to a slider): the rows follow the variables, not only the kind.
    bool rebuildNeeded = !m_mechanism || m_mechanism->kind() != mechanism->kind()
        || m_mechanism->variableInfo().size() != mechanism->variableInfo().size();
    for (std::size_t i = 0; !rebuildNeeded && i < mechanism->variableInfo().size(); ++i) {
        const VariableInfo &was = m_mechanism->variableInfo()[i], &is = mechanism->variableInfo()[i];
        rebuildNeeded = was.name != is.name || was.unit.symbol != is.unit.symbol || was.label != is.label;
    }
    m_mechanism = mechanism;
    if (rebuildNeeded)
        rebuild();
    updateRanges();
    fitLimits();
}

void VariablePanel::rebuild()
{
    while (QLayoutItem *item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_rows.clear();
    const auto &variables = m_mechanism->variableInfo();
    QFont big = font();
    if (!m_compact) // compact rows keep the panel's size (setCompact)
        big.setPointSizeF(big.pointSizeF() * 1.25);
    for (int i = 0; i < static_cast<int>(variables.size()); ++i) {
        const VariableInfo &info = variables[i];
        Row row;
        // The role wraps under the symbol where the panel is narrow (a projector at 1024×768)
        // rather than widening the window, on two lines at most (WrapLabel).
        row.name = new WrapLabel(2, this);
        row.name->setFont(big);
        row.minimum = new QLabel(this);
        row.maximum = new QLabel(this);
        row.minimum->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        row.slider = new QSlider(Qt::Horizontal, this);
        row.slider->setObjectName(QStringLiteral("slider_") + toQString(info.name));
        row.slider->setRange(0, sliderSteps);
        row.slider->setMinimumWidth(minimumSliderWidth);
        row.spinBox = new NumberSpinBox(this);
        row.spinBox->setObjectName(QStringLiteral("spin_") + toQString(info.name));
        row.spinBox->setDecimals(info.decimals);
        row.spinBox->setKeyboardTracking(false);
        row.spinBox->setAccelerated(true);
        row.spinBox->setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue); // past a limit: stop at it
        row.spinBox->setFont(big);
        row.spinBox->setMinimumWidth(110);
        row.spinBox->setAlignment(Qt::AlignRight);

        connect(row.slider, &QSlider::valueChanged, this, [this, i](int position) {
            if (m_updating)
                return;
            const Interval range = m_mechanism->variableRange(i);
            emit variableEdited(i, range.min + (range.max - range.min) * position / double(sliderSteps));
        });
        connect(row.slider, &QSlider::sliderPressed, this, &VariablePanel::sliderPressed);
        connect(row.slider, &QSlider::sliderReleased, this, &VariablePanel::sliderReleased);
        connect(row.spinBox, &QDoubleSpinBox::valueChanged, this, [this, i](double display) {
            if (m_updating)
                return;
            emit variableEdited(i, m_mechanism->variableInfo()[i].unit.fromDisplay(display));
        });

        m_rows.append(row);
        describe(i);
    }
    placeRows();
}

void VariablePanel::placeRows()
{
    // Compact, from four rows on, the rows share two blocks side by side (the inputs, then the
    // outputs): at 1280×720 the five-bar's four rows and a 3-DOF design's six, one under
    // another, left the linkage above them a strip 260 px high.
    const int count = int(m_rows.size());
    m_twoBlocks = wantsTwoBlocks();
    const int perBlock = m_twoBlocks ? (count + 1) / 2 : std::max(count, 1);
    for (Row &row : m_rows) {
        for (QWidget *widget : {static_cast<QWidget *>(row.name), static_cast<QWidget *>(row.minimum),
                 static_cast<QWidget *>(row.slider), static_cast<QWidget *>(row.maximum), static_cast<QWidget *>(row.spinBox)})
            m_grid->removeWidget(widget);
    }
    for (int i = 0; i < count; ++i) {
        const Row &row = m_rows[i];
        const int line = i % perBlock, first = (i / perBlock) * blockColumns;
        m_grid->addWidget(row.name, line, first);
        m_grid->addWidget(row.minimum, line, first + 1);
        m_grid->addWidget(row.slider, line, first + 2);
        m_grid->addWidget(row.maximum, line, first + 3);
        m_grid->addWidget(row.spinBox, line, first + 4);
    }
    const bool two = count > perBlock;
    m_grid->setColumnStretch(blockColumns + 2, two ? 1 : 0);
    m_grid->setColumnMinimumWidth(blockColumns - 1, two ? blockGap : 0);
}

void VariablePanel::describe(int i)
{
    const VariableInfo &info = m_mechanism->variableInfo()[std::size_t(i)];
    Row &row = m_rows[i];
    const QString symbol = toQString(info.symbol);
    const QString label = coreLabel(info.label);
    const QString role = info.actuated ? (m_compact ? tr("input") : tr("input, actuated")) : tr("output");
    row.name->setText(QStringLiteral("<b>%1</b> <span style='color:#555'>(%2)</span>").arg(symbolHtml(symbol), role));
    // compact: one line that the slider makes room for, never a second line the rows lack
    row.name->setWordWrap(!m_compact);
    row.name->setToolTip(label);
    const QString unit = unitText(info.unit);
    const QSignalBlocker blocker(row.spinBox);
    row.spinBox->setSuffix(unit.startsWith(QChar(0x00B0)) ? unit : QLatin1Char(' ') + unit);
}

int VariablePanel::blockWidth() const
{
    // a row without its limits: the name, a short slider and the spin box
    int name = 0, spin = 0;
    for (const Row &row : m_rows) {
        name = std::max(name, row.name->sizeHint().width());
        spin = std::max(spin, std::max(row.spinBox->minimumWidth(), row.spinBox->sizeHint().width()));
    }
    return name + minimumSliderWidth + spin + 2 * m_grid->horizontalSpacing();
}

bool VariablePanel::wantsTwoBlocks() const
{
    // only where both blocks fit: the O-X glide's Russian names asked for 1447 px
    const QMargins margins = m_grid->contentsMargins();
    return m_compact && m_rows.size() >= 4
        && width() >= 2 * blockWidth() + blockGap + m_grid->horizontalSpacing() + margins.left() + margins.right();
}

void VariablePanel::setCompact(bool compact)
{
    if (compact == m_compact)
        return;
    m_compact = compact;
    // Compact rows take the panel's text size, already large in presentation mode: the
    // quarter more of the usual rows would leave a 3-DOF design's six rows taller than a
    // 1280×720 projector's window has room for.
    QFont rows = font();
    if (!compact)
        rows.setPointSizeF(rows.pointSizeF() * 1.25);
    for (int i = 0; m_mechanism && i < m_rows.size(); ++i) {
        m_rows[i].name->setFont(rows);
        m_rows[i].spinBox->setFont(rows);
        describe(i);
    }
    placeRows();
    if (m_mechanism)
        updateRanges(); // the spin boxes' widths for their new text
}

void VariablePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        // The spin boxes show numbers in the panel's locale: the new language's (QLocale()).
        setLocale(QLocale());
        if (m_mechanism) {
            for (int i = 0; i < m_rows.size(); ++i)
                describe(i);
            updateRanges(); // the limits beside the sliders, in the new locale
        }
    } else if (event->type() == QEvent::FontChange && m_mechanism) {
        // A larger text size (presentation mode) needs wider spin boxes, or "183.10 mm" is cut
        // to "183.10 mı". Queued: the spin boxes take the new font after their panel does.
        QMetaObject::invokeMethod(this, [this] { if (m_mechanism) updateRanges(); }, Qt::QueuedConnection);
    }
    QWidget::changeEvent(event);
}

void VariablePanel::updateRanges()
{
    m_updating = true;
    const auto &variables = m_mechanism->variableInfo();
    for (int i = 0; i < m_rows.size(); ++i) {
        const VariableInfo &info = variables[i];
        const Interval range = m_mechanism->variableRange(i);
        Row &row = m_rows[i];
        row.minimum->setText(formatQuantity(range.min, info.unit, 1));
        row.maximum->setText(formatQuantity(range.max, info.unit, 1));
        row.slider->setToolTip(tr("Drag to set %1 (%2), from %3 to %4")
                                   .arg(toQString(info.symbol), coreLabel(info.label), row.minimum->text(), row.maximum->text()));
        // Round the spin box limits outwards to its decimals, so the exact limit is reachable.
        const double scale = std::pow(10.0, info.decimals);
        const double lo = info.unit.toDisplay(range.min), hi = info.unit.toDisplay(range.max);
        row.spinBox->setRange(std::floor(lo * scale) / scale, std::ceil(hi * scale) / scale);
        // One arrow click: about a hundredth of the range, as a power of ten (1° for ±60°).
        row.spinBox->setSingleStep(std::pow(10.0, std::floor(std::log10(std::max(hi - lo, 1e-9))) - 2));
        // Room for the longest value of the range with its unit: a narrow panel never cuts
        // "183.10 mm" to "183.10 mn".
        row.spinBox->setMinimumWidth(row.spinBox->sizeHint().width());
    }
    m_updating = false;
    // New limits' texts, a new language or text size change what the rows need: the limits
    // beside the sliders go where the panel no longer holds them, or the spin boxes were cut
    // at its edge (Russian in presentation mode) until the next resize.
    fitLimits();
}

int VariablePanel::limitsWidth() const
{
    int minimum = 0, maximum = 0;
    for (const Row &row : m_rows) {
        minimum = std::max(minimum, row.minimum->sizeHint().width());
        maximum = std::max(maximum, row.maximum->sizeHint().width());
    }
    return minimum + maximum + 2 * m_grid->horizontalSpacing();
}

QSize VariablePanel::minimumSizeHint() const
{
    QSize size = QWidget::minimumSizeHint();
    if (!m_rows.isEmpty() && !m_rows.first().minimum->isHidden())
        size.rwidth() -= limitsWidth();
    if (m_twoBlocks) { // narrower, the rows go one under another again
        const QMargins margins = m_grid->contentsMargins();
        size.setWidth(blockWidth() + margins.left() + margins.right());
    }
    return size;
}

void VariablePanel::fitLimits()
{
    if (m_rows.isEmpty())
        return;
    const bool shown = !m_rows.first().minimum->isHidden();
    const int without = QWidget::minimumSizeHint().width() - (shown ? limitsWidth() : 0);
    // A margin against flicker: shown again only with room to spare.
    const bool show = width() >= without + limitsWidth() + (shown ? 0 : 20);
    if (show == shown)
        return;
    for (Row &row : m_rows) {
        row.minimum->setVisible(show);
        row.maximum->setVisible(show);
    }
}

void VariablePanel::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    if (wantsTwoBlocks() != m_twoBlocks)
        placeRows();
    fitLimits();
}

void VariablePanel::setPose(const Pose &pose)
{
    m_updating = true;
    for (int i = 0; i < m_rows.size(); ++i) {
        const Interval range = m_mechanism->variableRange(i);
        const double value = m_mechanism->variableValue(pose, i);
        Row &row = m_rows[i];
        const double fraction = range.max > range.min ? (value - range.min) / (range.max - range.min) : 0.0;
        // While the user drags this slider, leave it where the hand is.
        if (!row.slider->isSliderDown())
            row.slider->setValue(static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * sliderSteps)));
        // The truth, also beyond the range: an output's range may be an estimate (the 3-RP̲R's
        // x is the workspace's extent at one orientation, and a pose at another goes past it),
        // and a spin box held to it showed 18.50 mm where the pose was at 19.41 mm.
        const double shown = m_mechanism->variableInfo()[i].unit.toDisplay(value);
        if (std::isfinite(shown) && (shown < row.spinBox->minimum() || shown > row.spinBox->maximum())) {
            const double scale = std::pow(10.0, row.spinBox->decimals());
            row.spinBox->setRange(std::min(row.spinBox->minimum(), std::floor(shown * scale) / scale),
                                  std::max(row.spinBox->maximum(), std::ceil(shown * scale) / scale));
        }
        row.spinBox->setValue(shown);
    }
    m_updating = false;
}

} // namespace pkm
