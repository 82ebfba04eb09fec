#pragma once
/// The headless `pkm` command (contract: CLI.md): list, show, eval and sweep, generic over the
/// Mechanism interface — every name, unit and quantity comes from parameterInfo(),
/// variableInfo() and reportLayout(), so a new mechanism needs no change here.
///
/// runCli() is the whole program minus main(): tests call it in-process, main_cli.cpp calls it
/// with stdout and stderr. It never exits the process and writes nothing to `out` unless the
/// command succeeds.
///
/// The parts: cliarguments (the command line), clidesign (the design after --set), clihelp,
/// clisweep and sweeprowformatter (`pkm sweep`), clireport and jsonwriter (JSON output),
/// texttable (text output), numberformat (the text of every number).

#include "mechanism.h"

#include <QStringList>

#include <cstdio>
#include <string>

namespace pkm {

/// Exit statuses of `pkm` (CLI.md): usage errors and "no solution" are distinguished so that
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
/// The report of one solved pose as `pkm eval --json` prints it (without a trailing newline):
/// {"mechanism", "parameters", "pose", "jacobian", "singularity", "derived"}.
std::string evalJson(const Mechanism &mechanism, const Pose &pose);
} // namespace cli

} // namespace pkm
