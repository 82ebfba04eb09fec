// Solid models of the П-joint and MOMA for the 3D view. The O-X glide's is in
// oxglidescene.cpp. Proportions follow the drawings of the documents: the П-joint as the
// spatial structure of its fig. 2 (two parallel parallelograms for stiffness normal to the
// plane, the stepper motor and its lead screw between them), MOMA as guides with carriages,
// two links in neighbouring layers and a platform.

#include "moma.h"
#include "pjoint.h"
#include "text.h"

#include <array>
#include <cmath>

namespace pkm {

namespace {
const Eigen::Vector3d ux = Eigen::Vector3d::UnitX(), uy = Eigen::Vector3d::UnitY(), uz = Eigen::Vector3d::UnitZ();

Eigen::Vector3d at(const Eigen::Vector2d &p, double z)
{
    return {p.x(), p.y(), z};
}

/// A flat bar in the plane z = `z` from p to q, its ends rounded out by half its width.
Solid bar(const Eigen::Vector2d &p, const Eigen::Vector2d &q, double z, double width, double thickness, PartRole role,
          std::string label)
{
    const Eigen::Vector2d u = (q - p).normalized();
    return Solid::box(at(p - 0.5 * width * u, z), at(q + 0.5 * width * u, z), width, thickness, uz, role, std::move(label));
}

/// A pin along z through (p, z0…z1).
Solid pin(const Eigen::Vector2d &p, double z0, double z1, double radius, std::string label)
{
    return Solid::cylinder(at(p, z0), at(p, z1), radius, PartRole::Joint, std::move(label));
}
} // namespace

Scene3D PJoint::scene3d(const Pose &pose) const
{
    const PJointDesign &p = m_design;
    const double theta = pose.outputs[0];
    const Eigen::Vector2d crank = p.a * Eigen::Vector2d(std::sin(theta), std::cos(theta));
    const Eigen::Vector2d o(0, 0), b(p.b, 0), a = b + crank, c = o + crank;
    // two parallelograms at z = ±plane, the motor between them in z = 0
    const double width = 0.085 * p.a, thickness = 0.04 * p.a, pinRadius = 0.03 * p.a;
    const double plane = 0.5 * p.motorWidth + 0.5 * thickness + 0.03 * p.a;
    const double outer = plane + 0.5 * thickness;
    Scene3D model;
    auto &parts = model.solids;
    const std::string crankOC = text::translate("core", "crank OC"), crankBA = text::translate("core", "crank BA"),
                      couplerCA = text::translate("core", "coupler CA");
    for (const double z : {-plane, plane}) {
        const std::string side = z < 0 ? text::translate("core", "%1 (back)") : text::translate("core", "%1 (front)");
        parts.push_back(bar(o, c, z, width, thickness, PartRole::Link, text::format(side, {crankOC})));
        parts.push_back(bar(b, a, z, width, thickness, PartRole::Link, text::format(side, {crankBA})));
        parts.push_back(bar(c, a, z, width, thickness, PartRole::Link, text::format(side, {couplerCA})));
    }
    // the base: a plate with a clevis at O and at B outside the parallelograms
    const double baseTop = -0.09 * p.a, baseHeight = 0.05 * p.a;
    parts.push_back(Solid::box({-0.22 * p.a, baseTop - 0.5 * baseHeight, 0.0}, {p.b + 0.22 * p.a, baseTop - 0.5 * baseHeight, 0.0},
                               2.0 * outer + 2.5 * thickness, baseHeight, uy, PartRole::Ground, text::translate("core", "base")));
    const std::string clevis = text::translate("core", "clevis");
    for (const Eigen::Vector2d &pivot : {o, b}) {
        for (const double z : {-(outer + 0.6 * thickness), outer + 0.6 * thickness})
            parts.push_back(Solid::box(at(Eigen::Vector2d(pivot.x(), baseTop), z), at(pivot, z) + 0.6 * width * uy, 1.6 * width, thickness, uz,
                                       PartRole::Ground, clevis));
    }
    const double pinEnd = outer + 1.2 * thickness;
    parts.push_back(pin(o, -pinEnd, pinEnd, pinRadius, "O"));
    parts.push_back(pin(b, -pinEnd, pinEnd, pinRadius, "B"));
    parts.push_back(pin(a, -outer - 0.3 * thickness, outer + 0.3 * thickness, pinRadius, "A"));
    parts.push_back(pin(c, -outer - 0.3 * thickness, outer + 0.3 * thickness, pinRadius, "C"));
    // the stepper motor pivoted at O and its lead screw to A: the screw's extension is d minus
    // the body, so it follows the actuator
    const Eigen::Vector2d u = (a - o).normalized();
    const double d = pose.inputs[0];
    const Eigen::Vector2d bodyEnd = o + std::min(p.motorLength, d) * u;
    parts.push_back(Solid::box(at(o - 0.15 * p.motorLength * u, 0.0), at(bodyEnd, 0.0), p.motorWidth, p.motorWidth, uz,
                               PartRole::Actuator, text::translate("core", "stepper motor")));
    parts.push_back(Solid::cylinder(at(bodyEnd, 0.0), at(a, 0.0), 0.5 * p.screwDiameter, PartRole::Screw,
                                    text::translate("core", "lead screw")));
    parts.push_back(Solid::cylinder(at(a - 0.06 * p.a * u, 0.0), at(a, 0.0), 0.5 * p.screwDiameter + 0.02 * p.a, PartRole::Screw,
                                    text::translate("core", "rod end")));

    // the extent over the whole θ range, so the view stays still while the joint moves
    Eigen::AlignedBox3d box;
    for (int i = 0; i <= 32; ++i) {
        const double t = p.thetaMin + (p.thetaMax - p.thetaMin) * i / 32.0;
        const Eigen::Vector2d r = p.a * Eigen::Vector2d(std::sin(t), std::cos(t));
        for (const Eigen::Vector2d &q : {Eigen::Vector2d(b + r), Eigen::Vector2d(o + r)}) {
            box.extend(at(q, 0.0) + Eigen::Vector3d::Constant(width));
            box.extend(at(q, 0.0) - Eigen::Vector3d::Constant(width));
        }
    }
    box.extend(Eigen::Vector3d(-0.22 * p.a, baseTop - baseHeight, -(outer + 1.5 * thickness)));
    box.extend(Eigen::Vector3d(p.b + 0.22 * p.a, 0.0, outer + 1.5 * thickness));
    const double motorReach = 0.15 * p.motorLength + p.motorWidth; // the motor's rear around O
    box.extend(Eigen::Vector3d(-motorReach, -motorReach, 0.0)).extend(Eigen::Vector3d(motorReach, motorReach, 0.0));
    model.extent = box;
    return model;
}

Scene3D Moma::scene3d(const Pose &pose) const
{
    const MomaDesign &d = m_design;
    const double gw = d.guideWidth;
    const double linkWidth = 0.55 * gw, linkThickness = 0.3 * gw;
    const Eigen::Vector2d platform = pose.outputs.head<2>();
    Scene3D model;
    auto &parts = model.solids;
    // layers, back to front: guides, carriages, link 1, link 2, the platform
    const double zGuide = -linkThickness - 0.55 * gw, zCarriage = -0.5 * linkThickness - 0.25 * gw;
    const std::array<double, 2> zLink = {0.0, linkThickness + 0.1 * gw};
    const std::string guidePattern = text::translate("core", "guide %1"), endStop = text::translate("core", "end stop"),
                      carriagePattern = text::translate("core", "carriage %1"),
                      linkPattern = text::translate("core", "link %1");
    for (int leg = 0; leg < 2; ++leg) {
        const std::string name = leg == 0 ? "1" : "2";
        const Eigen::Vector2d axis = moma::direction(d.alpha[leg]);
        const Eigen::Vector2d start = moma::sliderJoint(d, leg, d.strokeMin) - 0.9 * gw * axis;
        const Eigen::Vector2d end = moma::sliderJoint(d, leg, d.strokeMax) + 0.9 * gw * axis;
        parts.push_back(Solid::box(at(start, zGuide), at(end, zGuide), gw, 0.6 * gw, uz, PartRole::Guide,
                                   text::format(guidePattern, {"PO" + name})));
        for (const Eigen::Vector2d &stop : {start, end}) {
            parts.push_back(Solid::box(at(stop - 0.15 * gw * axis, zGuide), at(stop + 0.15 * gw * axis, zGuide), 1.5 * gw, 0.9 * gw, uz,
                                       PartRole::Ground, endStop));
        }
        const Eigen::Vector2d z = moma::sliderJoint(d, leg, pose.inputs[leg]);
        parts.push_back(Solid::box(at(z - 0.9 * gw * axis, zCarriage), at(z + 0.9 * gw * axis, zCarriage), 1.3 * gw, 0.5 * gw, uz,
                                   PartRole::Slider, text::format(carriagePattern, {"Z" + name})));
        parts.push_back(bar(z, platform, zLink[std::size_t(leg)], linkWidth, linkThickness, PartRole::Link,
                             text::format(linkPattern, {"S" + name})));
        parts.push_back(pin(z, zCarriage, zLink[std::size_t(leg)] + 0.6 * linkThickness, 0.2 * gw, "Z" + name));
    }
    parts.push_back(pin(platform, -0.6 * linkThickness, zLink[1] + 0.6 * linkThickness, 0.2 * gw, "P"));
    const double zPlatform = zLink[1] + linkThickness;
    parts.push_back(Solid::cylinder(at(platform, zPlatform), at(platform, zPlatform + 0.4 * gw), 0.85 * gw, PartRole::Platform,
                                    text::translate("core", "platform")));
    parts.push_back(Solid::sphere(at(platform, zPlatform + 0.55 * gw), 0.22 * gw, PartRole::Marker, "P"));

    // the 2D extent (constant over the workspace) with the guides' ends and the layers' depth
    const Scene flat = scene(pose);
    Eigen::AlignedBox3d box(flat.extent.min() - Eigen::Vector3d(gw, gw, 0.0), flat.extent.max() + Eigen::Vector3d(gw, gw, 0.0));
    box.min().z() = zGuide - 0.5 * gw;
    box.max().z() = zPlatform + 0.8 * gw;
    model.extent = box;
    return model;
}

} // namespace pkm
