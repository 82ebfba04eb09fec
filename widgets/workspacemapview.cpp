#include "workspacemapview.h"

#include "plotfont.h"
#include "plotfit.h"
#include "plotticker.h"
#include "quantityformat.h"

#include <qcustomplot.h>

#include <QBoxLayout>
#include <QComboBox>
#include <QElapsedTimer>
#include <QEvent>
#include <QFutureWatcher>
#include <QLabel>
#include <QLocale>
#include <QMouseEvent>
#include <QStackedWidget>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace pkm {

/// A finished computation, built entirely on the worker thread: the GUI thread only hands
/// `colours` to the colour map and copies the curves.
struct WorkspaceMapResult {
    MapSummary summary;
    MapQuantity quantity = MapQuantity::Determinant;
    std::vector<float> values;                 ///< as computed (NaN: unreachable)
    std::unique_ptr<QCPColorMapData> colours;  ///< values clipped to the colour range; null for a comparison
    double colourLimit = 0.0;                  ///< det J: ±limit; κ: 1…limit
    QVector<QCPCurveData> outline;             ///< closed polylines separated by NaN points
    QVector<QCPCurveData> inverse, direct;     ///< singular curves, separated by NaN points
    int inverseCount = 0, directCount = 0;
    std::string inverseMeaning, directMeaning; ///< for the legend
};

struct WorkspaceMapView::Job {
    JobKind kind = JobKind::Map;
    int generation = 0;
    std::shared_ptr<std::atomic<bool>> cancel;
    QFutureWatcher<std::shared_ptr<WorkspaceMapResult>> *watcher = nullptr;
};

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
/// The colours are clipped at these percentiles of the reachable, finite values, so that the
/// spikes at inverse singularities (det J, κ → ∞) do not flatten the rest of the map.
constexpr double lowPercentile = 0.02, highPercentile = 0.98;

constexpr QRgb inverseRgb = 0xa50f15;    // dark red
constexpr QRgb directRgb = 0x111111;     // black, dashed
constexpr QRgb outlineRgb = 0x404040;    // dark grey
constexpr QRgb comparisonRgb = 0xc51b7d; // magenta, dashed: apart from both gradients
constexpr QRgb axisRgb = 0x303030;
constexpr QRgb markerRgb = 0x202020;

constexpr double tickPoints = 11, labelPoints = 12, titlePoints = 13, legendPoints = 11, controlPoints = 11,
                 messagePoints = 14;

/// "−46.3", "1.34", "1.41·10⁵": three significant digits, a real minus sign, powers of ten
/// written out for very large and very small magnitudes.
QString significant(double value)
{
    const QLocale locale;
    auto minus = [](QString text) { return text.replace(QLatin1Char('-'), QChar(0x2212)); };
    const double magnitude = std::abs(value);
    if (!std::isfinite(value) || magnitude == 0.0 || (magnitude >= 1e-3 && magnitude < 1e4))
        return minus(locale.toString(value, 'g', 3));
    int exponent = int(std::floor(std::log10(magnitude)));
    double mantissa = value / std::pow(10.0, exponent);
    if (std::abs(mantissa) >= 9.995) { // rounds up to 10
        mantissa /= 10.0;
        ++exponent;
    }
    static const QString superscripts = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    QString power;
    for (const QChar digit : QString::number(std::abs(exponent)))
        power += superscripts[digit.digitValue()];
    return minus(locale.toString(mantissa, 'g', 3)) + QStringLiteral("·10") + (exponent < 0 ? QStringLiteral("⁻") : QString())
        + power;
}

/// Ticks for κ on a logarithmic colour scale: powers of ten over many decades, 1-2-5 over a
/// few, 1-1.5-2-3-4-5-6-8 over less than one (QCPAxisTickerLog falls back to linear steps there).
class ConditionTicker : public MinusTicker
{
protected:
    int getSubTickCount(double) override { return 0; }
    QVector<double> createTickVector(double, const QCPRange &range) override
    {
        static const std::vector<std::vector<double>> sequences {{1.0}, {1.0, 2.0, 5.0}, {1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0}};
        const double lower = std::max(range.lower, 1e-12), upper = std::max(range.upper, lower);
        const int first = int(std::floor(std::log10(lower))), last = int(std::ceil(std::log10(upper)));
        QVector<double> ticks;
        for (const std::vector<double> &steps : sequences) {
            ticks.clear();
            const int decadeStep = steps.size() == 1 ? std::max(1, (last - first + 7) / 8) : 1;
            for (int e = first; e <= last; e += decadeStep)
                for (const double step : steps) {
                    const double tick = step * std::pow(10.0, e);
                    if (tick >= lower * (1 - 1e-9) && tick <= upper * (1 + 1e-9))
                        ticks.append(tick);
                }
            if (ticks.size() >= 4)
                break;
        }
        return ticks;
    }
};

