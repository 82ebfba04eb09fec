#include "cli/clicapabilitymap.h"

#include "report/numberformat.h"
#include "text.h"

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
                                 std::vector<float> &values, std::vector<float> &margins,
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
    if (quantity != MapQuantity::Specification) {
        const Unit unit = unitOf(mechanism, capability::entryName(quantity));
        for (float &value : values)
            value = static_cast<float>(unit.toDisplay(value));
        summary.min = unit.toDisplay(summary.min);
        summary.max = unit.toDisplay(summary.max);
    }
    return summary;
}

std::string capabilityUnit(const Mechanism &mechanism, MapQuantity quantity)
{
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

} // namespace pkm::cli
