// The five-bar's planar drawing: the ground, the two cranks and the distal links meeting at C,
// the crank angles shown on it, and the handles that move C or turn a crank by dragging
// (docs/mathematics.md, section 5).

#include "fivebar.h"
#include "fivebarinternal.h"

#include "text.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pkm {

namespace {
using fivebar::pi;
using fivebar::representative;
using fivebar::scaleOf;
} // namespace

// -- drawing -------------------------------------------------------------------------------

Scene FiveBar::scene(const Pose &pose) const
{
    const FiveBarDesign &d = m_design;
    auto to3 = [](const Eigen::Vector2d &p) { return Eigen::Vector3d(p.x(), p.y(), 0.0); };
    const std::array<Eigen::Vector2d, 2> G = {fivebar::groundJoint(d, 0), fivebar::groundJoint(d, 1)};
    const Eigen::Vector2d B = fivebar::elbow(d, 0, pose.inputs[0]), D = fivebar::elbow(d, 1, pose.inputs[1]);
    const Eigen::Vector2d C = pose.outputs.head<2>();
    Scene s;
    s.joints.push_back({to3(G[0]), "A", JointKind::Ground});
    s.joints.push_back({to3(G[1]), "E", JointKind::Ground});
    s.joints.push_back({to3(B), "B", JointKind::Revolute});
    s.joints.push_back({to3(D), "D", JointKind::Revolute});
    s.joints.push_back({to3(C), "C", JointKind::Revolute});
    s.bars.push_back({0, 1, BarKind::Ground, "AE"});
    s.bars.push_back({0, 2, BarKind::Crank, "AB"});
    s.bars.push_back({1, 3, BarKind::Crank, "DE"});
    s.bars.push_back({2, 4, BarKind::Link, "BC"});
    s.bars.push_back({3, 4, BarKind::Link, "CD"});
    for (int leg = 0; leg < 2; ++leg) {
        const double theta = pose.inputs[leg];
        s.angles.push_back({leg, 0.0, theta, 0.3 * std::min(d.crank[leg], d.ground),
                            joinText({leg == 0 ? "θ₁ = " : "θ₄ = ", text::fixed(theta / units::degree, 1), "°"})});
    }
    s.handles.push_back({4, text::translate("core", "drag to move C (inverse kinematics)")});
    s.handles.push_back({2, text::translate("core", "drag to turn crank AB (sets θ₁, direct kinematics)")});
    s.handles.push_back({3, text::translate("core", "drag to turn crank DE (sets θ₄, direct kinematics)")});
    // constant over the motion: the cranks' circles and the workspace
    Eigen::AlignedBox3d extent;
    for (int leg = 0; leg < 2; ++leg) {
        extent.extend(to3(G[leg] - Eigen::Vector2d::Constant(d.crank[leg])));
        extent.extend(to3(G[leg] + Eigen::Vector2d::Constant(d.crank[leg])));
    }
    extent.extend(to3(m_bounds.min()));
    extent.extend(to3(m_bounds.max()));
    extent.extend(to3(C));
    const Eigen::Vector3d pad(0.08 * scaleOf(d), 0.08 * scaleOf(d), 0.0);
    s.extent = Eigen::AlignedBox3d(extent.min() - pad, extent.max() + pad);
    s.poseExtent = poseBox(s); // the cranks' circles make the range of motion far larger than a pose
    return s;
}

Result<Pose> FiveBar::dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const
{
    if (handle == 0)
        return solveInverse(target, &current);
    if (handle == 1 || handle == 2) {
        const int leg = handle - 1;
        const Eigen::Vector2d fromGround = target - fivebar::groundJoint(m_design, leg);
        if (fromGround.norm() < 1e-12 * scaleOf(m_design))
            return current;
        // the turn of the target's direction inside the range nearest the current angle, or
        // else the end of the range nearest to it
        const Interval &range = m_design.range[leg];
        const double raw = std::atan2(fromGround.y(), fromGround.x());
        double theta = representative(raw, range, current.inputs[leg], 0.0);
        if (std::isnan(theta)) {
            auto gap = [&](double end) { return std::abs(std::remainder(raw - end, 2.0 * pi)); };
            theta = gap(range.min) <= gap(range.max) ? range.min : range.max;
        }
        Coordinates inputs = current.inputs;
        inputs[leg] = theta;
        return solveDirect(inputs, &current);
    }
    return Failure{FailureKind::UnknownName, {}, text::translate("core", "No handle with that index.")};
}

} // namespace pkm
