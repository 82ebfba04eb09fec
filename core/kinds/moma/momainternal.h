// Helpers that MOMA's files share: the kinematics and design checks (moma.cpp), the analysis
// (momaanalysis.cpp) and the drawing (momascene.cpp) all name the legs and take the planar
// cross product.
#pragma once

#include <Eigen/Core>

#include <string>

namespace pkm::moma {

inline std::string legName(int leg)
{
    return leg == 0 ? "1" : "2";
}

/// The leg's number as a symbol's subscript: "₁" in "l₁", "p₁", "S₁", as the panels write them.
inline std::string legSubscript(int leg)
{
    return leg == 0 ? "₁" : "₂";
}

inline double cross(const Eigen::Vector2d &u, const Eigen::Vector2d &v)
{
    return u.x() * v.y() - u.y() * v.x();
}

} // namespace pkm::moma
