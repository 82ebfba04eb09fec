#pragma once
/// MOMA's governing equations at a pose, for the equations panel (core/equations.h).

#include "equations.h"

namespace pkm::moma {
/// (7–9) per leg, the direct kinematics (10–12) as the program solves it, (18), (20), (21).
std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose);
} // namespace pkm::moma
