#include "tolerancemap.h"

#include "solvedmap.h"

#include <cmath>
#include <limits>

namespace pkm::tolerance {

MapSummary computeMap(const Analysis &analysis, const Pose &near, const MapGrid &grid, std::span<float> values,
                      const std::atomic<bool> *cancel, const Progress &progress, int threads)
{
    MapSummary summary;
    summary.grid = grid;
    const Mechanism &m = analysis.mechanism();
    if (grid.columns <= 0 || grid.rows <= 0 || values.size() < grid.cells() || m.outputCount() < 2)
        return summary;
    const std::size_t columns = std::size_t(grid.columns);
    struct NoState {};
    return solvedmap::run(
        grid, threads, cancel, progress, [] { return NoState{}; },
        [&](int r, solvedmap::Tally &tally, NoState &) {
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
                cell = f.finite || std::isinf(f.worstNorm) ? float(f.worstNorm) : std::numeric_limits<float>::infinity();
                tally.add(cell);
            }
        },
        [](NoState &) {});
}

} // namespace pkm::tolerance
