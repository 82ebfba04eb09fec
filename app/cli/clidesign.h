#pragma once
/// The design a `pkm` command works on: a preset or a design file, with the --set parameters
/// applied and the --set pose variables solved.

#include "cli/cliarguments.h"
#include "document/designfile.h"
#include "mechanism.h"

#include <string>
#include <string_view>
#include <vector>

namespace pkm::cli {

struct PreparedDesign {
    std::string origin; ///< the DESIGN argument
    Design design; ///< as loaded
    MechanismPtr mechanism; ///< with the --set parameters
    Pose pose;
    std::vector<Setting> poseSets; ///< the --set values naming pose variables, in order
    std::string note; ///< why the stored pose was given up, if it was
};

/// Loads `origin` (a preset id or a .pkm.json file) and applies `sets` in order: parameters
/// first, then the pose variables — outputs by inverse kinematics, actuated inputs by direct
/// kinematics; giving both kinds is an error. Without pose variables the stored pose is kept,
/// re-solved from its outputs when a parameter changed (the home pose, with a note, if that
/// fails). The failure names the --set argument of the culprit.
Result<PreparedDesign> prepareDesign(const std::string &origin, const std::vector<Setting> &sets);

/// `origin` (a preset id or a .pkm.json file) as it is stored.
Result<PreparedDesign> loadDesign(const std::string &origin);
/// `prepared` with `sets` applied as prepareDesign() applies them; the pose variables given
/// before (poseSets) are replaced by those of `sets`.
Result<PreparedDesign> applySettings(PreparedDesign prepared, const std::vector<Setting> &sets);

/// Solves the pose variables given by --set on `mechanism`, starting from `current`; the
/// failure names the --set argument of the culprit.
Result<Pose> solvePoseSets(const Mechanism &mechanism, const Pose &current, const std::vector<Setting> &poseSets);


/// The failure for a NAME (of --set or --var) that is neither a parameter nor a pose variable.
Failure unknownSetName(
    const Mechanism &mechanism, const std::string &context, const std::string &name, const std::string &origin);

} // namespace pkm::cli
