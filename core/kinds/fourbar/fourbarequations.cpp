// The four-bar's governing equations with the numbers of a pose (equations.h), numbered as in
// the four-bar and mobility document (docs/mathematics.md, section 4).

#include "fourbarequations.h"

#include "fourbar.h"

#include <cmath>
#include <numbers>

namespace pkm::fourbar {

std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose)
{
    const auto *linkage = dynamic_cast<const FourBar *>(&mechanism);
    if (!linkage)
        return {};
    using namespace pkm::equations;
    const FourBarDesign &d = linkage->design();
    const Report report(mechanism, pose);
    const EquationNumber AB = parameter(mechanism, "AB"), BC = parameter(mechanism, "BC");
    const EquationNumber CD = parameter(mechanism, "CD"), AD = parameter(mechanism, "AD");
    const EquationNumber alpha = report.number("alpha"), delta = report.number("delta");
    const EquationNumber gamma = report.number("gamma"), delta1 = report.number("delta1");
    const EquationNumber beta = report.number("beta"), i31 = report.number("i31");
    const double ab = d.crank, bc = d.coupler, cd = d.rocker, ad = d.ground;
    constexpr double turn = 2.0 * std::numbers::pi;

    std::vector<Equation> list;
    list.push_back({.title = text::translate("core", "Transmission angle γ at C"),
                    .symbolic = "cos γ = (BC² + CD² − AB² − AD²)/(2·BC·CD) + (AB·AD)/(BC·CD)·cos α",
                    .substituted = "(%1² + %2² − %3² − %4²)/(2·%1·%2) + (%3·%4)/(%1·%2)·cos %5",
                    .numbers = {BC, CD, AB, AD, alpha},
                    .result = plain(std::cos(gamma.value)),
                    .formula = (bc * bc + cd * cd - ab * ab - ad * ad) / (2.0 * bc * cd) +
                               ab * ad / (bc * cd) * std::cos(alpha.value),
                    .source = cite(Document::FourBarDocument, "(5)")});
    list.push_back({.title = text::translate("core", "Angle at D from DA to DB"),
                    .symbolic = "δ₁ = atan2(AB·sin α, AD − AB·cos α)",
                    .substituted = "atan2(%1·sin %2, %3 − %1·cos %2)",
                    .numbers = {AB, alpha, AD},
                    .result = delta1,
                    .resultName = "delta1",
                    .formula = std::atan2(ab * std::sin(alpha.value), ad - ab * std::cos(alpha.value)),
                    .source = cite(Document::FourBarDocument, "(4)")});
    list.push_back({.title = text::translate("core", "Rocker angle"),
                    .symbolic = "δ = δ₁ + atan2(BC·sin γ, CD − BC·cos γ)",
                    .substituted = "%1 + atan2(%2·sin %3, %4 − %2·cos %3)",
                    .numbers = {delta1, BC, gamma, CD},
                    .result = delta,
                    .resultName = "delta",
                    .formula = std::fmod(delta1.value + std::atan2(bc * std::sin(gamma.value), cd - bc * std::cos(gamma.value)) + turn, turn),
                    .source = cite(Document::FourBarDocument, "(3, 6)"),
                    .note = text::translate("core", "The document takes the arctan of the ratio, which is 180° off wherever "
                                                    "CD − BC·cos γ < 0; the program uses atan2.")});
    list.push_back({.title = text::translate("core", "Angle at B"),
                    .symbolic = "β = 360° − (α + γ + δ)",
                    .substituted = "360° − (%1 + %2 + %3)",
                    .numbers = {alpha, gamma, delta},
                    .result = beta,
                    .resultName = "beta",
                    .formula = std::fmod(4.0 * turn - (alpha.value + gamma.value + delta.value), turn),
                    .source = cite(Document::FourBarDocument, "(7)")});
    list.push_back({.title = text::translate("core", "Transfer function dδ/dα"),
                    .symbolic = "i₃₁ = −AB·sin β / (CD·sin γ)",
                    .substituted = "−%1·sin %2 / (%3·sin %4)",
                    .numbers = {AB, beta, CD, gamma},
                    .result = i31,
                    .resultName = "i31",
                    .formula = -ab * std::sin(beta.value) / (cd * std::sin(gamma.value)),
                    .source = cite(Document::FourBarDocument, "(9)"),
                    .note = text::translate("core", "The document's (8) and (9) give the rocker's counter-clockwise rate "
                                                    "dθ₃/dt = −dδ/dt; the program's ω₃ and i₃₁ are their negatives.")});
    const EquationNumber omega1 = report.number("omega1");
    list.push_back({.title = text::translate("core", "Rocker angular velocity"),
                    .symbolic = "ω₃ = ω₁·i₃₁",
                    .substituted = "%1·%2",
                    .numbers = {omega1, i31},
                    .result = report.number("omega3"),
                    .resultName = "omega3",
                    .formula = omega1.value * i31.value,
                    .source = cite(Document::FourBarDocument, "(8)")});
    list.push_back({.title = text::translate("core", "Rocker angular acceleration at constant ω₁"),
                    .symbolic = "ε₃ = d²δ/dt²",
                    .result = report.number("epsilon3"),
                    .resultName = "epsilon3",
                    .source = cite(Document::FourBarDocument, "(10–14)"),
                    .note = text::translate("core", "The document's (14) agrees with neither sign of the exact second "
                                                    "derivative; the program differentiates the loop closure twice.")});
    list.push_back({.title = text::translate("core", "Input Jacobian (0: inverse singularity)"),
                    .symbolic = "J_q = ∂F/∂α = 2·AB·BC·sin β",
                    .substituted = "2·%1·%2·sin %3",
                    .numbers = {AB, BC, beta},
                    .result = report.number("Jq"),
                    .resultName = "Jq",
                    .formula = 2.0 * ab * bc * std::sin(beta.value),
                    .source = ownModel()});
    list.push_back({.title = text::translate("core", "Output Jacobian (0: direct singularity)"),
                    .symbolic = "J_x = −∂F/∂δ = −2·BC·CD·sin γ",
                    .substituted = "−2·%1·%2·sin %3",
                    .numbers = {BC, CD, gamma},
                    .result = report.number("Jx"),
                    .resultName = "Jx",
                    .formula = -2.0 * bc * cd * std::sin(gamma.value),
                    .source = ownModel()});
    const EquationNumber jq = report.number("Jq"), jx = report.number("Jx");
    list.push_back({.title = text::translate("core", "Jacobian, its own determinant (one input, one output)"),
                    .symbolic = "det J = J = J_q⁻¹·J_x",
                    .substituted = "%1 / %2",
                    .numbers = {jx, jq},
                    .result = report.number("det_J"),
                    .resultName = "det_J",
                    .formula = jx.value / jq.value,
                    .source = ownModel(),
                    .note = text::translate("core", "J maps the rocker's rate onto the crank's, α̇ = J·δ̇, so J = 1/i₃₁.")});
    return list;
}

} // namespace pkm::fourbar
