#pragma once
/// The help texts of `pkm`: `pkm --help` and `pkm COMMAND --help`.

#include "cli/cliarguments.h"

#include <optional>
#include <string_view>

namespace pkm::cli {

/// The help of `command`, or the overview of all commands.
std::string_view helpText(std::optional<Command> command);
/// The help of `pkm dxf`, which reads its own options (clidxf.h).
std::string_view dxfHelpText();

} // namespace pkm::cli
