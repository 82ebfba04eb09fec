#pragma once
/// Maps of what the actuators deliver (capability.h) over the workspace of a kind whose
/// outputs are a point of the plane, and the specification region: the cells where every
/// requirement the user states ("force_worst >= 50 N") holds.
///
/// A cell equals the values panel at the pose solved there, in the design's working and
/// assembly modes (a platform that turns at φ = phi_map), with the exact 0 or ∞ of a singular
/// one. Every kind with a planar workspace computes its rows in closed form in its own map loop
/// (PlanarWorkspace::fillCapabilityRow(), capabilitycell.h), at about the cost of its det J
/// map; otherwise — a platform held at another φ, a requirement on an entry no map shows —
/// each cell is solved by inverse kinematics near the given pose, classified and evaluated as
/// `pkm eval` evaluates a pose, some fifty times slower.

#include "capability.h"
#include "planarworkspace.h"

#include <atomic>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pkm::capability {

/// The capability entry a map quantity shows ("force_worst"…), or empty for det J, κ, the
/// orientation range and the specification.
std::string_view entryName(MapQuantity quantity);
/// The map quantity of an entry name, if it is one of the four maps.
std::optional<MapQuantity> mapQuantity(std::string_view entryName);

/// One stated requirement: entry `name` (a single value of the capability layout) at least or
/// at most `value`, in core units.
struct Requirement {
    std::string name;
    bool atLeast = true;
    double value = 0.0;
    bool operator==(const Requirement &) const = default;
};

/// Parses "force_worst>=50" (also "<=", ">" as ">=", "<" as "<=", spaces allowed) against the
/// layout of `actuators`, with `value` in the entry's display unit (N, mm/s, mm, N/mm, or N·m,
/// °/s, ° for an angular output). The error names the culprit.
Result<Requirement> parseRequirement(std::string_view text, const Actuators &actuators);

/// "force_worst ≥ 50 N", in display units.
std::string requirementText(const Requirement &requirement, const Actuators &actuators);

/// Whether the values of one pose (laid out by layoutFor()) meet `requirement`; an undefined
/// value meets nothing.
bool meets(const Requirement &requirement, const ReportLayout &layout, std::span<const double> values);

/// Turns a capability map computed by computeMap() (core units) into the display units of its
/// entry (°/s and ° for an angular output), values and summary alike, as the values panel and
/// `pkm eval` show them; returns the entry, or nullptr for the specification (left as it is).
const ReportEntry *toDisplayUnits(const Actuators &actuators, MapQuantity quantity, std::span<float> values,
                                  MapSummary &summary);

/// The pose every cell of a map starts from: `pose` (its modes), for a platform that turns at
/// φ = phi_map, the slice the workspace bounds and the singular curves are drawn for — solved
/// there if it can be, else `pose` as it is.
Pose mapStart(const Mechanism &mechanism, const Pose &pose);

using Progress = std::function<void(int done, int total)>;

struct SpecificationSummary {
    std::size_t metCells = 0;   ///< reachable cells where every requirement holds
    double metArea = 0.0;       ///< mm²
    std::vector<std::size_t> failing; ///< per requirement, the reachable cells where it fails
};

/// Fills `values` (grid.cells() floats, row-major from the bottom row) with `quantity`
/// (a capability entry, in core units; or Specification: 1 where every one of `requirements`
/// holds, 0 where one fails) for `mechanism` with `actuators`, and `margins` (if not empty)
/// with the singularity margin; NaN where unreachable. Runs on `threads` threads (0: all
/// cores), stops between rows once `*cancel` is true, tells `progress` (rows done, rows).
/// `specification`, if given, receives the region's cells and area.
MapSummary computeMap(const Mechanism &mechanism, const Actuators &actuators, MapQuantity quantity,
                      std::span<const Requirement> requirements, const Pose &near, const MapGrid &grid,
                      std::span<float> values, std::span<float> margins = {},
                      SpecificationSummary *specification = nullptr, const std::atomic<bool> *cancel = nullptr,
                      const Progress &progress = {}, int threads = 0);

} // namespace pkm::capability
