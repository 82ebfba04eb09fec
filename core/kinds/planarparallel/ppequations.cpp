// The planar parallel mechanism's governing equations with the numbers of a pose
// (equations.h): per leg its circle constraint for the leg type in use and its J_q entry,
// for a П̲RR leg the П-joint's (3–5) and (7), then the determinants (docs/mathematics.md,
// section 5a).

#include "ppequations.h"

#include "planarparallel.h"

#include <cmath>

namespace pkm::planar {

namespace {
const char *legTypeName(LegType type)
{
    switch (type) {
    case LegType::RRR: return "R̲RR";
    case LegType::PRR: return "P̲RR";
    case LegType::RPR: return "RP̲R";
    case LegType::PiRR: return "П̲RR";
    }
    return "";
}

/// "%1" → the leg's subscript in a symbolic form.
std::string legSymbol(const char *pattern, int leg)
{
    static const char *subscripts[3] = {"₁", "₂", "₃"};
    return text::format(pattern, {subscripts[leg]});
}
/// det J_x from J_x's entries in the report of the pose: the direct singularity's test, which
/// det J = det J_x / det J_q divides by.
Equation outputJacobian(int n, bool pjointLegs, const equations::Report &report)
{
    Eigen::Matrix3d jx = Eigen::Matrix3d::Zero();
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            jx(i, j) = report.value("Jx", i * n + j);
    using equations::plain;
    Equation equation{.title = text::translate("core", "Output Jacobian (0: direct singularity)"),
                      .result = report.number("det_Jx"),
                      .resultName = "det_Jx",
                      .source = equations::ownModel()};
    const std::string factor = pjointLegs ? "J_i·" : "";
    if (n == 2) {
        equation.symbolic = "det J_x = (J_x)₁₁·(J_x)₂₂ − (J_x)₁₂·(J_x)₂₁, (J_x)_i = −" + factor + "(P_i − C_i)ᵀ";
        equation.substituted = "%1·%2 − %3·%4";
        equation.numbers = {plain(jx(0, 0), 2), plain(jx(1, 1), 2), plain(jx(0, 1), 2), plain(jx(1, 0), 2)};
        equation.formula = jx(0, 0) * jx(1, 1) - jx(0, 1) * jx(1, 0);
    } else {
        equation.symbolic = "det J_x = det[(J_x)₁; (J_x)₂; (J_x)₃], (J_x)_i = −" + factor + "((P_i − C_i)ᵀ, (P_i − O)×(P_i − C_i))";
        equation.substituted = "det[(%1, %2, %3); (%4, %5, %6); (%7, %8, %9)]";
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                equation.numbers.push_back(plain(jx(i, j), 2));
        equation.formula = jx.determinant();
    }
    if (pjointLegs) {
        equation.note = text::translate("core", "J_i is the П-joint's Jacobian ∂d/∂θ of a П̲RR leg and 1 for the other "
                                                "leg types; C_i is A_i for an RP̲R leg.");
    } else {
        equation.note = text::translate("core", "C_i is the centre of leg i's circle: the elbow, the slider joint, or A_i "
                                                "for an RP̲R leg.");
    }
    return equation;
}
} // namespace

std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose)
{
    const auto *pp = dynamic_cast<const PlanarParallel *>(&mechanism);
    if (!pp)
        return {};
    using namespace pkm::equations;
    const PlanarParallelDesign &design = pp->design();
    const Report report(mechanism, pose);
    const int n = design.legCount();
    const Eigen::Vector3d X = pp->platformPose(pose.outputs);
    const std::string own = ownModel();

    std::vector<Equation> list;
    bool pjointLegs = false;
    for (int i = 0; i < n; ++i) {
        const PlanarLeg &leg = design.legs[std::size_t(i)];
        const LegCircle c = circle(leg, pose.inputs[i]);
        const Eigen::Vector2d P = platformPoint(leg, X), e = P - c.centre;
        const std::string legText = text::number(i + 1);
        const EquationNumber q = report.number(std::string("q") + legText);
        const std::string title =
            text::format(text::translate("core", "Leg %1 (%2): constraint"), {legText, legTypeName(leg.type)});
        Equation constraint{.title = title,
                            .substituted = "√((%1 − %2)² + (%3 − %4)²)",
                            .numbers = {length(P.x()), length(c.centre.x()), length(P.y()), length(c.centre.y())},
                            .result = length(c.radius),
                            .formula = e.norm(),
                            .source = own};
        switch (leg.type) {
        case LegType::RRR:
            constraint.symbolic = legSymbol("|P%1 − C%1| = l%1, C%1 = A%1 + r%1·(cos q%1, sin q%1)", i);
            break;
        case LegType::PRR:
            constraint.symbolic = legSymbol("|P%1 − C%1| = l%1, C%1 = A%1 + q%1·(cos α%1, sin α%1)", i);
            constraint.source = cite(Document::MomaDocument, "(5–6)");
            break;
        case LegType::RPR:
            constraint.symbolic = legSymbol("|P%1 − A%1| = q%1", i);
            constraint.result = q;
            constraint.resultName = std::string("q") + legText;
            break;
        case LegType::PiRR:
            constraint.symbolic = legSymbol("|P%1 − C%1| = l%1, C%1 = A%1 + a%1·(cos ψ%1, sin ψ%1), ψ%1 = α%1 + 90° − θ%1", i);
            break;
        }
        list.push_back(constraint);
        if (leg.type == LegType::PiRR) {
            const double a = leg.lever, k = leg.ratio, d = pose.inputs[i];
            list.push_back({.title = text::format(text::translate("core", "Leg %1 (%2): the П-joint's angle"),
                                                  {legText, legTypeName(leg.type)}),
                            .symbolic = legSymbol("θ%1 = arcsin((d%1² − a%1²(1 + k%1²))/(2a%1²k%1))", i),
                            .substituted = "arcsin((%1² − %2²·(1 + %3²))/(2·%2²·%3))",
                            .numbers = {q, length(a), plain(k)},
                            .result = angle(c.theta),
                            .formula = std::asin((d * d - a * a * (1.0 + k * k)) / (2.0 * a * a * k)),
                            .source = cite(Document::PJointDocument, "(3–5)")});
            list.push_back({.title = text::format(text::translate("core", "Leg %1 (%2): the П-joint's Jacobian"),
                                                  {legText, legTypeName(leg.type)}),
                            .symbolic = legSymbol("J%1 = a%1²k%1·cos θ%1 / d%1", i),
                            .substituted = "%1²·%2·cos %3 / %4",
                            .numbers = {length(a), plain(k), angle(c.theta), q},
                            .result = {c.pjointRate, units::millimetrePerRadian, 3},
                            .formula = a * a * k * std::cos(c.theta) / d,
                            .source = cite(Document::PJointDocument, "(7)"),
                            .note = text::translate("core", "The leg's row of J_x carries this J as a factor, so the "
                                                            "П-joint's own singularity (θ = ±90°) is a direct singularity "
                                                            "of the whole mechanism (the П-joint document, section 4).")});
        }
        // g = ½(|P − C(q)|² − ρ(q)²): ∂g/∂q = −e·∂C/∂q − ρ·∂ρ/∂q, as PlanarParallel::jacobianParts;
        // only a strut's radius moves with its input, only the others' centres
        Equation input{.title = text::format(text::translate("core", "Leg %1 (%2): input Jacobian (0: inverse singularity)"),
                                             {legText, legTypeName(leg.type)}),
                       .result = report.number("Jq", i * n + i),
                       .formula = -e.dot(c.centreRate) - c.radius * c.radiusRate,
                       .source = own};
        // g_i is in mm²: a row by a crank's or a П-joint's angle is in mm²/rad, by a slider's or
        // a strut's length in mm (the determinants' units, planaranalysis.cpp)
        const bool byAngle = leg.type == LegType::RRR || leg.type == LegType::PiRR;
        input.result.unit = byAngle ? units::squareMillimetrePerRadian : units::millimetre;
        const bool guide = leg.type == LegType::PRR; // ∂C/∂q is the guide's unit vector
        const auto rate = [&](double v) { return guide ? plain(v, 3) : length(v); };
        switch (leg.type) {
        case LegType::RRR:
            input.symbolic = legSymbol("(J_q)%1%1 = −(P%1 − C%1)·∂C%1/∂q%1, ∂C%1/∂q%1 = r%1·(−sin q%1, cos q%1)", i);
            break;
        case LegType::PRR:
            input.symbolic = legSymbol("(J_q)%1%1 = −(P%1 − C%1)·(cos α%1, sin α%1)", i);
            break;
        case LegType::PiRR:
            input.symbolic = legSymbol("(J_q)%1%1 = ∂g%1/∂θ%1 = −(P%1 − C%1)·∂C%1/∂θ%1, ∂C%1/∂θ%1 = a%1·(sin ψ%1, −cos ψ%1)", i);
            break;
        case LegType::RPR:
            input.symbolic = legSymbol("(J_q)%1%1 = −ρ%1·∂ρ%1/∂q%1 = −q%1", i);
            input.substituted = "−%1";
            input.numbers = {q};
            break;
        }
        if (leg.type != LegType::RPR) {
            input.substituted = "−(%1·%2 + %3·%4)";
            input.numbers = {length(e.x()), rate(c.centreRate.x()), length(e.y()), rate(c.centreRate.y())};
        }
        list.push_back(input);
        pjointLegs = pjointLegs || leg.type == LegType::PiRR;
    }
    // J_q is diagonal: its determinant is the product of the legs' entries
    Equation inputs{.title = text::translate("core", "Input Jacobian (0: inverse singularity)"),
                    .symbolic = n == 3 ? "det J_q = (J_q)₁₁·(J_q)₂₂·(J_q)₃₃" : "det J_q = (J_q)₁₁·(J_q)₂₂",
                    .substituted = n == 3 ? "%1·%2·%3" : "%1·%2",
                    .result = report.number("det_Jq"),
                    .resultName = "det_Jq",
                    .formula = 1.0,
                    .source = own};
    for (int i = 0; i < n; ++i) {
        inputs.numbers.push_back(report.number("Jq", i * n + i));
        inputs.formula *= report.value("Jq", i * n + i);
    }
    list.push_back(inputs);
    list.push_back(outputJacobian(n, pjointLegs, report));
    list.push_back({.title = text::translate("core", "Determinant of J"),
                    .symbolic = "det J = det J_x / det J_q",
                    .substituted = "%1 / %2",
                    .numbers = {report.number("det_Jx"), report.number("det_Jq")},
                    .result = report.number("det_J"),
                    .resultName = "det_J",
                    .formula = report.value("det_Jx") / report.value("det_Jq"),
                    .source = own});
    return list;
}

} // namespace pkm::planar
