// Helpers that the five-bar's files share: the design and its home pose (fivebar.cpp), the
// kinematics (fivebarkinematics.cpp), the analysis (fivebaranalysis.cpp) and the drawing
// (fivebarscene.cpp) use the same leg names, angle texts, tolerances and pose vectors.
#pragma once

#include "fivebar.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

namespace pkm::fivebar {

inline constexpr double pi = std::numbers::pi;
inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
/// Relative tolerance of the solvers: circles that touch up to it meet, modes hold up to it.
inline constexpr double solverTolerance = 1e-9;

/// The names of a leg's parts, for parameters and messages.
struct LegText {
    const char *number, *ground, *elbow, *crank, *link, *theta, *working, *thetaMin, *thetaMax;
};
inline constexpr std::array<LegText, 2> legText = {{
    {"1", "A", "B", "AB", "BC", "theta1", "working1", "theta1_min", "theta1_max"},
    {"2", "E", "D", "DE", "CD", "theta4", "working2", "theta4_min", "theta4_max"},
}};

inline double cross(const Eigen::Vector2d &u, const Eigen::Vector2d &v)
{
    return u.x() * v.y() - u.y() * v.x();
}

/// An angle for a message: "12.5°".
inline std::string deg(double radians)
{
    return joinText({text::number(radians / units::degree, 3), "°"});
}

/// An angle said to be outside `range`, with the digits that show why.
inline std::string degOutside(double radians, const Interval &range)
{
    return joinText({text::numberOutside(radians / units::degree, range.min / units::degree, range.max / units::degree), "°"});
}

inline std::string rangeText(const Interval &range)
{
    return text::format(text::translate("core", "[%1, %2]"), {deg(range.min), deg(range.max)});
}

inline double scaleOf(const FiveBarDesign &d)
{
    return std::max({d.ground, d.crank[0], d.crank[1], d.link[0], d.link[1]});
}

/// Of the angles raw + 2πk inside `range` (up to `tolerance`, rad), the one nearest
/// `reference`, clamped into the range; NaN when there is none.
inline double representative(double raw, const Interval &range, double reference, double tolerance)
{
    double chosen = nan;
    for (int k = -2; k <= 2; ++k) {
        const double theta = raw + 2.0 * pi * k;
        const bool nearer = std::isnan(chosen) || std::abs(theta - reference) < std::abs(chosen - reference);
        if (range.contains(theta, tolerance) && nearer)
            chosen = theta;
    }
    return std::isnan(chosen) ? nan : range.clamp(chosen);
}

/// The vectors of a pose the Jacobians and the margins are made of.
struct Vectors {
    std::array<Eigen::Vector2d, 2> crank; ///< P_i − G_i
    std::array<Eigen::Vector2d, 2> link;  ///< C − P_i (the rows of J_x)
    std::array<double, 2> k{};            ///< J_q's diagonal
    double detJx = 0.0;                   ///< (C − B)×(C − D)
};

inline Vectors vectorsOf(const FiveBarDesign &d, const std::array<Eigen::Vector2d, 2> &elbows, const Eigen::Vector2d &C)
{
    Vectors v;
    for (int leg = 0; leg < 2; ++leg) {
        v.crank[leg] = elbows[leg] - fivebar::groundJoint(d, leg);
        v.link[leg] = C - elbows[leg];
        v.k[leg] = cross(v.crank[leg], v.link[leg]);
    }
    v.detJx = cross(v.link[0], v.link[1]);
    return v;
}

inline Vectors vectorsOf(const FiveBarDesign &d, const Pose &pose)
{
    return vectorsOf(d, {fivebar::elbow(d, 0, pose.inputs[0]), fivebar::elbow(d, 1, pose.inputs[1])},
                     pose.outputs.head<2>());
}

/// The scale-free margins of a pose: the smaller |sin| of the elbow angles, |k_i|/(a_i·b_i)
/// (inverse), and the |sin| of the angle between the distal links (direct).
inline std::pair<double, double> marginsOf(const FiveBarDesign &d, const Vectors &v)
{
    const double leg1 = std::abs(v.k[0]) / (d.crank[0] * d.link[0]), leg2 = std::abs(v.k[1]) / (d.crank[1] * d.link[1]);
    return {std::min(leg1, leg2), std::abs(v.detJx) / (d.link[0] * d.link[1])};
}

} // namespace pkm::fivebar
