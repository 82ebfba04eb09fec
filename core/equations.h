#pragma once
/// The governing equations of a mechanism with the numbers of one pose put in, for the
/// "Equations" panel and `pkm eval --equations`: each kind lists its own (kinds/<kind>/
/// <kind>equations.cpp, registered beside its factory in kinds/registry.cpp).
///
/// An equation is text with holes: the symbolic form as printed in the source document
/// ("d = a·√(1 + k² + 2k·sin θ)"), the right side with %1, %2, … where the numbers go, and the
/// numbers themselves in core units with the unit and the decimals they are shown with. The
/// numbers are left to the caller to format, so that the GUI writes them exactly as the values
/// panel does (locale, ∞ and — at singular poses) and the CLI as its tables do. The result is
/// the program's own value: where the report has the quantity (`resultName`), the evaluated
/// report entry, so that a singular pose shows ∞ or — and never a huge number; `formula` is the
/// right side worked out from the numbers shown, for the tests to hold the printed formula, the
/// numbers and the report to each other.

#include "mechanism.h"

#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pkm {

/// A number in an equation: core units, shown in `unit` with `decimals` decimals.
struct EquationNumber {
    double value = 0.0;
    Unit unit = units::none;
    int decimals = 2;
};

struct Equation {
    std::string title = {};       ///< translated: "Inverse kinematics"
    std::string symbolic = {};    ///< the formula as printed: "d = a·√(1 + k² + 2k·sin θ)"
    /// The right side with %1 … %9 for `numbers` ("%1·√(1 + %2² + 2·%2·sin %3)"); empty when
    /// the quantity has no closed form to fill in (only the result is shown).
    std::string substituted = {};
    std::vector<EquationNumber> numbers = {};
    EquationNumber result = {};  ///< the value, "= 183.12 mm"
    std::string resultName = {};  ///< the report entry the result is, or empty
    /// The right side computed from `numbers` by the printed formula (NaN: nothing to compute).
    double formula = std::numeric_limits<double>::quiet_NaN();
    std::string source = {};      ///< translated: "eq. (2) of the П-joint document"
    std::string note = {};        ///< translated: where and why the program departs from the print
};

/// The equations of `mechanism`'s kind at `pose` (empty for a kind that lists none).
std::vector<Equation> mechanismEquations(const Mechanism &mechanism, const Pose &pose);

/// The substituted right side with every %n replaced by `format(numbers[n − 1])`, the number
/// given to `format` without its unit (the result carries it) unless it is an angle in degrees.
std::string fillEquation(const Equation &equation, const std::function<std::string(const EquationNumber &)> &format);
/// A number as the CLI and the tests write it: `decimals` decimals in the display unit, the unit
/// after a space (degrees glued on), "∞" when unbounded and "—" when undefined.
std::string plainEquationNumber(const EquationNumber &number);
/// "symbolic\n  = substituted = result" with plainEquationNumber, for `pkm eval --equations`.
std::string equationText(const Equation &equation);

namespace equations {

/// The evaluated report of one pose: what the kinds' equations take their numbers from.
class Report
{
public:
    Report(const Mechanism &mechanism, const Pose &pose);
    /// Entry `name`'s element `element` with the entry's unit and decimals; NaN if unknown.
    EquationNumber number(std::string_view name, int element = 0) const;
    double value(std::string_view name, int element = 0) const { return number(name, element).value; }
    const Singularity &singularity() const { return m_singularity; }

private:
    const ReportLayout &m_layout;
    std::vector<double> m_values;
    Singularity m_singularity;
};

/// Design parameter `name` as the design panel shows it (its unit and decimals).
EquationNumber parameter(const Mechanism &mechanism, std::string_view name);
inline EquationNumber length(double mm) { return {mm, units::millimetre, 2}; }
inline EquationNumber angle(double rad) { return {rad, units::angle, 2}; }
inline EquationNumber plain(double value, int decimals = 4) { return {value, units::none, decimals}; }

/// The documents the equations come from (docs/mathematics.md, Sources).
enum class Document { PJointDocument, MomaDocument, OxGlideDocument, FourBarDocument };
/// "eq. (2) of the П-joint document", translated; `numbers` as printed there ("(3–5)"), or
/// empty for a formula the document prints without a number ("the O-X glide document").
std::string cite(Document document, std::string_view numbers);
/// "fig. 10 of the П-joint document", translated.
std::string citeFigure(Document document, std::string_view figure);
/// For the kinds no document gives equations for: "PKM Studio's model", translated.
std::string ownModel();
/// Why a result worked out by hand from the rounded numbers can differ in its last digits
/// (MOMA 3c's C₁: 48138.0 mm² from the shown x, y against the exact 48140.9 mm²), translated.
std::string roundingNote();

} // namespace equations

} // namespace pkm
