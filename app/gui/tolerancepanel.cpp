#include "gui/tolerancepanel.h"

#include "document/document.h"
#include "gui/backgroundtask.h"
#include "quantityformat.h"
#include "symboltext.h"

#include <qcustomplot.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace pkm {

namespace {
enum Column { ColumnParameter, ColumnTolerance, ColumnContribution, ColumnShare, ColumnCount };
constexpr int histogramBins = 30;

/// "∞" for an unbounded value, "—" for an undefined one, else the quantity.
QString quantityText(double core, const Unit &unit, int decimals)
{
    if (std::isinf(core))
        return QStringLiteral("∞");
    if (std::isnan(core))
        return QStringLiteral("—");
    return formatQuantity(core, unit, decimals);
}
} // namespace

TolerancePanel::TolerancePanel(Document *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_table(new QTableWidget(0, ColumnCount, this))
    , m_summary(new QLabel(this))
    , m_samplesLabel(new QLabel(this))
    , m_samples(new QSpinBox(this))
    , m_normal(new QCheckBox(this))
    , m_runButton(new QPushButton(this))
    , m_mapButton(new QPushButton(this))
    , m_clearButton(new QPushButton(this))
    , m_result(new QLabel(this))
    , m_plot(new QCustomPlot(this))
    , m_tabs(new QTabWidget(this))
{
    setObjectName(QStringLiteral("tolerancePanel"));
    m_table->setObjectName(QStringLiteral("toleranceTable"));
    m_table->verticalHeader()->hide();
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    // Every column as wide as its text, the parameters' names whole ("x_R1 (mm)" was cut to
    // "x_R…" with the header "Paramete" in a 340 px dock); the share takes what is left, and
    // a narrower dock scrolls rather than cutting a name.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    m_summary->setWordWrap(true);
    m_summary->setObjectName(QStringLiteral("toleranceSummary"));
    m_result->setWordWrap(true);
    m_result->setObjectName(QStringLiteral("toleranceResult"));
    m_samples->setRange(100, tolerance::maxSamples);
    m_samples->setSingleStep(500);
    m_samples->setValue(tolerance::defaultSamples);
    m_runButton->setObjectName(QStringLiteral("toleranceRun"));
    m_mapButton->setObjectName(QStringLiteral("toleranceMap"));
    m_plot->setMinimumHeight(110);
    m_plot->setMinimumWidth(100);
    m_table->setMinimumWidth(100);
    m_plot->setObjectName(QStringLiteral("tolerancePlot"));

    // narrow rows: the dock shares the left column (at most 270 px wide on a 1024 px screen)
    auto *controls = new QHBoxLayout;
    controls->addWidget(m_samplesLabel);
    controls->addWidget(m_samples);
    controls->addStretch();
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_runButton);
    buttons->addWidget(m_mapButton);
    buttons->addWidget(m_clearButton);
    buttons->addStretch();
    // At 1280×720 the dock shares the left column with the design: the summary stays in
    // view, the table and the Monte Carlo take turns in two tabs.
    auto *runPage = new QWidget(this);
    auto *runLayout = new QVBoxLayout(runPage);
    runLayout->setContentsMargins(0, 0, 0, 0);
    runLayout->addLayout(controls);
    runLayout->addWidget(m_normal);
    runLayout->addLayout(buttons);
    runLayout->addWidget(m_result);
    runLayout->addWidget(m_plot, 1);
    m_tabs->addTab(m_table, QString());
    m_tabs->addTab(runPage, QString());
    m_tabs->setObjectName(QStringLiteral("toleranceTabs"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0); // as narrow as the other docks: 1024 px screens
    layout->addWidget(m_summary);
    layout->addWidget(m_tabs, 1);

    connect(m_runButton, &QPushButton::clicked, this, &TolerancePanel::runMonteCarlo);
    connect(m_mapButton, &QPushButton::clicked, this, &TolerancePanel::runMap);
    connect(m_clearButton, &QPushButton::clicked, m_document, &Document::clearTolerances);
    connect(m_document, &Document::designChanged, this, [this] {
        m_monteCarlo.reset();
        m_result->clear();
        m_plot->clearPlottables();
        m_plot->replot();
        rebuildRows();
    });
    connect(m_document, &Document::tolerancesChanged, this, &TolerancePanel::rebuildRows);
    connect(m_document, &Document::poseChanged, this, &TolerancePanel::updateFirstOrder);
    retranslate();
    rebuildRows();
}

std::shared_ptr<const tolerance::Analysis> TolerancePanel::analysis(QString *why)
{
    if (!m_analysisValid) {
        m_analysisValid = true;
        m_analysis.reset();
        m_why.clear();
        const MechanismPtr &mechanism = m_document->mechanism();
        if (!mechanism || m_document->tolerances().empty()) {
            m_why = tr("Give a tolerance to at least one parameter.");
        } else if (auto made = tolerance::Analysis::make(mechanism, m_document->tolerances())) {
            m_analysis = std::make_shared<const tolerance::Analysis>(std::move(*made));
        } else {
            m_why = QString::fromStdString(made.failure().message);
        }
    }
    if (why)
        *why = m_why;
    return m_analysis;
}

void TolerancePanel::rebuildRows()
{
    const MechanismPtr &mechanism = m_document->mechanism();
    m_analysisValid = false;
    m_filling = true;
    m_names.clear();
    m_table->setRowCount(0);
    if (mechanism) {
        for (const ParameterInfo &info : mechanism->parameterInfo()) {
            if (!tolerance::checkParameter(*mechanism, info.name))
                continue;
            const int row = m_table->rowCount();
            m_table->insertRow(row);
            m_names.push_back(info.name);
            // a ratio (λ, k) has no unit to name: "λ", not "λ ()"
            const QString unitName = unitText(info.unit);
            auto *name = new QTableWidgetItem(unitName.isEmpty() ? toQString(info.symbol)
                                                             : QStringLiteral("%1 (%2)").arg(toQString(info.symbol), unitName));
            name->setToolTip(coreLabel(info.label));
            name->setFlags(Qt::ItemIsEnabled);
            m_table->setItem(row, ColumnParameter, name);
            auto *spin = new NumberSpinBox(m_table);
            spin->setPrefix(QStringLiteral("±"));
            spin->setDecimals(info.decimals + 2);
            spin->setRange(0.0, 1e4);
            spin->setSingleStep(info.displayStep / 100.0);
            spin->setKeyboardTracking(false);
            spin->setFrame(false);
            const auto found = m_document->tolerances().find(info.name);
            spin->setValue(found == m_document->tolerances().end() ? 0.0 : info.unit.toDisplay(found->second));
            const std::string key = info.name;
            const Unit unit = info.unit;
            connect(spin, &QDoubleSpinBox::valueChanged, this, [this, key, unit](double display) {
                if (m_filling)
                    return;
                auto set = m_document->setTolerance(toQString(key), unit.fromDisplay(display));
                if (!set) {
                    m_summary->setText(QString::fromStdString(set.failure().message));
                    QTimer::singleShot(0, this, &TolerancePanel::rebuildRows); // back to the document's value
                }
            });
            m_table->setCellWidget(row, ColumnTolerance, spin);
            for (const int column : {ColumnContribution, ColumnShare}) {
                auto *item = new QTableWidgetItem;
                item->setFlags(Qt::ItemIsEnabled);
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                m_table->setItem(row, column, item);
            }
        }
    }
    m_filling = false;
    updateFirstOrder();
}

void TolerancePanel::updateFirstOrder()
{
    for (int row = 0; row < m_table->rowCount(); ++row) {
        m_table->item(row, ColumnContribution)->setText(QString());
        m_table->item(row, ColumnShare)->setText(QString());
    }
    QString why;
    const auto a = analysis(&why);
    m_runButton->setEnabled(a != nullptr);
    const MechanismPtr &mechanism = m_document->mechanism();
    m_mapButton->setEnabled(a && mechanism && mechanism->planarWorkspace());
    m_clearButton->setEnabled(!m_document->tolerances().empty());
    if (!a) {
        m_summary->setText(why);
        return;
    }
    const tolerance::FirstOrder f = a->firstOrder(m_document->pose());
    const Unit unit = tolerance::normUnit(*mechanism);
    for (const tolerance::Contribution &c : f.parameters) {
        const auto it = std::find(m_names.begin(), m_names.end(), c.name);
        if (it == m_names.end())
            continue;
        const int row = int(it - m_names.begin());
        m_table->item(row, ColumnContribution)->setText(quantityText(c.contribution, unit, 4));
        m_table->item(row, ColumnShare)->setText(std::isfinite(c.share) ? QLocale().toString(100.0 * c.share, 'f', 1) + QStringLiteral(" %")
                                                                        : QStringLiteral("—"));
    }
    QStringList outputs;
    for (int k = 0; k < mechanism->outputCount(); ++k) {
        const VariableInfo &info = mechanism->variableInfo()[std::size_t(mechanism->inputCount() + k)];
        outputs << QStringLiteral("Δ%1 ≤ ±%2").arg(toQString(info.symbol), quantityText(f.worst[k], info.unit, 4));
    }
    QString text = tr("First-order worst case at this pose: |Δx| ≤ %1 (%2).")
                       .arg(quantityText(f.worstNorm, unit, 4), outputs.join(QStringLiteral(", ")));
    if (!f.finite)
        text += QLatin1Char(' ') + QString::fromStdString(f.reason);
    m_summary->setText(text);
}

void TolerancePanel::runMonteCarlo()
{
    QString why;
    const auto a = analysis(&why);
    if (!a) {
        m_result->setText(why);
        return;
    }
    auto shared = a;
    auto result = std::make_shared<tolerance::MonteCarlo>();
    const Pose pose = m_document->pose();
    tolerance::MonteCarloOptions options;
    options.samples = m_samples->value();
    options.distribution = m_normal->isChecked() ? tolerance::Distribution::Normal : tolerance::Distribution::Uniform;
    runWithProgress(
        this, tr("Monte Carlo"), tr("Solving %1 designs within the tolerances…").arg(options.samples),
        [shared, result, pose, options](const std::atomic<bool> &cancel, const TaskProgress &progress) -> TaskFailure {
            *result = shared->monteCarlo(pose, options, &cancel, [&](int done, int total) { progress(done, total); });
            return std::nullopt;
        },
        [this, result, shared](const TaskFailure &, bool cancelled) {
            if (cancelled || result->cancelled) {
                m_result->setText(tr("Monte Carlo cancelled."));
                return;
            }
            m_monteCarlo = *result;
            m_tabs->setCurrentIndex(1);
            showHistogram();
        });
}

void TolerancePanel::showHistogram()
{
    const tolerance::MonteCarlo &mc = *m_monteCarlo;
    const MechanismPtr &mechanism = m_document->mechanism();
    const Unit unit = tolerance::normUnit(*mechanism);
    const QString failed = tr("%1 of %2 samples did not assemble (%3 %).")
                               .arg(mc.failed)
                               .arg(mc.samples)
                               .arg(QLocale().toString(100.0 * mc.failedFraction(), 'f', 1));
    m_plot->clearPlottables();
    if (mc.assembled() == 0) {
        m_result->setText(tr("No sample assembled: the distribution is undefined.") + QLatin1Char(' ') + failed);
        m_plot->replot();
        return;
    }
    m_result->setText(tr("Monte Carlo |Δx|: mean %1, σ %2, max %3. %4")
                          .arg(quantityText(mc.normMean, unit, 4), quantityText(mc.normDeviation, unit, 4),
                               quantityText(mc.normMax, unit, 4), failed));
    // the histogram of |Δx| in display units
    const double top = unit.toDisplay(mc.normMax) > 0 ? unit.toDisplay(mc.normMax) : 1.0;
    const double width = top / histogramBins;
    QVector<double> centres(histogramBins), counts(histogramBins, 0.0);
    for (int b = 0; b < histogramBins; ++b)
        centres[b] = (b + 0.5) * width;
    for (const double e : mc.norms)
        counts[std::min(histogramBins - 1, int(unit.toDisplay(e) / width))] += 1.0;
    auto *bars = new QCPBars(m_plot->xAxis, m_plot->yAxis);
    bars->setWidth(width);
    bars->setData(centres, counts, true);
    bars->setBrush(QColor(70, 120, 200, 160));
    bars->setPen(QPen(QColor(40, 80, 160)));
    m_plot->xAxis->setLabel(tr("|Δx| (%1)").arg(unitText(unit)));
    m_plot->yAxis->setLabel(tr("samples"));
    m_plot->xAxis->setRange(0.0, top * 1.05);
    m_plot->yAxis->setRange(0.0, *std::max_element(counts.begin(), counts.end()) * 1.1);
    m_plot->replot();
}

void TolerancePanel::runMap()
{
    QString why;
    auto a = analysis(&why);
    const MechanismPtr mechanism = m_document->mechanism();
    if (!a || !mechanism->planarWorkspace()) {
        m_result->setText(a ? tr("This mechanism has no planar workspace to map.") : why);
        return;
    }
    auto shared = a;
    const MapGrid grid = squareGrid(mechanism->planarWorkspace()->workspaceBounds(), tolerance::defaultMapGrid);
    auto values = std::make_shared<std::vector<float>>(grid.cells());
    auto summary = std::make_shared<MapSummary>();
    const Pose pose = m_document->pose();
    runWithProgress(
        this, tr("Worst-case map"), tr("Mapping the worst-case error over the workspace…"),
        [shared, values, summary, grid, pose](const std::atomic<bool> &cancel, const TaskProgress &progress) -> TaskFailure {
            *summary = tolerance::computeMap(*shared, pose, grid, *values, &cancel,
                                             [&](int done, int total) { progress(done, total); });
            return std::nullopt;
        },
        [this, values, summary, grid, mechanism](const TaskFailure &, bool cancelled) {
            if (cancelled || summary->cancelled || mechanism != m_document->mechanism()) {
                m_result->setText(tr("Map cancelled."));
                return;
            }
            m_tabs->setCurrentIndex(1);
            showMap(grid, *values, *summary);
        });
}

void TolerancePanel::showMap(const MapGrid &grid, const std::vector<float> &values, const MapSummary &summary)
{
    const Unit unit = tolerance::normUnit(*m_document->mechanism());
    m_plot->clearPlottables();
    auto *map = new QCPColorMap(m_plot->xAxis, m_plot->yAxis);
    map->data()->setSize(grid.columns, grid.rows);
    map->data()->setRange(QCPRange(grid.x(0), grid.x(grid.columns - 1)), QCPRange(grid.y(0), grid.y(grid.rows - 1)));
    for (int r = 0; r < grid.rows; ++r) {
        for (int c = 0; c < grid.columns; ++c) {
            const float v = values[std::size_t(r) * std::size_t(grid.columns) + std::size_t(c)];
            // an unbounded cell (direct singularity) shows at the top of the scale
            map->data()->setCell(c, r, std::isnan(v) ? std::nan("") : std::isinf(v) ? summary.max : double(v));
            if (std::isnan(v))
                map->data()->setAlpha(c, r, 0);
        }
    }
    map->setGradient(QCPColorGradient::gpThermal);
    map->setDataRange(QCPRange(summary.min, std::max(summary.max, summary.min * 1.0001 + 1e-12)));
    m_plot->xAxis->setLabel(QStringLiteral("x (%1)").arg(unitText(units::millimetre)));
    m_plot->yAxis->setLabel(QStringLiteral("y (%1)").arg(unitText(units::millimetre)));
    m_plot->rescaleAxes();
    m_plot->replot();
    m_result->setText(tr("Worst case over the workspace: %1 to %2 (%3 cells; dark: small, bright: large).")
                          .arg(quantityText(summary.min, unit, 4), quantityText(summary.max, unit, 4))
                          .arg(summary.reachableCells));
}

void TolerancePanel::retranslate()
{
    m_table->setHorizontalHeaderLabels({tr("Parameter"), tr("Tolerance"), tr("Error part"), tr("Share")});
    m_tabs->setTabText(0, tr("Parameters"));
    m_tabs->setTabText(1, tr("Monte Carlo and map"));
    m_samplesLabel->setText(tr("Samples:"));
    m_normal->setText(tr("Normal (tol = 3σ)"));
    m_normal->setToolTip(tr("Draw normal samples with the tolerance as 3σ instead of uniform ones within ±tol"));
    m_runButton->setText(tr("Monte Carlo"));
    m_runButton->setToolTip(tr("Solve many designs drawn within the tolerances at this pose (fixed seed)"));
    m_mapButton->setText(tr("Map"));
    m_mapButton->setToolTip(tr("The first-order worst case over the workspace"));
    m_clearButton->setText(tr("Clear"));
    m_clearButton->setToolTip(tr("Remove every tolerance (undoable)"));
    m_analysisValid = false; // its message is in the old language
    updateFirstOrder();
    if (m_monteCarlo)
        showHistogram();
}

void TolerancePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace pkm
