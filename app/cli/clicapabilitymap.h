#pragma once
/// What `pkm map --quantity force_worst|speed_worst|resolution_worst|stiffness_worst|spec` and
/// `pkm workspace --require NAME>=VALUE` add to the workspace commands: maps of what the
/// actuators deliver and the specification region (core/capabilitymap.h), in display units.

#include "capabilitymap.h"
#include "cli/cliarguments.h"
#include "cli/clidesign.h"
#include "report/jsonwriter.h"
#include "report/texttable.h"

#include <optional>
#include <span>
#include <string_view>
#include <string>
#include <vector>

namespace pkm::cli {

/// The map quantity of a --quantity key ("det", "force_worst", "spec"), if it is one: the one
/// list of the keys, for the argument parser and the command.
std::optional<MapQuantity> quantityOf(std::string_view key);
/// The --quantity key of a map quantity.
std::string_view quantityKey(MapQuantity quantity);
/// "det J", "force in the weakest direction (N)": the text output's and the picture's.
std::string quantityTitle(const Mechanism &mechanism, MapQuantity quantity);

/// The requirements of --require, else those the design file states.
Result<std::vector<capability::Requirement>> requirementsOf(const PreparedDesign &prepared, const Invocation &invocation);

/// Why `pkm map` cannot map `quantity` for this design, if it cannot: the orientation range of
/// a platform that does not turn, a capability map without actuators, the specification
/// without requirements, --require beside another quantity.
std::optional<Failure> capabilityMapFailure(const PreparedDesign &prepared, const Invocation &invocation,
                                            const PlanarWorkspace &workspace, MapQuantity quantity);

/// The --require texts parsed against the design's actuators; the failure names the first
/// culprit ("--require force_worst>=abc: …").
Result<std::vector<capability::Requirement>> parseRequirements(const Mechanism &mechanism,
                                                               const std::vector<std::string> &texts);

/// The capability map (or the specification) over squareGrid(the workspace bounds,
/// resolution), `values` in display units (N, mm/s, mm, N/mm; N·m, °/s, ° for an angular
/// output) and `margins` filled.
MapSummary computeCapabilityInto(const Mechanism &mechanism, const Pose &pose, MapQuantity quantity,
                                 std::span<const capability::Requirement> requirements, int resolution,
                                 MapCells &values, MapCells &margins,
                                 capability::SpecificationSummary *specification = nullptr);

/// The display unit of a capability map ("N"), empty for the specification and the others.
std::string capabilityUnit(const Mechanism &mechanism, MapQuantity quantity);

/// "specification": {"requirements": [{"name", "at_least", "value", "unit", "failing_cells"}…],
/// "met_cells", "area", "fraction"} (fraction of the reachable area).
void writeSpecificationJson(report::JsonWriter &json, const Mechanism &mechanism,
                            std::span<const capability::Requirement> requirements,
                            const capability::SpecificationSummary &specification, const MapSummary &summary);

/// The same as rows of the text output.
void addSpecificationRows(report::TextTable &table, const Mechanism &mechanism,
                          std::span<const capability::Requirement> requirements,
                          const capability::SpecificationSummary &specification, const MapSummary &summary);

} // namespace pkm::cli
