// The five-bar's analysis (docs/mathematics.md, section 5): the report of a pose with its
// Jacobians and margins, the neighbouring working and assembly modes, and the kinematic chain
// for the mobility analysis.

#include "fivebar.h"
#include "fivebarinternal.h"

#include "mobility.h"
#include "text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pkm {

namespace {
using fivebar::legText;
using fivebar::LegText;
using fivebar::marginsOf;
using fivebar::pi;
using fivebar::Vectors;
using fivebar::vectorsOf;

constexpr Unit millimetre4 = units::power(4, 0);
constexpr Unit radianPerMillimetre2 = units::power(-2, 2);

enum Slot {
    SlotTheta1, SlotTheta4, SlotX, SlotY,
    SlotJq, SlotJx = SlotJq + 4, SlotJ = SlotJx + 4, SlotDetJ = SlotJ + 4, SlotDetJq, SlotDetJx, SlotCond,
    SlotElbowAngle1, SlotElbowAngle2, SlotLinksAngle, SlotTransmission, SlotMarginInverse, SlotMarginDirect, SlotMargin,
    SlotCount
};
} // namespace

const ReportLayout &FiveBar::reportLayout() const
{
    static const ReportLayout layout = [] {
        using G = ReportGroup;
        ReportLayout l;
        l.add(G::Pose, "theta1", "θ₁", QT_TRANSLATE_NOOP("core", "crank AB angle at A, from +x counter-clockwise"), units::angle, 2);
        l.add(G::Pose, "theta4", "θ₄", QT_TRANSLATE_NOOP("core", "crank ED angle at E, from +x counter-clockwise"), units::angle, 2);
        l.add(G::Pose, "x", "x", QT_TRANSLATE_NOOP("core", "output point C, x"), units::millimetre, 2);
        l.add(G::Pose, "y", "y", QT_TRANSLATE_NOOP("core", "output point C, y"), units::millimetre, 2);
        l.add(G::Jacobian, "Jq", "J_q", "J_q = diag((B − A)×(C − B), (D − E)×(C − D))", units::squareMillimetre, 1, 2, 2);
        l.add(G::Jacobian, "Jx", "J_x", QT_TRANSLATE_NOOP("core", "J_x rows (C − B)ᵀ, (C − D)ᵀ"), units::millimetre, 2, 2, 2);
        l.add(G::Jacobian, "J", "J", "θ̇ = J·Ċ, J = J_q⁻¹·J_x", units::radianPerMillimetre, 5, 2, 2);
        l.add(G::Jacobian, "det_J", "det J", QT_TRANSLATE_NOOP("core", "determinant of J (0: direct, ∞: inverse singularity)"), radianPerMillimetre2, 8);
        l.add(G::Jacobian, "det_Jq", "det J_q", QT_TRANSLATE_NOOP("core", "0 at an inverse singularity (a leg stretched or folded)"), millimetre4, 0);
        l.add(G::Jacobian, "det_Jx", "det J_x", QT_TRANSLATE_NOOP("core", "0 at a direct singularity (the distal links in line)"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "cond", "κ(J)", QT_TRANSLATE_NOOP("core", "condition number of J"), units::none, 3);
        l.add(G::Derived, "elbow_angle1", "φ₁", QT_TRANSLATE_NOOP("core", "angle ABC between crank AB and link BC (0°, 180°: inverse singularity)"), units::angle, 2);
        l.add(G::Derived, "elbow_angle2", "φ₂", QT_TRANSLATE_NOOP("core", "angle EDC between crank ED and link DC (0°, 180°: inverse singularity)"), units::angle, 2);
        l.add(G::Derived, "links_angle", "ψ", QT_TRANSLATE_NOOP("core", "angle BCD between the distal links (0°, 180°: direct singularity)"), units::angle, 2);
        l.add(G::Derived, "transmission", "μ", QT_TRANSLATE_NOOP("core", "transmission angle between the distal links, min(ψ, 180° − ψ)"), units::angle, 2);
        l.add(G::Derived, "margin_inverse", "m_inv", QT_TRANSLATE_NOOP("core", "distance from the inverse singularities, min |sin φ_i| (0 … 1)"), units::none, 4);
        l.add(G::Derived, "margin_direct", "m_dir", QT_TRANSLATE_NOOP("core", "distance from the direct singularities, |sin ψ| (0 … 1)"), units::none, 4);
        l.add(G::Derived, "margin", "m", QT_TRANSLATE_NOOP("core", "distance from the nearest singularity (0 … 1)"), units::none, 4);
        // exact values at singular poses (mechanism.h: AtSingularity)
        l.atSingularityOfJ("det_Jq");
        return l;
    }();
    return layout;
}

Singularity FiveBar::singularity(const Pose &pose) const
{
    const auto [inverse, direct] = marginsOf(m_design, vectorsOf(m_design, pose));
    return classifySingularity(inverse, direct, singularTolerance);
}

Jacobians FiveBar::jacobians(const Pose &pose) const
{
    const Vectors v = vectorsOf(m_design, pose);
    Eigen::Matrix2d jq = Eigen::Matrix2d::Zero(), jx, full;
    for (int leg = 0; leg < 2; ++leg) {
        jq(leg, leg) = v.k[leg];
        jx.row(leg) = v.link[leg].transpose();
        full.row(leg) = v.link[leg].transpose() / v.k[leg];
    }
    return {jq, jx, full};
}

Singularity FiveBar::evaluate(const Pose &pose, std::span<double> values) const
{
    const FiveBarDesign &d = m_design;
    const Vectors v = vectorsOf(d, pose);
    values[SlotTheta1] = pose.inputs[0];
    values[SlotTheta4] = pose.inputs[1];
    values[SlotX] = pose.outputs[0];
    values[SlotY] = pose.outputs[1];
    double frobenius = 0.0;
    for (int leg = 0; leg < 2; ++leg) {
        values[SlotJq + 3 * leg] = v.k[leg];
        values[SlotJq + 1 + leg] = 0.0; // the off-diagonal zeros: slots 1 and 2 of the row-major 2×2
        for (int c = 0; c < 2; ++c) {
            values[SlotJx + 2 * leg + c] = v.link[leg][c];
            values[SlotJ + 2 * leg + c] = v.link[leg][c] / v.k[leg];
        }
        frobenius += v.link[leg].squaredNorm() / (v.k[leg] * v.k[leg]);
        // the elbow angle between P→G and P→C: |sin| = |k|/(a·b)
        values[SlotElbowAngle1 + leg] = std::atan2(std::abs(v.k[leg]), -v.crank[leg].dot(v.link[leg]));
    }
    const double detJq = v.k[0] * v.k[1];
    values[SlotDetJq] = detJq;
    values[SlotDetJx] = v.detJx;
    values[SlotDetJ] = v.detJx / detJq;
    values[SlotCond] = fivebar::conditionNumber(frobenius, std::abs(v.detJx / detJq));
    const double psi = std::atan2(std::abs(v.detJx), v.link[0].dot(v.link[1]));
    values[SlotLinksAngle] = psi;
    values[SlotTransmission] = std::min(psi, pi - psi);
    const auto [inverseMargin, directMargin] = marginsOf(d, v);
    values[SlotMarginInverse] = inverseMargin;
    values[SlotMarginDirect] = directMargin;
    const Singularity s = classifySingularity(inverseMargin, directMargin, singularTolerance);
    values[SlotMargin] = s.margin;
    settleSingularValues(reportLayout(), values, s.type);
    return s;
}

std::vector<ModeAlternative> FiveBar::modeNeighbours() const
{
    const FiveBarDesign &d = m_design;
    std::vector<ModeAlternative> neighbours;
    auto add = [&](const std::string &label, const ParameterSet &changes, bool sameInputs) {
        if (auto other = withParameters(changes))
            neighbours.push_back({label, changes, *other, sameInputs, {}});
    };
    // C mirrored across BD turns both distal links about that line: where that carries a leg
    // past its stretched or folded pose, its working mode flips along with the assembly.
    const std::string mirrored = -d.assembly == fivebar::right
        ? QT_TRANSLATE_NOOP("core", "other assembly mode (C right of B→D, same crank angles)")
        : QT_TRANSLATE_NOOP("core", "other assembly mode (C left of B→D, same crank angles)");
    for (int flips = 0; flips < 4; ++flips) {
        ParameterSet changes = {{"assembly", -double(d.assembly)}};
        for (int leg = 0; leg < 2; ++leg) {
            if (flips & (1 << leg))
                changes[legText[std::size_t(leg)].working] = -double(d.working[leg]);
        }
        add(mirrored, changes, true);
    }
    // Moving elbow i to its mirror image across G_i→C may carry it across the line through
    // the other elbow and C: then the assembly mode flips with it.
    for (int leg = 0; leg < 2; ++leg) {
        const LegText &t = legText[std::size_t(leg)];
        // fixed labels (the GUI keeps and translates them): leg × the side the elbow goes to
        static constexpr std::array<std::array<const char *, 2>, 2> labels = {{
            {QT_TRANSLATE_NOOP("core", "leg 1: other working mode (B left of A→C, same C)"),
             QT_TRANSLATE_NOOP("core", "leg 1: other working mode (B right of A→C, same C)")},
            {QT_TRANSLATE_NOOP("core", "leg 2: other working mode (D left of E→C, same C)"),
             QT_TRANSLATE_NOOP("core", "leg 2: other working mode (D right of E→C, same C)")},
        }};
        const std::string label = labels[std::size_t(leg)][-d.working[leg] == fivebar::right ? 1 : 0];
        const ParameterSet changes = {{t.working, -double(d.working[leg])}};
        add(label, changes, false);
        ParameterSet both = changes;
        both["assembly"] = -double(d.assembly);
        add(label, both, false);
    }
    return neighbours;
}

KinematicChain FiveBar::kinematicChain(const Pose &pose) const
{
    auto at = [](const Eigen::Vector2d &p) { return Eigen::Vector3d(p.x(), p.y(), 0.0); };
    const Eigen::Vector2d A = fivebar::groundJoint(m_design, 0), E = fivebar::groundJoint(m_design, 1);
    const Eigen::Vector2d B = fivebar::elbow(m_design, 0, pose.inputs[0]);
    const Eigen::Vector2d D = fivebar::elbow(m_design, 1, pose.inputs[1]);
    const Eigen::Vector2d C = pose.outputs.head<2>();
    KinematicChain chain;
    chain.links = {text::translate("core", "ground"), text::translate("core", "crank AB"),
                   text::translate("core", "link BC"), text::translate("core", "link CD"),
                   text::translate("core", "crank DE")};
    const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
    chain.pairs = {{"A", PairType::Revolute, 0, 1, at(A), z, 0.0, true},
                   {"B", PairType::Revolute, 1, 2, at(B), z, 0.0, false},
                   {"C", PairType::Revolute, 2, 3, at(C), z, 0.0, false},
                   {"D", PairType::Revolute, 3, 4, at(D), z, 0.0, false},
                   {"E", PairType::Revolute, 4, 0, at(E), z, 0.0, true}};
    chain.planar = true;
    chain.description = text::translate("core", "planar five-bar: ground AE, cranks AB and DE (driven at A and E), "
                                                "distal links BC and CD");
    return chain;
}

} // namespace pkm
