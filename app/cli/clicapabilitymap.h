#pragma once
/// What `pkm map --quantity force_worst|speed_worst|resolution_worst|stiffness_worst|spec` and
/// `pkm workspace --require NAME>=VALUE` add to the workspace commands: maps of what the
/// actuators deliver and the specification region (core/capabilitymap.h), in display units.

#include "capabilitymap.h"
#include "cli/clidesign.h"
#include "report/jsonwriter.h"
#include "report/texttable.h"

#include <span>
#include <string>
#include <vector>

namespace pkm::cli {

/// The --require texts parsed against the design's actuators; the failure names the first
/// culprit ("--require force_worst>=abc: …").
Result<std::vector<capability::Requirement>> parseRequirements(const Mechanism &mechanism,
                                                               const std::vector<std::string> &texts);

/// The capability map (or the specification) over squareGrid(the workspace bounds,
/// resolution), `values` in display units (N, mm/s, mm, N/mm; N·m, °/s, ° for an angular
/// output) and `margins` filled.
MapSummary computeCapabilityInto(const Mechanism &mechanism, const Pose &pose, MapQuantity quantity,
                                 std::span<const capability::Requirement> requirements, int resolution,
                                 std::vector<float> &values, std::vector<float> &margins,
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
