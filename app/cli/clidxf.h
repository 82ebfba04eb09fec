#pragma once
/// `pkm dxf DESIGN [--set NAME=VALUE]... -o FILE.dxf` (docs/cli.md): the linkage drawing of the
/// design in a pose as an AutoCAD R12 DXF file for CAD programs, drawn by dxfwriter.h from
/// Mechanism::scene() — every mechanism kind, in mm, in the scene's frame.
///
/// runCli() hands the command line to runDxfCommand() when isDxfCommand() says it is this
/// command's (`pkm dxf …` or `pkm help dxf`): it reads its own options, in the same words and
/// with the same messages as parseArguments(), and shares prepareDesign() with the others.
/// The file is written completely or not at all (cli.h: saveFile) before anything is printed.

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace pkm::cli {

/// Runs `pkm dxf`: the exit status (CliExit), one sentence on `err` on failure, and one line
/// on `out` ("Wrote FILE (…)") once the file is written.
int runDxfCommand(const std::vector<std::string> &arguments, std::FILE *out, std::FILE *err);

} // namespace pkm::cli
