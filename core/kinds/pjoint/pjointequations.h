#pragma once
/// The П-joint's governing equations at a pose, for the equations panel (core/equations.h).

#include "equations.h"

namespace pkm::pjoint {
/// (2), (3–5), (7), (10), (11), (13), (8), (15), (16–18), μ (fig. 10) and Δθ (fig. 15) with the pose's numbers.
std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose);
} // namespace pkm::pjoint