/// det J: blue (negative) – white (0, direct singularity) – orange (positive).
QCPColorGradient determinantGradient()
{
    QCPColorGradient gradient;
    gradient.setColorInterpolation(QCPColorGradient::ciRGB);
    gradient.setColorStopAt(0.0, QColor(0x053061));
    gradient.setColorStopAt(0.15, QColor(0x2166ac));
    gradient.setColorStopAt(0.32, QColor(0x67a9cf));
    gradient.setColorStopAt(0.45, QColor(0xd1e5f0));
    gradient.setColorStopAt(0.5, QColor(0xf7f7f7));
    gradient.setColorStopAt(0.55, QColor(0xfee0b6));
    gradient.setColorStopAt(0.68, QColor(0xfdb863));
    gradient.setColorStopAt(0.85, QColor(0xe08214));
    gradient.setColorStopAt(1.0, QColor(0x7f3b08));
    gradient.setNanHandling(QCPColorGradient::nhTransparent);
    return gradient;
}

/// κ(J): light yellow (κ = 1, isotropic) to dark blue (near a singularity).
QCPColorGradient conditionGradient()
{
    QCPColorGradient gradient;
    gradient.setColorInterpolation(QCPColorGradient::ciRGB);
    gradient.setColorStopAt(0.0, QColor(0xffffd9));
    gradient.setColorStopAt(0.2, QColor(0xc7e9b4));
    gradient.setColorStopAt(0.45, QColor(0x41b6c4));
    gradient.setColorStopAt(0.7, QColor(0x225ea8));
    gradient.setColorStopAt(1.0, QColor(0x081d58));
    gradient.setNanHandling(QCPColorGradient::nhTransparent);
    return gradient;
}

/// The boundary segments of workspaceOutline() joined into closed polylines, so that a dashed
/// pen runs along the boundary instead of restarting at every cell edge. Each boundary vertex
/// of a set of grid cells ends one horizontal and one vertical run, so the walk is unique.
QVector<QCPCurveData> chainOutline(const std::vector<Eigen::Vector2d> &segments, const MapGrid &grid)
{
    QVector<QCPCurveData> curve;
    const int ends = static_cast<int>(segments.size() / 2 * 2);
    if (ends == 0)
        return curve;
    const double x0 = grid.bounds.min().x(), y0 = grid.bounds.min().y();
    const double dx = grid.dx(), dy = grid.dy();
    auto vertex = [&](const Eigen::Vector2d &p) {
        const std::int64_t c = std::llround((p.x() - x0) / dx), r = std::llround((p.y() - y0) / dy);
        return c * (grid.rows + 3) + r;
    };
    std::unordered_map<std::int64_t, std::array<int, 2>> at;
    at.reserve(std::size_t(ends));
    for (int e = 0; e < ends; ++e) {
        auto &slot = at.try_emplace(vertex(segments[std::size_t(e)]), std::array<int, 2> {-1, -1}).first->second;
        (slot[0] < 0 ? slot[0] : slot[1]) = e;
    }
    std::vector<bool> used(std::size_t(ends / 2), false);
    double t = 0.0;
    curve.reserve(ends + ends / 4);
    for (int start = 0; start < ends / 2; ++start) {
        if (used[std::size_t(start)])
            continue;
        int enter = 2 * start;
        curve.append(QCPCurveData(t++, segments[std::size_t(enter)].x(), segments[std::size_t(enter)].y()));
        for (;;) {
            used[std::size_t(enter / 2)] = true;
            const Eigen::Vector2d &p = segments[std::size_t(enter ^ 1)];
            curve.append(QCPCurveData(t++, p.x(), p.y()));
            const auto &slot = at[vertex(p)];
            const int next = slot[0] == (enter ^ 1) ? slot[1] : slot[0];
            if (next < 0 || used[std::size_t(next / 2)])
                break;
            enter = next;
        }
        curve.append(QCPCurveData(t++, nan, nan)); // a gap before the next polyline
    }
    return curve;
}

void appendPolyline(QVector<QCPCurveData> &curve, const std::vector<Eigen::Vector2d> &points)
{
    double t = curve.isEmpty() ? 0.0 : curve.constLast().t + 1.0;
    for (const Eigen::Vector2d &p : points)
        curve.append(QCPCurveData(t++, p.x(), p.y()));
    curve.append(QCPCurveData(t, nan, nan));
}

