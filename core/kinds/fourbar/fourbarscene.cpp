// The four-bar's planar drawing: the ground, crank, coupler and rocker with the coupler point,
// the angles shown on them, and the handles that turn the crank or the rocker by dragging
// (docs/mathematics.md, section 4).

#include "fourbar.h"
#include "fourbarinternal.h"

#include "text.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pkm {

namespace {
using fourbar::crankJoint;
using fourbar::nearestTurn;
using fourbar::pi;
using fourbar::rockerJoint;
using fourbar::scaleOf;
} // namespace

// -- drawing -------------------------------------------------------------------------------

Scene FourBar::scene(const Pose &pose) const
{
    const FourBarDesign &d = m_design;
    const double alpha = pose.inputs[0], delta = pose.outputs[0];
    auto to3 = [](const Eigen::Vector2d &p) { return Eigen::Vector3d(p.x(), p.y(), 0.0); };
    const Eigen::Vector2d A(0.0, 0.0), D(d.ground, 0.0);
    const Eigen::Vector2d B = crankJoint(d, alpha), C = rockerJoint(d, delta);
    const Eigen::Vector2d M = B + d.couplerPoint * (C - B);
    const Eigen::Vector2d P = fourbar::instantCentre(d, alpha, delta);
    const fourbar::Angles a = fourbar::angles(d, alpha, delta);
    Scene s;
    s.joints.push_back({to3(A), "A", JointKind::Ground});
    s.joints.push_back({to3(D), "D", JointKind::Ground});
    s.joints.push_back({to3(B), "B", JointKind::Revolute});
    s.joints.push_back({to3(C), "C", JointKind::Revolute});
    s.joints.push_back({to3(M), "M", JointKind::Point});
    const bool parallel = !std::isfinite(P.x());
    if (!parallel)
        s.joints.push_back({to3(P), "P", JointKind::Point});
    s.bars.push_back({0, 1, BarKind::Ground, "AD"});
    s.bars.push_back({0, 2, BarKind::Crank, "AB"});
    s.bars.push_back({2, 3, BarKind::Coupler,
                      parallel ? text::translate("core", "BC (P at infinity: AB ∥ DC, the coupler translates)")
                               : std::string("BC")});
    s.bars.push_back({1, 3, BarKind::Link, "CD"});
    const double shortest = std::min({d.crank, d.coupler, d.rocker, d.ground});
    s.angles.push_back({0, 0.0, alpha, 0.3 * std::min(d.crank, d.ground), joinText({"α = ", text::fixed(alpha / units::degree, 1), "°"})});
    s.angles.push_back({1, pi, -delta, 0.3 * std::min(d.rocker, d.ground), joinText({"δ = ", text::fixed(delta / units::degree, 1), "°"})});
    const Eigen::Vector2d cb = B - C;
    s.angles.push_back({3, std::atan2(cb.y(), cb.x()), a.gamma, 0.3 * shortest,
                        joinText({"γ = ", text::fixed(a.gamma / units::degree, 1), "°"})});
    s.handles.push_back({2, text::translate("core", "drag to turn the crank (sets α, direct kinematics)")});
    s.handles.push_back({3, text::translate("core", "drag to swing the rocker (sets δ, inverse kinematics)")});
    ScenePolyline curve;
    curve.closed = m_fullTurn;
    curve.label = d.branch == fourbar::crossed ? text::translate("core", "coupler curve of M (crossed branch)")
                                               : text::translate("core", "coupler curve of M (open branch)");
    curve.points.reserve(m_curve.size());
    for (const Eigen::Vector2d &p : m_curve)
        curve.points.push_back(to3(p));
    s.polylines.push_back(std::move(curve));
    // constant over the motion: where the joints go in either branch (the constructor's samples)
    Eigen::AlignedBox3d extent;
    extent.extend(to3(m_motionBox.min()));
    extent.extend(to3(m_motionBox.max()));
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(0.08 * scaleOf(d));
    s.extent = Eigen::AlignedBox3d(extent.min() - pad, extent.max() + pad);
    s.extent.min().z() = s.extent.max().z() = 0.0;
    return s;
}

Result<Pose> FourBar::dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const
{
    auto representative = [](double angle, double reference, const Interval &range) {
        // the turn of `angle` inside the range nearest the reference, else the nearest at all
        double best = nearestTurn(angle, reference);
        for (int k = -2; k <= 2; ++k) {
            const double candidate = nearestTurn(angle, reference) + 2.0 * pi * k;
            if (range.contains(candidate) && (!range.contains(best) || std::abs(candidate - reference) < std::abs(best - reference)))
                best = candidate;
        }
        return best;
    };
    if (handle == 0) {
        if (target.norm() < 1e-12 * scaleOf(m_design))
            return current;
        Coordinates inputs(1);
        inputs << representative(std::atan2(target.y(), target.x()), current.inputs[0], m_alphaRange);
        return solveDirect(inputs, &current);
    }
    if (handle == 1) {
        const Eigen::Vector2d fromD = target - Eigen::Vector2d(m_design.ground, 0.0);
        if (fromD.norm() < 1e-12 * scaleOf(m_design))
            return current;
        Coordinates outputs(1);
        outputs << representative(pi - std::atan2(fromD.y(), fromD.x()), current.outputs[0], m_deltaRange);
        return solveInverse(outputs, &current);
    }
    return Failure{FailureKind::UnknownName, {}, text::translate("core", "No handle with that index.")};
}

} // namespace pkm
