// Maps of what the actuators deliver (core/capabilitymap.h) against the det J map of the same
// design on the same grid, in one run, all cores: the time per reachable cell of each and
// their ratio. The goal is a capability cell as fast as a det J cell (ratio ≤ 1); the benchmark
// fails only above `MAX_RATIO` (a regression guard), and says whether the goal is met.
//
//   bench_capmap [MAX_RATIO] [--design PRESET] [--grid N] [--runs N]

#include "capabilitymap.h"
#include "benchmachine.h"
#include "document/designfile.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

using pkm::bench::cpuText;

template <typename F>
double bestSeconds(int runs, F &&run)
{
    double best = 1e300;
    for (int i = 0; i < runs; ++i) {
        const auto start = Clock::now();
        run();
        best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
    }
    return best;
}

} // namespace

int main(int argc, char *argv[])
{
    double maxRatio = 200.0;
    std::string preset = "moma-3a";
    int resolution = 1000, runs = 5;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--design" && i + 1 < argc)
            preset = argv[++i];
        else if (a == "--grid" && i + 1 < argc)
            resolution = std::atoi(argv[++i]);
        else if (a == "--runs" && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else
            maxRatio = std::atof(argv[i]);
    }
    const auto design = pkm::designfile::load(QString::fromStdString(preset));
    if (!design || !design->mechanism->planarWorkspace()) {
        std::fprintf(stderr, "error: %s has no planar workspace\n", preset.c_str());
        return 1;
    }
    const pkm::Mechanism &mechanism = *design->mechanism;
    const pkm::PlanarWorkspace &workspace = *mechanism.planarWorkspace();
    const pkm::capability::Actuators actuators = pkm::capability::actuatorsOf(mechanism);
    const pkm::MapGrid grid = pkm::squareGrid(workspace.workspaceBounds(), resolution);
    std::vector<float> values(grid.cells());
    pkm::MapSummary det, force;
    const double detSeconds = bestSeconds(runs, [&] {
        det = pkm::computeMap(workspace, pkm::MapQuantity::Determinant, grid, values);
    });
    const pkm::Pose start = pkm::capability::mapStart(mechanism, design->pose);
    const double forceSeconds = bestSeconds(std::max(1, runs / 2), [&] {
        force = pkm::capability::computeMap(mechanism, actuators, pkm::MapQuantity::ForceWorst, {}, start, grid, values);
    });
    const double detCell = 1e9 * detSeconds / double(std::max<std::size_t>(1, det.reachableCells));
    const double forceCell = 1e9 * forceSeconds / double(std::max<std::size_t>(1, force.reachableCells));
    const double ratio = forceCell / detCell;
    std::printf("%s, %d x %d cells, %zu reachable, all cores; %s\n", preset.c_str(), grid.columns, grid.rows,
                det.reachableCells, cpuText().c_str());
    std::printf("det J map:        %.3f ms, %.1f ns per reachable cell\n", 1e3 * detSeconds, detCell);
    std::printf("force_worst map:  %.3f ms, %.1f ns per reachable cell\n", 1e3 * forceSeconds, forceCell);
    std::printf("ratio %.1f x (goal: <= 1 x, %s; fails above %.0f x)\n", ratio, ratio <= 1.0 ? "met" : "missed", maxRatio);
    return ratio <= maxRatio ? 0 : 1;
}
