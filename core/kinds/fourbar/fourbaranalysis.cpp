// The four-bar's analysis (docs/mathematics.md, section 4): the report of a pose with its
// Jacobians, velocities and accelerations, the other branch, and the kinematic chain for the
// mobility analysis.

#include "fourbar.h"
#include "fourbarinternal.h"

#include "mobility.h"
#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pkm {

namespace {
using fourbar::crankJoint;
using fourbar::perp;
using fourbar::pi;
using fourbar::rockerJoint;

constexpr Unit radianPerSecond2{QT_TRANSLATE_NOOP("core", "rad/s²"), 1.0};
} // namespace

// -- analysis ------------------------------------------------------------------------------

namespace {
enum Slot {
    SlotAlpha, SlotDelta, SlotGamma, SlotDelta1, SlotBeta,
    SlotJq, SlotJx, SlotJ, SlotDetJ,
    SlotI31, SlotOmega1, SlotOmega2, SlotOmega3, SlotEpsilon2, SlotEpsilon3, SlotTransmission, SlotMargin,
    SlotBD, SlotMx, SlotMy, SlotPx, SlotPy,
    SlotCount
};

/// J_q = ∂F/∂α and J_x = −∂F/∂δ of F = |C − B|² − BC².
std::pair<double, double> jacobianParts(const FourBarDesign &d, double alpha, double delta)
{
    const Eigen::Vector2d D(d.ground, 0.0);
    const Eigen::Vector2d B = crankJoint(d, alpha), C = rockerJoint(d, delta);
    const Eigen::Vector2d dB = perp(B);         // dB/dα
    const Eigen::Vector2d dC = -perp(C - D);    // dC/dδ
    const double jq = -2.0 * (C - B).dot(dB);   // = 2·AB·BC·sin β
    const double jx = -2.0 * (C - B).dot(dC);   // = −2·BC·CD·sin γ
    return {jq, jx};
}
} // namespace

