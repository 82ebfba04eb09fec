#include "cli/clicapabilitymap.h"

#include "cli/cliarguments.h"
#include "report/numberformat.h"
#include "text.h"
#include "tolerance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pkm::cli {

using namespace report;

namespace {

const ReportEntry *entryOf(const Mechanism &mechanism, std::string_view name)
{
    const ReportLayout *layout = capability::layoutFor(capability::actuatorsOf(mechanism));
    return layout ? layout->find(name) : nullptr;
}

Unit unitOf(const Mechanism &mechanism, std::string_view name)
{
    const ReportEntry *entry = entryOf(mechanism, name);
    return entry ? entry->unit : units::none;
}

} // namespace

namespace {
struct QuantityName {
    MapQuantity quantity;
    std::string_view key;   ///< --quantity and the JSON's "quantity"
    std::string_view title; ///< the text output's and the picture's
};
constexpr QuantityName quantityNames[] = {
    {MapQuantity::Determinant, "det", "det J"},
    {MapQuantity::Condition, "cond", "condition number of J"},
    {MapQuantity::OrientationRange, "range", "orientation range (°)"},
    {MapQuantity::ForceWorst, "force_worst", "force in the weakest direction"},
    {MapQuantity::SpeedWorst, "speed_worst", "speed in the slowest direction"},
    {MapQuantity::ResolutionWorst, "resolution_worst", "worst resolution"},
    {MapQuantity::StiffnessWorst, "stiffness_worst", "stiffness in the weakest direction"},
    {MapQuantity::Specification, "spec", "specification region"},
    {MapQuantity::ToleranceWorst, "tolerance", "worst-case error from the tolerances"},
};
} // namespace

std::optional<MapQuantity> quantityOf(std::string_view key)
{
    for (const QuantityName &name : quantityNames)
        if (name.key == key)
            return name.quantity;
    return std::nullopt;
}

std::string_view quantityKey(MapQuantity quantity)
{
    for (const QuantityName &name : quantityNames)
        if (name.quantity == quantity)
            return name.key;
    return "det";
}

std::string quantityTitle(const Mechanism &mechanism, MapQuantity quantity)
{
    std::string title = "det J";
    for (const QuantityName &name : quantityNames)
        if (name.quantity == quantity)
            title = name.title;
    const std::string unit = capabilityUnit(mechanism, quantity);
    return unit.empty() ? title : title + " (" + unit + ")";
}

Result<std::vector<capability::Requirement>> parseRequirements(const Mechanism &mechanism,
                                                               const std::vector<std::string> &texts)
{
    const capability::Actuators actuators = capability::actuatorsOf(mechanism);
    std::vector<capability::Requirement> requirements;
    for (const std::string &text : texts) {
        auto parsed = capability::parseRequirement(text, actuators);
        if (!parsed) {
            Failure failure = parsed.failure();
            failure.message = "--require: " + failure.message; // the message quotes the text
            failure.culprit = "--require";
            return failure;
        }
        requirements.push_back(*parsed);
    }
    return requirements;
}

MapSummary computeCapabilityInto(const Mechanism &mechanism, const Pose &pose, MapQuantity quantity,
                                 std::span<const capability::Requirement> requirements, int resolution,
                                 MapCells &values, MapCells &margins,
                                 capability::SpecificationSummary *specification)
{
    const PlanarWorkspace *workspace = mechanism.planarWorkspace();
    const MapGrid grid = squareGrid(workspace ? workspace->workspaceBounds() : Eigen::AlignedBox2d(), resolution);
    values.assign(grid.cells(), 0.0f);
    margins.assign(grid.cells(), 0.0f);
    const capability::Actuators actuators = capability::actuatorsOf(mechanism);
    MapSummary summary = capability::computeMap(mechanism, actuators, quantity, requirements,
                                                capability::mapStart(mechanism, pose), grid, values, margins,
                                                specification);
    capability::toDisplayUnits(actuators, quantity, values, summary);
    return summary;
}

std::string capabilityUnit(const Mechanism &mechanism, MapQuantity quantity)
{
    if (quantity == MapQuantity::ToleranceWorst)
        return std::string(tolerance::normUnit(mechanism).symbol);
    if (!isCapability(quantity) || quantity == MapQuantity::Specification)
        return {};
    return std::string(unitOf(mechanism, capability::entryName(quantity)).symbol);
}

