// The П-joint's governing equations with the numbers of a pose (equations.h), numbered as in
// the П-joint document (docs/mathematics.md, section 1).

#include "pjointequations.h"

#include "pjoint.h"

#include <cmath>
#include <numbers>

namespace pkm::pjoint {

std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose)
{
    const auto *joint = dynamic_cast<const PJoint *>(&mechanism);
    if (!joint)
        return {};
    using namespace pkm::equations;
    const PJointDesign &p = joint->design();
    const Report report(mechanism, pose);
    const EquationNumber a = parameter(mechanism, "a"), b = parameter(mechanism, "b"), k = parameter(mechanism, "k");
    const EquationNumber theta = report.number("theta"), d = report.number("d");
    const double sinTheta = std::sin(theta.value), cosTheta = std::cos(theta.value);
    const double aa = p.a * p.a;

    std::vector<Equation> list;
    list.push_back({.title = text::translate("core", "Inverse kinematics"),
                    .symbolic = "d = a·√(1 + k² + 2k·sin θ)",
                    .substituted = "%1·√(1 + %2² + 2·%2·sin %3)",
                    .numbers = {a, k, theta},
                    .result = d,
                    .resultName = "d",
                    .formula = p.a * std::sqrt(1.0 + p.k() * p.k() + 2.0 * p.k() * sinTheta),
                    .source = cite(Document::PJointDocument, "(2)")});
    list.push_back({.title = text::translate("core", "Direct kinematics"),
                    .symbolic = "θ = arcsin((d² − a²(1 + k²))/(2a²k)), cos θ ≥ 0",
                    .substituted = "arcsin((%1² − %2²·(1 + %3²))/(2·%2²·%3))",
                    .numbers = {d, a, k},
                    .result = theta,
                    .resultName = "theta",
                    .formula = std::asin((d.value * d.value - aa * (1.0 + p.k() * p.k())) / (2.0 * aa * p.k())),
                    .source = cite(Document::PJointDocument, "(3–5)")});
    list.push_back({.title = text::translate("core", "Jacobian J = ∂d/∂θ"),
                    .symbolic = "J = a²k·cos θ / d",
                    .substituted = "%1²·%2·cos %3 / %4",
                    .numbers = {a, k, theta, d},
                    .result = report.number("J"),
                    .resultName = "J",
                    .formula = aa * p.k() * cosTheta / d.value,
                    .source = cite(Document::PJointDocument, "(7)")});
    list.push_back({.title = text::translate("core", "Input Jacobian (0: inverse singularity)"),
                    .symbolic = "J_d = 2d",
                    .substituted = "2·%1",
                    .numbers = {d},
                    .result = report.number("J_d"),
                    .resultName = "J_d",
                    .formula = 2.0 * d.value,
                    .source = cite(Document::PJointDocument, "(10)")});
    list.push_back({.title = text::translate("core", "Output Jacobian (0: direct singularity)"),
                    .symbolic = "J_θ = 2a²k·cos θ",
                    .substituted = "2·%1²·%2·cos %3",
                    .numbers = {a, k, theta},
                    .result = report.number("J_theta"),
                    .resultName = "J_theta",
                    .formula = 2.0 * aa * p.k() * cosTheta,
                    .source = cite(Document::PJointDocument, "(11)")});
    list.push_back({.title = text::translate("core", "Transmission angle"),
                    .symbolic = "μ = arccos((a² + d² − b²)/(2ad))",
                    .substituted = "arccos((%1² + %2² − %3²)/(2·%1·%2))",
                    .numbers = {a, d, b},
                    .result = report.number("mu"),
                    .resultName = "mu",
                    .formula = std::acos((aa + d.value * d.value - p.b * p.b) / (2.0 * p.a * d.value)),
                    .source = citeFigure(Document::PJointDocument, "10")});
    const EquationNumber J = report.number("J");
    const EquationNumber force = parameter(mechanism, "force_max"), speed = parameter(mechanism, "speed_max");
    list.push_back({.title = text::translate("core", "Output torque at F_max"),
                    .symbolic = "T = J·F_max·10⁻³",
                    .substituted = "%1·%2·10⁻³",
                    .numbers = {J, force},
                    .result = report.number("torque"),
                    .resultName = "torque",
                    .formula = J.value * p.forceMax * 1e-3,
                    .source = cite(Document::PJointDocument, "(13)"),
                    .note = text::translate("core", "J in mm/rad times F in N gives N·mm; 10⁻³ turns it into N·m.")});
    list.push_back({.title = text::translate("core", "Output speed at the diagonal's top speed"),
                    .symbolic = "θ̇ = ḋ_max / J",
                    .substituted = "%1 / %2",
                    .numbers = {speed, J},
                    .result = report.number("speed"),
                    .resultName = "speed",
                    .formula = p.speedMax / J.value,
                    .source = cite(Document::PJointDocument, "(8)")});
    list.push_back({.title = text::translate("core", "Output resolution per motor step"),
                    .symbolic = "Δθ = Δd / J",
                    .substituted = "%1 / %2 · 180°/π", // J in mm/rad, Δθ shown in degrees
                    .numbers = {parameter(mechanism, "step"), J},
                    .result = report.number("resolution"),
                    .resultName = "resolution",
                    .formula = p.step / J.value,
                    .source = citeFigure(Document::PJointDocument, "15")});
    list.push_back({.title = text::translate("core", "Motor torque at F_max"),
                    .symbolic = "T_M = F_max·h/(2π·η)·10⁻³",
                    .substituted = "%1·%2/(2π·%3)·10⁻³",
                    .numbers = {force, parameter(mechanism, "lead"), parameter(mechanism, "efficiency")},
                    .result = report.number("motor_torque"),
                    .resultName = "motor_torque",
                    .formula = p.forceMax * p.lead / (2.0 * std::numbers::pi * p.efficiency) * 1e-3,
                    .source = cite(Document::PJointDocument, "(15)"),
                    .note = text::translate("core", "Table 1 gives no screw efficiency η; the presets assume 0.4.")});
    const double root = 1.0 + p.k() * p.k() + 2.0 * p.k() * sinTheta;
    list.push_back({.title = text::translate("core", "Derivative of J, for the diagonal's acceleration"),
                    .symbolic = "∂J/∂θ = −a·k·(k + sin θ)(1 + k·sin θ) / √(1 + k² + 2k·sin θ)³",
                    .substituted = "−%1·%2·(%2 + sin %3)·(1 + %2·sin %3) / √(1 + %2² + 2·%2·sin %3)³",
                    .numbers = {a, k, theta},
                    .result = report.number("dJ_dtheta"),
                    .resultName = "dJ_dtheta",
                    .formula = -p.a * p.k() * (p.k() + sinTheta) * (1.0 + p.k() * sinTheta) / std::pow(root, 1.5),
                    .source = cite(Document::PJointDocument, "(16–18)"),
                    .note = text::translate("core", "The document's acceleration (19–20) drops θ̈ from the first term and "
                                                    "writes θ̇ where θ̇² belongs; the program uses d̈ = J·θ̈ + (∂J/∂θ)·θ̇², "
                                                    "which agrees with the numerical second derivative.")});
    return list;
}

} // namespace pkm::pjoint
