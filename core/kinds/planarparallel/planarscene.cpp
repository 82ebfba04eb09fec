// What the planar parallel mechanism shows and how it is built: the workspace box (the map rows
// are in ppmaprow.cpp), the 2D scene of a pose, and the kinematic chain for the mobility
// analysis.
#include "planarparallel.h"

#include "mobility.h"
#include "text.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
const std::array<const char *, 3> subscripts = {"₁", "₂", "₃"};

Eigen::Vector3d to3(const Eigen::Vector2d &v)
{
    return {v.x(), v.y(), 0.0};
}

/// The side of a distal parallelogram: across the guide of a slider, along the coupler of a
/// П-joint (which stays parallel to its base line), a quarter of the link long.
Eigen::Vector2d parallelogramSide(const PlanarLeg &leg)
{
    const double angle = leg.type == LegType::PRR ? leg.alpha + 0.5 * pi : leg.alpha;
    return 0.25 * leg.link * planar::direction(angle);
}

/// A box that holds every point a leg's distal end can reach.
Eigen::AlignedBox2d reachBox(const PlanarLeg &leg)
{
    auto disc = [](const Eigen::Vector2d &c, double r) {
        return Eigen::AlignedBox2d(c - Eigen::Vector2d::Constant(r), c + Eigen::Vector2d::Constant(r));
    };
    switch (leg.type) {
    case LegType::RRR:
        return disc(leg.base, leg.crank + leg.link);
    case LegType::PRR: {
        Eigen::AlignedBox2d box = disc(leg.base + leg.range.min * planar::direction(leg.alpha), leg.link);
        box.extend(disc(leg.base + leg.range.max * planar::direction(leg.alpha), leg.link));
        return box;
    }
    case LegType::RPR:
        return disc(leg.base, leg.range.max);
    case LegType::PiRR:
        return disc(leg.base, leg.lever + leg.link);
    }
    return {};
}
} // namespace

Eigen::AlignedBox2d PlanarParallel::computeBounds() const
{
    const Eigen::AlignedBox2d reached = reachableBox(m_design.legCount() == 3 ? m_design.mapPhi : 0.0, 96);
    // nothing reached: the legs' common reach, or a unit box where they have none
    return reached.isEmpty() ? reachableBox(m_design.legCount() == 3 ? m_design.mapPhi : 0.0, 0) : reached;
}

Eigen::AlignedBox2d PlanarParallel::computeOutputBounds() const
{
    // A 3-DOF platform reaches farther at some angles than at phi_map: the x and y of a pose
    // at another angle went past a range that was the extent of one slice (x = 19.29 mm where
    // the 3-R̲PR's range ended at 18.49 mm). Every 7.5° of the turn, on a coarser grid.
    Eigen::AlignedBox2d box = m_bounds;
    if (m_design.legCount() != 3)
        return box;
    constexpr int angles = 48, samples = 40;
    for (int k = 0; k < angles; ++k) {
        const Eigen::AlignedBox2d slice = reachableBox(-pi + 2.0 * pi * k / angles, samples);
        if (!slice.isEmpty())
            box.extend(slice);
    }
    return box;
}

Eigen::AlignedBox2d PlanarParallel::reachableBox(double phi, int samples) const
{
    const int n = m_design.legCount();
    Eigen::AlignedBox2d box;
    for (int i = 0; i < n; ++i) {
        const PlanarLeg &leg = m_design.legs[std::size_t(i)];
        // the reference point (x, y) is P_i − R(φ)B_i
        const Eigen::Vector2d offset = planar::platformPoint(leg, Eigen::Vector3d(0.0, 0.0, phi));
        const Eigen::AlignedBox2d reach = reachBox(leg);
        const Eigen::AlignedBox2d shifted(reach.min() - offset, reach.max() - offset);
        box = i == 0 ? shifted : box.intersection(shifted);
    }
    if (box.isEmpty())
        return samples > 0 ? box : Eigen::AlignedBox2d(Eigen::Vector2d(-1.0, -1.0), Eigen::Vector2d(1.0, 1.0));
    if (samples <= 0)
        return box;
    // The legs' reach is a loose box: shrink it to the cells a coarse grid finds reachable,
    // padded by two cells, so that the maps show the workspace large.
    const Eigen::Vector2d step = box.sizes() / samples;
    Eigen::AlignedBox2d reached;
    Coordinates q;
    for (int r = 0; r < samples; ++r) {
        for (int c = 0; c < samples; ++c) {
            const Eigen::Vector2d point = box.min() + Eigen::Vector2d((c + 0.5) * step.x(), (r + 0.5) * step.y());
            int culprit = 0;
            if (inverseCheck(Eigen::Vector3d(point.x(), point.y(), phi), nullptr, q, culprit) == planar::Reach::Yes)
                reached.extend(point);
        }
    }
    if (reached.isEmpty())
        return reached;
    const Eigen::Vector2d pad = 2.0 * step + Eigen::Vector2d::Constant(1.0);
    return Eigen::AlignedBox2d(reached.min() - pad, reached.max() + pad).intersection(
        Eigen::AlignedBox2d(box.min() - pad, box.max() + pad));
}

