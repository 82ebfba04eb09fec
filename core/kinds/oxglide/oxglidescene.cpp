// The O-X glide's drawings: the planar front view (scene) and the solid model of the hybrid
// (scene3d). Both use the frame of oxglide.h; the guides lie below the rod-joint plane y = 0,
// stacked a apart (D at 0, A at a, B at 2a, C at 3a), so the pairs pass each other.

#include "oxglide.h"

#include "mobility.h"
#include "text.h"

#include <array>
#include <cmath>

namespace pkm {

namespace {
/// Guide k of the stack, in the order D, A, B, C (their distance below the rod-joint plane).
constexpr std::array<const char *, 4> guideNames = {"D", "A", "B", "C"};
constexpr int guideD = 0, guideA = 1, guideB = 2, guideC = 3;
} // namespace

Scene OxGlide::scene(const Pose &pose) const
{
    const OxGlideDesign &d = m_design;
    const double a = d.spacing, s = d.width, L = d.guideLength;
    const double xAB = pose.inputs[0], xCD = pose.inputs[1];
    const double x = pose.outputs[0], y = pose.outputs[1];
    Scene scene;
    auto joint = [&](double jx, double jy, const std::string &label, JointKind kind) {
        scene.joints.push_back({Eigen::Vector3d(jx, jy, 0.0), label, kind});
        return int(scene.joints.size()) - 1;
    };
    const int t = joint(x, y, "T", JointKind::Point);
    const int jointAB = joint(xAB, 0.0, "", JointKind::Revolute);
    const int jointCD = joint(xCD, 0.0, "", JointKind::Revolute);
    const int left = joint(x - 0.5 * s, y, "A′B′", JointKind::Spherical);
    const int right = joint(x + 0.5 * s, y, "C′D′", JointKind::Spherical);
    const int sliderA = joint(xAB, -guideA * a, "", JointKind::Slider);
    const int sliderB = joint(xAB, -guideB * a, "", JointKind::Slider);
    const int sliderC = joint(xCD, -guideC * a, "", JointKind::Slider);
    joint(xCD, -guideD * a, "", JointKind::Slider);
    // the compensation elements bring the rod joints of A, B and C up to the plane y = 0
    scene.bars.push_back({sliderB, jointAB, BarKind::Coupler, ""});
    scene.bars.push_back({sliderA, jointAB, BarKind::Coupler, ""});
    scene.bars.push_back({sliderC, jointCD, BarKind::Coupler, ""});
    scene.bars.push_back({jointAB, left, BarKind::Rod, "l"});
    scene.bars.push_back({jointCD, right, BarKind::Rod, "l"});
    scene.bars.push_back({left, right, BarKind::Platform, "s"});
    const double rail = std::min(0.55 * a, 10.0);
    for (int k = 0; k < 4; ++k) {
        SceneGuide guide;
        guide.start = Eigen::Vector3d(0.0, -k * a, 0.0);
        guide.end = Eigen::Vector3d(L, -k * a, 0.0);
        guide.width = rail;
        // the slider it carries and its depth below the rod-joint plane: "A · a"
        std::string label = guideNames[std::size_t(k)];
        label.append(" · ").append(k == 0 ? std::string("0") : (k == 1 ? std::string("a") : std::to_string(k) + "a"));
        guide.label = label;
        scene.guides.push_back(guide);
    }
    // ψ: the rods' angle to the guides, at the rod joint of AB
    const Eigen::Vector2d rod(x - 0.5 * s - xAB, y);
    if (rod.norm() > 1e-9) {
        const double direction = std::atan2(rod.y(), rod.x());
        const double start = rod.x() >= 0 ? 0.0 : std::numbers::pi;
        const double sweep = direction - start;
        scene.angles.push_back({jointAB, start, sweep, 0.3 * d.rod,
                                joinText({"ψ = ", text::fixed(std::atan2(std::abs(y), std::abs(rod.x())) / units::degree, 1),
                                          "°"})});
    }
    scene.handles.push_back(
        {t, text::translate("core", "drag to move the platform (inverse kinematics, in the current form)")});
    scene.handles.push_back({jointAB, text::translate("core", "drag along the guides to set x_AB (direct kinematics)")});
    scene.handles.push_back({jointCD, text::translate("core", "drag along the guides to set x_CD (direct kinematics)")});
    const double pad = 0.08 * std::max(L, d.rod);
    // room at the sides for the guides' labels
    scene.extent = Eigen::AlignedBox3d(Eigen::Vector3d(-2.0 * pad, -3.0 * a - rail - pad, 0.0),
                                       Eigen::Vector3d(L + 3.0 * pad, d.rod + pad, 0.0));
    return scene;
}

Scene3D OxGlide::scene3d(const Pose &pose) const
{
    const OxGlideDesign &d = m_design;
    const double a = d.spacing, s = d.width, L = d.guideLength, l = d.rod;
    const double xAB = pose.inputs[0], xCD = pose.inputs[1], z = pose.inputs[2];
    const double x = pose.outputs[0], y = pose.outputs[1];
    const double c = a; // depth pitch of the four rod planes
    auto depth = [&](int k) { return z + (k - 1.5) * c; };
    auto guideY = [&](int k) { return -k * a; };
    const Eigen::Vector3d ux = Eigen::Vector3d::UnitX(), uy = Eigen::Vector3d::UnitY();
    const double rail = 0.45 * a, sliderLength = 1.3 * a, sliderHeight = 0.75 * a, sliderWidth = 0.8 * c;
    const double frameGap = 0.8 * a, bottom = -4.3 * a;
    Scene3D model;
    auto &parts = model.solids;

    // the carriage of the serial axis: two end plates carrying the transverse guides, riding
    // the longitudinal guides below them
    const double z0 = depth(0) - 0.6 * c, z1 = depth(3) + 0.6 * c;
    const std::string carriage = text::translate("core", "longitudinal carriage"),
                      endPlate = text::translate("core", "end plate"),
                      longitudinalGuide = text::translate("core", "longitudinal guide");
    for (const double px : {-frameGap, L + frameGap}) {
        parts.push_back(Solid::box({px, bottom, z0}, {px, bottom, z1}, 0.5 * a, 0.7 * a, uy, PartRole::Slider, carriage));
        parts.push_back(Solid::box({px, bottom, 0.5 * (z0 + z1)}, {px, 0.5 * a, 0.5 * (z0 + z1)}, z1 - z0, 0.5 * a, ux, PartRole::Ground, endPlate));
        parts.push_back(Solid::box({px, bottom - 0.6 * a, d.zMin - 2.5 * c}, {px, bottom - 0.6 * a, d.zMax + 2.5 * c}, 0.5 * a, 0.5 * a, uy,
                                   PartRole::Guide, longitudinalGuide));
    }
    parts.push_back(Solid::box({-frameGap - a, bottom - 1.2 * a, 0.5 * (d.zMin + d.zMax)}, {L + frameGap + a, bottom - 1.2 * a, 0.5 * (d.zMin + d.zMax)},
                               d.zMax - d.zMin + 5.0 * c, 0.4 * a, uy, PartRole::Ground, text::translate("core", "base")));

    // the transverse guides and the sliders on them
    const std::array<double, 4> sliderX = {xCD, xAB, xAB, xCD};
    const std::string guidePattern = text::translate("core", "guide %1"),
                      sliderPattern = text::translate("core", "slider %1"),
                      compensationPattern = text::translate("core", "compensation element %1"),
                      rodJointPattern = text::translate("core", "rod joint %1");
    for (int k = 0; k < 4; ++k) {
        const std::string name = guideNames[std::size_t(k)];
        parts.push_back(Solid::box({-frameGap, guideY(k), depth(k)}, {L + frameGap, guideY(k), depth(k)}, rail, rail, uy, PartRole::Guide,
                                   text::format(guidePattern, {name})));
        const Eigen::Vector3d centre(sliderX[std::size_t(k)], guideY(k), depth(k));
        parts.push_back(Solid::box(centre - 0.5 * sliderLength * ux, centre + 0.5 * sliderLength * ux, sliderWidth, sliderHeight, uy,
                                   PartRole::Slider, text::format(sliderPattern, {name})));
        // compensation element: from the slider up to the rod-joint plane
        if (k != guideD) {
            parts.push_back(Solid::box({centre.x(), guideY(k) + 0.5 * sliderHeight, depth(k)}, {centre.x(), 0.0, depth(k)}, 0.5 * c, 0.45 * a, ux,
                                       PartRole::Compensation, text::format(compensationPattern, {name})));
        }
        // the rod joint: a pin across the rod's plane
        parts.push_back(Solid::cylinder({centre.x(), 0.0, depth(k) - 0.45 * c}, {centre.x(), 0.0, depth(k) + 0.45 * c}, 0.28 * a,
                                        PartRole::Joint, text::format(rodJointPattern, {name})));
        model.labels.push_back({Eigen::Vector3d(centre.x(), 0.0, depth(k)), name});
    }
    // the rigid pairs: A–B directly, C–D around below the other guides
    parts.push_back(Solid::box({xAB, guideY(guideA), depth(guideA)}, {xAB, guideY(guideB), depth(guideB)}, 0.35 * a, 0.35 * a, ux, PartRole::Slider,
                               text::translate("core", "pair AB")));
    const double under = guideY(guideC) - 0.8 * a;
    const std::string pairCD = text::translate("core", "pair CD");
    parts.push_back(Solid::box({xCD, 0.0, depth(guideD)}, {xCD, under, depth(guideD)}, 0.35 * c, 0.35 * a, ux, PartRole::Slider, pairCD));
    parts.push_back(Solid::box({xCD, under, depth(guideD)}, {xCD, under, depth(guideC)}, 0.35 * a, 0.35 * a, ux, PartRole::Slider, pairCD));
    parts.push_back(Solid::box({xCD, under, depth(guideC)}, {xCD, guideY(guideC), depth(guideC)}, 0.35 * c, 0.35 * a, ux, PartRole::Slider, pairCD));

    // rods and the platform with its spherical joints; A, B at the left end, C, D at the right
    const std::array<double, 4> platformX = {x + 0.5 * s, x - 0.5 * s, x - 0.5 * s, x + 0.5 * s};
    const std::string rodPattern = text::translate("core", "rod %1"),
                      sphericalPattern = text::translate("core", "spherical joint %1");
    for (int k = 0; k < 4; ++k) {
        const std::string name = guideNames[std::size_t(k)];
        const Eigen::Vector3d from(sliderX[std::size_t(k)], 0.0, depth(k)), to(platformX[std::size_t(k)], y, depth(k));
        parts.push_back(Solid::cylinder(from, to, 0.16 * a, PartRole::Rod, text::format(rodPattern, {name})));
        parts.push_back(Solid::sphere(to, 0.3 * a, PartRole::Joint,
                                     text::format(sphericalPattern, {name + "′"})));
    }
    const double thickness = 0.35 * a;
    parts.push_back(Solid::box({x - 0.5 * s - 0.25 * a, y + 0.5 * thickness, z}, {x + 0.5 * s + 0.25 * a, y + 0.5 * thickness, z},
                               4.0 * c, thickness, uy, PartRole::Platform, text::translate("core", "platform")));
    parts.push_back(Solid::sphere({x, y + thickness + 0.2 * a, z}, 0.25 * a, PartRole::Marker, "T"));
    // The model is built as the machine stands (guides stacked below the rods), not in the 2D
    // scene's frame: its own points are named, the rod joints on their guides and the tool T.
    model.labels.push_back({Eigen::Vector3d(x, y + thickness + 0.2 * a, z), "T"});

    model.extent = Eigen::AlignedBox3d(Eigen::Vector3d(-frameGap - a, bottom - 1.4 * a, d.zMin - 2.5 * c),
                                       Eigen::Vector3d(L + frameGap + a, l + thickness + 0.5 * a, d.zMax + 2.5 * c));
    return model;
}

KinematicChain OxGlide::kinematicChain(const Pose &pose) const
{
    const OxGlideDesign &d = m_design;
    const double xAB = pose.inputs[0], xCD = pose.inputs[1], z = pose.inputs[2];
    const double x = pose.outputs[0], y = pose.outputs[1];
    auto depth = [&](int k) { return z + (k - 1.5) * d.spacing; }; // as scene3d()
    enum { Ground, Carriage, PairAB, PairCD, Rods, Platform = Rods + 4 };
    const Eigen::Vector3d ux = Eigen::Vector3d::UnitX(), uz = Eigen::Vector3d::UnitZ();
    KinematicChain chain;
    chain.links = {text::translate("core", "ground"), text::translate("core", "carriage"),
                   text::translate("core", "slider pair AB"), text::translate("core", "slider pair CD")};
    const std::string rodPattern = text::translate("core", "rod %1");
    for (int k = 0; k < 4; ++k)
        chain.links.push_back(text::format(rodPattern, {guideNames[std::size_t(k)]}));
    chain.links.push_back(text::translate("core", "platform"));
    chain.pairs.push_back(
        mobility::makePair(PairType::Prismatic, "z", Ground, Carriage, Eigen::Vector3d(0.0, 0.0, z), uz, true));
    chain.pairs.push_back(mobility::makePair(
        PairType::Prismatic, "x_AB", Carriage, PairAB, Eigen::Vector3d(xAB, 0.0, depth(guideA)), ux, true));
    chain.pairs.push_back(mobility::makePair(
        PairType::Prismatic, "x_CD", Carriage, PairCD, Eigen::Vector3d(xCD, 0.0, depth(guideD)), ux, true));
    for (int k = 0; k < 4; ++k) {
        const bool cd = k == guideC || k == guideD;
        const std::string name = guideNames[std::size_t(k)];
        const Eigen::Vector3d slider(cd ? xCD : xAB, 0.0, depth(k)),
            platform(cd ? x + 0.5 * d.width : x - 0.5 * d.width, y, depth(k));
        chain.pairs.push_back(mobility::makePair(PairType::Revolute, name, cd ? PairCD : PairAB, Rods + k, slider, uz));
        chain.pairs.push_back(
            mobility::makePair(PairType::Spherical, joinText({name, "′"}), Rods + k, Platform, platform));
    }
    chain.planar = false;
    chain.description
        = text::translate("core", "O-X glide: carriage on the longitudinal guides, slider pairs AB and CD, four rods "
                                  "(revolute at the sliders, spherical at the platform), platform");
    // With these joints the platform keeps its tilt when the sliders are locked (tst_mobility:
    // the planar part alone keeps its swing), which the document's kinematics assume away.
    chain.underActuation = text::translate("core",
        "The rank counts the platform's x and y, the carriage's z and the platform's tilt (its "
        "swing about the longitudinal axis). The actuators drive x_AB, x_CD and z; the tilt is "
        "not held by them. With the joints the document describes (spherical at the platform, one "
        "hinge per rod at the slider, a pair's rods one behind the other) the platform can tilt "
        "with the sliders locked; the document's kinematics assume it stays level.");
    return chain;
}

} // namespace pkm
