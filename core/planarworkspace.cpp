#include "planarworkspace.h"
#include "mapclones.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace pkm {

const char *mapInstructionSet()
{
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#ifndef PKM_MAP_CLONES_NO_AVX512
    if (__builtin_cpu_supports("avx512f"))
        return "AVX-512";
#endif
    return __builtin_cpu_supports("avx2") ? "AVX2" : "x86-64";
#else
    return "portable";
#endif
}

namespace {
/// Rows are handed out in blocks from a shared counter, so a thread that meets cheap rows
/// (outside the workspace) takes more of them.
constexpr int rowsPerBlock = 8;

struct Partial {
    std::size_t reachable = 0;
    std::size_t nearSingular = 0;
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    int firstColumn = std::numeric_limits<int>::max(), lastColumn = -1;
    int firstRow = std::numeric_limits<int>::max(), lastRow = -1;
};
/// A float's bits as an integer that orders like the float (−0 just below +0), and back: the
/// row's minimum and maximum are taken on these, because an integer minimum vectorises
/// whatever the compiler's flags, while a float one does not (NaN and −0 make a select
/// differ from the processor's minimum instruction).
inline std::int32_t orderedKey(std::int32_t bits)
{
    return bits ^ ((bits >> 31) & 0x7fffffff);
}
inline float fromOrderedKey(std::int32_t key)
{
    return std::bit_cast<float>(key ^ ((key >> 31) & 0x7fffffff));
}

/// Adds a filled row to the tally: integer selects only, so that the loop vectorises as the
/// row did (a branch per cell cost as much as the row itself). `margins` may be empty.
PKM_MAP_CLONES void tallyRow(int r, std::span<const float> row, std::span<const float> margins, Partial &partial)
{
    constexpr std::int32_t infinityBits = 0x7f800000; // the magnitude of ±∞; above: NaN
    constexpr std::int32_t highest = std::numeric_limits<std::int32_t>::max();
    constexpr std::int32_t lowest = std::numeric_limits<std::int32_t>::min();
    const float near = static_cast<float>(nearSingularMargin);
    std::int32_t reached = 0, nearSingular = 0; // a row has < 2³¹ cells
    std::int32_t low = highest, high = lowest;
    for (std::size_t c = 0; c < row.size(); ++c) {
        const std::int32_t bits = std::bit_cast<std::int32_t>(row[c]);
        const std::int32_t magnitude = bits & 0x7fffffff;
        const std::int32_t key = orderedKey(bits);
        // all ones where the cell is finite: masks, not ?:, or the loop does not vectorise
        const std::int32_t finite = -std::int32_t(magnitude < infinityBits);
        reached += magnitude <= infinityBits;
        low = std::min(low, (key & finite) | (highest & ~finite));
        high = std::max(high, (key & finite) | (lowest & ~finite));
    }
    if (!margins.empty()) {
        for (std::size_t c = 0; c < row.size(); ++c) {
            const std::int32_t magnitude = std::bit_cast<std::int32_t>(row[c]) & 0x7fffffff;
            nearSingular += (magnitude <= infinityBits) & (margins[c] < near);
        }
    }
    if (low != highest) {
        partial.min = std::min(partial.min, double(fromOrderedKey(low)));
        partial.max = std::max(partial.max, double(fromOrderedKey(high)));
    }
    partial.reachable += static_cast<std::size_t>(reached);
    partial.nearSingular += static_cast<std::size_t>(nearSingular);
    if (reached > 0) {
        // the row's first and last reachable cells, read from either end: the cells between
        // them cannot widen the box
        int first = 0, last = static_cast<int>(row.size()) - 1;
        while (row[static_cast<std::size_t>(first)] != row[static_cast<std::size_t>(first)])
            ++first;
        while (row[static_cast<std::size_t>(last)] != row[static_cast<std::size_t>(last)])
            --last;
        partial.firstColumn = std::min(partial.firstColumn, first);
        partial.lastColumn = std::max(partial.lastColumn, last);
        partial.firstRow = std::min(partial.firstRow, r);
        partial.lastRow = std::max(partial.lastRow, r);
    }
}

/// computeMap() and summariseMap(): into `values` and `margins` when `keep`, else row by row
/// into each thread's own buffers (margins only when `withMargins`).
MapSummary run(const PlanarWorkspace &workspace, MapQuantity quantity, const MapGrid &grid, bool keep,
               std::span<float> values, std::span<float> margins, bool withMargins,
               const std::atomic<bool> *cancel, int threads)
{
    const auto start = std::chrono::steady_clock::now();
    MapSummary summary;
    summary.grid = grid;
    if (grid.columns <= 0 || grid.rows <= 0 || (keep && values.size() < grid.cells()))
        return summary;
    if (threads <= 0)
        threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, (grid.rows + rowsPerBlock - 1) / rowsPerBlock);

