#include "kinds/sweepplotspanel.h"

#include "plotfont.h"
#include "plotstyle.h"
#include "quantityformat.h"
#include "symboltext.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <cmath>
#include <limits>

namespace pkm {

namespace {

/// Samples along the input's range: as the parameter sheet's sweep plots.
constexpr int sweepSteps = 241;

/// The scalar report entries, the input variable's own left out.
std::vector<const ReportEntry *> plottable(const Mechanism &mechanism)
{
    std::vector<const ReportEntry *> entries;
    const std::string &input = mechanism.variableInfo().front().name;
    for (const ReportEntry &entry : mechanism.reportLayout().entries) {
        if (entry.rows * entry.cols == 1 && entry.name != input)
            entries.push_back(&entry);
    }
    return entries;
}

} // namespace

SweepPlotsPanel::SweepPlotsPanel(QWidget *parent)
    : KindPanel(parent)
    , m_quantity(new SymbolComboBox(this))
    , m_plot(new QCustomPlot(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *row = new QHBoxLayout;
    row->setContentsMargins(8, 4, 8, 0);
    auto *label = new QLabel(this);
    label->setObjectName(QStringLiteral("quantityLabel"));
    label->setBuddy(m_quantity);
    m_quantity->setObjectName(QStringLiteral("quantityBox"));
    m_quantity->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    row->addWidget(label);
    row->addWidget(m_quantity);
    row->addStretch(1);
    layout->addLayout(row);
    layout->addWidget(m_plot, 1);

    const plotstyle::Header header = plotstyle::apply(m_plot, font());
    m_title = header.title;
    m_cursorLayer = header.cursorLayer;
    m_curve = m_plot->addGraph();
    m_curve->setPen(QPen(QColor::fromRgb(plotstyle::designRgb), 2.5));
    m_cursor = m_plot->addGraph();
    m_cursor->setLayer(header.cursorLayer);
    m_cursor->setLineStyle(QCPGraph::lsNone);
    m_cursor->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QColor::fromRgb(plotstyle::cursorRgb),
                                              Qt::white, 9));
    m_cursor->removeFromLegend();
    m_plot->legend->setVisible(false);
    connect(m_quantity, &QComboBox::currentIndexChanged, this, [this] { recompute(); });
    retranslate();
}

bool SweepPlotsPanel::canShow(const Mechanism &mechanism)
{
    return mechanism.inputCount() == 1 && !mechanism.variableInfo().empty() && !plottable(mechanism).empty();
}

void SweepPlotsPanel::setDesign(const MechanismPtr &mechanism, const QString &)
{
    const bool sameKind = m_mechanism && mechanism && m_mechanism->kind() == mechanism->kind();
    m_mechanism = mechanism;
    if (!sameKind)
        fillQuantities(); // a design of the same kind keeps the quantity chosen
    recompute();
}

void SweepPlotsPanel::setPose(const Pose &pose)
{
    m_pose = pose;
    placeCursor();
    m_cursorLayer->replot();
}

void SweepPlotsPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        const QString chosen = m_quantity->currentData().toString();
        fillQuantities();
        const int index = m_quantity->findData(chosen);
        if (index >= 0)
            m_quantity->setCurrentIndex(index);
        recompute();
    }
    KindPanel::changeEvent(event);
}

void SweepPlotsPanel::retranslate()
{
    if (auto *label = findChild<QLabel *>(QStringLiteral("quantityLabel")))
        label->setText(tr("&Quantity:"));
}

void SweepPlotsPanel::fillQuantities()
{
    const QSignalBlocker blocker(m_quantity);
    m_quantity->clear();
    if (!m_mechanism || !canShow(*m_mechanism))
        return;
    for (const ReportEntry *entry : plottable(*m_mechanism)) {
        m_quantity->addItem(QStringLiteral("%1 — %2").arg(toQString(entry->symbol), coreLabel(entry->label)),
                            toQString(entry->name));
    }
}

void SweepPlotsPanel::recompute()
{
    m_inputs.clear();
    m_values.clear();
    m_curve->data()->clear();
    if (!m_mechanism || !canShow(*m_mechanism) || m_quantity->currentIndex() < 0) {
        m_plot->replot();
        return;
    }
    const Mechanism &mechanism = *m_mechanism;
    const VariableInfo &input = mechanism.variableInfo().front();
    const ReportEntry *entry = mechanism.reportLayout().find(m_quantity->currentData().toString().toStdString());
    if (!entry)
        return;
    const Interval range = mechanism.variableRange(0);
    std::vector<double> buffer(static_cast<std::size_t>(mechanism.reportLayout().size));
    Pose last = mechanism.homePose();
    const double gap = std::numeric_limits<double>::quiet_NaN(); // QCustomPlot breaks the line at NaN
    for (int i = 0; i < sweepSteps; ++i) {
        const double q = range.min + (range.max - range.min) * i / (sweepSteps - 1);
        Coordinates inputs = last.inputs;
        inputs[0] = q;
        double value = gap;
        if (auto solved = mechanism.solveDirect(inputs, &last)) {
            last = *solved;
            mechanism.evaluate(*solved, buffer);
            const double v = buffer[static_cast<std::size_t>(entry->offset)];
            if (std::isfinite(v))
                value = entry->unit.toDisplay(v);
        }
        m_inputs.push_back(input.unit.toDisplay(q));
        m_values.push_back(value);
        m_curve->addData(m_inputs.back(), value);
    }

    const QString inputName = QStringLiteral("%1 (%2)").arg(toQString(input.symbol), unitText(input.unit));
    const QString valueName = entry->unit.symbol.empty()
        ? toQString(entry->symbol)
        : QStringLiteral("%1 (%2)").arg(toQString(entry->symbol), unitText(entry->unit));
    m_plot->xAxis->setLabel(inputName);
    m_plot->yAxis->setLabel(valueName);
    plotstyle::setFittedText(m_title, tr("%1 against %2").arg(coreLabel(entry->label), coreLabel(input.label)));
    m_plot->xAxis->setRange(input.unit.toDisplay(range.min), input.unit.toDisplay(range.max));
    bool found = false;
    const QCPRange values = m_curve->data()->valueRange(found);
    if (found) {
        const double pad = values.size() > 0 ? 0.05 * values.size() : std::max(1.0, 0.05 * std::abs(values.center()));
        m_plot->yAxis->setRange(values.lower - pad, values.upper + pad);
    }
    placeCursor();
    m_plot->replot();
}

void SweepPlotsPanel::placeCursor()
{
    m_cursor->data()->clear();
    if (!m_mechanism || m_pose.inputs.size() < 1 || m_quantity->currentIndex() < 0)
        return;
    const Mechanism &mechanism = *m_mechanism;
    const ReportEntry *entry = mechanism.reportLayout().find(m_quantity->currentData().toString().toStdString());
    if (!entry)
        return;
    std::vector<double> buffer(static_cast<std::size_t>(mechanism.reportLayout().size));
    mechanism.evaluate(m_pose, buffer);
    m_cursorInput = mechanism.variableInfo().front().unit.toDisplay(m_pose.inputs[0]);
    const double v = buffer[static_cast<std::size_t>(entry->offset)];
    if (std::isfinite(v))
        m_cursor->addData(m_cursorInput, entry->unit.toDisplay(v));
}

} // namespace pkm
