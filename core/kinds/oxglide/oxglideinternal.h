// Helpers that the O-X glide's files share: the design's bounds (oxglide.cpp) and the exact
// workspace area (oxglidemaps.cpp) both ask at what height a slice of the workspace closes.
#pragma once

#include <cmath>

namespace pkm::oxglide {

/// The height below which a slice of half-width-loss `w` exceeds `limit`: y with w(y) = limit.
inline double heightWhereW(double l, double limit)
{
    return limit < l ? std::sqrt(l * l - limit * limit) : 0.0;
}

} // namespace pkm::oxglide
