// MOMA's planar drawing: the guides with their sliders, the two links and the platform joint,
// the slider positions and guide angles shown on it, and the handles that move the platform
// or a slider by dragging (docs/mathematics.md, section 2).

#include "moma.h"
#include "momainternal.h"

#include "text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
using moma::cross;
} // namespace

// -- drawing -------------------------------------------------------------------------------

Scene Moma::scene(const Pose &pose) const
{
    const MomaDesign &d = m_design;
    Scene s;
    auto to3 = [](const Eigen::Vector2d &v) { return Eigen::Vector3d(v.x(), v.y(), 0.0); };
    const Eigen::Vector2d platform = pose.outputs.head<2>();
    const std::array<Eigen::Vector2d, 2> z = {moma::sliderJoint(d, 0, pose.inputs[0]), moma::sliderJoint(d, 1, pose.inputs[1])};
    s.joints.push_back({to3(platform), "P", JointKind::Revolute});
    s.joints.push_back({to3(z[0]), "Z₁", JointKind::Slider});
    s.joints.push_back({to3(z[1]), "Z₂", JointKind::Slider});
    s.joints.push_back({to3(d.reference[0]), "R₁", JointKind::Point});
    s.joints.push_back({to3(d.reference[1]), "R₂", JointKind::Point});
    s.bars.push_back({1, 0, BarKind::Link, "S₁"});
    s.bars.push_back({2, 0, BarKind::Link, "S₂"});
    for (int leg = 0; leg < 2; ++leg) {
        SceneGuide guide;
        guide.start = to3(moma::sliderJoint(d, leg, d.strokeMin));
        guide.end = to3(moma::sliderJoint(d, leg, d.strokeMax));
        guide.width = d.guideWidth;
        guide.label = "PO" + std::string(leg == 0 ? "₁" : "₂");
        s.guides.push_back(guide);
        const double p = pose.inputs[leg];
        if (std::abs(p) > 1.0) {
            // p_i measured from R_i, on the side of the guide away from the link
            const double c = cross(moma::direction(d.alpha[leg]), platform - z[leg]);
            const double offset = (c > 0 ? -1.0 : 1.0) * (d.guideWidth + 14.0);
            s.dimensions.push_back({3 + leg, 1 + leg, p > 0 ? offset : -offset,
                                    joinText({leg == 0 ? "p₁ = " : "p₂ = ", text::fixed(p, 1)})});
        }
        const double gamma = std::remainder(d.alpha[leg] - 1.5 * pi, 2 * pi);
        if (std::abs(gamma) > 1e-9 && std::abs(gamma) <= 45.0 * units::degree) {
            s.angles.push_back({3 + leg, 1.5 * pi, gamma, 0.25 * (d.strokeMax - d.strokeMin),
                                joinText({leg == 0 ? "γ₁ = " : "γ₂ = ", text::number(gamma / units::degree, 1), "°"})});
        }
    }
    s.handles.push_back({0, text::translate("core", "drag to move the platform (inverse kinematics)")});
    s.handles.push_back({1, text::translate("core", "drag along guide 1 to set p₁ (direct kinematics)")});
    s.handles.push_back({2, text::translate("core", "drag along guide 2 to set p₂ (direct kinematics)")});
    Eigen::AlignedBox3d extent;
    for (const SceneGuide &g : s.guides) {
        extent.extend(g.start);
        extent.extend(g.end);
    }
    extent.extend(to3(d.reference[0]));
    extent.extend(to3(d.reference[1]));
    extent.extend(Eigen::Vector3d(m_bounds.min().x(), m_bounds.min().y(), 0.0));
    extent.extend(Eigen::Vector3d(m_bounds.max().x(), m_bounds.max().y(), 0.0));
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(d.guideWidth);
    s.extent = Eigen::AlignedBox3d(extent.min() - pad, extent.max() + pad);
    return s;
}

Result<Pose> Moma::dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const
{
    if (handle == 0) {
        Coordinates outputs(2);
        outputs << target.x(), target.y();
        return solveInverse(outputs, &current);
    }
    if (handle == 1 || handle == 2) {
        const int leg = handle - 1;
        Coordinates inputs = current.inputs;
        const double p = moma::direction(m_design.alpha[leg]).dot(target - m_design.reference[leg]);
        inputs[leg] = std::clamp(p, m_design.strokeMin, m_design.strokeMax);
        return solveDirect(inputs, &current);
    }
    return Failure{FailureKind::UnknownName, {}, text::translate("core", "No handle with that index.")};
}

} // namespace pkm
