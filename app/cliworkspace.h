#pragma once
/// `pkm workspace` and `pkm map`: the reachable workspace and the singularity maps of any
/// mechanism whose outputs are a point of the plane (Mechanism::planarWorkspace()), on a grid
/// of square cells (squareGrid), with a picture or the full map written to -o FILE.
///
/// workspace: the area, bounds and cell count of the design's current modes, and the area of
/// every combination of its ±1 mode parameters (ParameterGroup::Mode with domain [−1, 1]);
/// -o FILE.png (the reachable cells) or FILE.svg (the outline, in mm).
/// map: det J or the condition number of J over the workspace bounds, summarised;
/// -o FILE.png (a colour picture) or FILE.csv (x,y,value,margin per reachable cell).
///
/// Output files are written atomically (QSaveFile) and before anything goes to stdout, so a
/// failure leaves neither a file nor half an output.

#include "cliarguments.h"
#include "clidesign.h"
#include "planarworkspace.h"

#include <QImage>

#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace pkm::cli {

/// Runs `pkm workspace` or `pkm map` (invocation.command) on `prepared`: the exit status, with
/// one sentence on `err` on failure and nothing on `out` unless the command succeeds.
int runWorkspaceCommand(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err);

/// The picture of `pkm workspace -o FILE.png`: reachable cells (finite or infinite values,
/// not NaN) light blue on white with a darker outline, y up, at least 400 pixels along the
/// longer side (a whole number of pixels per cell).
QImage workspaceImage(const MapGrid &grid, std::span<const float> values);
/// Regions on one grid (a flag per cell) painted over each other, later layers over earlier
/// ones, with the boundary of their union: the workspaces of a design's modes (fig. 5 of the
/// O-X glide), as `pkm workspace -o FILE.png` draws them for a mechanism with named modes.
QImage regionsImage(const MapGrid &grid, const std::vector<std::pair<const std::vector<char> *, QRgb>> &layers);

/// The picture of `pkm map -o FILE.png`: one pixel per cell, y up, unreachable cells
/// transparent. Determinant: a diverging blue–white–red scale over [−limit, limit];
/// condition number: a sequential scale over log₁₀ κ from 0 to log₁₀ limit.
QImage mapImage(const MapGrid &grid, std::span<const float> values, MapQuantity quantity, double limit);

/// The colour limit mapImage() uses by default: for det J the 98th percentile of |det J| over
/// the finite cells (so the spikes near inverse singularities do not wash the picture out),
/// for the condition number 100.
double mapColourLimit(std::span<const float> values, MapQuantity quantity);

// -- the parts of `pkm workspace`, shared with the parameter sheet (sheet.h) -----------------

/// The map of `workspace` over squareGrid(its bounds, resolution) into `values` (and
/// `margins`, if not null), resized to the grid.
MapSummary computeInto(const PlanarWorkspace &workspace, MapQuantity quantity, int resolution,
    std::vector<float> &values, std::vector<float> *margins);
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
    const MapSummary &current, int resolution, std::vector<float> &buffer);

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
/// The picture of `pkm workspace -o FILE.png` for a mechanism with named modes: every mode's
/// workspace over each other, larger ones first, the design's own darker, the union outlined.
QImage modeRegionsImage(const ModeRegions &regions);

/// The travel (mm) of the axis that carries the whole mechanism (the O-X glide's z), if any.
std::optional<double> carriedTravel(const Mechanism &mechanism);
/// For a single mode parameter with named values (the O-X glide's mode): ("O", area), ("X",
/// area), sorted by name; empty otherwise.
std::vector<std::pair<std::string, double>> namedModeAreas(
    const std::vector<const ParameterInfo *> &modes, const std::vector<ModeArea> &areas);

/// The outline of the reachable cells as an SVG document, in mm (viewBox), y up.
std::string workspaceSvg(const MapGrid &grid, std::span<const float> values, const std::string &title);

} // namespace pkm::cli
