#pragma once
/// The commands that draw: `pkm render`, `pkm sheet`, `pkm dxf` and the PNG pictures of
/// `pkm workspace -o` and `pkm map -o`. They need QtGui, QtWidgets, QCustomPlot and OpenGL,
/// which the other commands do not, so they live in a program of their own, pkm-draw
/// (main_draw.cpp, drawingcommands.h): `pkm` looks at its command line first (drawsPictures)
/// and hands a drawing command to pkm-draw, so that `pkm eval`, `sweep`, `workspace --json` and
/// `map --json` start without loading the GUI libraries. runCli() runs the drawing commands
/// set here; pkm-draw and the tests that run the whole command in-process set them.

#include "cli/cliarguments.h"
#include "cli/clidesign.h"

#include <cstdio>
#include <string>
#include <vector>

namespace pkm::cli {

struct DrawingCommands {
    /// `pkm dxf …` and `pkm help dxf`, with their own options (clidxf.h).
    int (*dxf)(const std::vector<std::string> &arguments, std::FILE *out, std::FILE *err) = nullptr;
    int (*render)(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err)
        = nullptr;
    int (*sheet)(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err)
        = nullptr;
};
void setDrawingCommands(const DrawingCommands &commands);
const DrawingCommands &drawingCommands();

/// Whether `arguments` (without the program name) are `pkm dxf …` or `pkm help dxf`.
bool isDxfCommand(const std::vector<std::string> &arguments);
/// Whether the command line draws (see above). A line the parser refuses, help and --version
/// do not: `pkm` answers those itself, in the same words.
bool drawsPictures(const std::vector<std::string> &arguments);

/// The failure of a drawing command in a program that cannot draw.
std::string cannotDrawMessage(std::string_view command);

} // namespace pkm::cli
