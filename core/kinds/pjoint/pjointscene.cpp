// The П-joint's planar drawing: the parallelogram OBAC with its telescopic diagonal, the
// angles and dimensions shown on it, and the handles that set θ by dragging (docs/mathematics.md,
// section 1).

#include "pjoint.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pkm {

namespace {
/// Signed angle from direction u to direction v, in (−π, π].
double signedAngle(const Eigen::Vector2d &u, const Eigen::Vector2d &v)
{
    return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}
} // namespace

Scene PJoint::scene(const Pose &pose) const
{
    const PJointDesign &p = m_design;
    const double theta = pose.outputs[0];
    const Eigen::Vector2d crank = p.a * Eigen::Vector2d(std::sin(theta), std::cos(theta));
    const Eigen::Vector2d o(0, 0), b(p.b, 0), a = b + crank, c = o + crank;
    auto v3 = [](const Eigen::Vector2d &v) { return Eigen::Vector3d(v.x(), v.y(), 0.0); };

    Scene s;
    enum { O, B, A, C };
    s.joints = {{v3(o), "O", JointKind::Ground},
                {v3(b), "B", JointKind::Ground},
                {v3(a), "A", JointKind::Revolute},
                {v3(c), "C", JointKind::Revolute}};
    // B–A and O–B carry dimension lines with their lengths; a name on them would collide.
    s.bars = {{O, B, BarKind::Ground, ""},
              {B, A, BarKind::Crank, ""},
              {O, C, BarKind::Crank, "a"},
              {C, A, BarKind::Coupler, "b"}};
    s.actuators = {{O, A, p.motorLength, p.motorWidth, p.screwDiameter, "d"}};

    const double arc = 0.22 * p.a;
    const double phi = pjoint::passiveAngle(p, theta);
    const Eigen::Vector2d toO = (o - a).normalized(), toB = (b - a).normalized();
    const double muStart = std::atan2(toB.y(), toB.x());
    const double mu = signedAngle(toB, toO);
    // pose values with a fixed decimal, so that their labels keep their width while θ moves
    auto deg = [](double r) { return text::fixed(units::angle.toDisplay(r), 1); };
    s.angles = {{B, 0.5 * std::numbers::pi, -theta, arc, joinText({"θ = ", deg(theta), "°"})},
                {O, 0.0, phi, 1.15 * arc, joinText({"φ = ", deg(phi), "°"})},
                {A, muStart, mu, 0.8 * arc, joinText({"μ = ", deg(std::abs(mu)), "°"})}};

    const double d = pose.inputs[0];
    // O lies to the left of B→A for every |θ| < 90°: a negative offset keeps the a-dimension
    // outside the parallelogram.
    const double sideB = -1.0;
    // "b = 68 mm": the unit is the locale's ("мм")
    auto length = [](const char *symbol, const std::string &value) {
        return joinText({symbol, " = ", text::format(text::translate("core", "%1 mm"), {value})});
    };
    s.dimensions = {{O, B, -0.18 * p.a, length("b", text::number(p.b, 1))},
                    {B, A, sideB * 0.16 * p.a, length("a", text::number(p.a, 1))},
                    {O, A, 0.0, length("d", text::fixed(d, 1))}};
    s.handles = {{A, text::translate("core", "drag A to set θ")}, {C, text::translate("core", "drag C to set θ")}};

    // Extent over the whole θ range so that fitting the view does not follow the motion.
    Eigen::AlignedBox3d box;
    box.extend(v3(o)).extend(v3(b));
    for (int i = 0; i <= 32; ++i) {
        const double t = p.thetaMin + (p.thetaMax - p.thetaMin) * i / 32.0;
        const Eigen::Vector2d r = p.a * Eigen::Vector2d(std::sin(t), std::cos(t));
        box.extend(v3(b + r)).extend(v3(o + r));
    }
    const Eigen::Vector3d margin(0.12 * p.a, 0.12 * p.a, 0.0);
    box.extend(box.min() - margin).extend(box.max() + margin);
    s.extent = box;
    return s;
}

Result<Pose> PJoint::dragHandle(const Pose &, int handle, const Eigen::Vector2d &target) const
{
    // A = B + a(sin θ, cos θ) and C = O + a(sin θ, cos θ): θ is the direction of the target
    // seen from the handle's ground pivot, measured from the vertical.
    const Eigen::Vector2d pivot = handle == 0 ? Eigen::Vector2d(m_design.b, 0) : Eigen::Vector2d(0, 0);
    const Eigen::Vector2d r = target - pivot;
    if (r.norm() < 1e-9 * m_design.a)
        return Failure{FailureKind::Unreachable, "theta",
                       text::translate("core", "The pointer is on the pivot: θ is undefined there.")};
    // Past a limit the joint stops at it; the caller sees the pose at the limit.
    const double theta = std::clamp(std::atan2(r.x(), r.y()), m_design.thetaMin, m_design.thetaMax);
    return solveInverse(Coordinates::Constant(1, theta));
}

} // namespace pkm
