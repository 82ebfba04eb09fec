// Following a 3-DOF platform's pose as its inputs move (Mechanism::solveWith(): Play, a
// slider, a sweep): small steps of the inputs, Newton's method from the previous pose at each,
// and the sign of det J_x kept, so that the platform stays in its assembly mode or the move
// fails where that mode ends, rather than the pose snapping to another mode.
#include "planarparallel.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
} // namespace

namespace planar {

Followed follow(const std::array<PlanarLeg, 3> &legs, const std::function<std::array<LegCircle, 3>(double)> &circlesAt,
                int steps, Eigen::Vector3d &X)
{
    // Taking the solution nearest to a Newton start on the final inputs alone snapped the
    // 3-R̲RR's platform to another assembly mode once its own had ended between two steps of
    // Play (φ turned 116° in one frame), and near the fold where two modes meet a large step
    // could land on the other one. Small steps, each checked, follow the branch or say why not.
    const double sign = circleJacobian(legs, circlesAt(0.0), X).determinant();
    for (int k = 1; k <= steps; ++k) {
        const std::array<LegCircle, 3> circles = circlesAt(double(k) / steps);
        if (!polish(legs, circles, X))
            return Followed::Lost;
        if (circleJacobian(legs, circles, X).determinant() * sign < 0.0)
            return Followed::Crossed;
    }
    return Followed::Along;
}

} // namespace planar

Result<Pose> PlanarParallel::followDirect(const Coordinates &inputs, const Pose &current) const
{
    if (m_design.legCount() != 3 || current.outputs.size() != 3 || !inputs.allFinite())
        return solveDirect(inputs, &current);
    const double L = std::max(1.0, m_bounds.sizes().norm());
    Eigen::Vector3d X = platformPose(current.outputs);
    const std::optional<planar::Followed> followed = followedFrom(current, inputs, L, X);
    if (!followed) // not a pose of this design: its outputs are a hint
        return solveDirect(inputs, &current);
    if (followed != planar::Followed::Along) {
        // an input out of its range or a leg out of reach says so in its own words
        if (Result<Pose> nearest = solveDirect(inputs, &current); !nearest)
            return nearest;
        return Failure{FailureKind::Unreachable, "q1",
                       text::translate("core", "At these inputs the platform would have left its assembly mode: it "
                                               "ends on the way, where it meets another at a direct singularity. "
                                               "Switch the assembly mode to go on.")};
    }
    Pose along = current; // the solution nearest the pose followed, on the same turn of φ
    along.outputs = Coordinates(3);
    along.outputs << X.x(), X.y(), current.outputs[2] + std::remainder(X.z() - current.outputs[2], 2 * pi);
    return solveDirect(inputs, &along); // checks the inputs' ranges and the legs' reach too
}

std::optional<planar::Followed> PlanarParallel::followedFrom(const Pose &near, const Coordinates &inputs, double size,
                                                             Eigen::Vector3d &X) const
{
    // Only from a pose of this design at its own inputs: after a design change the old pose
    // is just a start for Newton's method.
    const Coordinates &from = near.inputs;
    if (from.size() != inputs.size() || planar::residual(m_design.legs, circles(from), 3, X) > 1e-7 * size)
        return std::nullopt;
    // steps of at most 2° of a crank or 1 % of the workspace's size of a stroke
    int steps = 1;
    for (int i = 0; i < inputs.size(); ++i) {
        const double most = m_variables[std::size_t(i)].unit.scale != 1.0 ? 2.0 * pi / 180.0 : 0.01 * size;
        steps = std::max(steps, int(std::ceil(std::abs(inputs[i] - from[i]) / most)));
    }
    const auto circlesAt = [&](double t) {
        std::array<planar::LegCircle, 3> c;
        for (std::size_t i = 0; i < 3; ++i)
            c[i] = planar::circle(m_design.legs[i], from[Eigen::Index(i)] + t * (inputs[Eigen::Index(i)] - from[Eigen::Index(i)]));
        return c;
    };
    return planar::follow(m_design.legs, circlesAt, std::min(steps, 512), X);
}

} // namespace pkm
