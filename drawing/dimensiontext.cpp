#include "dimensiontext.h"

#include "mechanism.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <system_error>

namespace pkm::drawing {

std::string dimensionText(std::string_view sceneText, double distance)
{
    std::string name;
    std::optional<double> stated;
    if (const std::size_t equals = sceneText.find('='); equals != std::string_view::npos) {
        std::string_view left = sceneText.substr(0, equals);
        while (!left.empty() && left.back() == ' ')
            left.remove_suffix(1);
        name = std::string(left);
        std::string_view right = sceneText.substr(equals + 1);
        while (!right.empty() && right.front() == ' ')
            right.remove_prefix(1);
        std::string number(right);
        // "−" (U+2212), as typeset minus signs are, reads as '-'
        if (number.starts_with("\xE2\x88\x92"))
            number.replace(0, 3, "-");
        double value = 0.0;
        const auto result = std::from_chars(number.data(), number.data() + number.size(), value);
        if (result.ec == std::errc() && std::isfinite(value))
            stated = value;
    } else {
        std::string_view whole = sceneText;
        while (!whole.empty() && whole.back() == ' ')
            whole.remove_suffix(1);
        name = std::string(whole);
        double value = 0.0;
        const auto result = std::from_chars(whole.data(), whole.data() + whole.size(), value);
        if (result.ec == std::errc() && result.ptr == whole.data() + whole.size())
            name.clear(); // the text is the number alone
    }
    // a signed coordinate (p₁ = −20.0) keeps its sign when its magnitude is the distance
    const bool negative = stated && *stated < 0.0 && std::abs(std::abs(*stated) - distance) <= 0.5 + 1e-6 * distance;
    char buffer[400];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, distance, std::chars_format::fixed, 2);
    const std::string_view digits(
        buffer, static_cast<std::size_t>((result.ec == std::errc() ? result.ptr : buffer) - buffer));
    const std::string_view sign = negative && digits != "0.00" ? "-" : "";
    return name.empty() ? joinText({sign, digits}) : joinText({name, " = ", sign, digits});
}

} // namespace pkm::drawing
