#include "scene.h"

namespace pkm {

std::vector<bool> shownJoints(const Scene &scene, double margin)
{
    const std::size_t n = scene.joints.size();
    std::vector<bool> shown(n, true);
    if (scene.extent.isEmpty() || !scene.extent.min().head<2>().allFinite()
        || !scene.extent.max().head<2>().allFinite())
        return shown;
    std::vector<bool> used(n, false);
    const auto use = [&](int joint) {
        if (joint >= 0 && static_cast<std::size_t>(joint) < n)
            used[static_cast<std::size_t>(joint)] = true;
    };
    for (const SceneBar &bar : scene.bars) {
        use(bar.from);
        use(bar.to);
    }
    for (const SceneActuator &actuator : scene.actuators) {
        use(actuator.from);
        use(actuator.to);
    }
    for (const SceneDimension &dimension : scene.dimensions) {
        use(dimension.from);
        use(dimension.to);
    }
    for (const SceneAngle &angle : scene.angles)
        use(angle.vertex);
    const Eigen::Vector2d low = scene.extent.min().head<2>(), high = scene.extent.max().head<2>();
    const Eigen::Vector2d reach = Eigen::Vector2d::Constant(margin * (high - low).maxCoeff());
    const Eigen::AlignedBox2d near(Eigen::Vector2d(low - reach), Eigen::Vector2d(high + reach));
    for (std::size_t j = 0; j < n; ++j) {
        const SceneJoint &joint = scene.joints[j];
        if (joint.kind == JointKind::Point && !used[j] && !near.contains(Eigen::Vector2d(joint.position.head<2>())))
            shown[j] = false;
    }
    return shown;
}

Eigen::AlignedBox3d poseBox(const Scene &scene, double margin)
{
    Eigen::AlignedBox3d box;
    for (const SceneJoint &joint : scene.joints) {
        if (joint.kind != JointKind::Point && joint.position.allFinite())
            box.extend(joint.position);
    }
    if (box.isEmpty())
        return box;
    const double pad = margin * std::max(box.sizes().head<2>().maxCoeff(), 1e-3);
    return {box.min() - Eigen::Vector3d(pad, pad, 0.0), box.max() + Eigen::Vector3d(pad, pad, 0.0)};
}

} // namespace pkm
