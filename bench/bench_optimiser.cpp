// Benchmark: what an optimiser pays per design. For a preset, DESIGNS variants are made
// (one length changed by up to ±5 %, as a search steps), and for each the workspace bounds,
// a 200² grid over them, the det J map and the κ map are computed on one thread: the area,
// det J's range and the worst κ are the summary an objective needs. The time per design is
// the whole of it (withParameter included); min, median and 95th percentile are printed with
// the designs per second. Target: median ≤ LIMIT_MS (argv[1], default 0.5 ms) for MOMA 3a.
//
//   bench_optimiser [LIMIT_MS] [--preset ID] [--parameter NAME] [--designs N] [--grid K]
#include "benchmachine.h"
#include "document/designfile.h"
#include "planarworkspace.h"

#include <QCoreApplication>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

int usage(const char *program)
{
    std::fprintf(stderr, "usage: %s [LIMIT_MS] [--preset ID] [--parameter NAME] [--designs N] [--grid K]\n", program);
    return 2;
}

struct Summary {
    double area = 0.0, detMin = 0.0, detMax = 0.0, conditionMax = 0.0;
};

/// The summary of one design: what an objective of an optimiser reads.
Summary summarize(const pkm::PlanarWorkspace &workspace, int resolution, std::vector<float> &values)
{
    const pkm::MapGrid grid = pkm::squareGrid(workspace.workspaceBounds(), resolution);
    values.resize(grid.cells());
    const pkm::MapSummary det = pkm::computeMap(workspace, pkm::MapQuantity::Determinant, grid, values, {}, nullptr, 1);
    const pkm::MapSummary condition = pkm::computeMap(workspace, pkm::MapQuantity::Condition, grid, values, {}, nullptr, 1);
    return {det.area, det.min, det.max, condition.max};
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication application(argc, argv);
    double limitMs = 0.5;
    std::string preset = "moma-3a", parameter = "l1";
    int designs = 2000, resolution = 200;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--preset" && hasValue)
            preset = argv[++i];
        else if (arg == "--parameter" && hasValue)
            parameter = argv[++i];
        else if (arg == "--designs" && hasValue)
            designs = std::atoi(argv[++i]);
        else if (arg == "--grid" && hasValue)
            resolution = std::atoi(argv[++i]);
        else if (!arg.empty() && arg[0] != '-')
            limitMs = std::atof(arg.c_str());
        else
            return usage(argv[0]);
    }
    if (designs < 10 || resolution < 10 || !(limitMs > 0))
        return usage(argv[0]);

    auto loaded = pkm::designfile::load(QString::fromStdString(preset));
    if (!loaded) {
        std::fprintf(stderr, "error: %s\n", loaded.failure().message.c_str());
        return 1;
    }
    const pkm::MechanismPtr base = loaded->mechanism;
    const auto parameters = base->parameters();
    const auto found = parameters.find(parameter);
    if (found == parameters.end() || !base->planarWorkspace()) {
        std::fprintf(stderr, "error: %s has no parameter %s or no planar workspace\n", preset.c_str(), parameter.c_str());
        return 1;
    }
    const double nominal = found->second;

    std::vector<float> values;
    std::vector<double> times;
    times.reserve(std::size_t(designs));
    int refused = 0;
    double areaSum = 0.0;
    for (int i = 0; i < designs + 20; ++i) {
        // a deterministic sweep of ±5 % (no random generator to seed): what a search visits
        const double change = 0.05 * std::sin(0.7 * i);
        const auto start = Clock::now();
        auto design = base->withParameter(parameter, nominal * (1.0 + change));
        Summary summary;
        if (design && (*design)->planarWorkspace())
            summary = summarize(*(*design)->planarWorkspace(), resolution, values);
        const auto end = Clock::now();
        if (i < 20)
            continue; // warm-up
        if (!design)
            ++refused;
        areaSum += summary.area;
        times.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    }
    std::sort(times.begin(), times.end());
    const double median = times[times.size() / 2];
    std::printf("%s, %s within +-5 %%, %d designs, %d^2 grid, one thread, on %s\n", preset.c_str(), parameter.c_str(),
                designs, resolution, pkm::bench::cpuText().c_str());
    std::printf("per design (new design, bounds, det J and kappa maps, summary): min %.3f ms, median %.3f ms, "
                "p95 %.3f ms; %.0f designs/s; mean area %.1f mm^2; %d refused\n",
                times.front(), median, times[std::min(times.size() - 1, times.size() * 95 / 100)], 1e3 / median,
                areaSum / double(designs - refused), refused);
    std::printf("target: median <= %.3f ms (%s)\n", limitMs, median <= limitMs ? "met" : "MISSED");
    return median <= limitMs ? 0 : 1;
}
