#pragma once
/// Small builders of solids that the kinds' 3D models share: a point of the mechanism plane
/// lifted to a depth, a flat bar in a plane z = const and a pin along z. The 3D models of the
/// kinds (kinds/<kind>/…3d.cpp) are made of these and of Solid's own box, cylinder and sphere.

#include "scene3d.h"

#include <string>
#include <utility>

namespace pkm::solids {

inline const Eigen::Vector3d unitX = Eigen::Vector3d::UnitX();
inline const Eigen::Vector3d unitY = Eigen::Vector3d::UnitY();
inline const Eigen::Vector3d unitZ = Eigen::Vector3d::UnitZ();

/// The point p of the mechanism plane at depth z.
inline Eigen::Vector3d at(const Eigen::Vector2d &p, double z)
{
    return {p.x(), p.y(), z};
}

/// A flat bar in the plane z = `z` from p to q, its ends rounded out by half its width.
inline Solid bar(const Eigen::Vector2d &p, const Eigen::Vector2d &q, double z, double width, double thickness,
                 PartRole role, std::string label)
{
    const Eigen::Vector2d u = (q - p).normalized();
    return Solid::box(at(p - 0.5 * width * u, z), at(q + 0.5 * width * u, z), width, thickness, unitZ, role,
                      std::move(label));
}

/// A pin along z through (p, z0…z1).
inline Solid pin(const Eigen::Vector2d &p, double z0, double z1, double radius, std::string label)
{
    return Solid::cylinder(at(p, z0), at(p, z1), radius, PartRole::Joint, std::move(label));
}

} // namespace pkm::solids