/// The worker: the map (and for the shown map its colours and singular curves) of one design.
/// Touches nothing but its arguments, so it may outlive the request that started it.
std::shared_ptr<WorkspaceMapResult> compute(const MechanismPtr &mechanism, MapQuantity quantity, int resolution,
    bool full, const std::shared_ptr<std::atomic<bool>> &cancel)
{
    auto result = std::make_shared<WorkspaceMapResult>();
    result->quantity = quantity;
    const PlanarWorkspace *workspace = mechanism ? mechanism->planarWorkspace() : nullptr;
    if (!workspace || cancel->load()) {
        result->summary.cancelled = true;
        return result;
    }
    const MapGrid grid = squareGrid(workspace->workspaceBounds(), resolution);
    result->values.resize(grid.cells());
    std::vector<float> margins(full ? grid.cells() : 0);
    result->summary = computeMap(*workspace, quantity, grid, result->values, margins, cancel.get());
    if (result->summary.cancelled || cancel->load()) {
        result->summary.cancelled = true;
        return result;
    }
    result->outline = chainOutline(workspaceOutline(grid, result->values), grid);
    if (!full)
        return result;

    // Colour limits from the percentiles of the reachable, finite values.
    std::vector<float> finite;
    finite.reserve(result->summary.reachableCells);
    for (const float v : result->values)
        if (std::isfinite(v))
            finite.push_back(v);
    auto percentile = [&](double share) {
        const auto k = std::size_t(share * double(finite.size() - 1) + 0.5);
        std::nth_element(finite.begin(), finite.begin() + std::ptrdiff_t(k), finite.end());
        return double(finite[k]);
    };
    const bool condition = quantity == MapQuantity::Condition;
    double limit = condition ? 10.0 : 1.0;
    if (!finite.empty()) {
        if (condition) {
            const double high = percentile(highPercentile);
            limit = high > 1.001 ? high : std::max(10.0, result->summary.max);
        } else {
            const double high = std::max(std::abs(percentile(lowPercentile)), std::abs(percentile(highPercentile)));
            limit = high > 0.0 ? high : std::max(1.0, std::max(-result->summary.min, result->summary.max));
        }
    }
    result->colourLimit = limit;
    const double lower = condition ? 1.0 : -limit;

    // The colour data, clipped to the colour range: QCPColorGradient turns values into indices
    // with int(), which an infinite value would overflow.
    auto colours = std::make_unique<QCPColorMapData>(grid.columns, grid.rows,
        QCPRange(grid.x(0), grid.x(grid.columns - 1)), QCPRange(grid.y(0), grid.y(grid.rows - 1)));
    for (int r = 0; r < grid.rows; ++r) {
        const float *row = result->values.data() + std::size_t(r) * std::size_t(grid.columns);
        for (int c = 0; c < grid.columns; ++c) {
            const double v = row[c];
            colours->setCell(c, r, std::isnan(v) ? nan : std::clamp(v, lower, limit));
        }
    }
    result->colours = std::move(colours);

    if (cancel->load()) {
        result->summary.cancelled = true;
        return result;
    }
    result->inverseMeaning = workspace->singularityMeaning(SingularCurve::Type::Inverse);
    result->directMeaning = workspace->singularityMeaning(SingularCurve::Type::Direct);
    for (const SingularCurve &curve : workspace->singularCurves()) {
        if (curve.type == SingularCurve::Type::Inverse) {
            appendPolyline(result->inverse, curve.points);
            ++result->inverseCount;
        } else {
            appendPolyline(result->direct, curve.points);
            ++result->directCount;
        }
    }
    return result;
}

QCPCurve *addCurve(QCustomPlot *plot, const QPen &pen)
{
    auto *curve = new QCPCurve(plot->xAxis, plot->yAxis);
    curve->setPen(pen);
    curve->setSelectable(QCP::stNone);
    curve->removeFromLegend();
    return curve;
}

QPen dashedPen(QRgb rgb, double width, const QVector<qreal> &pattern)
{
    QPen pen(QColor(rgb), width);
    pen.setDashPattern(pattern);
    pen.setCapStyle(Qt::FlatCap);
    pen.setJoinStyle(Qt::RoundJoin);
    return pen;
}

} // namespace

