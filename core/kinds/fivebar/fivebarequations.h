#pragma once
/// The five-bar's governing equations at a pose, for the equations panel (core/equations.h).

#include "equations.h"

namespace pkm::fivebar {
/// The Jacobians' entries and determinants, the transmission angle and the margins with the
/// pose's numbers.
std::vector<Equation> equations(const Mechanism &mechanism, const Pose &pose);
} // namespace pkm::fivebar
