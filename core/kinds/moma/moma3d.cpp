// MOMA's solid model for the 3D view, after the MOMA document's drawings: guides with
// carriages, two links in neighbouring layers and a platform.

#include "moma.h"

#include "solidparts.h"
#include "text.h"

#include <array>
#include <cmath>

namespace pkm {

namespace {
using solids::at;
using solids::bar;
using solids::pin;
const Eigen::Vector3d &ux = solids::unitX, &uy = solids::unitY, &uz = solids::unitZ;
} // namespace

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
    model.labels = jointLabels(scene(pose), model.solids); // the same frame as the 2D scene
    return model;
}

} // namespace pkm
