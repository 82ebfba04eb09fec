#pragma once
/// Device-space vector helpers shared by the scene layout, its labels and its renderers.
/// Internal to pkm_drawing.
///
/// Device coordinates have y down; scene angles are counter-clockwise from +x with y up.

#include <QPointF>
#include <QSizeF>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pkm::detail {

inline constexpr double pi = std::numbers::pi;
inline constexpr double degree = pi / 180.0;

inline double length(const QPointF &v)
{
    return std::hypot(v.x(), v.y());
}
inline QPointF unit(const QPointF &v)
{
    const double l = length(v);
    return l > 0.0 ? v / l : QPointF(1.0, 0.0);
}
/// The device direction of a scene angle (rad, counter-clockwise from +x, y up).
inline QPointF deviceDirection(double sceneAngle)
{
    return {std::cos(sceneAngle), -std::sin(sceneAngle)};
}
/// The scene angle of a device direction.
inline double sceneAngle(const QPointF &deviceVector)
{
    return std::atan2(-deviceVector.y(), deviceVector.x());
}
inline double dot(const QPointF &a, const QPointF &b)
{
    return a.x() * b.x() + a.y() * b.y();
}
/// How far `p` lies from the segment from `a` to `b`.
inline double distanceToSegment(const QPointF &p, const QPointF &a, const QPointF &b)
{
    const QPointF d = b - a;
    const double squared = dot(d, d);
    const double t = squared > 0.0 ? std::clamp(dot(p - a, d) / squared, 0.0, 1.0) : 0.0;
    return length(p - (a + t * d));
}
/// Left-hand normal as seen on screen (y down): turns +x into −y (up).
inline QPointF screenLeft(const QPointF &u)
{
    return {u.y(), -u.x()};
}

/// Half the extent of a w × h box, centred on the origin, along unit direction `u`: how far
/// the box's centre must sit from a point for the box to just touch it.
inline double support(const QPointF &u, const QSizeF &size)
{
    return 0.5 * (std::abs(u.x()) * size.width() + std::abs(u.y()) * size.height());
}

/// Text direction that is never upside down, degrees in (−90, 90].
inline double readableRotation(const QPointF &direction)
{
    double rotation = std::atan2(direction.y(), direction.x()) / pi * 180.0;
    if (rotation > 90.0)
        rotation -= 180.0;
    else if (rotation <= -90.0)
        rotation += 180.0;
    return rotation;
}

} // namespace pkm::detail
