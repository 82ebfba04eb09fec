// Editing a design of the leg library: which parameters a design uses (the design panel shows
// only those), and, when an edit leaves a design that cannot be assembled, which leg is to
// blame and why — said at the pose the edit starts from, so the message points at the leg the
// user just changed rather than at "the mechanism".
#include "planarparallel.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace pkm {

Result<MechanismPtr> PlanarParallel::withParameters(const ParameterSet &changes) const
{
    return withParameters(changes, nullptr);
}

Result<MechanismPtr> PlanarParallel::withParameters(const ParameterSet &changes, SharedSearch *shared) const
{
    auto design = table().apply(m_design, changes, true);
    if (!design)
        return design.failure();
    const Eigen::Vector3d reference = platformPose(m_home.outputs);
    return blameChange(assemble(*design, &reference, shared), changes);
}

bool PlanarParallel::parameterApplies(std::string_view name) const
{
    if (name == "load_moment")
        return m_design.legCount() == 3; // a moment only on a platform that turns
    const std::size_t digit = name.find_first_of("123");
    if (digit == std::string_view::npos || name.starts_with("phi"))
        return name != "phi_map" || m_design.legCount() == 3;
    const int leg = name[digit] - '1';
    if (leg >= m_design.legCount())
        return false;
    const LegType type = m_design.legs[std::size_t(leg)].type;
    const std::string_view prefix = name.substr(0, digit);
    if (prefix == "leg" || prefix == "A")
        return true;
    if (prefix == "B")
        return m_design.platform != PlatformType::Point; // a point platform's legs meet at its point
    if (prefix == "r")
        return type == LegType::RRR;
    if (prefix == "l" || prefix == "working")
        return type != LegType::RPR; // a strut has no distal link and one working mode
    if (prefix == "alpha")
        return type == LegType::PRR || type == LegType::PiRR;
    if (prefix == "a" || prefix == "k")
        return type == LegType::PiRR;
    if (prefix == "q")
        return type != LegType::RRR; // a crank's limits are theta_i_min/max
    if (prefix == "theta")
        return type == LegType::RRR;
    // a crank's actuator is a rotary one, the others' linear (actuatorparameters.h)
    if (prefix == "torque_max" || prefix == "rate_max" || prefix == "angle_step" || prefix == "torsion")
        return type == LegType::RRR;
    if (prefix == "force_max" || prefix == "speed_max" || prefix == "step" || prefix == "stiffness")
        return type != LegType::RRR;
    return true;
}

std::string PlanarParallel::assemblyFailure(const Eigen::Vector3d &X) const
{
    const int n = m_design.legCount();
    const std::string where = n == 3
        ? text::format(text::translate("core", "(%1, %2) mm, φ = %3°"), {text::number(X.x()), text::number(X.y()), text::number(X.z() / units::degree)})
        : text::format(text::translate("core", "(%1, %2) mm"), {text::number(X.x()), text::number(X.y())});
    Coordinates q;
    int culprit = 0;
    const planar::Reach r = inverseCheck(X, nullptr, q, culprit);
    if (r == planar::Reach::Yes)
        return {};
    if (culprit < 0)
        return text::format(text::translate("core", "At the platform's position %1 the legs would hold it only in the other assembly mode."), {where});
    const std::string leg = std::to_string(culprit + 1);
    switch (r) {
    case planar::Reach::TooFar:
        return text::format(text::translate("core", "At the platform's position %1 leg %2 cannot reach it: its platform point is too far from its base point A%2 for its links."), {where, leg});
    case planar::Reach::TooNear:
        return text::format(text::translate("core", "At the platform's position %1 leg %2 cannot reach it: its platform point is too near its base point A%2 for its links."), {where, leg});
    case planar::Reach::Range:
        return text::format(text::translate("core", "At the platform's position %1 leg %2 cannot reach it: its input would leave its range."), {where, leg});
    case planar::Reach::Undetermined:
    case planar::Reach::Yes:
        break;
    }
    return text::format(text::translate("core", "At the platform's position %1 the input of leg %2 is undetermined."), {where, leg});
}

PlanarLeg PlanarParallel::fitLeg(PlanarLeg leg, LegType type, const Eigen::Vector2d &P)
{
    constexpr double pi = std::numbers::pi;
    leg.type = type;
    const Eigen::Vector2d r = P - leg.base;
    const double d = std::max(r.norm(), 1.0);
    const double heading = r.norm() > 0.0 ? std::atan2(r.y(), r.x()) : 0.5 * pi;
    switch (type) {
    case LegType::RRR:
        // equal links of 0.7 |AP|: the elbow well bent at P, the crank free to turn
        leg.crank = 0.7 * d;
        leg.link = 0.7 * d;
        leg.crankRange = {-pi, pi};
        break;
    case LegType::PRR:
        // the guide 30° off AP: the link meets it at an angle, the slider at 0.31 or 1.42 |AP|
        leg.alpha = heading - pi / 6.0;
        leg.link = 0.75 * d;
        leg.range = {0.0, 2.0 * d};
        break;
    case LegType::RPR:
        leg.range = {0.5 * d, 1.5 * d};
        break;
    case LegType::PiRR: {
        // crank and link of 0.7 |AP|; the П-joint's base turned so that its crank is at θ = 0
        // (perpendicular to the base) at P, its diagonal free over θ ∈ [−60°, 60°]
        leg.lever = 0.7 * d;
        leg.link = 0.7 * d;
        leg.ratio = 0.4;
        const Eigen::Vector2d u = r / d, left(-u.y(), u.x());
        const double h = std::sqrt(std::max(0.0, leg.lever * leg.lever - 0.25 * d * d));
        const Eigen::Vector2d elbow = leg.base + 0.5 * r + double(leg.working) * h * left;
        const double psi = std::atan2(elbow.y() - leg.base.y(), elbow.x() - leg.base.x());
        leg.alpha = std::remainder(psi - 0.5 * pi, 2.0 * pi);
        const double low = planar::pjointDiagonal(leg, -pi / 3.0), high = planar::pjointDiagonal(leg, pi / 3.0);
        leg.range = {std::min(low, high), std::max(low, high)};
        break;
    }
    }
    leg.guide = planar::direction(leg.alpha);
    return leg;
}

