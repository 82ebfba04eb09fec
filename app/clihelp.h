#pragma once
/// The help texts of `pkm`: `pkm --help` and `pkm COMMAND --help`.

#include "cliarguments.h"

#include <optional>
#include <string_view>

namespace pkm::cli {

/// The help of `command`, or the overview of all commands.
std::string_view helpText(std::optional<Command> command);

} // namespace pkm::cli
