#include "cli/cliworkspace.h"

#include "cli/clicapabilitymap.h"
#include "report/jsonwriter.h"
#include "report/report.h"

#include <cstdint>
#include <optional>

namespace pkm::cli {

using namespace report;

std::string workspaceJson(const PreparedDesign &prepared, const CommandWorkspace &computed, int resolution)
{
    const Mechanism &mechanism = *prepared.mechanism;
    const auto &[map, box, modes, areas, united, named, requirements, region, specification, seconds] = computed;
    std::string out;
    JsonWriter json(out, JsonWriter::Style::Pretty);
    json.beginObject();
    json.key("design").string(prepared.origin);
    json.key("mechanism").string(mechanism.kind());
    writeParametersJson(json, mechanism, true);
    // Where an area is known in closed form (the O-X glide's), that is the area, and the
    // grid's count is given beside it as "…_grid", an estimate of it.
    const PlanarWorkspace *planar = mechanism.planarWorkspace();
    const std::vector<ExactArea> exact = planar ? planar->exactAreas() : std::vector<ExactArea> {};
    const auto exactArea = [&](const std::string &key) -> std::optional<double> {
        for (const ExactArea &known : exact)
            if (known.key == key)
                return known.area;
        return std::nullopt;
    };
    const auto writeArea = [&](const std::string &key, double gridArea) {
        const auto known = exactArea(key);
        json.key(key).number(known ? *known : gridArea);
        if (known)
            json.key(key + "_grid").number(gridArea);
    };
    writeArea("area", map.summary.area);
    json.key("bounds");
    json.beginObject(true);
    writeBoxJson(json, box);
    json.endObject();
    writeGridJson(json, map.grid, resolution);
    json.key("reachable_cells").integer(static_cast<std::int64_t>(map.summary.reachableCells));
    for (const auto &[name, area] : named)
        writeArea("area_" + name, area);
    if (!modes.empty())
        json.key("area_union").number(united.unionArea);
    json.key("exact_areas");
    if (exact.empty()) {
        json.null();
    } else {
        json.beginObject(true);
        for (const ExactArea &known : exact)
            json.key(known.key).number(known.area);
        json.endObject();
    }
    // a mechanism carried by an axis (the O-X glide on z): its 3D workspace is the planar
    // one extruded over that axis' travel
    if (const auto travel = carriedTravel(mechanism)) {
        json.key("travel").number(*travel);
        json.key("volume").number(exactArea("area").value_or(map.summary.area) * *travel);
        if (!modes.empty())
            json.key("volume_union").number(united.unionArea * *travel);
    }
    json.key("modes");
    json.beginArray();
    for (const ModeArea &mode : areas) {
        json.beginObject(true);
        for (std::size_t i = 0; i < modes.size(); ++i) {
            if (modes[i]->choices.empty())
                json.key(modes[i]->name).number(mode.values[i]);
            else
                json.key(modes[i]->name).string(modeValueText(*modes[i], mode.values[i]));
        }
        json.key("area").number(mode.area);
        json.key("reachable_cells").integer(static_cast<std::int64_t>(mode.reachableCells));
        json.key("current").boolean(mode.current);
        if (!mode.note.empty())
            json.key("note").string(mode.note);
        json.endObject();
    }
    json.endArray();
    if (!requirements.empty())
        writeSpecificationJson(json, mechanism, requirements, specification, region.summary);
    json.key("seconds").number(seconds);
    json.endObject();
    out += '\n';
    return out;
}

} // namespace pkm::cli
