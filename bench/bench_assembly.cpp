// Benchmark: every direct solution of the pp-3rpr preset's 3-RP̲R (the sextic of the planar
// 3-RPR forward problem, docs/mathematics.md section 5a) at the preset's stored inputs
// q = (14.98, 15.38, 12), where all six assembly modes are real. It goes through the generic
// interface only (the preset loader and Mechanism::assemblyModes), so it names no kind class and
// measures what `pkm eval --all-modes` and the mode ghosts pay. The process is pinned to one
// core so that the scheduler moving it does not show up as a slow run; each call is timed on its
// own after a warm-up, and min, median and 95th percentile are printed.
// Target: median ≤ LIMIT_US (argv[1], default 20 µs).
//
// With --map (the default; --no-map skips it) it also times the det J map of the leg-library
// MOMA (preset pp-2prr-moma3a) against the MOMA kind's own (preset moma-3a) on the same grid,
// one thread each, and prints the ratio of their times, which is the ratio per cell. Target:
// ratio ≤ MAP_RATIO (--map-ratio, default 3), so that building MOMA from the leg library costs
// no more than that against the hand-written kind. The other 2-DOF leg presets (pp-5r,
// pp-5r-pjoint, pp-pa-pjoint) are timed on grids of as many cells over their own bounds and held
// to the same ratio per cell. Each run times MOMA's map and the leg preset's in turn; the figure
// is the median of the ratios of the pairs.
//
//   bench_assembly [LIMIT_US] [--runs N] [--no-map] [--map-ratio R] [--map-size N] [--map-runs N]
#include "benchmachine.h"
#include "document/designfile.h"
#include "planarworkspace.h"

#include <QCoreApplication>

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

int usage(const char *program)
{
    std::fprintf(stderr, "usage: %s [LIMIT_US] [--runs N] [--no-map] [--map-ratio R] [--map-size N] [--map-runs N]\n",
                 program);
    return 2;
}

struct Stats {
    double min, median, p95;
};

/// Sorts the samples; the 95th percentile is the sample below which 95 % lie.
Stats statsOf(std::vector<double> &samples)
{
    std::sort(samples.begin(), samples.end());
    return {samples.front(), samples[samples.size() / 2],
            samples[std::min(samples.size() - 1, samples.size() * 95 / 100)]};
}

/// One core only: the timings compare runs, not where the scheduler put them.
void pinToOneCore()
{
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
            if (CPU_ISSET(cpu, &set)) {
                CPU_ZERO(&set);
                CPU_SET(cpu, &set);
                sched_setaffinity(0, sizeof set, &set);
                return;
            }
        }
    }
}

pkm::Design loadPreset(const char *id)
{
    auto design = pkm::designfile::load(QString::fromLatin1(id));
    if (!design) {
        std::fprintf(stderr, "error: preset %s: %s\n", id, design.failure().message.c_str());
        std::exit(1);
    }
    return *design;
}

/// The assembly-mode benchmark; false when the median misses the target.
bool benchAssemblyModes(double limitUs, int runs)
{
    const pkm::Design design = loadPreset("pp-3rpr");
    const pkm::Mechanism &m = *design.mechanism;
    const pkm::Pose &pose = design.pose;
    std::vector<pkm::Pose> modes = m.assemblyModes(pose);
    // the preset is the one with six real solutions: fewer means the solver lost some
    if (modes.size() != 6) {
        std::printf("FAIL: %zu assembly modes at the preset's inputs, 6 expected\n", modes.size());
        return false;
    }
    for (int i = 0; i < 1000; ++i) // warm-up: caches, branch predictors, the core's clock
        modes = m.assemblyModes(pose);

    std::vector<double> times(static_cast<std::size_t>(runs));
    std::size_t found = 0;
    for (double &t : times) {
        const auto start = Clock::now();
        modes = m.assemblyModes(pose);
        const auto end = Clock::now();
        found += modes.size(); // used, so that the call is not optimised away
        t = std::chrono::duration<double, std::micro>(end - start).count();
    }
    const Stats s = statsOf(times);
    std::printf("pp-3rpr (%.*s), every assembly mode at q = (%.2f, %.2f, %.2f) mm: %zu solutions, %d runs, one core\n",
                int(m.kind().size()), m.kind().data(), pose.inputs[0], pose.inputs[1], pose.inputs[2],
                found / times.size(), runs);
    std::printf("time: min %.2f us, median %.2f us, p95 %.2f us (target: median <= %.2f us)\n", s.min, s.median, s.p95,
                limitUs);
    if (s.median > limitUs) {
        std::printf("FAIL: median %.2f us is over the %.2f us limit\n", s.median, limitUs);
        return false;
    }
    return true;
}

