#pragma once
/// The values on pkm's command line read as numbers, sizes and file types: locale-independent
/// and strict, so that "5mm", "nan" or "1,5" is refused with a message naming it.

#include "cli/cliarguments.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace pkm::cli {

/// The whole text as a finite number ('.' as the decimal point), or nothing.
std::optional<double> parseNumber(std::string_view text);
/// "--from abc: 'abc' is not a number." (with a hint at ',' used as the decimal point)
Failure notANumber(const std::string &context, const std::string &culprit, std::string_view text);
/// "a .png, .svg or .pdf file"
std::string fileTypes(const std::array<std::string_view, 6> &types);
/// "1600x1200" (also "1600X1200", "1600×1200"): whole numbers, or nothing.
std::optional<std::pair<double, double>> parseSize(std::string_view text);

} // namespace pkm::cli
