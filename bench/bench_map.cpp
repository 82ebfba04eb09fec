// Benchmark: the MOMA det J map of configuration 3a (Moma::createFrom({})) on a 1000×1000 grid
// over its workspace bounds, computed with every core as the workspace view does. After a
// warm-up the map is computed RUNS times; min, median and 95th percentile are printed with the
// cell rate, and the best time on one thread. Target: median ≤ LIMIT_MS (argv[1], default 5 ms).
//
//   bench_map [LIMIT_MS] [--runs N] [--size N] [--write FILE] [--json FILE]
//
// --write FILE: the map as raw little-endian float32, row-major from the bottom row, NaN where
//               unreachable (what bench/moma_map_numpy.py compares its own map with).
// --json FILE:  the grid, the design and the timings, so that the NumPy script computes the same
//               map: Moma's bounds come from sampling, so they are handed over, not recomputed.
#include "benchmachine.h"
#include "kinds/moma/moma.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace {

int usage(const char *program)
{
    std::fprintf(stderr, "usage: %s [LIMIT_MS] [--runs N] [--size N] [--write FILE] [--json FILE]\n", program);
    return 2;
}

/// A double for JSON: NaN and infinities are not JSON numbers.
std::string json(double v)
{
    if (!std::isfinite(v))
        return "null";
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

} // namespace

