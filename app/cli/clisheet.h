#pragma once
/// `pkm sheet DESIGN [--set NAME=VALUE]... -o FILE.pdf|FILE.json|FILE.csv` (docs/cli.md): the
/// parameter sheet of a design in a pose (sheet.h), for building the prototype. The PDF is
/// drawn on Qt's offscreen platform (clirender.h: prepareRenderPlatform), so no display is
/// needed. The file is written completely or not at all (cli.h: saveFile), before anything is
/// printed.

#include "cli/cliarguments.h"
#include "cli/clidesign.h"
#include "export/sheet.h"

#include <cstdio>

namespace pkm::cli {

/// The title block's source of a prepared design: the preset id or the file's name, its title
/// and description.
sheet::Source sheetSource(const PreparedDesign &prepared);

/// Runs `pkm sheet` on `prepared`: the exit status (CliExit), one sentence on `err` on failure,
/// one line on `out` ("Wrote FILE (…)") once the file is written.
int runSheetCommand(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err);

} // namespace pkm::cli
