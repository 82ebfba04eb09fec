// Maps of what the actuators deliver (core/capabilitymap.h) against the det J map of the same
// design on the same grid, in one run, all cores, both with the singularity margins as the map
// view and `pkm map` compute them: the time per reachable cell of each and their ratio, for a
// design of every kind with a planar workspace (or the --design ones). The goal is a
// capability cell as fast as a det J cell (ratio ≤ 1); the benchmark fails only above
// `MAX_RATIO` (a regression guard), and says whether the goal is met.
//
//   bench_capmap [MAX_RATIO] [--design PRESET]... [--grid N] [--runs N]

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

namespace {

/// One design's line: the per-cell time of each map and their ratio, or -1 if it has no map.
double measure(const std::string &preset, int resolution, int runs)
{
    const auto design = pkm::designfile::load(QString::fromStdString(preset));
    if (!design || !design->mechanism->planarWorkspace()) {
        std::fprintf(stderr, "error: %s has no planar workspace\n", preset.c_str());
        return -1.0;
    }
    const pkm::Mechanism &mechanism = *design->mechanism;
    const pkm::PlanarWorkspace &workspace = *mechanism.planarWorkspace();
    const pkm::capability::Actuators actuators = pkm::capability::actuatorsOf(mechanism);
    const pkm::MapGrid grid = pkm::squareGrid(workspace.workspaceBounds(), resolution);
    std::vector<float> values(grid.cells()), margins(grid.cells());
    pkm::MapSummary det, force;
    // as the map view and `pkm map` compute both: with the singularity margins
    const double detSeconds = bestSeconds(runs, [&] {
        det = pkm::computeMap(workspace, pkm::MapQuantity::Determinant, grid, values, margins);
    });
    const pkm::Pose start = pkm::capability::mapStart(mechanism, design->pose);
    const double forceSeconds = bestSeconds(runs, [&] {
        force = pkm::capability::computeMap(mechanism, actuators, pkm::MapQuantity::ForceWorst, {}, start, grid, values,
                                            margins);
    });
    const double detCell = 1e9 * detSeconds / double(std::max<std::size_t>(1, det.reachableCells));
    const double forceCell = 1e9 * forceSeconds / double(std::max<std::size_t>(1, force.reachableCells));
    std::printf("%-18s %4d x %-4d %8zu cells  det J %7.1f ns  force_worst %7.1f ns  ratio %.2f x\n", preset.c_str(),
                grid.columns, grid.rows, det.reachableCells, detCell, forceCell, forceCell / detCell);
    return forceCell / detCell;
}

} // namespace

int main(int argc, char *argv[])
{
    double maxRatio = 200.0;
    std::vector<std::string> presets;
    int resolution = 1000, runs = 15;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--design" && i + 1 < argc)
            presets.push_back(argv[++i]);
        else if (a == "--grid" && i + 1 < argc)
            resolution = std::atoi(argv[++i]);
        else if (a == "--runs" && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else
            maxRatio = std::atof(argv[i]);
    }
    // one design of every kind with a planar workspace: the closed-form rows of each kind's
    // map loop, and the leg library's (a 3-DOF platform at φ = phi_map)
    const bool all = presets.empty();
    if (all)
        presets = {"moma-3a", "fivebar-example", "oxglide-prototype", "pp-5r", "pp-3rrr"};
    std::printf("per reachable cell, best of %d, all cores; %s\n", runs, pkm::bench::cpuText().c_str());
    double worst = 0.0;
    for (const std::string &preset : presets) {
        // the leg library's rows cost a hundred times MOMA's: a coarser grid, the same ratio
        const bool legs = preset.rfind("pp-", 0) == 0;
        const double ratio = measure(preset, all && legs ? resolution / 4 : resolution, runs);
        if (ratio < 0.0)
            return 1;
        worst = std::max(worst, ratio);
    }
    std::printf("largest ratio %.2f x (goal: <= 1 x, %s; fails above %.1f x)\n", worst, worst <= 1.0 ? "met" : "missed",
                maxRatio);
    return worst <= maxRatio ? 0 : 1;
}
