// MOMA's governing equations with the numbers of a pose (equations.h), numbered as in the
// MOMA document (docs/mathematics.md, section 2).

#include "momaequations.h"

#include "moma.h"

#include <cmath>

namespace pkm::moma {

std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose)
{
    const auto *moma = dynamic_cast<const Moma *>(&mechanism);
    if (!moma)
        return {};
    using namespace pkm::equations;
    const MomaDesign &m = moma->design();
    const Report report(mechanism, pose);
    const EquationNumber x = report.number("x"), y = report.number("y");
    const Eigen::Vector2d P(x.value, y.value);
    const char *sub[2] = {"₁", "₂"};
    const char *name[2] = {"1", "2"};
    auto symbol = [&](const char *pattern, int leg) { return text::format(pattern, {sub[leg], name[leg]}); };

    std::vector<Equation> list;
    std::array<Eigen::Vector2d, 2> L;
    std::array<double, 2> jp{};
    for (int leg = 0; leg < 2; ++leg) {
        const Eigen::Vector2d R = m.reference[std::size_t(leg)];
        const double alpha = m.alpha[std::size_t(leg)], l = m.length[std::size_t(leg)];
        const double B = projection(m, leg, P);
        const double C = (P - R).squaredNorm() - l * l;
        const EquationNumber p = report.number(leg == 0 ? "p1" : "p2");
        const std::string legText = text::number(leg + 1);
        list.push_back({.title = text::format(text::translate("core", "Projection on guide %1"), {legText}),
                        .symbolic = symbol("B%1 = cos α%1·(x − x_R%2) + sin α%1·(y − y_R%2)", leg),
                        .substituted = "cos %1·(%2 − %3) + sin %1·(%4 − %5)",
                        .numbers = {angle(alpha), x, length(R.x()), y, length(R.y())},
                        .result = length(B),
                        .formula = std::cos(alpha) * (P.x() - R.x()) + std::sin(alpha) * (P.y() - R.y()),
                        .source = cite(Document::MomaDocument, "(8)")});
        list.push_back({.title = text::format(text::translate("core", "Reach of link %1"), {legText}),
                        .symbolic = symbol("C%1 = (x − x_R%2)² + (y − y_R%2)² − l%1²", leg),
                        .substituted = "(%1 − %2)² + (%3 − %4)² − %5²",
                        .numbers = {x, length(R.x()), y, length(R.y()), length(l)},
                        .result = {C, units::squareMillimetre, 1},
                        .formula = (P.x() - R.x()) * (P.x() - R.x()) + (P.y() - R.y()) * (P.y() - R.y()) - l * l,
                        .source = cite(Document::MomaDocument, "(9)")});
        const double beta = m.branch[std::size_t(leg)];
        list.push_back({.title = text::format(text::translate("core", "Inverse kinematics of leg %1"), {legText}),
                        .symbolic = symbol("p%1 = B%1 + β%1·√(B%1² − C%1)", leg),
                        .substituted = "%1 + %2·√(%1² − %3)",
                        .numbers = {length(B), plain(beta, 0), {C, units::squareMillimetre, 1}},
                        .result = p,
                        .resultName = leg == 0 ? "p1" : "p2",
                        .formula = B + beta * std::sqrt(B * B - C),
                        .source = cite(Document::MomaDocument, "(7)"),
                        .note = leg == 0 ? text::translate("core", "The program takes B_i² − C_i as l_i² − (a_i × (P − R_i))², "
                                                                   "the same number without cancelling two large ones.")
                                         : std::string()});
        L[std::size_t(leg)] = P - sliderJoint(m, leg, p.value);
        jp[std::size_t(leg)] = 2.0 * p.value - 2.0 * B;
    }
    const Eigen::Vector2d Z1 = sliderJoint(m, 0, pose.inputs[0]), Z2 = sliderJoint(m, 1, pose.inputs[1]);
    const double e = (Z2 - Z1).norm(), l1 = m.length[0], l2 = m.length[1];
    list.push_back({.title = text::translate("core", "Direct kinematics: P along Z₁→Z₂"),
                    .symbolic = "s = (l₁² − l₂² + e²)/(2e), e = |Z₂ − Z₁|",
                    .substituted = "(%1² − %2² + %3²)/(2·%3)",
                    .numbers = {length(l1), length(l2), length(e)},
                    // the program's P measured along Z₁→Z₂
                    .result = length((P - Z1).dot(Z2 - Z1) / e),
                    .formula = (l1 * l1 - l2 * l2 + e * e) / (2.0 * e),
                    .source = cite(Document::MomaDocument, "(10–12)"),
                    .note = text::translate("core", "The document's (10–12) divide by x_Z2 − x_Z1 and fail with the slider "
                                                    "joints one above the other; the program intersects the circles "
                                                    "measured along Z₁→Z₂: P = Z₁ + s·u + σ·h·n, h = √(l₁² − s²).")});
    list.push_back({.title = text::translate("core", "Input Jacobian (0: inverse singularity)"),
                    .symbolic = "det J_p = (2p₁ − 2B₁)·(2p₂ − 2B₂)",
                    .substituted = "%1·%2",
                    .numbers = {length(jp[0]), length(jp[1])},
                    .result = report.number("det_Jp"),
                    .resultName = "det_Jp",
                    .formula = jp[0] * jp[1],
                    .source = cite(Document::MomaDocument, "(18)")});
    list.push_back({.title = text::translate("core", "Output Jacobian (0: direct singularity)"),
                    .symbolic = "det J_x = 4·(P − Z₁)×(P − Z₂)",
                    .substituted = "4·(%1·%2 − %3·%4)",
                    .numbers = {length(L[0].x()), length(L[1].y()), length(L[0].y()), length(L[1].x())},
                    .result = report.number("det_Jx"),
                    .resultName = "det_Jx",
                    .formula = 4.0 * (L[0].x() * L[1].y() - L[0].y() * L[1].x()),
                    .source = cite(Document::MomaDocument, "(20)")});
    const EquationNumber detJx = report.number("det_Jx"), detJp = report.number("det_Jp");
    list.push_back({.title = text::translate("core", "Determinant of J"),
                    .symbolic = "det J = det J_x / det J_p",
                    .substituted = "%1 / %2",
                    .numbers = {detJx, detJp},
                    .result = report.number("det_J"),
                    .resultName = "det_J",
                    .formula = detJx.value / detJp.value,
                    .source = cite(Document::MomaDocument, "(21)"),
                    .note = text::translate("core", "From J_p·ṗ + J_x·Ṗ = 0 the program's J is −J_p⁻¹·J_x; the document's "
                                                    "(21) has no minus sign. For the 2×2 J the determinant is the same.")});
    return list;
}

} // namespace pkm::moma
