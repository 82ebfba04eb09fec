// The pieces `pkm workspace` and `pkm map` print about their grid, in JSON and in text
// (cliworkspace.cpp runs the commands).

#include "cli/cliworkspaceparts.h"

#include "registry.h"
#include "report/numberformat.h"

#include <limits>

namespace pkm::cli {

using namespace report;

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

} // namespace pkm::cli
