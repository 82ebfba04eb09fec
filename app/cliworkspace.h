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
#include <span>
#include <string>

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

/// The outline of the reachable cells as an SVG document, in mm (viewBox), y up.
std::string workspaceSvg(const MapGrid &grid, std::span<const float> values, const std::string &title);

} // namespace pkm::cli
