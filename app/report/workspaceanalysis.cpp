// The workspace of a planar design as numbers: its map on a square grid, the box of the
// reachable cells, the areas of every combination of its mode parameters and the union of
// their regions. Shared by `pkm workspace`/`pkm map` and the parameter sheet.

#include "report/workspaceanalysis.h"

#include "report/numberformat.h"

#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace pkm::report {

namespace {
/// At most 2^8 combinations of mode parameters are enumerated.
constexpr std::size_t maxModeParameters = 8;
/// The condition number at the top of the colour scale of a condition map.
constexpr double conditionColourLimit = 100.0;
/// The percentile of |det J| at the ends of the colour scale of a det map.
constexpr double determinantColourPercentile = 0.95; // the GUI's map's, see its colour limits

bool reachable(float value)
{
    return reachableCell(value);
}

/// `buffer` resized to `count` cells, not zeroed (computeMap() writes every one; the
/// threads that compute the rows also fault their pages in), its pages 2 MB huge pages where
/// the kernel allows them (madvise; transparent huge pages in "madvise" mode, Debian's
/// default): a 3000² map is 36 MB, and on a virtual machine its 9000 faults of 4 KB pages cost
/// more than the map itself (170 ms against 7 ms for the Python module's call).
void sizedCells(MapCells &buffer, std::size_t count)
{
    if (buffer.capacity() < count) {
        MapCells().swap(buffer);
        buffer.reserve(count); // allocated, not yet touched
#ifdef MADV_HUGEPAGE
        constexpr std::uintptr_t huge = std::uintptr_t(2) << 20;
        const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(buffer.data()) + huge - 1) & ~(huge - 1);
        const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(buffer.data() + count) & ~(huge - 1);
        if (end > begin)
            madvise(reinterpret_cast<void *>(begin), end - begin, MADV_HUGEPAGE); // a hint: failure is harmless
#endif
    }
    buffer.resize(count);
}
} // namespace

/// The map of `workspace` over squareGrid(its bounds, resolution); `values` is reused.
MapSummary computeInto(const PlanarWorkspace &workspace, MapQuantity quantity, int resolution,
    MapCells &values, MapCells *margins)
{
    const MapGrid grid = squareGrid(workspace.workspaceBounds(), resolution);
    sizedCells(values, grid.cells());
    if (margins)
        sizedCells(*margins, grid.cells());
    return computeMap(workspace, quantity, grid, values, margins ? std::span<float>(*margins) : std::span<float>());
}

/// The box of the reachable cells (their edges, mm); empty when no cell is reachable.
Eigen::AlignedBox2d reachableBounds(const MapGrid &grid, std::span<const float> values)
{
    int cMin = grid.columns, cMax = -1, rMin = grid.rows, rMax = -1;
    for (int r = 0; r < grid.rows; ++r) {
        const auto ends = reachableEnds(values.subspan(static_cast<std::size_t>(r) * static_cast<std::size_t>(grid.columns),
                                                       static_cast<std::size_t>(grid.columns)));
        if (!ends)
            continue;
        const auto [first, last] = *ends;
        cMin = std::min(cMin, first);
        cMax = std::max(cMax, last);
        rMin = std::min(rMin, r);
        rMax = std::max(rMax, r);
    }
    Eigen::AlignedBox2d box; // empty
    if (cMax < 0)
        return box;
    const Eigen::Vector2d origin = grid.bounds.min();
    box.extend(origin + Eigen::Vector2d(cMin * grid.dx(), rMin * grid.dy()));
    box.extend(origin + Eigen::Vector2d((cMax + 1) * grid.dx(), (rMax + 1) * grid.dy()));
    return box;
}

// -- modes ---------------------------------------------------------------------------------

/// The ±1 mode parameters of a design: working and assembly modes (MOMA's branch1, branch2,
/// assembly), not the 0/1 switches.
std::vector<const ParameterInfo *> modeParameters(const Mechanism &mechanism)
{
    std::vector<const ParameterInfo *> modes;
    for (const ParameterInfo &info : mechanism.parameterInfo()) {
        if (info.group == ParameterGroup::Mode && info.domain.min == -1.0 && info.domain.max == 1.0
            && modes.size() < maxModeParameters)
            modes.push_back(&info);
    }
    return modes;
}

namespace {
/// "+1", "-1"
std::string signText(double value)
{
    std::string text(value > 0 ? "+" : "");
    text += numberText(value);
    return text;
}
} // namespace

/// A mode value as the user names it: its choice name ("X") where the parameter has names,
/// else "+1" or "-1".
std::string modeValueText(const ParameterInfo &info, double value)
{
    for (const auto &[name, choice] : info.choices) {
        if (choice == value)
            return name;
    }
    return signText(value);
}

/// "branch1 = -1, branch2 = -1, assembly = +1"; empty without mode parameters.
std::string modeText(const std::vector<const ParameterInfo *> &modes, const ParameterSet &parameters)
{
    std::string text;
    for (const ParameterInfo *info : modes) {
        const auto it = parameters.find(info->name);
        if (it == parameters.end())
            continue;
        text.append(text.empty() ? "" : ", ").append(info->name).append(" = ");
        text.append(modeValueText(*info, info->unit.toDisplay(it->second)));
    }
    return text;
}