WorkspaceMapView::WorkspaceMapView(QWidget *parent)
    : QWidget(parent)
    , m_debounce(new QTimer(this))
    , m_quantityBox(new QComboBox(this))
    , m_quantityLabel(new QLabel(this))
    , m_stack(new QStackedWidget(this))
    , m_messageLabel(new QLabel)
    , m_plot(new QCustomPlot)
{
    m_debounce->setSingleShot(true);
    m_debounce->setInterval(debounceMilliseconds);
    connect(m_debounce, &QTimer::timeout, this, &WorkspaceMapView::startMap);

    // -- controls above the plot -------------------------------------------------------------
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    auto *controls = new QHBoxLayout;
    controls->setContentsMargins(4, 0, 4, 0);
    m_quantityLabel->setFont(fontOf(font(), controlPoints));
    m_quantityBox->setFont(fontOf(font(), controlPoints));
    m_quantityBox->addItem(QString(), int(MapQuantity::Determinant));
    m_quantityBox->addItem(QString(), int(MapQuantity::Condition));
    m_quantityLabel->setBuddy(m_quantityBox);
    controls->addWidget(m_quantityLabel);
    controls->addWidget(m_quantityBox);
    controls->addStretch(1);
    layout->addLayout(controls);
    layout->addWidget(m_stack, 1);
    connect(m_quantityBox, &QComboBox::activated, this,
        [this](int index) { setQuantity(MapQuantity(m_quantityBox->itemData(index).toInt())); });

    m_stack->addWidget(m_plot);
    m_messageLabel->setAlignment(Qt::AlignCenter);
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setFont(fontOf(font(), messagePoints));
    m_messageLabel->setStyleSheet(QStringLiteral("color: #505050; background: white;"));
    m_stack->addWidget(m_messageLabel);

    // -- the plot ------------------------------------------------------------------------------
    QCustomPlot *plot = m_plot;
    plot->setBackground(Qt::white);
    plot->setMinimumSize(320, 260);
    plot->installEventFilter(this);
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot->setNoAntialiasingOnDrag(false);

    // Layers, bottom to top: background, map (the colours), grid, main (boundaries, singular
    // curves), axes, legend, overlay, pose. The pose has its own buffer, so setPose() redraws
    // it alone; the overlay (QCP's selection rect, unused here) shares the buffer below.
    plot->addLayer(QStringLiteral("map"), plot->layer(QStringLiteral("grid")), QCustomPlot::limBelow);
    plot->layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    plot->addLayer(QStringLiteral("pose"), plot->layer(QStringLiteral("overlay")), QCustomPlot::limAbove);
    m_poseLayer = plot->layer(QStringLiteral("pose"));
    m_poseLayer->setMode(QCPLayer::lmBuffered);

    // Title and legend across the top; below them the axis rect with the colour scale at its
    // right, in a grid of their own so that the title may use the whole width.
    QCPLayoutGrid *grid = plot->plotLayout();
    QCPAxisRect *axisRect = plot->axisRect();
    grid->take(axisRect);
    grid->simplify();
    m_title = new QCPTextElement(plot, QString(), fontOf(font(), titlePoints, true));
    grid->addElement(0, 0, m_title);
    axisRect->insetLayout()->take(plot->legend);
    grid->addElement(1, 0, plot->legend);
    auto *mapRow = new QCPLayoutGrid;
    grid->addElement(2, 0, mapRow);
    mapRow->addElement(0, 0, axisRect);
    m_colorScale = new QCPColorScale(plot);
    mapRow->addElement(0, 1, m_colorScale);
    mapRow->setColumnStretchFactor(1, 0.001);
    mapRow->setColumnSpacing(4);
    for (int row = 0; row < 2; ++row)
        grid->setRowStretchFactor(row, 0.001);
    grid->setRowSpacing(2);
    auto *margins = new QCPMarginGroup(plot);
    axisRect->setMarginGroup(QCP::msTop | QCP::msBottom, margins);
    m_colorScale->setMarginGroup(QCP::msTop | QCP::msBottom, margins);

    plot->legend->setVisible(true);
    plot->legend->setFont(fontOf(font(), legendPoints));
    plot->legend->setBorderPen(Qt::NoPen);
    plot->legend->setIconSize(34, 14);
    plot->legend->setColumnSpacing(18);
    plot->legend->setRowSpacing(1);
    plot->legend->setMargins(QMargins(8, 2, 8, 2));
    plot->legend->setSelectableParts(QCPLegend::spNone);

    for (QCPAxis *axis : {plot->xAxis, plot->yAxis, plot->xAxis2, plot->yAxis2, m_colorScale->axis()}) {
        const QPen pen(QColor(axisRgb), 1.2);
        axis->setBasePen(pen);
        axis->setTickPen(pen);
        axis->setSubTickPen(QPen(QColor(axisRgb), 1.0));
        axis->setTickLabelFont(fontOf(font(), tickPoints));
        axis->setLabelFont(fontOf(font(), labelPoints));
        axis->grid()->setPen(QPen(QColor(0, 0, 0, 30), 1.0));
        axis->grid()->setZeroLinePen(QPen(QColor(0, 0, 0, 60), 1.0));
    }
    for (QCPAxis *axis : {plot->xAxis2, plot->yAxis2}) { // a closed frame, no second scale
        axis->setVisible(true);
        axis->setTicks(false);
        axis->setTickLabels(false);
        axis->grid()->setVisible(false);
    }
    for (QCPAxis *axis : {plot->xAxis, plot->yAxis})
        axis->setTicker(QSharedPointer<MinusTicker>::create());
    m_colorScale->setBarWidth(16);
    m_colorScale->setRangeDrag(false);
    m_colorScale->setRangeZoom(false);
    m_colorScale->axis()->grid()->setVisible(false);

    m_colorMap = new QCPColorMap(plot->xAxis, plot->yAxis);
    m_colorMap->setLayer(QStringLiteral("map"));
    m_colorMap->setSelectable(QCP::stNone);
    m_colorMap->removeFromLegend();
    m_colorMap->setColorScale(m_colorScale);
    m_colorMap->setGradient(determinantGradient());
    m_colorMap->data()->setSize(0, 0);

    // Boundaries and singular curves; each singular curve over a white halo of the same data,
    // so it shows on the darkest colours too.
    m_comparisonOutline = addCurve(plot, dashedPen(comparisonRgb, 2.5, {4.0, 2.5}));
    m_outline = addCurve(plot, QPen(QColor(outlineRgb), 1.5));
    m_inverseHalo = addCurve(plot, QPen(QColor(255, 255, 255, 200), 5.0));
    m_directHalo = addCurve(plot, QPen(QColor(255, 255, 255, 200), 5.0));
    m_inverse = addCurve(plot, QPen(QColor(inverseRgb), 2.5));
    m_direct = addCurve(plot, dashedPen(directRgb, 2.2, {4.0, 2.5}));
    m_inverseHalo->setData(m_inverse->data());
    m_directHalo->setData(m_direct->data());
    for (QCPCurve *curve : {m_outline, m_inverse, m_direct})
        curve->addToLegend();
    m_comparisonOutline->setVisible(false);

    // The current pose: a white disc with a dark rim and a cross.
    m_poseCircle = new QCPItemTracer(plot);
    m_poseCircle->setStyle(QCPItemTracer::tsCircle);
    m_poseCircle->setSize(17);
    m_poseCircle->setPen(QPen(QColor(markerRgb), 2.0));
    m_poseCircle->setBrush(Qt::white);
    m_poseCross = new QCPItemTracer(plot);
    m_poseCross->setStyle(QCPItemTracer::tsPlus);
    m_poseCross->setSize(11);
    m_poseCross->setPen(QPen(QColor(markerRgb), 1.6));
    for (QCPItemTracer *item : {m_poseCircle, m_poseCross}) {
        item->setLayer(m_poseLayer);
        item->setSelectable(false);
        item->setVisible(false);
    }

    // "computing…", over the plot's top-right corner: a child widget, so showing it costs no replot.
    m_busyLabel = new QLabel(plot);
    m_busyLabel->setFont(fontOf(font(), controlPoints));
    m_busyLabel->setStyleSheet(QStringLiteral(
        "color: #303030; background: rgba(255, 255, 255, 225); border: 1px solid #a0a0a0; padding: 2px 8px;"));
    m_busyLabel->hide();

    connect(plot, &QCustomPlot::afterLayout, this, &WorkspaceMapView::fitView);
    connect(plot, &QCustomPlot::mousePress, this, &WorkspaceMapView::mousePressed);
    connect(plot, &QCustomPlot::mouseRelease, this, &WorkspaceMapView::mouseReleased);
    connect(plot, &QCustomPlot::mouseMove, this, &WorkspaceMapView::mouseMoved);
    connect(plot, &QCustomPlot::mouseWheel, this, [this] { m_userView = true; });
    connect(plot, &QCustomPlot::mouseDoubleClick, this, [this] { resetView(); });

    retranslate();
    showMessage(messageText());
}

