// The five-bar's governing equations with the numbers of a pose (equations.h). The four-bar
// and mobility document shows the five-bar (fig. 1) without equations, so these are PKM
// Studio's model (docs/mathematics.md, section 5).

#include "fivebarequations.h"

#include "fivebar.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pkm::fivebar {

std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose)
{
    const auto *linkage = dynamic_cast<const FiveBar *>(&mechanism);
    if (!linkage)
        return {};
    using namespace pkm::equations;
    const FiveBarDesign &d = linkage->design();
    const Report report(mechanism, pose);
    const EquationNumber x = report.number("x"), y = report.number("y");
    const Eigen::Vector2d C(x.value, y.value);
    const Eigen::Vector2d B = elbow(d, 0, pose.inputs[0]), D = elbow(d, 1, pose.inputs[1]);
    const EquationNumber xB = length(B.x()), yB = length(B.y()), xD = length(D.x()), yD = length(D.y());
    const std::string source = ownModel();

    std::vector<Equation> list;
    list.push_back({.title = text::translate("core", "Input Jacobian of leg 1 (0: inverse singularity)"),
                    .symbolic = "k₁ = (B − A)×(C − B), B = AB·(cos θ₁, sin θ₁)",
                    .substituted = "%1·(%2 − %3) − %3·(%4 − %1)",
                    .numbers = {xB, y, yB, x},
                    .result = report.number("Jq", 0),
                    .formula = B.x() * (C.y() - B.y()) - B.y() * (C.x() - B.x()),
                    .source = source});
    const double ex = D.x() - d.ground;
    list.push_back({.title = text::translate("core", "Input Jacobian of leg 2 (0: inverse singularity)"),
                    .symbolic = "k₄ = (D − E)×(C − D), D = E + DE·(cos θ₄, sin θ₄)",
                    .substituted = "%1·(%2 − %3) − %3·(%4 − %5)",
                    .numbers = {length(ex), y, yD, x, xD},
                    .result = report.number("Jq", 3),
                    .formula = ex * (C.y() - D.y()) - D.y() * (C.x() - D.x()),
                    .source = source});
    list.push_back({.title = text::translate("core", "Output Jacobian (0: direct singularity)"),
                    .symbolic = "det J_x = (C − B)×(C − D)",
                    .substituted = "(%1 − %2)·(%3 − %4) − (%3 − %5)·(%1 − %6)",
                    .numbers = {x, xB, y, yD, yB, xD},
                    .result = report.number("det_Jx"),
                    .resultName = "det_Jx",
                    .formula = (C.x() - B.x()) * (C.y() - D.y()) - (C.y() - B.y()) * (C.x() - D.x()),
                    .source = source});
    const EquationNumber detJx = report.number("det_Jx"), k1 = report.number("Jq", 0), k4 = report.number("Jq", 3);
    const EquationNumber detJq = report.number("det_Jq");
    list.push_back({.title = text::translate("core", "Input Jacobian (0: inverse singularity)"),
                    .symbolic = "det J_q = k₁·k₄",
                    .substituted = "%1·%2",
                    .numbers = {k1, k4},
                    .result = detJq,
                    .resultName = "det_Jq",
                    .formula = k1.value * k4.value,
                    .source = source});
    list.push_back({.title = text::translate("core", "Determinant of J"),
                    .symbolic = "det J = det J_x / det J_q",
                    .substituted = "%1 / %2",
                    .numbers = {detJx, detJq},
                    .result = report.number("det_J"),
                    .resultName = "det_J",
                    .formula = detJx.value / detJq.value,
                    .source = source,
                    .note = text::translate("core", "J = J_q⁻¹·J_x maps lengths to angles, so det J is in rad²/mm², not "
                                                    "dimensionless as MOMA's and the O-X glide's.")});
    const EquationNumber psi = report.number("links_angle");
    list.push_back({.title = text::translate("core", "Transmission angle between the distal links"),
                    .symbolic = "μ = min(ψ, 180° − ψ)",
                    .substituted = "min(%1, 180° − %1)",
                    .numbers = {psi},
                    .result = report.number("transmission"),
                    .resultName = "transmission",
                    .formula = std::min(psi.value, std::numbers::pi - psi.value),
                    .source = source});
    const EquationNumber phi1 = report.number("elbow_angle1"), phi2 = report.number("elbow_angle2");
    list.push_back({.title = text::translate("core", "Distance from the inverse singularities"),
                    .symbolic = "m_inv = min(|sin φ₁|, |sin φ₂|)",
                    .substituted = "min(|sin %1|, |sin %2|)",
                    .numbers = {phi1, phi2},
                    .result = report.number("margin_inverse"),
                    .resultName = "margin_inverse",
                    .formula = std::min(std::abs(std::sin(phi1.value)), std::abs(std::sin(phi2.value))),
                    .source = source});
    list.push_back({.title = text::translate("core", "Distance from the direct singularities"),
                    .symbolic = "m_dir = |sin ψ|",
                    .substituted = "|sin %1|",
                    .numbers = {psi},
                    .result = report.number("margin_direct"),
                    .resultName = "margin_direct",
                    .formula = std::abs(std::sin(psi.value)),
                    .source = source});
    return list;
}

} // namespace pkm::fivebar
