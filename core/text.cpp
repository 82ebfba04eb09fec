#include "text.h"

#include "mechanism.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <mutex>
#include <shared_mutex>

namespace pkm::text {

namespace {

std::shared_mutex &hooksMutex()
{
    static std::shared_mutex mutex;
    return mutex;
}

Hooks &hooks()
{
    static Hooks current;
    return current;
}

void replaceAll(std::string &text, std::string_view from, std::string_view to)
{
    if (from == to)
        return;
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
}

} // namespace

void install(Hooks newHooks)
{
    std::unique_lock lock(hooksMutex());
    hooks() = std::move(newHooks);
}

Hooks installed()
{
    std::shared_lock lock(hooksMutex());
    return hooks();
}

std::string translate(const char *context, const char *source, const char *disambiguation, int n)
{
    decltype(Hooks::translate) look = nullptr;
    {
        std::shared_lock lock(hooksMutex());
        look = hooks().translate;
    }
    if (look)
        return look(context, source, disambiguation, n);
    std::string text(source);
    if (n >= 0)
        replaceAll(text, "%n", std::to_string(n));
    return text;
}

std::string label(std::string_view source)
{
    if (source.empty())
        return {};
    return translate("core", std::string(source).c_str());
}

std::string format(std::string_view pattern, std::initializer_list<std::string_view> args)
{
    std::string text;
    text.reserve(pattern.size() + 16 * args.size());
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] >= '1' && pattern[i + 1] <= '9') {
            const auto index = static_cast<std::size_t>(pattern[i + 1] - '1');
            if (index < args.size()) {
                text.append(*(args.begin() + index));
                ++i;
                continue;
            }
        }
        text.push_back(pattern[i]);
    }
    return text;
}

namespace {
/// `text` (a C-locale number) with the locale's decimal point and minus sign.
std::string localised(std::string text)
{
    std::string point, minus;
    {
        std::shared_lock lock(hooksMutex());
        point = hooks().decimalPoint;
        minus = hooks().minusSign;
    }
    if (!point.empty())
        replaceAll(text, ".", point);
    if (!minus.empty() && !text.empty() && text.front() == '-')
        text.replace(0, 1, minus);
    return text;
}
} // namespace

std::string number(double value, int decimals)
{
    return localised(formatNumber(value, decimals));
}

std::string fixed(double value, int decimals)
{
    if (!std::isfinite(value))
        return localised(formatNumber(value, decimals));
    char buffer[400];
    // −0.04 to one decimal is "0.0", not "−0.0"
    const double scale = std::pow(10.0, decimals);
    const double rounded = std::round(value * scale) / scale;
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, rounded == 0.0 ? 0.0 : value, std::chars_format::fixed, decimals);
    return ec == std::errc() ? localised(std::string(buffer, end)) : localised(formatNumber(value, decimals));
}

std::string millimetres(double value)
{
    return format(translate("core", "%1 mm"), {number(value, 2)});
}

std::pair<std::string, std::string> millimetresApart(double a, double b)
{
    int decimals = 2;
    while (decimals < 12 && number(a, decimals) == number(b, decimals))
        ++decimals;
    const std::string pattern = translate("core", "%1 mm");
    return {format(pattern, {number(a, decimals)}), format(pattern, {number(b, decimals)})};
}

std::string numberOutside(double value, double lo, double hi, int decimals)
{
    const double bound = std::abs(value - lo) < std::abs(value - hi) ? lo : hi;
    std::string shown = number(value, decimals);
    for (int d = decimals + 1; d <= 12 && shown == number(bound, d - 1); ++d)
        shown = number(value, d);
    return shown;
}

std::string printable(std::string_view outside, std::size_t maxCharacters)
{
    static constexpr char hex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(std::min(outside.size(), maxCharacters * 4) + 4);
    const auto escape = [&](unsigned char byte) {
        out += "\\x";
        out += hex[byte >> 4];
        out += hex[byte & 15];
    };
    std::size_t characters = 0;
    for (std::size_t i = 0; i < outside.size(); ++characters) {
        if (characters == maxCharacters) {
            out += "…";
            break;
        }
        const auto byte = static_cast<unsigned char>(outside[i]);
        // the length of a well-formed UTF-8 sequence starting here (0: not one)
        const std::size_t length = byte < 0x80 ? 1 : (byte & 0xE0) == 0xC0 ? 2 : (byte & 0xF0) == 0xE0 ? 3
                                 : (byte & 0xF8) == 0xF0 ? 4 : 0;
        bool wellFormed = length > 0 && i + length <= outside.size();
        char32_t code = length == 1 ? byte : length == 2 ? byte & 0x1F : length == 3 ? byte & 0x0F : byte & 0x07;
        for (std::size_t k = 1; wellFormed && k < length; ++k) {
            const auto next = static_cast<unsigned char>(outside[i + k]);
            wellFormed = (next & 0xC0) == 0x80;
            code = (code << 6) | (next & 0x3F);
        }
        const bool overlong = (length == 2 && code < 0x80) || (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
        const bool control = code < 0x20 || (code >= 0x7F && code <= 0x9F);
        if (!wellFormed || overlong || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
            escape(byte);
            ++i;
        } else if (control) {
            for (std::size_t k = 0; k < length; ++k)
                escape(static_cast<unsigned char>(outside[i + k]));
            i += length;
        } else {
            out.append(outside.substr(i, length));
            i += length;
        }
    }
    return out;
}

} // namespace pkm::text
