// MOMA's analysis (docs/mathematics.md, section 2): the report of a pose with its Jacobians,
// the singularity margins, the neighbouring working and assembly modes and the kinematic chain
// for the mobility analysis.

#include "moma.h"
#include "momainternal.h"

#include "mobility.h"
#include "text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pkm {

namespace {
using moma::cross;
using moma::legName;
} // namespace

// -- analysis ------------------------------------------------------------------------------

namespace {
enum Slot {
    SlotP1, SlotP2, SlotX, SlotY,
    SlotJp, SlotJx = SlotJp + 4, SlotJ = SlotJx + 4, SlotDetJ = SlotJ + 4, SlotDetJp, SlotDetJx, SlotCond,
    SlotLinkAngle1, SlotLinkAngle2, SlotLinksAngle, SlotMargin,
    SlotCount
};
} // namespace

const ReportLayout &Moma::reportLayout() const
{
    static const ReportLayout layout = [] {
        using G = ReportGroup;
        ReportLayout l;
        l.add(G::Pose, "p1", "p₁", QT_TRANSLATE_NOOP("core", "slider 1 position"), units::millimetre, 2);
        l.add(G::Pose, "p2", "p₂", QT_TRANSLATE_NOOP("core", "slider 2 position"), units::millimetre, 2);
        l.add(G::Pose, "x", "x", QT_TRANSLATE_NOOP("core", "platform x"), units::millimetre, 2);
        l.add(G::Pose, "y", "y", QT_TRANSLATE_NOOP("core", "platform y"), units::millimetre, 2);
        l.add(G::Jacobian, "Jp", "J_p", "J_p = diag(2p_i − 2B_i) (18)", units::millimetre, 1, 2, 2);
        l.add(G::Jacobian, "Jx", "J_x", QT_TRANSLATE_NOOP("core", "J_x rows 2(P − Z_i) (20)"), units::millimetre, 1, 2, 2);
        l.add(G::Jacobian, "J", "J", QT_TRANSLATE_NOOP("core", "ṗ = J·Ṗ, J = −J_p⁻¹·J_x ((21) up to its sign)"), units::none, 3, 2, 2);
        l.add(G::Jacobian, "det_J", "det J", QT_TRANSLATE_NOOP("core", "determinant of J (0: direct, ∞: inverse singularity)"), units::none, 4);
        l.add(G::Jacobian, "det_Jp", "det J_p", QT_TRANSLATE_NOOP("core", "0 at an inverse singularity"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "det_Jx", "det J_x", QT_TRANSLATE_NOOP("core", "0 at a direct singularity"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "cond", "κ(J)", QT_TRANSLATE_NOOP("core", "condition number of J"), units::none, 3);
        l.add(G::Derived, "link_angle1", "ψ₁", QT_TRANSLATE_NOOP("core", "angle between link S₁ and guide 1 (90°: inverse singularity)"), units::angle, 2);
        l.add(G::Derived, "link_angle2", "ψ₂", QT_TRANSLATE_NOOP("core", "angle between link S₂ and guide 2 (90°: inverse singularity)"), units::angle, 2);
        l.add(G::Derived, "links_angle", "ψ₁₂", QT_TRANSLATE_NOOP("core", "angle between the links (0°, 180°: direct singularity)"), units::angle, 2);
        l.add(G::Derived, "margin", "m", QT_TRANSLATE_NOOP("core", "distance from the nearest singularity (0 … 1)"), units::none, 4);
        // exact values at singular poses (mechanism.h: AtSingularity)
        l.atSingularityOfJ("det_Jp");
        return l;
    }();
    return layout;
}

Singularity Moma::singularity(const Pose &pose) const
{
    const Eigen::Vector2d platform = pose.outputs.head<2>();
    const Eigen::Vector2d z1 = moma::sliderJoint(m_design, 0, pose.inputs[0]);
    const Eigen::Vector2d z2 = moma::sliderJoint(m_design, 1, pose.inputs[1]);
    const double inverseMargin = std::min(moma::inverseMargin(m_design, 0, pose.inputs[0], platform),
                                          moma::inverseMargin(m_design, 1, pose.inputs[1], platform));
    const double directMargin = moma::directMargin(m_design, z1, z2, platform);
    return classifySingularity(inverseMargin, directMargin, singularTolerance);
}

Jacobians Moma::jacobians(const Pose &pose) const
{
    const Eigen::Vector2d platform = pose.outputs.head<2>();
    Eigen::Matrix2d jp = Eigen::Matrix2d::Zero(), jx;
    for (int leg = 0; leg < 2; ++leg) {
        const double p = pose.inputs[leg];
        jp(leg, leg) = 2.0 * p - 2.0 * moma::projection(m_design, leg, platform); // (18)
        jx.row(leg) = 2.0 * (platform - moma::sliderJoint(m_design, leg, p)).transpose(); // (20)
    }
    Jacobians j;
    j.inputs = jp;
    j.outputs = -jx; // J_q·q̇ = J_x·ẋ in the interface's convention
    j.full = Eigen::Matrix2d(jp.diagonal().cwiseInverse().asDiagonal() * (-jx));
    return j;
}

Singularity Moma::evaluate(const Pose &pose, std::span<double> v) const
{
    const Eigen::Vector2d platform = pose.outputs.head<2>();
    v[SlotP1] = pose.inputs[0];
    v[SlotP2] = pose.inputs[1];
    v[SlotX] = platform.x();
    v[SlotY] = platform.y();
    std::array<Eigen::Vector2d, 2> link;
    double detJp = 1.0;
    for (int leg = 0; leg < 2; ++leg) {
        const double p = pose.inputs[leg];
        const double jp = 2.0 * p - 2.0 * moma::projection(m_design, leg, platform);
        link[leg] = platform - moma::sliderJoint(m_design, leg, p);
        v[SlotJp + 3 * leg] = jp;
        v[SlotJp + 1 + leg] = 0.0; // off-diagonal zeros: slots 1 and 2 of the row-major 2×2
        v[SlotJx + 2 * leg] = 2.0 * link[leg].x();
        v[SlotJx + 2 * leg + 1] = 2.0 * link[leg].y();
        v[SlotJ + 2 * leg] = -2.0 * link[leg].x() / jp;
        v[SlotJ + 2 * leg + 1] = -2.0 * link[leg].y() / jp;
        detJp *= jp;
        const double cosine = std::abs(link[leg].dot(moma::direction(m_design.alpha[leg]))) / link[leg].norm();
        v[SlotLinkAngle1 + leg] = std::acos(std::min(1.0, cosine));
    }
    const double detJx = 4.0 * cross(link[0], link[1]);
    v[SlotDetJp] = detJp;
    v[SlotDetJx] = detJx;
    v[SlotDetJ] = detJx / detJp;
    const Eigen::Matrix2d J = Eigen::Map<const Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(&v[SlotJ]);
    const double frobenius = J.squaredNorm(), det = std::abs(J.determinant());
    const double spread = std::sqrt(std::max(0.0, frobenius * frobenius - 4.0 * det * det));
    v[SlotCond] = det > 0 ? (frobenius + spread) / (2.0 * det) : std::numeric_limits<double>::infinity();
    v[SlotLinksAngle] = std::atan2(std::abs(cross(link[0], link[1])), link[0].dot(link[1]));
    const Singularity s = singularity(pose);
    v[SlotMargin] = s.margin;
    settleSingularValues(reportLayout(), v, s.type);
    return s;
}

std::vector<ModeAlternative> Moma::modeNeighbours() const
{
    std::vector<ModeAlternative> neighbours;
    auto add = [&](const std::string &label, const ParameterSet &changes, bool sameInputs) {
        if (auto other = withParameters(changes))
            neighbours.push_back({label, changes, *other, sameInputs, {}});
    };
    const double assembly = -double(m_design.assembly);
    // The platform mirrored across Z₁Z₂ turns both links about the line: where that carries a
    // link past perpendicular to its guide, the working modes flip along with the assembly.
    const std::string mirrored = QT_TRANSLATE_NOOP("core", "other assembly mode (same slider positions)");
    add(mirrored, {{"assembly", assembly}}, true);
    add(mirrored, {{"assembly", assembly}, {"branch1", -double(m_design.branch[0])}}, true);
    add(mirrored, {{"assembly", assembly}, {"branch2", -double(m_design.branch[1])}}, true);
    add(mirrored, {{"assembly", assembly}, {"branch1", -double(m_design.branch[0])}, {"branch2", -double(m_design.branch[1])}},
        true);
    for (int leg = 0; leg < 2; ++leg) {
        const std::string name = "branch" + legName(leg);
        const std::string label = leg == 0
            ? QT_TRANSLATE_NOOP("core", "leg 1: other working mode (same platform position)")
            : QT_TRANSLATE_NOOP("core", "leg 2: other working mode (same platform position)");
        const double branch = -double(m_design.branch[leg]);
        // Moving slider i to the other root may carry Z_i across the platform's side of Z₁Z₂:
        // then the assembly mode flips with it.
        add(label, {{name, branch}}, false);
        add(label, {{name, branch}, {"assembly", assembly}}, false);
    }
    return neighbours;
}

KinematicChain Moma::kinematicChain(const Pose &pose) const
{
    const std::array<Eigen::Vector2d, 2> z
        = {moma::sliderJoint(m_design, 0, pose.inputs[0]), moma::sliderJoint(m_design, 1, pose.inputs[1])};
    KinematicChain chain;
    chain.links = {text::translate("core", "ground"), text::translate("core", "slider K₁"),
                   text::translate("core", "slider K₂"), text::translate("core", "link S₁"),
                   text::translate("core", "link S₂")};
    for (int leg = 0; leg < 2; ++leg) {
        chain.pairs.push_back(mobility::planarPrismatic(
            leg == 0 ? text::translate("core", "guide PO₁") : text::translate("core", "guide PO₂"), 0, 1 + leg,
            z[std::size_t(leg)], moma::direction(m_design.alpha[std::size_t(leg)]), true));
        chain.pairs.push_back(
            mobility::planarRevolute(joinText({"Z", leg == 0 ? "₁" : "₂"}), 1 + leg, 3 + leg, z[std::size_t(leg)]));
    }
    chain.pairs.push_back(mobility::planarRevolute("P", 3, 4, pose.outputs.head<2>()));
    chain.description
        = text::translate("core", "MOMA: two sliders on powered guides, two links meeting at the platform joint P");
    return chain;
}

} // namespace pkm
