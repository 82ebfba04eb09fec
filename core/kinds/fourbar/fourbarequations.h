#pragma once
/// The four-bar's governing equations at a pose, for the equations panel (core/equations.h).

#include "equations.h"

namespace pkm::fourbar {
/// (3)–(9) with the corrections of docs/mathematics.md, ε₃ and the Jacobians, with the pose's
/// numbers.
std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose);
} // namespace pkm::fourbar