/// One det J map of `workspace` over `grid` on one thread, ms.
double mapTime(const pkm::PlanarWorkspace &workspace, const pkm::MapGrid &grid, std::vector<float> &values,
               pkm::MapSummary &summary)
{
    const auto start = Clock::now();
    summary = pkm::computeMap(workspace, pkm::MapQuantity::Determinant, grid, values, {}, nullptr, 1);
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// The map benchmark; false when a leg preset's map costs more than `limitRatio` times MOMA's
/// per cell. Each run times MOMA's map and the leg preset's in turn, and the ratio is taken pair
/// by pair, so that a change of the machine's speed during the run meets both.
bool benchMapRatio(double limitRatio, int size, int runs)
{
    const pkm::Design moma = loadPreset("moma-3a");
    const pkm::PlanarWorkspace *momaWorkspace = moma.mechanism->planarWorkspace();
    if (!momaWorkspace) {
        std::printf("FAIL: moma-3a has no planar workspace\n");
        return false;
    }
    const pkm::MapGrid momaGrid{momaWorkspace->workspaceBounds(), size, size};
    std::vector<float> momaValues(momaGrid.cells()), legValues;
    pkm::MapSummary momaSummary, legSummary;
    mapTime(*momaWorkspace, momaGrid, momaValues, momaSummary); // warm-up
    std::printf("det J map, %dx%d cells, one thread, %d runs, each paired with moma-3a's over its own bounds (%zu "
                "reachable cells)\n",
                size, size, runs, momaSummary.reachableCells);
    bool ok = true;
    // MOMA 3a from legs on MOMA's grid, so that the ratio is the ratio per cell of one map; the
    // other 2-DOF presets (every leg type, the platform of constant orientation) on grids of
    // as many cells over their own bounds
    for (const char *id : {"pp-2prr-moma3a", "pp-5r", "pp-5r-pjoint", "pp-pa-pjoint"}) {
        const pkm::Design legs = loadPreset(id);
        const pkm::PlanarWorkspace *workspace = legs.mechanism->planarWorkspace();
        if (!workspace) {
            std::printf("FAIL: %s has no planar workspace\n", id);
            return false;
        }
        const pkm::MapGrid grid = std::string_view(id) == "pp-2prr-moma3a" ? momaGrid
                                                                           : pkm::MapGrid{workspace->workspaceBounds(), size, size};
        legValues.resize(grid.cells());
        mapTime(*workspace, grid, legValues, legSummary); // warm-up
        std::vector<double> ratios, legTimes, momaTimes;
        for (int run = 0; run < runs; ++run) {
            const double m = mapTime(*momaWorkspace, momaGrid, momaValues, momaSummary);
            const double l = mapTime(*workspace, grid, legValues, legSummary);
            momaTimes.push_back(m);
            legTimes.push_back(l);
            ratios.push_back(l / m);
        }
        const Stats ratio = statsOf(ratios), legTime = statsOf(legTimes), momaTime = statsOf(momaTimes);
        std::printf("  %-15s median %.3f ms (min %.3f), %.1f ns/cell, %zu reachable cells; moma-3a median %.3f ms: "
                    "%.2f x MOMA per cell (pairs: min %.2f, p95 %.2f; target <= %.2f)\n",
                    id, legTime.median, legTime.min, legTime.median * 1e6 / double(grid.cells()), legSummary.reachableCells,
                    momaTime.median, ratio.median, ratio.min, ratio.p95, limitRatio);
        if (ratio.median > limitRatio) {
            std::printf("FAIL: %s's map is %.2f times MOMA's per cell, over %.2f\n", id, ratio.median, limitRatio);
            ok = false;
        }
    }
    return ok;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv); // the presets are Qt resources
    std::printf("machine: %s\n", pkm::bench::cpuText().c_str());
    double limitUs = 20.0, mapRatio = 3.0;
    int runs = 20000, mapSize = 400, mapRuns = 25;
    bool map = true;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--runs" && hasValue)
            runs = std::atoi(argv[++i]);
        else if (arg == "--no-map")
            map = false;
        else if (arg == "--map-ratio" && hasValue)
            mapRatio = std::atof(argv[++i]);
        else if (arg == "--map-size" && hasValue)
            mapSize = std::atoi(argv[++i]);
        else if (arg == "--map-runs" && hasValue)
            mapRuns = std::atoi(argv[++i]);
        else if (!arg.empty() && arg[0] != '-')
            limitUs = std::atof(arg.c_str());
        else
            return usage(argv[0]);
    }
    if (runs < 1 || mapSize < 2 || mapRuns < 1 || !(limitUs > 0) || !(mapRatio > 0))
        return usage(argv[0]);

    pinToOneCore();
    bool ok = benchAssemblyModes(limitUs, runs);
    if (map)
        ok = benchMapRatio(mapRatio, mapSize, mapRuns) && ok;
    return ok ? 0 : 1;
}