    std::atomic<int> nextRow{0};
    std::atomic<bool> stopped{false};
    std::vector<Partial> partials(static_cast<std::size_t>(threads));
    const std::size_t columns = static_cast<std::size_t>(grid.columns);
    auto work = [&](Partial &partial) {
        // streamed: one row of each, reused (a few kB that stay in the cache, where a kept
        // 3000² map would first fault in and zero 70 MB)
        std::vector<float> rowBuffer(keep ? 0 : columns), marginBuffer(keep || !withMargins ? 0 : columns);
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
                const std::size_t offset = static_cast<std::size_t>(r) * columns;
                const std::span<float> row = keep ? values.subspan(offset, columns) : std::span<float>(rowBuffer);
                const std::span<float> marginRow = !withMargins ? std::span<float>()
                    : keep                                      ? margins.subspan(offset, columns)
                                                                : std::span<float>(marginBuffer);
                workspace.fillMapRow(quantity, grid.y(r), grid.x(0), grid.dx(), row, marginRow);
                tallyRow(r, row, marginRow, partial);
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
        total.firstColumn = std::min(total.firstColumn, p.firstColumn);
        total.lastColumn = std::max(total.lastColumn, p.lastColumn);
        total.firstRow = std::min(total.firstRow, p.firstRow);
        total.lastRow = std::max(total.lastRow, p.lastRow);
    }
    summary.reachableCells = total.reachable;
    summary.nearSingularCells = total.nearSingular;
    summary.min = std::isfinite(total.min) ? total.min : 0.0;
    summary.max = std::isfinite(total.max) ? total.max : 0.0;
    summary.area = double(total.reachable) * grid.cellArea();
    if (total.lastColumn >= 0) {
        const Eigen::Vector2d origin = grid.bounds.min();
        summary.reachableBox.extend(origin + Eigen::Vector2d(total.firstColumn * grid.dx(), total.firstRow * grid.dy()));
        summary.reachableBox.extend(
            origin + Eigen::Vector2d((total.lastColumn + 1) * grid.dx(), (total.lastRow + 1) * grid.dy()));
    }
    summary.cancelled = stopped;
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

} // namespace

MapSummary computeMap(const PlanarWorkspace &workspace, MapQuantity quantity, const MapGrid &grid,
                      std::span<float> values, std::span<float> margins, const std::atomic<bool> *cancel, int threads)
{
    return run(workspace, quantity, grid, true, values, margins, margins.size() >= grid.cells(), cancel, threads);
}

MapSummary summariseMap(const PlanarWorkspace &workspace, MapQuantity quantity, const MapGrid &grid,
                        bool withMargins, const std::atomic<bool> *cancel, int threads)
{
    return run(workspace, quantity, grid, false, {}, {}, withMargins, cancel, threads);
}

std::optional<std::pair<int, int>> reachableEnds(std::span<const float> row)
{
    const auto first = std::find_if(row.begin(), row.end(), reachableCell);
    if (first == row.end())
        return std::nullopt;
    const auto last = std::find_if(row.rbegin(), row.rend(), reachableCell);
    return std::pair{static_cast<int>(first - row.begin()), static_cast<int>(row.rend() - last) - 1};
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