ParameterSet PlanarParallel::restructure(const Pose &pose, PlatformType platform, const std::array<LegType, 3> &types) const
{
    PlanarParallelDesign d = m_design;
    const int was = d.legCount();
    d.platform = platform;
    const int n = d.legCount();
    Eigen::Vector3d X = platformPose(pose.outputs);
    if (n == 2)
        X.z() = 0.0;
    auto &legs = d.legs;
    const double span = std::max({(legs[1].base - legs[0].base).norm(), (X.head<2>() - legs[0].base).norm(), 1.0});
    if (platform == PlatformType::Point) {
        legs[0].platform.setZero();
        legs[1].platform.setZero();
    } else if (platform == PlatformType::Translating && m_design.platform != PlatformType::Translating) {
        const double w = 0.15 * span;
        legs[0].platform = {-w, 0.0};
        legs[1].platform = {w, 0.0};
    } else if (platform == PlatformType::Free && m_design.platform != PlatformType::Free) {
        if ((legs[1].platform - legs[0].platform).norm() < 1e-9 * span) {
            // an equilateral triangle about the platform's point
            const double rho = 0.15 * span;
            legs[0].platform = rho * planar::direction(7.0 * std::numbers::pi / 6.0);
            legs[1].platform = rho * planar::direction(-std::numbers::pi / 6.0);
        }
        const Eigen::Vector2d bar = legs[1].platform - legs[0].platform, middle = 0.5 * (legs[0].platform + legs[1].platform);
        legs[2].platform = middle + 0.866 * Eigen::Vector2d(-bar.y(), bar.x());
    }
    if (n == 3 && was == 2) {
        // the new leg opposite the other two, as long as they are
        const Eigen::Vector2d P3 = planar::platformPoint(legs[2], X);
        Eigen::Vector2d away = X.head<2>() - 0.5 * (legs[0].base + legs[1].base);
        away = away.norm() > 1e-9 * span ? Eigen::Vector2d(away.normalized()) : Eigen::Vector2d(0.0, 1.0);
        const double length = 0.5 * ((planar::platformPoint(legs[0], X) - legs[0].base).norm()
                                     + (planar::platformPoint(legs[1], X) - legs[1].base).norm());
        legs[2].base = P3 + std::max(length, 0.2 * span) * away;
        legs[2].working = 1;
        if (d.assembly < 1)
            d.assembly = 1;
    }
    if (n == 2 && (d.assembly < -1 || d.assembly > 1 || d.assembly == 0))
        d.assembly = 1;
    for (int i = 0; i < n; ++i) {
        PlanarLeg &leg = legs[std::size_t(i)];
        LegType type = types[std::size_t(i)];
        if (platform == PlatformType::Translating && type != LegType::PRR && type != LegType::PiRR)
            type = LegType::PiRR; // a distal parallelogram hangs from a body that does not turn
        const Eigen::Vector2d P = planar::platformPoint(leg, X);
        double q = 0.0;
        const bool reaches = leg.type == type && planar::inverse(leg, P, 0.0, q) == planar::Reach::Yes;
        if (!reaches || (n == 3 && was == 2 && i == 2))
            leg = fitLeg(leg, type, P);
    }
    if (n == 2) {
        // the assembly mode the platform is in at X
        Coordinates q(2);
        for (int i = 0; i < 2; ++i) {
            double value = 0.0;
            planar::inverse(legs[std::size_t(i)], planar::platformPoint(legs[std::size_t(i)], X), 0.0, value);
            q[i] = value;
        }
        const planar::LegCircle c0 = planar::circle(legs[0], q[0]), c1 = planar::circle(legs[1], q[1]);
        const Eigen::Vector2d p = c0.centre - legs[0].platform, o = c1.centre - legs[1].platform;
        const double side = planar::cross(o - p, X.head<2>() - p);
        if (side != 0.0)
            d.assembly = side > 0.0 ? 1 : -1;
    }
    const ParameterSet before = table().values(m_design), after = table().values(d);
    ParameterSet changes;
    for (const auto &[name, value] : after) {
        if (before.at(name) != value)
            changes.emplace(name, value);
    }
    return changes;
}

} // namespace pkm
