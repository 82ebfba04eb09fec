#include "equations.h"

#include "registry.h"
#include "text.h"

#include <charconv>
#include <cmath>

namespace pkm {

std::vector<Equation> mechanismEquations(const Mechanism &mechanism, const Pose &pose)
{
    const MechanismKind *kind = findMechanismKind(mechanism.kind());
    if (!kind || !kind->equations)
        return {};
    return kind->equations(mechanism, pose);
}

namespace {
/// A number inside a formula goes without its unit, which the result carries, except for
/// degrees: "sin 30°" must not read as 30 radians.
EquationNumber inFormula(const EquationNumber &number)
{
    if (std::string_view(number.unit.symbol).starts_with("°"))
        return number;
    return {number.unit.toDisplay(number.value), units::none, number.decimals};
}
} // namespace

std::string fillEquation(const Equation &equation, const std::function<std::string(const EquationNumber &)> &format)
{
    const std::string &pattern = equation.substituted;
    std::string text;
    text.reserve(pattern.size() + 12 * equation.numbers.size());
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] >= '1' && pattern[i + 1] <= '9') {
            const auto index = static_cast<std::size_t>(pattern[i + 1] - '1');
            if (index < equation.numbers.size()) {
                // a negative number in brackets: "x − (−5.00)", not "x − −5.00", and "(−5.00)²";
                // where it opens a bracket or a list and nothing raises it to a power, bare:
                // "det[(−14.92, 1.34); …]", "−288816494.0 / 5715540237669.9"
                const std::string number = format(inFormula(equation.numbers[index]));
                const bool negative = number.starts_with("-") || number.starts_with("−");
                const std::string_view before = std::string_view(text), after = std::string_view(pattern).substr(i + 2);
                const bool opens = before.empty() || before.ends_with("(") || before.ends_with("[") || before.ends_with(", ")
                                   || before.ends_with("; ");
                const bool raised = after.starts_with("²") || after.starts_with("³") || after.starts_with("^");
                text += negative && !(opens && !raised) ? "(" + number + ")" : number;
                ++i;
                continue;
            }
        }
        text.push_back(pattern[i]);
    }
    return text;
}

std::string plainEquationNumber(const EquationNumber &number)
{
    double display = number.unit.toDisplay(number.value);
    if (std::isinf(display))
        return "∞";
    if (!std::isfinite(display))
        return "—";
    const int decimals = std::max(0, number.decimals);
    // as the values panel: a value that rounds to zero is 0, never "-0.00"
    if (std::abs(display) < 0.5 * std::pow(10.0, -decimals))
        display = 0.0;
    char buffer[64];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, display, std::chars_format::fixed, decimals);
    std::string text = ec == std::errc() ? std::string(buffer, end) : std::string("?");
    if (!text.empty() && text.front() == '-')
        text.replace(0, 1, "−");
    const std::string unit = text::label(number.unit.symbol);
    if (unit.empty())
        return text;
    if (unit.rfind("°", 0) == 0) // degrees glued on, as the values panel writes them
        return text + unit;
    return text + " " + unit;
}

std::string equationText(const Equation &equation)
{
    std::string text = equation.symbolic + "\n  = ";
    if (!equation.substituted.empty())
        text += fillEquation(equation, plainEquationNumber) + " = ";
    text += plainEquationNumber(equation.result);
    return text;
}

namespace equations {

Report::Report(const Mechanism &mechanism, const Pose &pose)
    : m_layout(mechanism.reportLayout())
    , m_values(std::size_t(mechanism.reportLayout().size), 0.0)
{
    m_singularity = mechanism.evaluate(pose, m_values);
}

EquationNumber Report::number(std::string_view name, int element) const
{
    const ReportEntry *entry = m_layout.find(name);
    if (!entry || element < 0 || element >= entry->rows * entry->cols)
        return {std::numeric_limits<double>::quiet_NaN(), units::none, 3};
    return {m_values[std::size_t(entry->offset + element)], entry->unit, entry->decimals};
}

EquationNumber parameter(const Mechanism &mechanism, std::string_view name)
{
    const ParameterInfo *info = mechanism.findParameter(name);
    const ParameterSet values = mechanism.parameters();
    const auto found = values.find(name);
    if (!info || found == values.end())
        return {std::numeric_limits<double>::quiet_NaN(), units::none, 3};
    return {found->second, info->unit, info->decimals};
}

namespace {
enum class Reference { Equation, Figure, Whole };

const char *documentPattern(Document document, Reference reference)
{
    switch (document) {
    case Document::PJointDocument:
        switch (reference) {
        case Reference::Equation: return QT_TRANSLATE_NOOP("core", "eq. %1 of the П-joint document");
        case Reference::Figure: return QT_TRANSLATE_NOOP("core", "fig. %1 of the П-joint document");
        case Reference::Whole: return QT_TRANSLATE_NOOP("core", "the П-joint document");
        }
        break;
    case Document::MomaDocument:
        switch (reference) {
        case Reference::Equation: return QT_TRANSLATE_NOOP("core", "eq. %1 of the MOMA document");
        case Reference::Figure: return QT_TRANSLATE_NOOP("core", "fig. %1 of the MOMA document");
        case Reference::Whole: return QT_TRANSLATE_NOOP("core", "the MOMA document");
        }
        break;
    case Document::OxGlideDocument:
        switch (reference) {
        case Reference::Equation: return QT_TRANSLATE_NOOP("core", "eq. %1 of the O-X glide document");
        case Reference::Figure: return QT_TRANSLATE_NOOP("core", "fig. %1 of the O-X glide document");
        case Reference::Whole: return QT_TRANSLATE_NOOP("core", "the O-X glide document");
        }
        break;
    case Document::FourBarDocument:
        switch (reference) {
        case Reference::Equation: return QT_TRANSLATE_NOOP("core", "eq. %1 of the four-bar and mobility document");
        case Reference::Figure: return QT_TRANSLATE_NOOP("core", "fig. %1 of the four-bar and mobility document");
        case Reference::Whole: return QT_TRANSLATE_NOOP("core", "the four-bar and mobility document");
        }
        break;
    }
    return "%1";
}
} // namespace

std::string cite(Document document, std::string_view numbers)
{
    if (numbers.empty())
        return text::translate("core", documentPattern(document, Reference::Whole));
    return text::format(text::translate("core", documentPattern(document, Reference::Equation)), {numbers});
}

std::string citeFigure(Document document, std::string_view figure)
{
    return text::format(text::translate("core", documentPattern(document, Reference::Figure)), {figure});
}

std::string ownModel()
{
    return text::translate("core", "PKM Studio's model");
}

std::string roundingNote()
{
    return text::translate("core", "The numbers put in are rounded as shown; every result is worked out from the "
                                   "unrounded values, so the last digits of a result can differ from one worked out by "
                                   "hand from the shown numbers.");
}

} // namespace equations

} // namespace pkm
