#pragma once
/// The headless `pkm` command (contract: CLI.md): list, show, eval, sweep, workspace and map,
/// generic over the Mechanism interface — every name, unit and quantity comes from
/// parameterInfo(), variableInfo(), reportLayout() and planarWorkspace(), so a new mechanism
/// needs no change here.
///
/// runCli() is the whole program minus main(): tests call it in-process, main_cli.cpp calls it
/// with stdout and stderr. It never exits the process and writes nothing to `out` unless the
/// command succeeds.
///
/// The parts: cliarguments (the command line), clidesign (the design after --set), clihelp,
/// clisweep and sweeprowformatter (`pkm sweep`), cliworkspace (`pkm workspace`, `pkm map`),
/// clireport and jsonwriter (JSON output), texttable (text output), numberformat (the text of
/// every number).

#include "mechanism.h"

#include <QStringList>

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

class QByteArray;
class QImage;

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
struct PreparedDesign;

/// The report of one solved pose as `pkm eval --json` prints it (without a trailing newline):
/// {"mechanism", "parameters", "pose", "jacobian", "singularity", "derived"}.
std::string evalJson(const Mechanism &mechanism, const Pose &pose);

/// The first lines of show, eval, workspace and map: "Design     moma-3a: …" and
/// "Mechanism  moma (…)".
std::string designHeading(const PreparedDesign &prepared);
/// The title of a mechanism kind ("Active П-joint"), or the kind itself if it is not registered.
std::string kindTitle(std::string_view kind);

/// "pkm: MESSAGE" on `err`.
void printError(std::FILE *err, const std::string &message);
/// Writes `text` to `out`: CliSuccess, or CliOutputError with a message on `err`.
int printOutput(std::FILE *out, std::FILE *err, std::string_view text);

// -- output files: written completely or not at all -----------------------------------------

/// Hands one chunk of a file to saveFile(): false when it could not be written.
using ChunkWriter = std::function<bool(std::string_view)>;
/// Writes `path` atomically: the chunks `produce` gives its ChunkWriter go to a temporary file
/// (QSaveFile) that replaces `path` only once all of them were written and `produce` returned
/// true; otherwise `path` is left as it was. The failure is one sentence naming the file.
std::optional<std::string> saveFile(const std::string &path, const std::function<bool(const ChunkWriter &)> &produce);
/// saveFile() with the whole content at once.
std::optional<std::string> saveBytes(const std::string &path, const QByteArray &bytes);
/// `image` encoded as PNG (with its text keys, e.g. "Title"), saved by saveBytes().
std::optional<std::string> savePng(const std::string &path, const QImage &image);
} // namespace cli

} // namespace pkm
