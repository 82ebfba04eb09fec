#pragma once
/// A map of the first-order worst-case error (tolerance.h, (T3)) over the workspace of a kind
/// whose outputs are a point of the plane (Mechanism::planarWorkspace()): each cell is solved
/// by inverse kinematics near the given pose (so in its working modes; a platform that turns
/// keeps the pose's angle φ) and its |Δx| bound computed there. NaN where unreachable, +∞ at a
/// direct singularity. Self-contained beside planarworkspace.h, whose maps are closed forms per
/// kind: this one needs 2 solves per toleranced parameter and cell, so grids stay coarse.

#include "planarworkspace.h"
#include "tolerance.h"

#include <atomic>
#include <span>

namespace pkm::tolerance {

inline constexpr int defaultMapGrid = 60;
inline constexpr int maxMapGrid = 400;

/// Fills `values` (grid.cells() floats, row-major from the bottom row) with the worst-case
/// error bound in core units (mm), on `threads` threads (0: all cores), stopping between rows
/// once `*cancel` is true; `progress` hears (rows done, rows). Summary as computeMap()'s.
MapSummary computeMap(const Analysis &analysis, const Pose &near, const MapGrid &grid, std::span<float> values,
                      const std::atomic<bool> *cancel = nullptr, const Progress &progress = {}, int threads = 0);

} // namespace pkm::tolerance
