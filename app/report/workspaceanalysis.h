#pragma once
/// The workspace of a design whose outputs are a point of the plane (Mechanism::
/// planarWorkspace()) as numbers, on a grid of square cells (squareGrid): its map, the box of
/// the reachable cells, the area of every combination of its ±1 mode parameters and the union
/// of their regions. `pkm workspace`, `pkm map` and the parameter sheet all read these.

#include "mechanism.h"
#include "planarworkspace.h"

#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace pkm::report {

using pkm::reachableCell; // the core's (planarworkspace.h), under the name the reports use

/// The map of `workspace` over squareGrid(its bounds, resolution) into `values` (and
/// `margins`, if not null), resized to the grid.
MapSummary computeInto(const PlanarWorkspace &workspace, MapQuantity quantity, int resolution,
    MapCells &values, MapCells *margins);
/// The box of the reachable cells (their edges, mm); empty when no cell is reachable.
Eigen::AlignedBox2d reachableBounds(const MapGrid &grid, std::span<const float> values);

/// The ±1 mode parameters of a design: working and assembly modes (MOMA's branch1, branch2,
/// assembly; the O-X glide's mode), not the 0/1 switches.
std::vector<const ParameterInfo *> modeParameters(const Mechanism &mechanism);
/// A mode value as the user names it: its choice name ("X") where the parameter has names,
/// else "+1" or "-1".
std::string modeValueText(const ParameterInfo &info, double value);
/// "branch1 = -1, branch2 = -1, assembly = +1"; empty without mode parameters.
std::string modeText(const std::vector<const ParameterInfo *> &modes, const ParameterSet &parameters);

/// The workspace of one combination of the mode parameters.
struct ModeArea {
    std::vector<double> values; ///< of the mode parameters, display units
    double area = 0.0;
    std::size_t reachableCells = 0;
    bool current = false;
    std::string note; ///< why the combination has no workspace
    bool empty = false; ///< the note says the workspace is empty
};
/// Every combination of the mode parameters, the first varying slowest, −1 before +1; the
/// current one is `current` (its area is not computed again).
std::vector<ModeArea> modeAreas(const Mechanism &mechanism, const std::vector<const ParameterInfo *> &modes,
    const MapSummary &current, int resolution, MapCells &buffer);

/// The workspaces of every mode combination on one grid over all of them: the union is the
/// region the mechanism reaches when it may change mode (the O-X glide's O and X), and the
/// regions drawn over each other are the O-X glide document's fig. 5.
struct ModeRegions {
    MapGrid grid;
    std::vector<std::vector<char>> reached; ///< per combination with a workspace, per cell
    std::vector<bool> current;              ///< whether that combination is the design's own
    std::size_t unionCells = 0;
    double unionArea = 0.0;
};
ModeRegions modeRegions(const Mechanism &mechanism, const std::vector<const ParameterInfo *> &modes, int resolution);
/// The travel (mm) of the axis that carries the whole mechanism (the O-X glide's z), if any.
std::optional<double> carriedTravel(const Mechanism &mechanism);
/// For a single mode parameter with named values (the O-X glide's mode): ("O", area), ("X",
/// area), sorted by name; empty otherwise.
std::vector<std::pair<std::string, double>> namedModeAreas(
    const std::vector<const ParameterInfo *> &modes, const std::vector<ModeArea> &areas);

/// The colour limit mapImage() uses by default: for det J the 95th percentile of |det J| over
/// the finite cells (so the spikes near inverse singularities do not wash the picture out),
/// for the condition number 100.
double mapColourLimit(std::span<const float> values, MapQuantity quantity);

} // namespace pkm::report