WorkspaceMapView::~WorkspaceMapView()
{
    m_debounce->stop();
    for (const auto &job : m_jobs)
        job->cancel->store(true);
    // Each worker stops within one block of rows; wait so none outlives the widget's thread
    // objects (they hold nothing of the widget, but the pool and the process may be going away).
    for (const auto &job : m_jobs)
        job->watcher->waitForFinished();
}

// -- requests ----------------------------------------------------------------------------------

void WorkspaceMapView::setMechanism(MechanismPtr mechanism)
{
    m_mechanism = std::move(mechanism);
    if (!m_mechanism || !m_mechanism->planarWorkspace()) {
        ++m_generation;
        cancel(JobKind::Map);
        m_debounce->stop();
        m_mapPending = false;
        clearMap();
        showMessage(messageText());
        updateBusy();
        return;
    }
    m_stack->setCurrentWidget(m_plot);
    m_quantityBox->setEnabled(true);
    requestMap();
}

void WorkspaceMapView::setPose(const Pose &pose)
{
    const bool valid = pose.outputs.size() >= 2 && std::isfinite(pose.outputs[0]) && std::isfinite(pose.outputs[1]);
    m_hasPose = valid;
    if (valid)
        m_pose = Eigen::Vector2d(pose.outputs[0], pose.outputs[1]);
    for (QCPItemTracer *item : {m_poseCircle, m_poseCross}) {
        item->position->setCoords(m_pose.x(), m_pose.y());
        item->setVisible(valid && !m_mapBounds.isEmpty());
    }
    if (m_plot->isVisible())
        m_poseLayer->replot(); // the marker alone; a full replot only if the buffers are stale
}

void WorkspaceMapView::setQuantity(MapQuantity quantity)
{
    const int index = m_quantityBox->findData(int(quantity));
    if (index != m_quantityBox->currentIndex()) {
        const QSignalBlocker blocker(m_quantityBox);
        m_quantityBox->setCurrentIndex(index);
    }
    if (quantity == m_quantity)
        return;
    m_quantity = quantity;
    if (m_mechanism && m_mechanism->planarWorkspace())
        requestMap();
}

void WorkspaceMapView::setResolution(int cells)
{
    cells = std::max(2, cells);
    if (cells == m_resolution)
        return;
    m_resolution = cells;
    if (m_mechanism && m_mechanism->planarWorkspace())
        requestMap();
    if (m_comparison)
        startComparison();
}

void WorkspaceMapView::setComparison(MechanismPtr other, const QString &label)
{
    if (!other || !other->planarWorkspace()) {
        clearComparison();
        return;
    }
    m_comparison = std::move(other);
    m_comparisonLabel = label;
    startComparison();
}

