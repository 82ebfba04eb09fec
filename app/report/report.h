#pragma once
/// The quantities of a mechanism as `pkm eval` and `pkm sweep` report them: the JSON keys of
/// the report groups, their order, and the report of one pose as JSON.

#include "capability.h"
#include "capabilityshapes.h"
#include "report/jsonwriter.h"
#include "mechanism.h"
#include "report/texttable.h"

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace pkm::report {

/// "pose", "jacobian", "derived": the JSON key of a report group.
std::string_view reportGroupKey(ReportGroup group);

/// The order of eval's report (docs/cli.md): pose, jacobian, then singularity, then derived.
inline constexpr std::array<ReportGroup, 2> groupsBeforeSingularity = {ReportGroup::Pose, ReportGroup::Jacobian};
inline constexpr std::array<ReportGroup, 1> groupsAfterSingularity = {ReportGroup::Derived};

/// Whether every value of `entry` in the buffer filled by Mechanism::evaluate() is finite.
bool allFinite(const ReportEntry &entry, std::span<const double> values);

/// The value of parameter `info` in `values` (Mechanism::parameters()) in display units; NaN
/// when the set does not hold it.
double parameterDisplayValue(const ParameterSet &values, const ParameterInfo &info);

/// "parameters": every parameter, stored and derived (k), in display units and
/// parameterInfo() order. `inlined`: on one line.
void writeParametersJson(JsonWriter &json, const Mechanism &mechanism, bool inlined);

/// "pose", "jacobian", "singularity", "derived" into the open object. Quantities that are not
/// finite at this pose are null and listed in singularity.undefined, so a script learns why.
/// `text` adds the words of the report (the O-X glide's "mode": "X") to their groups.
/// `settled`: the class the values are settled for (capability::settleNearSingular()); where
/// it is not the pose's own, singularity.reason says why (near a singular pose).
void writeReportJson(JsonWriter &json, const ReportLayout &layout, std::span<const double> values,
    const Singularity &singularity, const std::vector<ReportText> &text = {},
    std::optional<SingularityType> settled = std::nullopt);

/// What the actuators deliver at a pose (core/capability.h): the layout of the "capability"
/// group (nullptr when the mechanism declares no actuators) and its values.
struct CapabilityReport {
    const ReportLayout *layout = nullptr;
    std::vector<double> values;
    /// The exact velocity and force polygons, and whether the mechanism has them
    /// (hasCapabilityPolygons()).
    capability::Shapes polygons;
    bool hasPolygons = false;
    /// The class the values are settled for (capability::deliveryClass()) and the kind's own.
    SingularityType type = SingularityType::None;
    SingularityType kindType = SingularityType::None;
};
/// Evaluates the capability group of `pose`, whose class (Mechanism::evaluate()) is `type`.
CapabilityReport evaluateCapability(const Mechanism &mechanism, const Pose &pose, SingularityType type);
/// Whether these actuators have velocity and force polygons: a platform point moved by two or
/// more of them.
bool hasCapabilityPolygons(const capability::Actuators &actuators);
/// "capability": its values in display units (null where not finite), then, where the report
/// has them, "velocity_polygon" and "force_polygon" (vertices [x, y] in mm/s and N, counter-
/// clockwise; null where unbounded or undefined), then "undefined" and "infinite", the names
/// of the values that are not finite and of those unbounded at this pose (why:
/// singularity.reason), then "singular", the class the values are settled for, and "reason",
/// why it differs from the pose's class (near a singular pose), else null; null when the
/// mechanism declares no actuators.
void writeCapabilityJson(JsonWriter &json, const CapabilityReport &capability);

/// "mobility": the chain of the mechanism at `pose` counted by Chebyshev's and
/// Somov–Malyshev's formulas and ranked (core/mobility.h): moving_links, pairs {P5…P1}, loops,
/// freedoms, chebyshev (null unless planar), somov_malyshev, rank, numerical (F − rank at the
/// pose), finite (near the pose), singular, redundant_constraints, planar_redundant_constraints,
/// idle_freedoms, actuators, locked_freedoms, fully_actuated, chebyshev_fails,
/// somov_malyshev_fails, formula_fails, chain, verdict. Numbers are null when the mechanism
/// describes no chain (the verdict says so).
void writeMobilityJson(JsonWriter &json, const Mechanism &mechanism, const Pose &pose);
/// The same as rows of eval's text report, under the heading "Mobility".
void addMobilityRows(TextTable &table, const Mechanism &mechanism, const Pose &pose);

} // namespace pkm::report