int main(int argc, char *argv[])
{
    double limitMs = 5.0;
    int runs = 30;
    int size = 1000;
    const char *writePath = nullptr;
    const char *jsonPath = nullptr;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--runs" && hasValue)
            runs = std::atoi(argv[++i]);
        else if (arg == "--size" && hasValue)
            size = std::atoi(argv[++i]);
        else if (arg == "--write" && hasValue)
            writePath = argv[++i];
        else if (arg == "--json" && hasValue)
            jsonPath = argv[++i];
        else if (!arg.empty() && arg[0] != '-')
            limitMs = std::atof(arg.c_str());
        else
            return usage(argv[0]);
    }
    if (runs < 1 || size < 2 || !(limitMs > 0))
        return usage(argv[0]);

    auto made = pkm::Moma::createFrom({});
    if (!made) {
        std::fprintf(stderr, "error: %s\n", made.failure().message.c_str());
        return 1;
    }
    const auto &moma = static_cast<const pkm::Moma &>(**made);
    const pkm::MapGrid grid{moma.workspaceBounds(), size, size};
    std::vector<float> values(grid.cells());

    // Warm-up: page in the buffer, start the clocks of the cores, resolve the AVX2 clones.
    pkm::MapSummary summary;
    for (int i = 0; i < 3; ++i)
        summary = pkm::computeMap(moma, pkm::MapQuantity::Determinant, grid, values);

    std::vector<double> times;
    times.reserve(static_cast<std::size_t>(runs));
    for (int i = 0; i < runs; ++i) {
        const auto start = std::chrono::steady_clock::now();
        summary = pkm::computeMap(moma, pkm::MapQuantity::Determinant, grid, values);
        const auto end = std::chrono::steady_clock::now();
        times.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    }
    std::sort(times.begin(), times.end());
    // One core alone, for the per-core comparison with NumPy (which uses one): best of a few.
    double singleThread = std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::max(3, runs / 3); ++i) {
        const auto start = std::chrono::steady_clock::now();
        pkm::computeMap(moma, pkm::MapQuantity::Determinant, grid, values, {}, nullptr, 1);
        const auto end = std::chrono::steady_clock::now();
        singleThread = std::min(singleThread, std::chrono::duration<double, std::milli>(end - start).count());
    }
    const double best = times.front();
    const double median = times[times.size() / 2];
    const double p95 = times[std::min(times.size() - 1, times.size() * 95 / 100)];
    const double cellsPerSecond = double(grid.cells()) / (median * 1e-3);
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());

    const Eigen::AlignedBox2d &b = grid.bounds;
    std::printf("MOMA 3a det J map, %dx%d cells over x [%.3f, %.3f] mm, y [%.3f, %.3f] mm, %u threads, %d runs\n",
                grid.columns, grid.rows, b.min().x(), b.max().x(), b.min().y(), b.max().y(), threads, runs);
    std::printf("reachable %zu cells, area %.1f mm^2, det J in [%.4g, %.4g]\n", summary.reachableCells, summary.area,
                summary.min, summary.max);
    std::printf("time: min %.3f ms, median %.3f ms, p95 %.3f ms; %.1f Mcells/s", best, median, p95,
                cellsPerSecond * 1e-6);
    if (limitMs < 1e5) // a huge limit means "no target" (the ratio benchmark)
        std::printf(" (target: median <= %.2f ms)", limitMs);
    std::printf("\n");
    std::printf("one thread: best %.3f ms\n", singleThread);
    std::printf("machine: %s\n", pkm::bench::cpuText().c_str());

    if (writePath) {
        std::FILE *f = std::fopen(writePath, "wb");
        if (!f || std::fwrite(values.data(), sizeof(float), values.size(), f) != values.size()) {
            std::fprintf(stderr, "error: cannot write %s: %s\n", writePath, std::strerror(errno));
            if (f)
                std::fclose(f);
            return 1;
        }
        std::fclose(f);
    }
    if (jsonPath) {
        std::FILE *f = std::fopen(jsonPath, "w");
        if (!f) {
            std::fprintf(stderr, "error: cannot write %s: %s\n", jsonPath, std::strerror(errno));
            return 1;
        }
        const pkm::MomaDesign &d = moma.design();
        std::fprintf(f, "{\n  \"quantity\": \"det_J\",\n");
        std::fprintf(f, "  \"bounds\": [%s, %s, %s, %s],\n", json(b.min().x()).c_str(), json(b.min().y()).c_str(),
                     json(b.max().x()).c_str(), json(b.max().y()).c_str());
        std::fprintf(f, "  \"columns\": %d,\n  \"rows\": %d,\n", grid.columns, grid.rows);
        std::fprintf(f, "  \"design\": {\"R1\": [%s, %s], \"R2\": [%s, %s],\n", json(d.reference[0].x()).c_str(),
                     json(d.reference[0].y()).c_str(), json(d.reference[1].x()).c_str(),
                     json(d.reference[1].y()).c_str());
        std::fprintf(f, "             \"alpha\": [%s, %s], \"length\": [%s, %s],\n", json(d.alpha[0]).c_str(),
                     json(d.alpha[1]).c_str(), json(d.length[0]).c_str(), json(d.length[1]).c_str());
        std::fprintf(f, "             \"stroke\": [%s, %s], \"branch\": [%d, %d],\n", json(d.strokeMin).c_str(),
                     json(d.strokeMax).c_str(), d.branch[0], d.branch[1]);
        std::fprintf(f, "             \"assembly\": %d, \"one_side\": %d,\n", d.assembly, d.oneSide ? 1 : 0);
        // the inner side of each guide, for the one-side constraint (0 when it is off)
        std::fprintf(f, "             \"inner_side\": [%d, %d]},\n", d.oneSide ? pkm::moma::innerSide(d, 0) : 0,
                     d.oneSide ? pkm::moma::innerSide(d, 1) : 0);
        std::fprintf(f, "  \"reachable_cells\": %zu,\n  \"threads\": %u,\n  \"runs\": %d,\n", summary.reachableCells,
                     threads, runs);
        std::fprintf(f, "  \"min_ms\": %s,\n  \"median_ms\": %s,\n  \"p95_ms\": %s,\n", json(best).c_str(),
                     json(median).c_str(), json(p95).c_str());
        std::fprintf(f, "  \"single_thread_min_ms\": %s\n}\n", json(singleThread).c_str());
        std::fclose(f);
    }
    if (median > limitMs) {
        std::printf("FAIL: median %.3f ms is over the %.2f ms limit\n", median, limitMs);
        return 1;
    }
    return 0;
}
