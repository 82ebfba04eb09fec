#include "planarworkspace.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace pkm {

namespace {
/// Rows are handed out in blocks from a shared counter, so a thread that meets cheap rows
/// (outside the workspace) takes more of them.
constexpr int rowsPerBlock = 8;

struct Partial {
    std::size_t reachable = 0;
    std::size_t nearSingular = 0;
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
};
/// Adds a filled row to the tally: selects only, in floats, so that the loop vectorises as the
/// row did (a branch per cell cost as much as the row itself). `margins` may be empty.
void tallyRow(std::span<const float> row, std::span<const float> margins, Partial &partial)
{
    constexpr float infinity = std::numeric_limits<float>::infinity();
    const float near = static_cast<float>(nearSingularMargin);
    std::size_t reached = 0, nearSingular = 0;
    float low = infinity, high = -infinity;
    for (std::size_t c = 0; c < row.size(); ++c) {
        const float v = row[c];
        const bool reachable = v == v, finite = reachable & (std::abs(v) != infinity);
        reached += reachable;
        low = std::min(low, finite ? v : infinity);
        high = std::max(high, finite ? v : -infinity);
    }
    if (!margins.empty()) {
        for (std::size_t c = 0; c < row.size(); ++c)
            nearSingular += (row[c] == row[c]) & (margins[c] < near);
    }
    partial.reachable += reached;
    partial.nearSingular += nearSingular;
    partial.min = std::min(partial.min, double(low));
    partial.max = std::max(partial.max, double(high));
}

} // namespace

MapSummary computeMap(const PlanarWorkspace &workspace, MapQuantity quantity, const MapGrid &grid,
                      std::span<float> values, std::span<float> margins, const std::atomic<bool> *cancel, int threads)
{
    const auto start = std::chrono::steady_clock::now();
    MapSummary summary;
    summary.grid = grid;
    if (grid.columns <= 0 || grid.rows <= 0 || values.size() < grid.cells())
        return summary;
    const bool withMargins = margins.size() >= grid.cells();
    if (threads <= 0)
        threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, (grid.rows + rowsPerBlock - 1) / rowsPerBlock);

    std::atomic<int> nextRow{0};
    std::atomic<bool> stopped{false};
    std::vector<Partial> partials(static_cast<std::size_t>(threads));
    const std::size_t columns = static_cast<std::size_t>(grid.columns);
    auto work = [&](Partial &partial) {
        for (;;) {
            if (cancel && cancel->load(std::memory_order_relaxed)) {
                stopped = true;
                return;
            }
            const int first = nextRow.fetch_add(rowsPerBlock);
            if (first >= grid.rows)
                return;
            const int last = std::min(grid.rows, first + rowsPerBlock);
            for (int r = first; r < last; ++r) {
                const std::span<float> row = values.subspan(static_cast<std::size_t>(r) * columns, columns);
                const std::span<float> marginRow =
                    withMargins ? margins.subspan(static_cast<std::size_t>(r) * columns, columns) : std::span<float>();
                workspace.fillMapRow(quantity, grid.y(r), grid.x(0), grid.dx(), row, marginRow);
                tallyRow(row, marginRow, partial);
            }
        }
    };
    {
        std::vector<std::jthread> pool;
        for (int t = 1; t < threads; ++t)
            pool.emplace_back(work, std::ref(partials[static_cast<std::size_t>(t)]));
        work(partials[0]);
    }
    Partial total;
    for (const Partial &p : partials) {
        total.reachable += p.reachable;
        total.nearSingular += p.nearSingular;
        total.min = std::min(total.min, p.min);
        total.max = std::max(total.max, p.max);
    }
    summary.reachableCells = total.reachable;
    summary.nearSingularCells = total.nearSingular;
    summary.min = std::isfinite(total.min) ? total.min : 0.0;
    summary.max = std::isfinite(total.max) ? total.max : 0.0;
    summary.area = double(total.reachable) * grid.cellArea();
    summary.cancelled = stopped;
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

MapGrid squareGrid(const Eigen::AlignedBox2d &bounds, int resolution)
{
    resolution = std::max(2, resolution);
    MapGrid grid;
    const Eigen::Vector2d size = bounds.sizes();
    const double longer = std::max(size.x(), size.y());
    if (!(longer > 0) || !std::isfinite(longer)) {
        grid.bounds = Eigen::AlignedBox2d(bounds.min(), bounds.min() + Eigen::Vector2d::Ones());
        grid.columns = grid.rows = resolution;
        return grid;
    }
    const double cell = longer / resolution;
    grid.columns = std::max(1, static_cast<int>(std::ceil(size.x() / cell - 1e-9)));
    grid.rows = std::max(1, static_cast<int>(std::ceil(size.y() / cell - 1e-9)));
    // centre the grid of square cells on the bounds
    const Eigen::Vector2d covered(grid.columns * cell, grid.rows * cell);
    const Eigen::Vector2d origin = bounds.center() - 0.5 * covered;
    grid.bounds = Eigen::AlignedBox2d(origin, origin + covered);
    return grid;
}

std::vector<Eigen::Vector2d> workspaceOutline(const MapGrid &grid, std::span<const float> values)
{
    std::vector<Eigen::Vector2d> segments;
    if (values.size() < grid.cells())
        return segments;
    auto reachable = [&](int c, int r) {
        if (c < 0 || r < 0 || c >= grid.columns || r >= grid.rows)
            return false;
        return !std::isnan(values[static_cast<std::size_t>(r) * static_cast<std::size_t>(grid.columns) + static_cast<std::size_t>(c)]);
    };
    const double x0 = grid.bounds.min().x(), y0 = grid.bounds.min().y(), dx = grid.dx(), dy = grid.dy();
    // Boundary edges of the reachable cells; consecutive edges along a row or column are merged.
    for (int r = 0; r <= grid.rows; ++r) { // horizontal edges between rows r−1 and r
        int runStart = -1;
        for (int c = 0; c <= grid.columns; ++c) {
            const bool edge = c < grid.columns && reachable(c, r - 1) != reachable(c, r);
            if (edge && runStart < 0)
                runStart = c;
            if (!edge && runStart >= 0) {
                segments.emplace_back(x0 + runStart * dx, y0 + r * dy);
                segments.emplace_back(x0 + c * dx, y0 + r * dy);
                runStart = -1;
            }
        }
    }
    for (int c = 0; c <= grid.columns; ++c) { // vertical edges between columns c−1 and c
        int runStart = -1;
        for (int r = 0; r <= grid.rows; ++r) {
            const bool edge = r < grid.rows && reachable(c - 1, r) != reachable(c, r);
            if (edge && runStart < 0)
                runStart = r;
            if (!edge && runStart >= 0) {
                segments.emplace_back(x0 + c * dx, y0 + runStart * dy);
                segments.emplace_back(x0 + c * dx, y0 + r * dy);
                runStart = -1;
            }
        }
    }
    return segments;
}

} // namespace pkm
