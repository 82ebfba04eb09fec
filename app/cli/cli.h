#pragma once
/// The headless `pkm` command (reference: docs/cli.md): list, show, eval, sweep, workspace and map,
/// generic over the Mechanism interface — every name, unit and quantity comes from
/// parameterInfo(), variableInfo(), reportLayout() and planarWorkspace(), so a new mechanism
/// needs no change here.
///
/// runCli() is the whole program minus main(): tests call it in-process, main.cpp (pkm) and
/// main_draw.cpp (pkm-draw) call it with stdout and stderr. It never exits the process and
/// writes nothing to `out` unless the command succeeds. The commands that draw are run through
/// clidrawing.h, set only where the drawing code is linked in (drawingcommands.h).
///
/// The parts: cliarguments (the command line), clidesign (the design after --set), clihelp,
/// clisweep (`pkm sweep`), cliworkspace (`pkm workspace`, `pkm map`); the numbers and words
/// they print come from the Qt-free report library (report/: report, jsonwriter, texttable,
/// numberformat, sweeprowformatter, workspaceanalysis).

#include "mechanism.h"

#include <QStringList>

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace pkm {

/// Exit statuses of `pkm` (docs/cli.md): usage errors and "no solution" are distinguished so that
/// scripts can tell a typo from an unreachable pose.
enum CliExit : int {
    CliSuccess = 0,
    CliOutputError = 1, ///< the output could not be written (disk full, closed pipe)
    CliUsageError = 2, ///< bad command line, unknown name, not a number, invalid parameter, bad file
    CliNoSolution = 3, ///< pose out of range, unreachable or singular
};

/// Runs `pkm` with `arguments` (without the program name). Output goes to `out` (UTF-8),
/// one-sentence error messages to `err`; returns the exit status.
int runCli(const QStringList &arguments, std::FILE *out, std::FILE *err);

/// Exit status for a core failure: 3 for a pose that has no solution, 2 for everything else.
int cliExitCode(const Failure &failure);

namespace cli {
struct PreparedDesign;

/// The report of one solved pose as `pkm eval --json` prints it (without a trailing newline):
/// {"mechanism", "parameters", "pose", "jacobian", "singularity", "derived"}.
/// With `allModes` it adds "assembly_modes": [{output: value, …}, …], every real assembly
/// mode at the pose's inputs (Mechanism::assemblyModes), in display units.
/// With `equations` it adds "equations": [{"title", "symbolic", "substituted", "result", "unit",
/// "source", "note"}, …], the kind's governing equations with the pose's numbers put in
/// (core/equations.h); "result" in display units, null where it is not finite.
std::string evalJson(const Mechanism &mechanism, const Pose &pose, bool allModes = false, bool equations = false);

/// The first lines of show, eval, workspace and map: "Design     moma-3a: …" and
/// "Mechanism  moma (…)".
std::string designHeading(const PreparedDesign &prepared);
/// The title of a mechanism kind ("Active П-joint"), or the kind itself if it is not registered.
std::string kindTitle(std::string_view kind);

/// "pkm: MESSAGE" on `err`.
void printError(std::FILE *err, const std::string &message);
/// Writes `text` to `out`: CliSuccess, or CliOutputError with a message on `err`.
int printOutput(std::FILE *out, std::FILE *err, std::string_view text);

} // namespace cli

} // namespace pkm
