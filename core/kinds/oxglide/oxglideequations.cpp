// The O-X glide's governing equations with the numbers of a pose (equations.h): the planar
// kinematics of the O-X glide document, which prints them without numbers
// (docs/mathematics.md, section 3).

#include "oxglideequations.h"

#include "oxglide.h"

#include <algorithm>
#include <cmath>

namespace pkm::oxglide {

std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose)
{
    const auto *glide = dynamic_cast<const OxGlide *>(&mechanism);
    if (!glide)
        return {};
    using namespace pkm::equations;
    const OxGlideDesign &g = glide->design();
    const Report report(mechanism, pose);
    const EquationNumber x = report.number("x"), y = report.number("y");
    const EquationNumber xAB = report.number("x_AB"), xCD = report.number("x_CD");
    const EquationNumber l = parameter(mechanism, "l"), s = parameter(mechanism, "s");
    const double w = std::sqrt(std::max(0.0, g.rod * g.rod - y.value * y.value));
    const bool O = g.form == formO;
    const std::string form = text::label(formTitle(g.form));
    const std::string source = cite(Document::OxGlideDocument, "");

    std::vector<Equation> list;
    list.push_back({.title = text::translate("core", "Run of a rod along the guides"),
                    .symbolic = "w = √(l² − y²)",
                    .substituted = "√(%1² − %2²)",
                    .numbers = {l, y},
                    .result = length(w),
                    .formula = std::sqrt(g.rod * g.rod - y.value * y.value),
                    .source = source});
    list.push_back({.title = text::format(text::translate("core", "Inverse kinematics, %1 form"), {form}),
                    .symbolic = O ? "x_AB = x − s/2 − w" : "x_AB = x − s/2 + w",
                    .substituted = O ? "%1 − %2/2 − %3" : "%1 − %2/2 + %3",
                    .numbers = {x, s, length(w)},
                    .result = xAB,
                    .resultName = "x_AB",
                    .formula = x.value - 0.5 * g.width - g.form * w,
                    .source = source});
    list.push_back({.title = text::format(text::translate("core", "Inverse kinematics, %1 form"), {form}),
                    .symbolic = O ? "x_CD = x + s/2 + w" : "x_CD = x + s/2 − w",
                    .substituted = O ? "%1 + %2/2 + %3" : "%1 + %2/2 − %3",
                    .numbers = {x, s, length(w)},
                    .result = xCD,
                    .resultName = "x_CD",
                    .formula = x.value + 0.5 * g.width + g.form * w,
                    .source = source});
    list.push_back({.title = text::translate("core", "Direct kinematics, both forms"),
                    .symbolic = "x = (x_AB + x_CD)/2",
                    .substituted = "(%1 + %2)/2",
                    .numbers = {xAB, xCD},
                    .result = x,
                    .resultName = "x",
                    .formula = 0.5 * (xAB.value + xCD.value),
                    .source = source});
    const double gap = xCD.value - xAB.value - g.width;
    list.push_back({.title = text::translate("core", "Direct kinematics, both forms"),
                    .symbolic = "y = ½·√(4l² − (x_CD − x_AB − s)²)",
                    .substituted = "½·√(4·%1² − (%2 − %3 − %4)²)",
                    .numbers = {l, xCD, xAB, s},
                    .result = y,
                    .resultName = "y",
                    .formula = 0.5 * std::sqrt(4.0 * g.rod * g.rod - gap * gap),
                    .source = source,
                    .note = text::translate("core", "The document prints “+ s” in the X form's direct kinematics, which "
                                                    "contradicts its own inverse kinematics; with “− s” both forms return "
                                                    "their poses exactly. The sign of x_CD − x_AB − s is the form.")});
    // J_q = diag(−2u₁, −2u₂) and J_x rows 2·(u_i, y) with u₁ = x − s/2 − x_AB = ±w and
    // u₂ = x + s/2 − x_CD = ∓w (upper signs the O form): w = 0 makes both vanish
    list.push_back({.title = text::translate("core", "Input Jacobian (0: inverse singularity)"),
                    .symbolic = "det J_q = 4·u₁·u₂ = −4w²",
                    .substituted = "−4·%1²",
                    .numbers = {length(w)},
                    .result = report.number("det_Jq"),
                    .resultName = "det_Jq",
                    .formula = -4.0 * w * w,
                    .source = ownModel()});
    list.push_back({.title = text::translate("core", "Output Jacobian (0: direct singularity)"),
                    .symbolic = O ? "det J_x = 4y·(u₁ − u₂) = 8y·w" : "det J_x = 4y·(u₁ − u₂) = −8y·w",
                    .substituted = O ? "8·%1·%2" : "−8·%1·%2",
                    .numbers = {y, length(w)},
                    .result = report.number("det_Jx"),
                    .resultName = "det_Jx",
                    .formula = 8.0 * g.form * y.value * w,
                    .source = ownModel(),
                    .note = text::translate("core", "u₁ = x − s/2 − x_AB and u₂ = x + s/2 − x_CD are the rods' runs along "
                                                    "the guides, w and −w in the O form, −w and w in the X form.")});
    list.push_back({.title = text::translate("core", "Determinant of J"),
                    .symbolic = O ? "det J = −2y/w" : "det J = 2y/w",
                    .substituted = O ? "−2·%1/%2" : "2·%1/%2",
                    .numbers = {y, length(w)},
                    .result = report.number("det_J"),
                    .resultName = "det_J",
                    .formula = -2.0 * g.form * y.value / w,
                    .source = ownModel(),
                    .note = text::translate("core", "J = −J_q⁻¹·J_x = [1, y/u₁; 1, y/u₂] from the constraints "
                                                    "(x ∓ s/2 − x_i)² + y² − l² = 0; w = 0 (rods perpendicular to the guides "
                                                    "or parallel to each other) is singular.")});
    list.push_back({.title = text::translate("core", "Condition number of J"),
                    .symbolic = "κ(J) = max(y/w, w/y)",
                    .substituted = "max(%1/%2, %2/%1)",
                    .numbers = {y, length(w)},
                    .result = report.number("cond"),
                    .resultName = "cond",
                    .formula = std::max(y.value / w, w / y.value),
                    .source = ownModel()});
    return list;
}

} // namespace pkm::oxglide
