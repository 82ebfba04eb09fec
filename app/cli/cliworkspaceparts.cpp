// The pieces `pkm workspace` and `pkm map` print about their grid, in JSON and in text, and
// the whole JSON of `pkm workspace` (cliworkspace.cpp runs the commands).

#include "cli/cliworkspaceparts.h"

#include "cli/clicapabilitymap.h"
#include "cli/cliworkspace.h"
#include "report/report.h"

#include "registry.h"
#include "document/savefile.h"
#include "report/numberformat.h"

#include <charconv>
#include <cstdint>
#include <optional>
#include <cmath>
#include <limits>

namespace pkm::cli {

using namespace report;

namespace {
/// A float map value as the shortest text that reads back as the same float ("0.1", not
/// "0.100000001490116"), locale-free.
void appendFloat(std::string &out, float value)
{
    if (value == 0.0f)
        value = 0.0f;
    char buffer[32];
    out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}
} // namespace

std::string shortNumber(double value)
{
    if (std::isinf(value))
        return value > 0 ? "∞" : "-∞";
    if (std::isnan(value))
        return "undefined";
    if (value == 0.0)
        value = 0.0; // no "-0"
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 6).ptr;
    return std::string(buffer, end);
}


std::optional<std::string> saveMapCsv(const std::string &path, const ComputedMap &map)
{
    return files::saveFile(path, [&](const files::ChunkWriter &write) {
        constexpr std::size_t flushBytes = std::size_t {1} << 20;
        std::string text = "x,y,value,margin\n";
        text.reserve(flushBytes + 256);
        const MapGrid &grid = map.grid;
        const std::size_t columns = static_cast<std::size_t>(grid.columns);
        for (int r = 0; r < grid.rows; ++r) {
            const double y = cleanCoordinate(grid.y(r));
            for (int c = 0; c < grid.columns; ++c) {
                const std::size_t i = static_cast<std::size_t>(r) * columns + static_cast<std::size_t>(c);
                const float value = map.values[i];
                if (std::isnan(value)) // unreachable
                    continue;
                appendNumber(text, cleanCoordinate(grid.x(c)));
                text += ',';
                appendNumber(text, y);
                text += ',';
                if (std::isfinite(value)) // ±∞ at a singularity: an empty field, as in sweep
                    appendFloat(text, value);
                text += ',';
                if (i < map.margins.size() && std::isfinite(map.margins[i]))
                    appendFloat(text, map.margins[i]);
                text += '\n';
            }
            if (text.size() >= flushBytes) {
                if (!write(text))
                    return false;
                text.clear();
            }
        }
        return write(text);
    });
}


/// The kinds whose designs have a planar workspace: "moma".
std::string planarKinds()
{
    std::string kinds;
    for (const MechanismKind &kind : mechanismKinds()) {
        const auto made = kind.create({});
        if (made && (*made)->planarWorkspace())
            kinds += (kinds.empty() ? "" : ", ") + std::string(kind.id);
    }
    return kinds;
}

void writeBoxJson(JsonWriter &json, const Eigen::AlignedBox2d &box)
{
    const bool empty = box.isEmpty();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    json.key("x_min").number(empty ? nan : cleanCoordinate(box.min().x()));
    json.key("x_max").number(empty ? nan : cleanCoordinate(box.max().x()));
    json.key("y_min").number(empty ? nan : cleanCoordinate(box.min().y()));
    json.key("y_max").number(empty ? nan : cleanCoordinate(box.max().y()));
}

void writeGridJson(JsonWriter &json, const MapGrid &grid, int resolution)
{
    json.key("grid");
    json.beginObject(true);
    json.key("resolution").integer(resolution);
    json.key("columns").integer(grid.columns);
    json.key("rows").integer(grid.rows);
    writeBoxJson(json, grid.bounds);
    json.endObject();
    json.key("cell_size").number(grid.dx());
}

/// "[-150.00, 150.00]"
std::string intervalText(double a, double b)
{
    std::string text("[");
    text += fixedText(cleanCoordinate(a), 2) + ", " + fixedText(cleanCoordinate(b), 2) + "]";
    return text;
}

void addGridRows(TextTable &table, const MapGrid &grid, int resolution, const Eigen::AlignedBox2d &reachableBox,
    std::size_t reachableCells)
{
    table.cells({"grid", std::to_string(grid.columns) + " × " + std::to_string(grid.rows),
        "cells (--grid " + std::to_string(resolution) + ")"});
    table.cells({"cell size", fixedText(grid.dx(), 3), "mm"});
    table.cells({"grid x", intervalText(grid.bounds.min().x(), grid.bounds.max().x()), "mm"});
    table.cells({"grid y", intervalText(grid.bounds.min().y(), grid.bounds.max().y()), "mm"});
    table.cells({"reachable cells", std::to_string(reachableCells), ""});
    if (!reachableBox.isEmpty()) {
        table.cells({"reachable x", intervalText(reachableBox.min().x(), reachableBox.max().x()), "mm"});
        table.cells({"reachable y", intervalText(reachableBox.min().y(), reachableBox.max().y()), "mm"});
    }
}

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
            if (modes[i]->choices.empty() || modes[i]->numberInJson)
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