/// Every combination of the mode parameters, the first varying slowest, −1 before +1; the
/// current one is `current` (its area is not computed again).
std::vector<ModeArea> modeAreas(const Mechanism &mechanism, const std::vector<const ParameterInfo *> &modes,
    const MapSummary &current, int resolution, MapCells &buffer)
{
    std::vector<ModeArea> areas;
    if (modes.empty())
        return areas;
    const ParameterSet parameters = mechanism.parameters();
    const std::size_t count = std::size_t {1} << modes.size();
    for (std::size_t combination = 0; combination < count; ++combination) {
        ModeArea mode;
        ParameterSet changes;
        bool isCurrent = true;
        for (std::size_t i = 0; i < modes.size(); ++i) {
            const ParameterInfo &info = *modes[i];
            const bool plus = (combination >> (modes.size() - 1 - i)) & 1u;
            const double value = info.unit.fromDisplay(plus ? 1.0 : -1.0);
            mode.values.push_back(plus ? 1.0 : -1.0);
            changes[info.name] = value;
            const auto it = parameters.find(info.name);
            isCurrent = isCurrent && it != parameters.end() && it->second == value;
        }
        mode.current = isCurrent;
        if (isCurrent) {
            mode.area = current.area;
            mode.reachableCells = current.reachableCells;
        } else if (auto changed = mechanism.withParameters(changes); !changed) {
            mode.note = changed.failure().message;
            mode.empty = changed.failure().kind == FailureKind::Unreachable;
        } else if (const PlanarWorkspace *workspace = (*changed)->planarWorkspace(); !workspace) {
            mode.note = "no planar workspace in this mode.";
        } else {
            const MapSummary summary = computeInto(*workspace, MapQuantity::Determinant, resolution, buffer, nullptr);
            mode.area = summary.area;
            mode.reachableCells = summary.reachableCells;
        }
        areas.push_back(std::move(mode));
    }
    return areas;
}


ModeRegions modeRegions(const Mechanism &mechanism, const std::vector<const ParameterInfo *> &modes, int resolution)
{
    std::vector<MechanismPtr> designs;
    ModeRegions regions;
    const ParameterSet parameters = mechanism.parameters();
    const std::size_t count = std::size_t {1} << modes.size();
    for (std::size_t combination = 0; combination < count; ++combination) {
        ParameterSet changes;
        bool isCurrent = true;
        for (std::size_t i = 0; i < modes.size(); ++i) {
            const bool plus = (combination >> (modes.size() - 1 - i)) & 1u;
            changes[modes[i]->name] = modes[i]->unit.fromDisplay(plus ? 1.0 : -1.0);
            isCurrent = isCurrent && parameters.at(modes[i]->name) == changes[modes[i]->name];
        }
        if (auto changed = mechanism.withParameters(changes); changed && (*changed)->planarWorkspace()) {
            designs.push_back(*changed);
            regions.current.push_back(isCurrent);
        }
    }
    Eigen::AlignedBox2d box;
    for (const MechanismPtr &design : designs)
        box.extend(design->planarWorkspace()->workspaceBounds());
    if (designs.empty() || box.isEmpty())
        return regions;
    regions.grid = squareGrid(box, resolution);
    std::vector<float> values(regions.grid.cells());
    std::vector<char> any(regions.grid.cells(), 0);
    for (const MechanismPtr &design : designs) {
        computeMap(*design->planarWorkspace(), MapQuantity::Determinant, regions.grid, values);
        std::vector<char> reached(values.size(), 0);
        for (std::size_t i = 0; i < values.size(); ++i) {
            reached[i] = reachable(values[i]) ? 1 : 0;
            any[i] = static_cast<char>(any[i] | reached[i]);
        }
        regions.reached.push_back(std::move(reached));
    }
    regions.unionCells = static_cast<std::size_t>(std::count(any.begin(), any.end(), 1));
    regions.unionArea = static_cast<double>(regions.unionCells) * regions.grid.cellArea();
    return regions;
}

/// The travel (mm) of the axis that carries the whole mechanism, if it has one.
std::optional<double> carriedTravel(const Mechanism &mechanism)
{
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        if (variables[i].independent) {
            const Interval range = mechanism.variableRange(static_cast<int>(i));
            return range.max - range.min;
        }
    }
    return std::nullopt;
}

/// For a single mode parameter with named values (the O-X glide's mode): "area_O", "area_X".
std::vector<std::pair<std::string, double>> namedModeAreas(
    const std::vector<const ParameterInfo *> &modes, const std::vector<ModeArea> &areas)
{
    std::vector<std::pair<std::string, double>> named;
    if (modes.size() != 1 || modes.front()->choices.empty())
        return named;
    for (const ModeArea &mode : areas)
        named.emplace_back(modeValueText(*modes.front(), mode.values.front()), mode.area);
    std::sort(named.begin(), named.end());
    return named;
}

double mapColourLimit(std::span<const float> values, MapQuantity quantity)
{
    if (quantity == MapQuantity::Condition)
        return conditionColourLimit;
    if (quantity == MapQuantity::OrientationRange)
        return 360.0; // a full turn, in the degrees the command line maps
    if (quantity == MapQuantity::Specification)
        return 1.0; // met or not
    // det J and what the actuators deliver: clipped at a percentile of the finite magnitudes
    std::vector<float> magnitudes;
    for (float value : values) {
        if (std::isfinite(value))
            magnitudes.push_back(std::abs(value));
    }
    if (magnitudes.empty())
        return 1.0;
    const auto k = static_cast<std::size_t>(determinantColourPercentile * static_cast<double>(magnitudes.size() - 1));
    std::nth_element(magnitudes.begin(), magnitudes.begin() + static_cast<std::ptrdiff_t>(k), magnitudes.end());
    double limit = magnitudes[k];
    if (!(limit > 0.0)) // most cells at 0: fall back to the largest value
        limit = *std::max_element(magnitudes.begin(), magnitudes.end());
    return limit > 0.0 ? limit : 1.0;
}

} // namespace pkm::report
