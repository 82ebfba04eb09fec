#pragma once
/// The planar parallel mechanism's governing equations at a pose, for the equations panel
/// (core/equations.h).

#include "equations.h"

namespace pkm::planar {
/// Per leg its circle constraint (for the leg type in use), the П-joint's (3–5) and (7) for a
/// П̲RR leg and its J_q entry; then det J, with the pose's numbers.
std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose);
} // namespace pkm::planar
