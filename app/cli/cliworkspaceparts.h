#pragma once
/// What `pkm workspace` and `pkm map` print about their grid (cliworkspaceparts.cpp).

#include "planarworkspace.h"
#include "report/jsonwriter.h"
#include "report/texttable.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pkm::cli {

/// The kinds whose designs have a planar workspace: "moma, …".
std::string planarKinds();
/// x_min … y_max of `box` (NaN for an empty box).
void writeBoxJson(report::JsonWriter &json, const Eigen::AlignedBox2d &box);
/// The "grid" object and "cell_size".
void writeGridJson(report::JsonWriter &json, const MapGrid &grid, int resolution);
/// "[-150.00, 150.00]"
std::string intervalText(double a, double b);
/// The grid's rows of the text table: its size, cell size, bounds and reachable box.
void addGridRows(report::TextTable &table, const MapGrid &grid, int resolution, const Eigen::AlignedBox2d &reachableBox,
                 std::size_t reachableCells);

/// A map as the commands compute it: its grid, summary, values and margins.
struct ComputedMap {
    MapGrid grid;
    MapSummary summary;
    MapCells values;
    MapCells margins;
};

/// Up to 6 significant digits, locale-free ("∞", "undefined"): min and max in the text output.
std::string shortNumber(double value);

/// `pkm map -o FILE.csv`: the header x,y,value,margin and one row per reachable cell, from the
/// bottom row up, written atomically; the failure sentence, or nothing.
std::optional<std::string> saveMapCsv(const std::string &path, const ComputedMap &map);

} // namespace pkm::cli
