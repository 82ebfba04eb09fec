// The П-joint's solid model for the 3D view: the spatial structure of the П-joint document's
// fig. 2 — two parallel parallelograms for stiffness normal to the plane, the stepper motor
// and its lead screw between them.

#include "pjoint.h"

#include "solidparts.h"
#include "text.h"

#include <array>
#include <cmath>

namespace pkm {

namespace {
using solids::at;
using solids::bar;
using solids::pin;
const Eigen::Vector3d &uy = solids::unitY, &uz = solids::unitZ;
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
    model.labels = jointLabels(scene(pose), model.solids); // the same frame as the 2D scene
    return model;
}


} // namespace pkm