void WorkspaceMapView::clearComparison()
{
    m_comparison.reset();
    m_comparisonLabel.clear();
    ++m_comparisonGeneration;
    cancel(JobKind::Comparison);
    m_comparisonArea = 0.0;
    m_comparisonBounds.setEmpty();
    m_comparisonOutline->data()->clear();
    m_comparisonOutline->setVisible(false);
    m_comparisonOutline->removeFromLegend();
    updateLegend();
    updateBusy();
    m_plot->replot();
}

// -- computation -------------------------------------------------------------------------------

void WorkspaceMapView::requestMap()
{
    ++m_generation; // whatever is running now is stale
    cancel(JobKind::Map);
    m_mapPending = true;
    m_debounce->start(); // restarts: a burst of edits computes once, after the last
    updateBusy();
}

void WorkspaceMapView::startMap()
{
    m_mapPending = false;
    if (m_mechanism && m_mechanism->planarWorkspace()) {
        ++m_computationsStarted;
        start(JobKind::Map, m_mechanism);
    }
    updateBusy();
}

void WorkspaceMapView::startComparison()
{
    ++m_comparisonGeneration;
    cancel(JobKind::Comparison);
    start(JobKind::Comparison, m_comparison);
    updateBusy();
}

void WorkspaceMapView::start(JobKind kind, const MechanismPtr &mechanism)
{
    auto job = std::make_unique<Job>();
    job->kind = kind;
    job->generation = kind == JobKind::Map ? m_generation : m_comparisonGeneration;
    job->cancel = std::make_shared<std::atomic<bool>>(false);
    job->watcher = new QFutureWatcher<std::shared_ptr<WorkspaceMapResult>>(this);
    // The comparison needs only the boundary: det J is the cheaper quantity.
    const bool full = kind == JobKind::Map;
    const MapQuantity quantity = full ? m_quantity : MapQuantity::Determinant;
    QFutureWatcher<std::shared_ptr<WorkspaceMapResult>> *watcher = job->watcher;
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        const auto it = std::find_if(
            m_jobs.begin(), m_jobs.end(), [watcher](const std::unique_ptr<Job> &j) { return j->watcher == watcher; });
        if (it == m_jobs.end())
            return;
        const JobKind finishedKind = (*it)->kind;
        const int generation = (*it)->generation;
        m_jobs.erase(it);
        std::shared_ptr<WorkspaceMapResult> result = watcher->result();
        watcher->deleteLater(); // not delete: we are inside its signal
        finished(finishedKind, generation, std::move(result));
    });
    watcher->setFuture(QtConcurrent::run([mechanism, quantity, resolution = m_resolution, full, cancel = job->cancel] {
        return compute(mechanism, quantity, resolution, full, cancel);
    }));
    m_jobs.push_back(std::move(job));
}

void WorkspaceMapView::cancel(JobKind kind)
{
    for (const auto &job : m_jobs)
        if (job->kind == kind)
            job->cancel->store(true);
}

void WorkspaceMapView::finished(JobKind kind, int generation, std::shared_ptr<WorkspaceMapResult> result)
{
    if (kind == JobKind::Map) {
        if (generation == m_generation && result && !result->summary.cancelled) {
            applyMap(*result);
            updateBusy();
            emit mapReady();
            return;
        }
    } else if (generation == m_comparisonGeneration && result && !result->summary.cancelled) {
        applyComparison(*result);
        updateBusy();
        emit comparisonReady();
        return;
    }
    updateBusy(); // a stale result: dropped
}

bool WorkspaceMapView::busy() const
{
    if (m_mapPending)
        return true;
    return std::any_of(m_jobs.begin(), m_jobs.end(), [this](const std::unique_ptr<Job> &job) {
        return job->generation == (job->kind == JobKind::Map ? m_generation : m_comparisonGeneration);
    });
}

void WorkspaceMapView::updateBusy()
{
    const bool show = busy() && m_stack->currentWidget() == m_plot;
    if (show) {
        m_busyLabel->adjustSize();
        m_busyLabel->move(m_plot->width() - m_busyLabel->width() - 10, 8);
        m_busyLabel->raise();
    }
    m_busyLabel->setVisible(show);
}

// -- applying results (GUI thread) -------------------------------------------------------------

