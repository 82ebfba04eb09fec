#pragma once
/// `pkm list` and `pkm show` (clishow.cpp).

#include "cli/clidesign.h"

#include <string>

namespace pkm::cli {

/// The presets and kinds, as text or JSON.
std::string listOutput(bool json);
/// A design's kind, parameters (by group), variables and modes as JSON.
std::string showJson(const PreparedDesign &prepared);
/// The same for a person to read.
std::string showText(const PreparedDesign &prepared);

} // namespace pkm::cli