// -- drawing -------------------------------------------------------------------------------

Scene PlanarParallel::scene(const Pose &pose) const
{
    const int n = m_design.legCount();
    const Eigen::Vector3d X = platformPose(pose.outputs);
    Scene s;
    auto joint = [&](const Eigen::Vector2d &p, const std::string &label, JointKind kind) {
        s.joints.push_back({to3(p), label, kind});
        return int(s.joints.size()) - 1;
    };
    // joint 0: the platform's reference point, the handle
    const int reference = joint(X.head<2>(), n == 2 && m_design.platform == PlatformType::Point ? "P" : "Oₚ",
                                m_design.platform == PlatformType::Point ? JointKind::Revolute : JointKind::Point);
    std::array<int, 3> ends{};
    std::array<int, 3> bases{};
    for (int i = 0; i < n; ++i) {
        const std::size_t k = std::size_t(i);
        const PlanarLeg &leg = m_design.legs[k];
        const planar::LegCircle c = planar::circle(leg, pose.inputs[i]);
        const Eigen::Vector2d P = planar::platformPoint(leg, X);
        const std::string sub = subscripts[k];
        ends[k] = m_design.platform == PlatformType::Point ? reference : joint(P, joinText({"P", sub}), JointKind::Revolute);
        int proximal = -1; // the joint the distal link starts from
        switch (leg.type) {
        case LegType::RRR: {
            const int a = joint(leg.base, joinText({"A", sub}), JointKind::Ground);
            bases[k] = a;
            proximal = joint(c.centre, joinText({"C", sub}), JointKind::Revolute);
            s.bars.push_back({a, proximal, BarKind::Crank, joinText({"r", sub})});
            break;
        }
        case LegType::PRR: {
            bases[k] = joint(leg.base, joinText({"A", sub}), JointKind::Point);
            proximal = joint(c.centre, joinText({"C", sub}), JointKind::Slider);
            SceneGuide guide;
            guide.start = to3(leg.base + leg.range.min * planar::direction(leg.alpha));
            guide.end = to3(leg.base + leg.range.max * planar::direction(leg.alpha));
            guide.width = 16.0;
            s.guides.push_back(guide);
            break;
        }
        case LegType::RPR: {
            const int a = joint(leg.base, joinText({"A", sub}), JointKind::Ground);
            bases[k] = a;
            const double body = 0.45 * leg.range.min;
            s.actuators.push_back({a, ends[k], body, std::max(8.0, 0.12 * body), std::max(3.0, 0.04 * body), joinText({"q", sub})});
            break;
        }
        case LegType::PiRR: {
            // the П-joint's parallelogram O-B-A-C: B at A_i, O along −α, the coupler parallel to OB
            const Eigen::Vector2d base = planar::direction(leg.alpha) * leg.ratio * leg.lever;
            const int o = joint(leg.base - base, joinText({"O", sub}), JointKind::Ground);
            const int b = joint(leg.base, joinText({"A", sub}), JointKind::Ground);
            bases[k] = b;
            proximal = joint(c.centre, joinText({"C", sub}), JointKind::Revolute);
            const int other = joint(c.centre - base, "", JointKind::Revolute);
            s.bars.push_back({o, b, BarKind::Ground, ""});
            s.bars.push_back({b, proximal, BarKind::Crank, joinText({"a", sub})});
            s.bars.push_back({o, other, BarKind::Crank, ""});
            s.bars.push_back({other, proximal, BarKind::Coupler, ""});
            s.actuators.push_back({o, proximal, 45.0, 28.0, 4.8, joinText({"d", sub})});
            break;
        }
        }
        if (proximal >= 0) {
            s.bars.push_back({proximal, ends[k], BarKind::Link, joinText({"l", sub})});
            if (m_design.platform == PlatformType::Translating) {
                const Eigen::Vector2d side = parallelogramSide(leg);
                const int from = joint(c.centre + side, "", JointKind::Revolute);
                const int to = joint(P + side, "", JointKind::Revolute);
                s.bars.push_back({from, to, BarKind::Link, ""});
                s.bars.push_back({proximal, from, BarKind::Coupler, ""});
                s.bars.push_back({ends[k], to, BarKind::Platform, ""});
            }
        }
    }
    if (m_design.platform != PlatformType::Point) {
        for (int i = 0; i < n; ++i)
            s.bars.push_back({ends[std::size_t(i)], ends[std::size_t((i + 1) % n)], BarKind::Platform, ""});
        if (n == 2)
            s.bars.push_back({reference, ends[0], BarKind::Platform, ""});
    }
    s.handles.push_back({reference, text::translate("core", "drag to move the platform (inverse kinematics)")});
    // The attachment points edit the design: A_i in the base frame, B_i in the platform's
    // (a point platform has none of its own: its legs meet at the platform's point).
    for (int i = 0; i < n; ++i) {
        const std::string number = std::to_string(i + 1);
        SceneHandle a;
        a.joint = bases[std::size_t(i)];
        a.hint = text::format(text::translate("core", "drag to move the base point A%1 (changes the design)"), {number});
        a.xParameter = joinText({"A", number, "x"});
        a.yParameter = joinText({"A", number, "y"});
        s.handles.push_back(a);
        if (m_design.platform == PlatformType::Point)
            continue;
        SceneHandle b;
        b.joint = ends[std::size_t(i)];
        b.hint = text::format(text::translate("core", "drag to move the platform point B%1 (changes the design)"), {number});
        b.xParameter = joinText({"B", number, "x"});
        b.yParameter = joinText({"B", number, "y"});
        b.frameOrigin = X.head<2>();
        b.frameAngle = X.z();
        s.handles.push_back(b);
    }
    Eigen::AlignedBox3d extent;
    for (const SceneJoint &j : s.joints)
        extent.extend(j.position);
    // The reach of a 3-RP̲R's platform is about three times the mechanism: fitted to it, the
    // mechanism would be a thumbnail in the middle of the view.
    s.poseExtent = poseBox(s);
    extent.extend(Eigen::Vector3d(m_bounds.min().x(), m_bounds.min().y(), 0.0));
    extent.extend(Eigen::Vector3d(m_bounds.max().x(), m_bounds.max().y(), 0.0));
    for (const PlanarLeg &leg : m_design.legs) {
        if (&leg - m_design.legs.data() < n)
            extent.extend(to3(leg.base));
    }
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(20.0);
    s.extent = Eigen::AlignedBox3d(extent.min() - pad, extent.max() + pad);
    return s;
}

