#pragma once
/// The mechanisms PKM Studio knows, by kind id. Adding a mechanism means adding one entry here.

#include "equations.h"
#include "mechanism.h"

#include <string_view>
#include <vector>

namespace pkm {

struct MechanismKind {
    std::string_view id;    ///< "pjoint"
    std::string_view title; ///< "Active П-joint": English source, QT_TRANSLATE_NOOP("core", …)
    /// Builds a validated design from named values; missing ones take the kind's defaults,
    /// unknown names are refused.
    Result<MechanismPtr> (*create)(const ParameterSet &parameters);
    /// The kind's governing equations with the numbers of a pose (equations.h), from its own
    /// folder (kinds/<kind>/<kind>equations.cpp); `mechanism` is of this kind.
    std::vector<Equation> (*equations)(const Mechanism &mechanism, const Pose &pose) = nullptr;
};

const std::vector<MechanismKind> &mechanismKinds();
const MechanismKind *findMechanismKind(std::string_view id);
/// Refuses names the kind does not know, then builds the design.
Result<MechanismPtr> createMechanism(std::string_view kind, const ParameterSet &parameters);

} // namespace pkm
