#include "tolerancemap.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

namespace pkm::tolerance {

MapSummary computeMap(const Analysis &analysis, const Pose &near, const MapGrid &grid, std::span<float> values,
                      const std::atomic<bool> *cancel, const Progress &progress, int threads)
{
    const auto start = std::chrono::steady_clock::now();
    MapSummary summary;
    summary.grid = grid;
    const Mechanism &m = analysis.mechanism();
    if (grid.columns <= 0 || grid.rows <= 0 || values.size() < grid.cells() || m.outputCount() < 2)
        return summary;
    if (threads <= 0)
        threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::clamp(threads, 1, grid.rows);

    std::atomic<int> nextRow{0}, rowsDone{0};
    std::atomic<bool> stopped{false};
    std::mutex merge;
    double min = std::numeric_limits<double>::infinity(), max = -min;
    std::size_t reachable = 0;
    const std::size_t columns = std::size_t(grid.columns);
    auto work = [&] {
        double localMin = std::numeric_limits<double>::infinity(), localMax = -localMin;
        std::size_t localReachable = 0;
        for (;;) {
            if (cancel && cancel->load(std::memory_order_relaxed)) {
                stopped = true;
                break;
            }
            const int r = nextRow.fetch_add(1);
            if (r >= grid.rows)
                break;
            // each cell starts from the pose given (its modes, z and φ); the previous cell of
            // the row is no better a start: inverse kinematics is closed form per working mode
            Coordinates outputs = near.outputs;
            for (std::size_t c = 0; c < columns; ++c) {
                float &cell = values[std::size_t(r) * columns + c];
                outputs[0] = grid.x(int(c));
                outputs[1] = grid.y(r);
                const auto pose = m.solveInverse(outputs, &near);
                if (!pose) {
                    cell = std::numeric_limits<float>::quiet_NaN();
                    continue;
                }
                const FirstOrder f = analysis.firstOrder(*pose);
                ++localReachable;
                cell = f.finite || std::isinf(f.worstNorm) ? float(f.worstNorm) : std::numeric_limits<float>::infinity();
                if (std::isfinite(cell)) {
                    localMin = std::min(localMin, double(cell));
                    localMax = std::max(localMax, double(cell));
                }
            }
            const int done = ++rowsDone;
            if (progress)
                progress(done, grid.rows);
        }
        const std::lock_guard lock(merge);
        min = std::min(min, localMin);
        max = std::max(max, localMax);
        reachable += localReachable;
    };
    {
        std::vector<std::jthread> pool;
        for (int t = 1; t < threads; ++t)
            pool.emplace_back(work);
        work();
    }
    summary.reachableCells = reachable;
    summary.min = std::isfinite(min) ? min : 0.0;
    summary.max = std::isfinite(max) ? max : 0.0;
    summary.area = double(reachable) * grid.cellArea();
    summary.cancelled = stopped;
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

} // namespace pkm::tolerance
