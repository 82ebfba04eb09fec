#pragma once
/// The O-X glide's governing equations at a pose, for the equations panel (core/equations.h).

#include "equations.h"

namespace pkm::oxglide {
/// The planar inverse and direct kinematics of the design's form (the X form's direct
/// kinematics corrected), det J and κ(J) with the pose's numbers.
std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose);
} // namespace pkm::oxglide