Result<Pose> PlanarParallel::dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const
{
    if (handle != 0)
        return Failure{FailureKind::UnknownName, {}, text::translate("core", "No handle with that index.")};
    Coordinates outputs = current.outputs;
    outputs[0] = target.x();
    outputs[1] = target.y();
    return solveInverse(outputs, &current);
}

// -- structure -----------------------------------------------------------------------------

KinematicChain PlanarParallel::kinematicChain(const Pose &pose) const
{
    const int n = m_design.legCount();
    const Eigen::Vector3d X = platformPose(pose.outputs);
    KinematicChain chain;
    chain.links = {text::translate("core", "ground")};
    auto link = [&](const std::string &name) {
        chain.links.push_back(name);
        return int(chain.links.size()) - 1;
    };
    auto revolute = [&](const std::string &name, int a, int b, const Eigen::Vector2d &p) {
        chain.pairs.push_back(mobility::planarRevolute(name, a, b, p));
    };
    const int platform = m_design.platform == PlatformType::Point ? -1 : link(text::translate("core", "platform"));
    int firstDistal = -1;
    for (int i = 0; i < n; ++i) {
        const std::size_t k = std::size_t(i);
        const PlanarLeg &leg = m_design.legs[k];
        const planar::LegCircle c = planar::circle(leg, pose.inputs[i]);
        const Eigen::Vector2d P = planar::platformPoint(leg, X);
        const std::string sub = subscripts[k], legNumber = std::to_string(i + 1);
        int distal = -1, holder = -1; // holder: the body a distal parallelogram hangs from
        switch (leg.type) {
        case LegType::RRR: {
            const int crank = link(text::format(text::translate("core", "crank %1"), {legNumber}));
            distal = link(text::format(text::translate("core", "link %1"), {legNumber}));
            chain.pairs.push_back(mobility::planarRevolute(joinText({"A", sub}), 0, crank, leg.base, true));
            revolute(joinText({"C", sub}), crank, distal, c.centre);
            break;
        }
        case LegType::PRR: {
            const int slider = link(text::format(text::translate("core", "slider %1"), {legNumber}));
            distal = link(text::format(text::translate("core", "link %1"), {legNumber}));
            chain.pairs.push_back(mobility::planarPrismatic(text::format(text::translate("core", "guide %1"), {legNumber}), 0, slider,
                                                            c.centre, planar::direction(leg.alpha), true));
            revolute(joinText({"C", sub}), slider, distal, c.centre);
            holder = slider;
            break;
        }
        case LegType::RPR: {
            const int body = link(text::format(text::translate("core", "strut %1, motor body"), {legNumber}));
            distal = link(text::format(text::translate("core", "strut %1, rod"), {legNumber}));
            revolute(joinText({"A", sub}), 0, body, leg.base);
            chain.pairs.push_back(mobility::planarPrismatic(joinText({"q", sub}), body, distal, leg.base, P - leg.base, true));
            break;
        }
        case LegType::PiRR: {
            // the П-joint's own chain (the pjoint kind's): parallelogram O-B-A-C and the diagonal
            const Eigen::Vector2d base = planar::direction(leg.alpha) * leg.ratio * leg.lever;
            const Eigen::Vector2d o = leg.base - base, tip = c.centre, other = tip - base;
            const int crank = link(text::format(text::translate("core", "crank %1"), {legNumber}));
            const int rocker = link(text::format(text::translate("core", "П-joint %1: crank OC"), {legNumber}));
            const int coupler = link(text::format(text::translate("core", "П-joint %1: coupler"), {legNumber}));
            const int motor = link(text::format(text::translate("core", "П-joint %1: motor body"), {legNumber}));
            const int screw = link(text::format(text::translate("core", "П-joint %1: screw"), {legNumber}));
            distal = link(text::format(text::translate("core", "link %1"), {legNumber}));
            revolute(joinText({"A", sub}), 0, crank, leg.base);
            revolute(joinText({"O", sub}), 0, rocker, o);
            revolute(joinText({"C", sub}), crank, coupler, tip);
            revolute(joinText({"C'", sub}), rocker, coupler, other);
            revolute(joinText({"O'", sub}), 0, motor, o);
            revolute(joinText({"C''", sub}), crank, screw, tip);
            chain.pairs.push_back(mobility::planarPrismatic(joinText({"d", sub}), motor, screw, o, tip - o, true));
            // the distal link hangs from the coupler, which keeps the base line's direction
            revolute(joinText({"C'''", sub}), coupler, distal, tip);
            holder = coupler;
            break;
        }
        }
        if (m_design.platform == PlatformType::Point) {
            if (firstDistal < 0)
                firstDistal = distal;
            else
                revolute("P", firstDistal, distal, P);
            continue;
        }
        revolute(joinText({"P", sub}), distal, platform, P);
        if (m_design.platform == PlatformType::Translating) {
            // the distal parallelogram: a second link beside the first, from the slider or the
            // П-joint's coupler (the body the distal link hangs from) to the platform
            const Eigen::Vector2d side = parallelogramSide(leg);
            const int second = link(text::format(text::translate("core", "link %1, parallel"), {legNumber}));
            revolute(joinText({"E", sub}), holder, second, c.centre + side);
            revolute(joinText({"F", sub}), second, platform, P + side);
        }
    }
    chain.description = text::translate("core", "planar parallel mechanism: legs from the leg library joined at the platform");
    return chain;
}

} // namespace pkm
