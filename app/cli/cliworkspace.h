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
#include "cli/clidesign.h"
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

/// Writers of the PNG pictures of `pkm workspace -o` and `pkm map -o`. They need QtGui, which
/// `pkm` does not load: the drawing half of the command line (pkm-draw, clidrawing.h) sets them
/// and `pkm` hands it the commands that write pictures (writesPicture). Each returns the
/// failure sentence, or nothing once the file is written.
struct WorkspacePictureWriters {
    std::optional<std::string> (*workspace)(
        const std::string &path, const MapGrid &grid, std::span<const float> values, const std::string &title)
        = nullptr;
    std::optional<std::string> (*regions)(
        const std::string &path, const report::ModeRegions &regions, const std::string &title)
        = nullptr;
    std::optional<std::string> (*map)(const std::string &path, const MapGrid &grid, std::span<const float> values,
        MapQuantity quantity, double limit, const std::string &title)
        = nullptr;
};
void setWorkspacePictureWriters(const WorkspacePictureWriters &writers);
/// Whether `invocation` (workspace or map) writes a PNG picture.
bool writesPicture(const Invocation &invocation);

} // namespace pkm::cli
