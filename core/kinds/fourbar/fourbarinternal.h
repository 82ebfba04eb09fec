// Helpers that the four-bar's files share: the closed forms and the design (fourbar.cpp), the
// kinematics (fourbarkinematics.cpp), the analysis (fourbaranalysis.cpp) and the drawing
// (fourbarscene.cpp) place the joints, wrap the angles and word lengths and angles alike.
#pragma once

#include "fourbar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace pkm::fourbar {

inline constexpr double pi = std::numbers::pi;
inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
/// Samples of the input range for the output range, the home pose and the coupler curve.
inline constexpr int rangeSamples = 720;

inline double cross(const Eigen::Vector2d &u, const Eigen::Vector2d &v)
{
    return u.x() * v.y() - u.y() * v.x();
}

inline Eigen::Vector2d perp(const Eigen::Vector2d &u)
{
    return {-u.y(), u.x()};
}

/// A length for a sentence, up to three decimals.
inline std::string mm(double value)
{
    return text::format(text::translate("core", "%1 mm"), {text::number(value, 3)});
}

/// An angle for a sentence, in degrees.
inline std::string deg(double radians)
{
    return joinText({text::number(radians / units::degree, 3), "°"});
}

/// An angle said to be outside [lo, hi] (rad), with the digits that show why: 360.0001°
/// beside a bound of 360°, not "360°".
inline std::string degOutside(double radians, double lo, double hi)
{
    return joinText({text::numberOutside(radians / units::degree, lo / units::degree, hi / units::degree), "°"});
}

inline double scaleOf(const FourBarDesign &d)
{
    return std::max({d.crank, d.coupler, d.rocker, d.ground});
}

/// C from δ: C = D + CD·(−cos δ, sin δ).
inline Eigen::Vector2d rockerJoint(const FourBarDesign &d, double delta)
{
    return {d.ground - d.rocker * std::cos(delta), d.rocker * std::sin(delta)};
}

inline Eigen::Vector2d crankJoint(const FourBarDesign &d, double alpha)
{
    return {d.crank * std::cos(alpha), d.crank * std::sin(alpha)};
}

/// δ of a rocker joint C, in (−π, π]… up to a turn: π − θ₃.
inline double deltaOf(const FourBarDesign &d, const Eigen::Vector2d &c)
{
    return pi - std::atan2(c.y(), c.x() - d.ground);
}

/// The value of `angle` + 2πk nearest `reference`.
inline double nearestTurn(double angle, double reference)
{
    return angle + 2.0 * pi * std::round((reference - angle) / (2.0 * pi));
}

} // namespace pkm::fourbar
