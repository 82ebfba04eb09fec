#pragma once
/// The command line of `pkm`, parsed: which command, its options and the --set values. Only
/// the syntax is checked here; names are checked against the design (clidesign.h).

#include "result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pkm::cli {

enum class Command { List, Show, Eval, Sweep };

/// "list", "show", "eval", "sweep".
std::string_view commandName(Command command);

/// One --set NAME=VALUE.
struct Setting {
    std::string text; ///< as typed, "theta=30", for messages
    std::string name;
    double value = 0.0;
};

struct Invocation {
    std::optional<Command> command; ///< none for `pkm --help` and `pkm --version`
    bool help = false;
    bool version = false;
    bool json = false;
    bool csv = false;
    std::optional<std::string> design;
    std::vector<Setting> sets;
    std::optional<std::string> var;
    std::optional<double> from;
    std::optional<double> to;
    std::optional<std::int64_t> steps;
};

/// Parses `arguments` (without the program name). A command that needs a DESIGN has one, and
/// sweep has all of --var, --from, --to and --steps.
Result<Invocation> parseArguments(const std::vector<std::string> &arguments);

/// A mistake on the command line: exit status 2.
Failure usageFailure(std::string culprit, std::string message);

/// Prefixes a core message with the argument that caused it ("--set theta=75: θ = 75° is …"),
/// so the sentence names the culprit as the user typed it.
Failure inContext(Failure failure, const std::string &context);

} // namespace pkm::cli
