#pragma once
/// The drawing half of the command line: `pkm render`, `pkm sheet`, `pkm dxf` and the PNG
/// pictures of `pkm workspace` and `pkm map`, over the exports (export/). pkm-draw calls
/// registerDrawingCommands() before runCli(); so do tests that run those commands in-process.

namespace pkm::cli {

/// Sets the drawing commands (clidrawing.h) and the workspace pictures (cliworkspace.h).
void registerDrawingCommands();

} // namespace pkm::cli
