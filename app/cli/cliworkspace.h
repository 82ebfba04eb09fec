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

#include "cli/cliarguments.h"
#include "capabilitymap.h"
#include "cli/clidesign.h"
#include "cli/cliworkspaceparts.h"
#include "planarworkspace.h"
#include "report/workspaceanalysis.h"

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

/// The design's planar workspace, or the failure that says the command (workspace, map)
/// needs one and which kinds have one.
Result<const PlanarWorkspace *> planarWorkspaceOf(const PreparedDesign &prepared, Command command);

/// A map as `pkm map` computes it from --quantity, --grid and --require (or the design's
/// requirements), in display units (the orientation range in degrees). The failure says why
/// the design cannot be mapped so, or that no cell of the grid is reachable. The command and
/// the Python module both map through it, so their maps are the same numbers.
struct CommandMap {
    MapQuantity quantity = MapQuantity::Determinant;
    ComputedMap map;
    std::vector<capability::Requirement> requirements;
    capability::SpecificationSummary specification;
    ParameterSet tolerances; ///< --quantity tolerance: core units
    Eigen::AlignedBox2d box; ///< the reachable cells' box, mm
};
/// Without `keepCells` a det J or κ map is summarised row by row and map.values stays empty
/// (`pkm map --json` without -o needs only the summary).
Result<CommandMap> computeCommandMap(const PreparedDesign &prepared, const Invocation &invocation,
                                     bool keepCells = true);

/// The workspace as `pkm workspace` computes it from --grid and --require (or the design's
/// requirements): the det J map of the design's modes (its reachable cells are the finite
/// ones), the box of those cells, the area of every mode combination and their union, and
/// the specification region. The failure says the design has no planar workspace or that no
/// cell of the grid is reachable.
struct CommandWorkspace {
    ComputedMap map;
    Eigen::AlignedBox2d box;
    std::vector<const ParameterInfo *> modes; ///< the ±1 mode parameters
    std::vector<report::ModeArea> areas;      ///< per combination of them
    report::ModeRegions united;               ///< their regions on one grid
    std::vector<std::pair<std::string, double>> named; ///< ("O", area), ("X", area)
    std::vector<capability::Requirement> requirements;
    ComputedMap region; ///< where every requirement holds (when there are requirements)
    capability::SpecificationSummary specification;
    double seconds = 0.0;
};
Result<CommandWorkspace> computeCommandWorkspace(const PreparedDesign &prepared, const Invocation &invocation);
/// What `pkm workspace --json` prints for it on a grid of `resolution` (cliworkspaceparts.cpp).
std::string workspaceJson(const PreparedDesign &prepared, const CommandWorkspace &computed, int resolution);

/// Writers of the PNG pictures of `pkm workspace -o` and `pkm map -o`. They need QtGui, which
/// `pkm` does not load: the drawing half of the command line (pkm-draw, clidrawing.h) sets them
/// and `pkm` hands it the commands that write pictures (writesPicture). Each returns the
/// failure sentence, or nothing once the file is written.
struct WorkspacePictureWriters {
    std::optional<std::string> (*workspace)(const std::string &path, const MapGrid &grid, std::span<const float> values,
        std::span<const SingularCurve> curves, const std::string &title)
        = nullptr;
    std::optional<std::string> (*regions)(
        const std::string &path, const report::ModeRegions &regions, const std::string &title)
        = nullptr;
    std::optional<std::string> (*map)(const std::string &path, const MapGrid &grid, std::span<const float> values,
        MapQuantity quantity, double limit, std::span<const SingularCurve> curves, const std::string &title)
        = nullptr;
};
void setWorkspacePictureWriters(const WorkspacePictureWriters &writers);
/// Whether `invocation` (workspace or map) writes a PNG picture.
bool writesPicture(const Invocation &invocation);

} // namespace pkm::cli