void WorkspaceMapView::applyMap(WorkspaceMapResult &result)
{
    QElapsedTimer timer;
    timer.start();
    const bool condition = result.quantity == MapQuantity::Condition;
    m_summary = result.summary;
    m_shownQuantity = result.quantity;
    m_values = std::move(result.values);
    m_colourLimit = result.colourLimit;
    m_mapBounds = result.summary.grid.bounds;

    m_colorMap->setData(result.colours.release()); // takes ownership, no copy
    m_colorMap->setGradient(condition ? conditionGradient() : determinantGradient());
    m_colorScale->setDataScaleType(condition ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
    if (condition)
        m_colorScale->axis()->setTicker(QSharedPointer<ConditionTicker>::create());
    else
        m_colorScale->axis()->setTicker(QSharedPointer<MinusTicker>::create());
    m_colorScale->axis()->setNumberFormat(QStringLiteral("gb"));
    m_colorScale->axis()->setNumberPrecision(3);
    m_colorScale->setDataRange(condition ? QCPRange(1.0, m_colourLimit) : QCPRange(-m_colourLimit, m_colourLimit));

    m_outline->data()->set(result.outline, true);
    m_inverse->data()->set(result.inverse, true);
    m_direct->data()->set(result.direct, true);
    m_curveCounts = {result.inverseCount, result.directCount};
    m_singularityMeanings = {result.inverseMeaning, result.directMeaning};
    for (QCPItemTracer *item : {m_poseCircle, m_poseCross})
        item->setVisible(m_hasPose);

    updateTitle();
    updateLegend();
    m_plot->replot();
    m_lastApplyMilliseconds = double(timer.nsecsElapsed()) * 1e-6;
}

void WorkspaceMapView::applyComparison(WorkspaceMapResult &result)
{
    m_comparisonArea = result.summary.area;
    m_comparisonBounds = result.summary.grid.bounds;
    m_comparisonOutline->data()->set(result.outline, true);
    m_comparisonOutline->setVisible(true);
    m_comparisonOutline->addToLegend();
    updateLegend();
    m_plot->replot();
}

void WorkspaceMapView::clearMap()
{
    m_summary = MapSummary();
    m_values.clear();
    m_colourLimit = 0.0;
    m_mapBounds.setEmpty();
    m_curveCounts = {};
    m_colorMap->data()->setSize(0, 0);
    for (QCPCurve *curve : {m_outline, m_inverse, m_direct})
        curve->data()->clear();
    for (QCPItemTracer *item : {m_poseCircle, m_poseCross})
        item->setVisible(false);
    updateTitle();
    updateLegend();
}

void WorkspaceMapView::showMessage(const QString &text)
{
    m_messageLabel->setText(text);
    m_stack->setCurrentWidget(m_messageLabel);
    m_quantityBox->setEnabled(false);
}

QString WorkspaceMapView::messageText() const
{
    return m_mechanism ? tr("No planar workspace: the outputs of this mechanism are not a point of the plane, so "
                            "there is no workspace map to show.")
                       : tr("No mechanism.");
}

QString WorkspaceMapView::message() const
{
    return m_stack->currentWidget() == m_messageLabel ? m_messageLabel->text() : QString();
}

// -- texts -------------------------------------------------------------------------------------

void WorkspaceMapView::updateTitle()
{
    const bool condition = m_shownQuantity == MapQuantity::Condition;
    const QString symbol = condition ? QStringLiteral("κ(J)") : QStringLiteral("det J"); // symbols
    if (m_mapBounds.isEmpty()) {
        m_title->setText(tr("Workspace map"));
        m_colorScale->setLabel(QString());
        return;
    }
    if (m_summary.reachableCells == 0) {
        m_title->setText(tr("Workspace empty in the design's working and assembly modes"));
    } else {
        m_title->setText(tr("Workspace %1 · %2 from %3 to %4")
                             .arg(formatQuantity(m_summary.area, units::squareMillimetre, 0), symbol,
                                 significant(m_summary.min), significant(m_summary.max)));
    }
    m_colorScale->setLabel(condition ? tr("κ(J), log scale (colours end at %1)").arg(significant(m_colourLimit))
                                     : tr("det J (colours clipped at ±%1)").arg(significant(m_colourLimit)));
    m_plot->setToolTip(condition
            ? tr("The colours end at the 98th percentile of κ(J) over the workspace, %1; κ → ∞ at the "
                 "singularities.")
                  .arg(significant(m_colourLimit))
            : tr("The colours are clipped at ±%1, the larger of the 2nd and 98th percentiles of |det J| "
                 "over the workspace: det J → ±∞ at inverse singularities, 0 at direct ones.")
                  .arg(significant(m_colourLimit)));
}

void WorkspaceMapView::updateLegend()
{
    m_outline->setName(tr("workspace boundary"));
    const QString none = tr(": none");
    const auto name = [](const QString &kind, const QString &meaning) {
        return meaning.isEmpty() ? kind : tr("%1 (%2)").arg(kind, meaning);
    };
    m_inverse->setName(name(tr("inverse singularity"), coreLabel(m_singularityMeanings[0]))
                       + (m_curveCounts[0] || m_mapBounds.isEmpty() ? QString() : none));
    m_direct->setName(name(tr("direct singularity"), coreLabel(m_singularityMeanings[1]))
                      + (m_curveCounts[1] || m_mapBounds.isEmpty() ? QString() : none));
    if (m_comparisonArea > 0.0) {
        QString text = tr("%1: boundary, %2").arg(m_comparisonLabel, formatQuantity(m_comparisonArea, units::squareMillimetre, 0));
        if (m_summary.area > 0.0) {
            const double change = 100.0 * (m_comparisonArea / m_summary.area - 1.0);
            text += tr(" (%1%2 %)").arg(change >= 0.0 ? QStringLiteral("+") : QString(QChar(0x2212)),
                QLocale().toString(std::abs(change), 'f', 1));
        }
        m_comparisonOutline->setName(text);
    }

    // Two columns when they fit beside the colour scale, else one; filled row by row.
    QCPLegend *legend = m_plot->legend;
    int widest = 0, count = 0;
    for (int j = 0; j < legend->itemCount(); ++j)
        if (const QCPAbstractLegendItem *item = legend->item(j)) {
            ++count;
            widest = std::max(widest, item->minimumOuterSizeHint().width());
        }
    const int available = m_plot->width() - m_colorScale->outerRect().width() - legend->margins().left()
        - legend->margins().right();
    const int columns = count > 1 && 2 * widest + legend->columnSpacing() <= available ? 2 : 1;
    legend->setWrap(columns);
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true); // also re-flows after items came or went
}