const ReportLayout &FourBar::reportLayout() const
{
    static const ReportLayout layout = [] {
        using G = ReportGroup;
        ReportLayout l;
        l.add(G::Pose, "alpha", "α", QT_TRANSLATE_NOOP("core", "crank angle at A, from AD counter-clockwise"), units::angle, 2);
        l.add(G::Pose, "delta", "δ", QT_TRANSLATE_NOOP("core", "rocker angle at D, from DA clockwise"), units::angle, 2);
        l.add(G::Pose, "gamma", "γ", QT_TRANSLATE_NOOP("core", "transmission angle at C, from CB to CD counter-clockwise (< 0: crossed)"), units::angle, 2);
        l.add(G::Pose, "delta1", "δ₁", QT_TRANSLATE_NOOP("core", "angle at D from DA to DB (4)"), units::angle, 2);
        l.add(G::Pose, "beta", "β", QT_TRANSLATE_NOOP("core", "angle at B from BA to BC, 360° − (α + γ + δ)"), units::angle, 2);
        l.add(G::Jacobian, "Jq", "J_q", QT_TRANSLATE_NOOP("core", "J_q = ∂F/∂α = 2·AB·BC·sin β (0: inverse singularity)"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "Jx", "J_x", QT_TRANSLATE_NOOP("core", "J_x = −∂F/∂δ = −2·BC·CD·sin γ (0: direct singularity)"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "J", "J", QT_TRANSLATE_NOOP("core", "α̇ = J·δ̇, J = J_q⁻¹·J_x = dα/dδ"), units::none, 4);
        l.add(G::Jacobian, "det_J", "det J", QT_TRANSLATE_NOOP("core", "determinant of J (0: direct, ∞: inverse singularity)"), units::none, 4);
        l.add(G::Derived, "i31", "i₃₁", QT_TRANSLATE_NOOP("core", "transfer function dδ/dα = ω₃/ω₁ = −(9)"), units::none, 4);
        l.add(G::Derived, "omega1", "ω₁", QT_TRANSLATE_NOOP("core", "crank angular velocity (constant)"), units::radianPerSecond, 3);
        l.add(G::Derived, "omega2", "ω₂", QT_TRANSLATE_NOOP("core", "coupler angular velocity, counter-clockwise"), units::radianPerSecond, 3);
        l.add(G::Derived, "omega3", "ω₃", QT_TRANSLATE_NOOP("core", "dδ/dt, exact (the document's (8) with the opposite sign)"), units::radianPerSecond, 3);
        l.add(G::Derived, "epsilon2", "ε₂", QT_TRANSLATE_NOOP("core", "coupler angular acceleration, counter-clockwise"), radianPerSecond2, 3);
        l.add(G::Derived, "epsilon3", "ε₃", QT_TRANSLATE_NOOP("core", "d²δ/dt² at constant ω₁, exact (not the document's (14))"), radianPerSecond2, 3);
        l.add(G::Derived, "transmission", "μ", QT_TRANSLATE_NOOP("core", "acute transmission angle min(|γ|, 180° − |γ|) (below 40°: poor)"), units::angle, 2);
        l.add(G::Derived, "margin", "m", QT_TRANSLATE_NOOP("core", "distance from the nearest singularity, min(|sin β|, |sin γ|)"), units::none, 4);
        l.add(G::Derived, "BD", "BD", QT_TRANSLATE_NOOP("core", "diagonal |BD|"), units::millimetre, 2);
        l.add(G::Derived, "M_x", "x_M", QT_TRANSLATE_NOOP("core", "coupler point M, x"), units::millimetre, 2);
        l.add(G::Derived, "M_y", "y_M", QT_TRANSLATE_NOOP("core", "coupler point M, y"), units::millimetre, 2);
        l.add(G::Derived, "P_x", "x_P", QT_TRANSLATE_NOOP("core", "instantaneous centre P of the coupler, x (none: AB ∥ DC)"), units::millimetre, 2);
        l.add(G::Derived, "P_y", "y_P", QT_TRANSLATE_NOOP("core", "instantaneous centre P of the coupler, y (none: AB ∥ DC)"), units::millimetre, 2);
        // exact values at singular poses (mechanism.h: AtSingularity)
        using S = AtSingularity;
        l.atSingularity("Jq", S::Zero, S::Computed);
        l.atSingularity("Jx", S::Computed, S::Zero);
        l.atSingularity("J", S::Infinite, S::Zero);
        l.atSingularity("det_J", S::Infinite, S::Zero);
        l.atSingularity("i31", S::Zero, S::Infinite);
        l.atSingularity("omega2", S::Computed, S::Infinite);
        l.atSingularity("omega3", S::Computed, S::Infinite);
        l.atSingularity("epsilon2", S::Computed, S::Infinite);
        l.atSingularity("epsilon3", S::Computed, S::Infinite);
        return l;
    }();
    return layout;
}

Singularity FourBar::singularity(const Pose &pose) const
{
    const fourbar::Angles a = fourbar::angles(m_design, pose.inputs[0], pose.outputs[0]);
    return classifySingularity(std::abs(std::sin(a.beta)), std::abs(std::sin(a.gamma)), singularTolerance);
}

Jacobians FourBar::jacobians(const Pose &pose) const
{
    const auto [jq, jx] = jacobianParts(m_design, pose.inputs[0], pose.outputs[0]);
    Jacobians j;
    j.inputs = Eigen::MatrixXd::Constant(1, 1, jq);
    j.outputs = Eigen::MatrixXd::Constant(1, 1, jx);
    j.full = Eigen::MatrixXd::Constant(1, 1, jx / jq);
    return j;
}

Singularity FourBar::evaluate(const Pose &pose, std::span<double> v) const
{
    const FourBarDesign &d = m_design;
    const double alpha = pose.inputs[0], delta = pose.outputs[0];
    const fourbar::Angles a = fourbar::angles(d, alpha, delta);
    v[SlotAlpha] = alpha;
    v[SlotDelta] = delta;
    v[SlotGamma] = a.gamma;
    v[SlotDelta1] = a.delta1;
    v[SlotBeta] = a.beta;
    const auto [jq, jx] = jacobianParts(d, alpha, delta);
    v[SlotJq] = jq;
    v[SlotJx] = jx;
    v[SlotJ] = jx / jq;
    v[SlotDetJ] = jx / jq;
    v[SlotI31] = jq / jx;
    const fourbar::Motion m = fourbar::motion(d, alpha, delta, d.omega1);
    v[SlotOmega1] = d.omega1;
    v[SlotOmega2] = m.omega2;
    v[SlotOmega3] = m.omega3;
    v[SlotEpsilon2] = m.epsilon2;
    v[SlotEpsilon3] = m.epsilon3;
    const double gamma = std::abs(a.gamma);
    v[SlotTransmission] = std::min(gamma, pi - gamma);
    const Eigen::Vector2d B = crankJoint(d, alpha), C = rockerJoint(d, delta);
    v[SlotBD] = (Eigen::Vector2d(d.ground, 0.0) - B).norm();
    const Eigen::Vector2d M = B + d.couplerPoint * (C - B);
    v[SlotMx] = M.x();
    v[SlotMy] = M.y();
    const Eigen::Vector2d P = fourbar::instantCentre(d, alpha, delta);
    v[SlotPx] = P.x();
    v[SlotPy] = P.y();
    const Singularity s = classifySingularity(std::abs(std::sin(a.beta)), std::abs(std::sin(a.gamma)), singularTolerance);
    v[SlotMargin] = s.margin;
    settleSingularValues(reportLayout(), v, s.type);
    return s;
}

std::vector<ReportText> FourBar::reportText(const Pose &) const
{
    return {{ReportGroup::Pose, "branch", fourbar::branchName(m_design.branch),
             QT_TRANSLATE_NOOP("core", "assembly branch: open (C left of B→D) or crossed")},
            {ReportGroup::Derived, "grashof", fourbar::grashofName(grashof(m_design)),
             QT_TRANSLATE_NOOP("core", "Grashof class from s + l against p + q")}};
}

std::vector<ModeAlternative> FourBar::modeNeighbours() const
{
    std::vector<ModeAlternative> neighbours;
    const int other = -m_design.branch;
    const ParameterSet changes = {{"branch", double(other)}};
    if (auto made = withParameters(changes))
        neighbours.push_back({other == fourbar::crossed ? QT_TRANSLATE_NOOP("core", "crossed branch (same crank angle)")
                                                        : QT_TRANSLATE_NOOP("core", "open branch (same crank angle)"),
                              changes, *made, true, {}});
    return neighbours;
}

KinematicChain FourBar::kinematicChain(const Pose &pose) const
{
    KinematicChain chain;
    chain.links = {text::translate("core", "ground AD"), text::translate("core", "crank AB"),
                   text::translate("core", "coupler BC"), text::translate("core", "rocker CD")};
    chain.pairs = {mobility::planarRevolute("A", 0, 1, Eigen::Vector2d(0.0, 0.0), true),
        mobility::planarRevolute("B", 1, 2, crankJoint(m_design, pose.inputs[0])),
        mobility::planarRevolute("C", 2, 3, rockerJoint(m_design, pose.outputs[0])),
        mobility::planarRevolute("D", 3, 0, Eigen::Vector2d(m_design.ground, 0.0))};
    chain.description
        = text::translate("core", "planar four-bar: ground AD, crank AB (driven at A), coupler BC, rocker CD");
    return chain;
}

} // namespace pkm
