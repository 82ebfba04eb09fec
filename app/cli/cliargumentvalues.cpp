// The values on pkm's command line: numbers, sizes and the names of file types.

#include "cli/cliargumentvalues.h"

#include <charconv>
#include <cmath>
#include <system_error>
#include <vector>

namespace pkm::cli {

/// Locale-independent: std::from_chars reads '.' as the decimal separator whatever LC_NUMERIC
/// says. The whole text must be a finite number ("5mm", "nan" and "1e999" are refused).
std::optional<double> parseNumber(std::string_view text)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
        text.remove_suffix(1);
    if (text.size() > 1 && text.front() == '+' && text[1] != '-')
        text.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

Failure notANumber(const std::string &context, const std::string &culprit, std::string_view text)
{
    std::string message = context + ": '" + std::string(text) + "' is not a number";
    if (text.find(',') != std::string_view::npos)
        message += " (use '.' as the decimal separator)";
    return usageFailure(culprit, message + ".");
}

/// "a .png, .svg or .pdf file"
std::string fileTypes(const std::array<std::string_view, 6> &types)
{
    std::vector<std::string_view> used;
    for (std::string_view type : types) {
        if (!type.empty())
            used.push_back(type);
    }
    std::string text("a ");
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (i > 0)
            text.append(i + 1 == used.size() ? " or " : ", ");
        text.append(".").append(used[i]);
    }
    return text.append(" file");
}

/// "1600x1200" (also "1600X1200", "1600×1200"): whole numbers, or nothing.
std::optional<std::pair<double, double>> parseSize(std::string_view text)
{
    std::size_t at = text.find_first_of("xX");
    std::size_t separator = 1;
    if (const std::size_t times = text.find("×"); times != std::string_view::npos && times < at) {
        at = times;
        separator = std::string_view("×").size();
    }
    if (at == std::string_view::npos)
        return std::nullopt;
    const auto width = parseNumber(text.substr(0, at));
    const auto height = parseNumber(text.substr(at + separator));
    if (!width || !height)
        return std::nullopt;
    return std::pair {*width, *height};
}

} // namespace pkm::cli