void writeSpecificationJson(JsonWriter &json, const Mechanism &mechanism,
                            std::span<const capability::Requirement> requirements,
                            const capability::SpecificationSummary &specification, const MapSummary &summary)
{
    json.key("specification");
    json.beginObject();
    json.key("requirements");
    json.beginArray();
    for (std::size_t k = 0; k < requirements.size(); ++k) {
        const capability::Requirement &r = requirements[k];
        const Unit unit = unitOf(mechanism, r.name);
        json.beginObject(true);
        json.key("name").string(r.name);
        json.key("at_least").boolean(r.atLeast);
        json.key("value").number(unit.toDisplay(r.value));
        json.key("unit").string(unit.symbol);
        json.key("failing_cells")
            .integer(static_cast<std::int64_t>(k < specification.failing.size() ? specification.failing[k] : 0));
        json.endObject();
    }
    json.endArray();
    json.key("met_cells").integer(static_cast<std::int64_t>(specification.metCells));
    json.key("area").number(specification.metArea);
    json.key("fraction").number(summary.area > 0 ? specification.metArea / summary.area : 0.0);
    json.endObject();
}

void addSpecificationRows(TextTable &table, const Mechanism &mechanism,
                          std::span<const capability::Requirement> requirements,
                          const capability::SpecificationSummary &specification, const MapSummary &summary)
{
    const capability::Actuators actuators = capability::actuatorsOf(mechanism);
    for (std::size_t k = 0; k < requirements.size(); ++k) {
        const std::size_t failing = k < specification.failing.size() ? specification.failing[k] : 0;
        table.cells({k == 0 ? "required" : "", capability::requirementText(requirements[k], actuators),
                     "fails in " + std::to_string(failing) + " of " + std::to_string(summary.reachableCells)
                         + " cells"});
    }
    const double fraction = summary.area > 0 ? specification.metArea / summary.area : 0.0;
    table.cells({"area met", fixedText(specification.metArea, 1),
                 "mm² (" + fixedText(100.0 * fraction, 1) + " % of the workspace)"});
}

/// The requirements of --require, else those the design file states.
Result<std::vector<capability::Requirement>> requirementsOf(const PreparedDesign &prepared, const Invocation &invocation)
{
    if (invocation.requirements.empty())
        return prepared.design.requirements;
    return parseRequirements(*prepared.mechanism, invocation.requirements);
}

/// Why `pkm map` cannot map `quantity` for this design, if it cannot.
std::optional<Failure> capabilityMapFailure(const PreparedDesign &prepared, const Invocation &invocation,
                                            const PlanarWorkspace &workspace, MapQuantity quantity)
{
    if (quantity == MapQuantity::OrientationRange && !workspace.offers(quantity)) {
        return usageFailure("--quantity",
            "'--quantity range' maps the orientation range of a platform that turns (a 3-DOF planar-parallel "
            "design); the platform of " + prepared.origin + " does not turn.");
    }
    if (isCapability(quantity) && !capability::layoutFor(capability::actuatorsOf(*prepared.mechanism))) {
        return usageFailure("--quantity", "'--quantity " + std::string(quantityKey(quantity)) + "' maps what the "
            "actuators deliver, but " + prepared.origin + " does not declare every actuator's limits.");
    }
    if (quantity == MapQuantity::Specification && invocation.requirements.empty()
        && prepared.design.requirements.empty()) {
        return usageFailure("--quantity", "'--quantity spec' maps where the requirements hold, and "
            + prepared.origin + " states none: give at least one --require NAME>=VALUE (for example "
            "--require force_worst>=50).");
    }
    if (quantity != MapQuantity::ToleranceWorst && !invocation.tolerances.empty()) {
        return usageFailure("--tol", "--tol maps the worst-case error from the tolerances (--quantity tolerance); it "
                                     "does not go with '--quantity " + std::string(quantityKey(quantity)) + "'.");
    }
    if (quantity != MapQuantity::Specification && !invocation.requirements.empty()) {
        return usageFailure("--require", "--require maps where the requirements hold (--quantity spec); it does "
                                         "not go with '--quantity " + std::string(quantityKey(quantity)) + "'.");
    }
    return std::nullopt;
}

} // namespace pkm::cli
