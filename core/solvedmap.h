#pragma once
/// What the maps that solve every cell share (the tolerance map, tolerancemap.h, and the maps of
/// what the actuators deliver, capabilitymap.h): rows handed out one at a time to a few threads,
/// each with its own tally, stopped between rows on cancel, with progress, and the summary of
/// the values they leave in the buffer. The closed-form maps of planarworkspace.h have their
/// own loop, in blocks of rows, with no per-thread state to merge.

#include "planarworkspace.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace pkm::solvedmap {

/// One thread's tally of the cells it filled; merged into the summary at the end.
struct Tally {
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    std::size_t reachable = 0;
    std::size_t nearSingular = 0;

    /// A reachable cell's value: a finite one counts in min and max.
    void add(float value)
    {
        ++reachable;
        if (std::isfinite(value)) {
            min = std::min(min, double(value));
            max = std::max(max, double(value));
        }
    }
    void merge(const Tally &other)
    {
        min = std::min(min, other.min);
        max = std::max(max, other.max);
        reachable += other.reachable;
        nearSingular += other.nearSingular;
    }
};

/// Runs `fillRow(r, tally, state)` for every row r of `grid` on `threads` threads (0: all
/// cores), each thread with a State made by `makeState()`, until the rows run out or `*cancel`
/// becomes true; `progress` hears (rows done, rows); `finish(state)` runs once per thread under
/// a lock. Returns the summary of the tallies (areas from the grid).
template <typename MakeState, typename FillRow, typename Finish>
MapSummary run(const MapGrid &grid, int threads, const std::atomic<bool> *cancel,
               const std::function<void(int, int)> &progress, MakeState makeState, FillRow fillRow, Finish finish)
{
    const auto start = std::chrono::steady_clock::now();
    MapSummary summary;
    summary.grid = grid;
    if (threads <= 0)
        threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::clamp(threads, 1, std::max(1, grid.rows));
    std::atomic<int> nextRow{0}, rowsDone{0};
    std::atomic<bool> stopped{false};
    std::mutex lock;
    Tally total;
    auto work = [&] {
        Tally tally;
        auto state = makeState();
        for (;;) {
            if (cancel && cancel->load(std::memory_order_relaxed)) {
                stopped = true;
                break;
            }
            const int r = nextRow.fetch_add(1);
            if (r >= grid.rows)
                break;
            fillRow(r, tally, state);
            const int done = ++rowsDone;
            if (progress)
                progress(done, grid.rows);
        }
        const std::lock_guard guard(lock);
        total.merge(tally);
        finish(state);
    };
    {
        std::vector<std::jthread> pool;
        for (int t = 1; t < threads; ++t)
            pool.emplace_back(work);
        work();
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

} // namespace pkm::solvedmap
