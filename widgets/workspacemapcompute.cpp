// The workspace map's computation, off the GUI thread: the worker that computes a map with its
// outline, colours and singular curves, and the jobs that run, cancel and collect it — one for
// the shown map and one for the comparison (docs/mathematics.md, section 6).

#include "workspacemapview.h"
#include "workspacemapviewinternal.h"

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
#include <numbers>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace pkm {

namespace {
using workspacemap::nan;

/// The colours are clipped at these percentiles of the reachable, finite values, so that the
/// spikes at inverse singularities (det J, κ → ∞) do not flatten the rest of the map. det J's
/// tail is heavier: in the O-X glide's O form 5 % of the cells lie beyond −23 and 2 % beyond
/// −136, while half are between −2 and −5, so the 2nd/98th percentiles left the map almost white.
constexpr double lowPercentile = 0.02, highPercentile = 0.98;
constexpr double determinantLowPercentile = 0.05, determinantHighPercentile = 0.95;

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
    bool full, const std::shared_ptr<std::atomic<bool>> &cancel, const Pose &pose,
    const std::vector<capability::Requirement> &requirements, const ParameterSet &tolerances)
{
    auto result = std::make_shared<WorkspaceMapResult>();
    result->quantity = quantity;
    const PlanarWorkspace *workspace = mechanism ? mechanism->planarWorkspace() : nullptr;
    if (!workspace || cancel->load()) {
        result->summary.cancelled = true;
        return result;
    }
    const bool delivered = isPoseValue(quantity);
    const MapGrid grid = squareGrid(workspace->workspaceBounds(), resolution);
    result->values.resize(grid.cells());
    std::vector<float> margins(full ? grid.cells() : 0);
    result->summary = quantity == MapQuantity::ToleranceWorst
        ? workspacemap::computeTolerance(mechanism, pose, tolerances, grid, *result, margins, cancel.get())
        : delivered
        ? workspacemap::computeCapability(*mechanism, pose, quantity, requirements, grid, *result, margins, cancel.get())
        : computeMap(*workspace, quantity, grid, result->values, margins, cancel.get());
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
    const bool range = quantity == MapQuantity::OrientationRange;
    double limit = condition ? 10.0 : 1.0;
    if (range) {
        limit = 360.0; // degrees: the whole turn, the same scale for every design
    } else if (quantity == MapQuantity::Specification) {
        limit = 1.0; // met or not
    } else if (delivered && !finite.empty()) {
        // from 0 (nothing delivered: a singularity) to the 95th percentile, so that the spikes
        // beside a singularity (the resolution → ∞) do not flatten the rest
        const double high = percentile(determinantHighPercentile);
        limit = high > 0.0 ? high : std::max(1.0, result->summary.max);
    } else if (!finite.empty()) {
        if (condition) {
            const double high = percentile(highPercentile);
            limit = high > 1.001 ? high : std::max(10.0, result->summary.max);
        } else {
            const double high
                = std::max(std::abs(percentile(determinantLowPercentile)), std::abs(percentile(determinantHighPercentile)));
            limit = high > 0.0 ? high : std::max(1.0, std::max(-result->summary.min, result->summary.max));
        }
    }
    result->colourLimit = limit;
    const double lower = condition ? 1.0 : range || delivered ? 0.0 : -limit;
    const double toColour = range ? 180.0 / std::numbers::pi : 1.0; // the range in radians, coloured in degrees

    // The colour data, clipped to the colour range: QCPColorGradient turns values into indices
    // with int(), which an infinite value would overflow.
    auto colours = std::make_unique<QCPColorMapData>(grid.columns, grid.rows,
        QCPRange(grid.x(0), grid.x(grid.columns - 1)), QCPRange(grid.y(0), grid.y(grid.rows - 1)));
    for (int r = 0; r < grid.rows; ++r) {
        const float *row = result->values.data() + std::size_t(r) * std::size_t(grid.columns);
        for (int c = 0; c < grid.columns; ++c) {
            const double v = row[c];
            colours->setCell(c, r, std::isnan(v) ? nan : std::clamp(v * toColour, lower, limit));
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
} // namespace

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
    watcher->setFuture(QtConcurrent::run([mechanism, quantity, resolution = m_resolution, full, cancel = job->cancel,
                                          pose = m_fullPose, requirements = m_requirements,
                                          tolerances = m_tolerances] {
        return compute(mechanism, quantity, resolution, full, cancel, pose, requirements, tolerances);
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

} // namespace pkm
