// What the mobility analysis's files share: the analysis (mobility.cpp) words its result by
// the verdict of mobilityverdict.cpp (docs/mathematics.md, section 7).
#pragma once

#include "mobility.h"

#include <string>

namespace pkm::mobility {

/// The report's verdict: the counts, the formulas' W against the numerical mobility, the
/// actuation.
std::string verdictOf(const MobilityReport &r);

} // namespace pkm::mobility