void WorkspaceMapView::retranslate()
{
    m_quantityLabel->setText(tr("&Map:"));
    m_quantityBox->setItemText(0, QStringLiteral("det J")); // a symbol
    m_quantityBox->setItemText(1, tr("condition number κ(J)"));
    m_busyLabel->setText(tr("computing…"));
    m_plot->xAxis->setLabel(tr("x (mm)"));
    m_plot->yAxis->setLabel(tr("y (mm)"));
    if (m_stack->currentWidget() == m_messageLabel)
        m_messageLabel->setText(messageText());
    updateTitle();
    updateLegend();
}

void WorkspaceMapView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        updateBusy(); // "computing…" changed its width
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    }
    QWidget::changeEvent(event);
}

// -- view --------------------------------------------------------------------------------------

Eigen::Vector2d WorkspaceMapView::markerPosition() const
{
    if (!m_poseCircle->visible())
        return Eigen::Vector2d::Constant(nan);
    return {m_poseCircle->position->key(), m_poseCircle->position->value()};
}

double WorkspaceMapView::valueAt(const Eigen::Vector2d &pointMm) const
{
    const MapGrid &grid = m_summary.grid;
    if (m_values.size() < grid.cells() || grid.columns <= 0 || grid.rows <= 0)
        return nan;
    const double c = std::floor((pointMm.x() - grid.bounds.min().x()) / grid.dx());
    const double r = std::floor((pointMm.y() - grid.bounds.min().y()) / grid.dy());
    if (!(c >= 0 && c < grid.columns && r >= 0 && r < grid.rows))
        return nan;
    return m_values[std::size_t(r) * std::size_t(grid.columns) + std::size_t(c)];
}

/// Runs after every layout (so the axis rect's size is known) and gives both axes the same
/// mm per pixel: the whole map (and comparison) fitted, or the user's zoom kept.
void WorkspaceMapView::fitView()
{
    const QRect pixels = m_plot->axisRect()->rect();
    if (pixels.width() < 10 || pixels.height() < 10)
        return;
    QCPAxis *x = m_plot->xAxis, *y = m_plot->yAxis;
    Eigen::Vector2d centre;
    double mmPerPixel = 0.0;
    if (m_userView) {
        centre = {x->range().center(), y->range().center()};
        mmPerPixel = x->range().size() / pixels.width();
    } else {
        Eigen::AlignedBox2d box = m_mapBounds;
        box.extend(m_comparisonBounds);
        if (box.isEmpty())
            return;
        const Eigen::Vector2d size = box.sizes() * 1.04; // a little air around the boundary
        centre = box.center();
        mmPerPixel = std::max(size.x() / pixels.width(), size.y() / pixels.height());
    }
    if (!(mmPerPixel > 0.0))
        return;
    const QCPRange xRange(centre.x() - 0.5 * mmPerPixel * pixels.width(), centre.x() + 0.5 * mmPerPixel * pixels.width());
    const QCPRange yRange(centre.y() - 0.5 * mmPerPixel * pixels.height(), centre.y() + 0.5 * mmPerPixel * pixels.height());
    applyFittedRanges(m_plot, xRange, yRange, m_refits);
}

void WorkspaceMapView::resetView()
{
    m_userView = false;
    m_plot->replot();
}

// -- mouse -------------------------------------------------------------------------------------

void WorkspaceMapView::mousePressed(QMouseEvent *event)
{
    m_pressPosition = event->position().toPoint();
    m_pressInside = event->button() == Qt::LeftButton && !m_mapBounds.isEmpty()
        && m_plot->axisRect()->rect().contains(m_pressPosition);
}

void WorkspaceMapView::mouseMoved(QMouseEvent *event)
{
    if ((event->buttons() & Qt::LeftButton) && (event->position().toPoint() - m_pressPosition).manhattanLength() > 3)
        m_userView = true; // a drag of the map
}

void WorkspaceMapView::mouseReleased(QMouseEvent *event)
{
    const QPoint position = event->position().toPoint();
    const bool click = m_pressInside && event->button() == Qt::LeftButton
        && (position - m_pressPosition).manhattanLength() <= 3 && m_plot->axisRect()->rect().contains(position);
    m_pressInside = false;
    if (click)
        emit pointClicked(
            Eigen::Vector2d(m_plot->xAxis->pixelToCoord(event->position().x()), m_plot->yAxis->pixelToCoord(event->position().y())));
}

bool WorkspaceMapView::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_plot && event->type() == QEvent::Resize) {
        updateLegend();
        updateBusy();
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace pkm
