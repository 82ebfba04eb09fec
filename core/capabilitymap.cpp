#include "capabilitymap.h"

#include "capabilitycell.h"
#include "solvedmap.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace pkm::capability {

namespace {

constexpr float notReached = std::numeric_limits<float>::quiet_NaN();

struct Named {
    MapQuantity quantity;
    std::string_view name;
};
constexpr Named mapped[] = {
    {MapQuantity::ForceWorst, "force_worst"},
    {MapQuantity::SpeedWorst, "speed_worst"},
    {MapQuantity::ResolutionWorst, "resolution_worst"},
    {MapQuantity::StiffnessWorst, "stiffness_worst"},
};

Failure badRequirement(std::string_view text, const char *pattern, std::string_view more = {})
{
    return Failure{FailureKind::InvalidParameter, text::printable(text, 40),
                   text::format(text::translate("core", pattern), {text::printable(text, 80), more})};
}

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

/// The scalar entries a requirement may name, for a message: "force_worst, force_best, …".
std::string scalarNames(const ReportLayout &layout)
{
    std::string names;
    for (const ReportEntry &entry : layout.entries) {
        if (entry.rows * entry.cols != 1)
            continue;
        names += names.empty() ? "" : ", ";
        names += entry.name;
    }
    return names;
}

/// Whether the kind's own map rows give the cells a solve near `near` would: the kind has
/// them, and a platform that turns is held at the angle its map rows take (phi_map).
bool rowsInClosedForm(const Mechanism &mechanism, const Pose &near)
{
    const PlanarWorkspace *closed = mechanism.planarWorkspace();
    if (!closed || !closed->fillsCapabilityRows())
        return false;
    if (mechanism.outputCount() != 3)
        return true;
    const ParameterSet parameters = mechanism.parameters();
    const auto phi = parameters.find("phi_map");
    return phi != parameters.end() && near.outputs.size() >= 3 && near.outputs[2] == phi->second;
}

/// The limits of the quantities a cell needs: the map's own, or one per requirement (the
/// specification); none when a requirement names an entry that no map row gives.
std::vector<CellLimits> neededLimits(const Actuators &actuators, MapQuantity quantity,
                                     std::span<const Requirement> requirements)
{
    std::vector<CellLimits> needed;
    if (quantity != MapQuantity::Specification) {
        needed.push_back(cellLimits(actuators, quantity));
        return needed;
    }
    for (const Requirement &r : requirements) {
        const std::optional<MapQuantity> q = mapQuantity(r.name);
        if (!q)
            return {};
        needed.push_back(cellLimits(actuators, *q));
    }
    return needed;
}

} // namespace

std::string_view entryName(MapQuantity quantity)
{
    for (const Named &n : mapped)
        if (n.quantity == quantity)
            return n.name;
    return {};
}

std::optional<MapQuantity> mapQuantity(std::string_view name)
{
    for (const Named &n : mapped)
        if (n.name == name)
            return n.quantity;
    return std::nullopt;
}

Result<Requirement> parseRequirement(std::string_view text, const Actuators &actuators)
{
    const ReportLayout *layout = layoutFor(actuators);
    if (!layout)
        return badRequirement(text, QT_TRANSLATE_NOOP("core", "The requirement '%1' cannot be checked: this design declares no actuators."));
    // the first comparison sign splits the name from the value
    const std::size_t sign = text.find_first_of("<>");
    if (sign == std::string_view::npos) {
        return badRequirement(text,
            QT_TRANSLATE_NOOP("core", "The requirement '%1' has no comparison: write it as NAME>=VALUE or "
                                      "NAME<=VALUE, for example force_worst>=50."));
    }
    Requirement r;
    r.atLeast = text[sign] == '>';
    const std::size_t valueStart = sign + 1 + (sign + 1 < text.size() && text[sign + 1] == '=' ? 1 : 0);
    const std::string_view name = trimmed(text.substr(0, sign));
    const ReportEntry *entry = layout->find(name);
    if (!entry || entry->rows * entry->cols != 1) {
        return badRequirement(text, QT_TRANSLATE_NOOP("core", "The requirement '%1' names no single capability value; it may name %2."),
                              scalarNames(*layout));
    }
    const std::string_view number = trimmed(text.substr(valueStart));
    double value = 0.0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (number.empty() || error != std::errc() || end != number.data() + number.size() || !std::isfinite(value))
        return badRequirement(text, QT_TRANSLATE_NOOP("core", "The requirement '%1' does not end in a finite number."));
    r.name = std::string(name);
    r.value = entry->unit.fromDisplay(value);
    return r;
}

std::string requirementText(const Requirement &requirement, const Actuators &actuators)
{
    const ReportLayout *layout = layoutFor(actuators);
    const ReportEntry *entry = layout ? layout->find(requirement.name) : nullptr;
    const Unit unit = entry ? entry->unit : units::none;
    std::string out = requirement.name + (requirement.atLeast ? " ≥ " : " ≤ ")
        + text::number(unit.toDisplay(requirement.value), 6);
    if (!unit.symbol.empty()) {
        if (unit.symbol != "°")
            out += ' ';
        out += text::label(unit.symbol);
    }
    return out;
}

bool meets(const Requirement &requirement, const ReportLayout &layout, std::span<const double> values)
{
    const ReportEntry *entry = layout.find(requirement.name);
    if (!entry || std::size_t(entry->offset) >= values.size())
        return false;
    const double v = values[std::size_t(entry->offset)];
    if (std::isnan(v))
        return false;
    return requirement.atLeast ? v >= requirement.value : v <= requirement.value;
}

const ReportEntry *toDisplayUnits(const Actuators &actuators, MapQuantity quantity, std::span<float> values,
                                  MapSummary &summary)
{
    const ReportLayout *layout = layoutFor(actuators);
    const ReportEntry *entry = layout ? layout->find(entryName(quantity)) : nullptr;
    if (!entry)
        return nullptr;
    for (float &value : values)
        value = float(entry->unit.toDisplay(value));
    summary.min = entry->unit.toDisplay(summary.min);
    summary.max = entry->unit.toDisplay(summary.max);
    return entry;
}

Pose mapStart(const Mechanism &mechanism, const Pose &pose)
{
    if (mechanism.outputCount() != 3 || pose.outputs.size() < 3 || !mechanism.parameterApplies("phi_map"))
        return pose;
    const ParameterSet parameters = mechanism.parameters();
    const auto phi = parameters.find("phi_map");
    if (phi == parameters.end())
        return pose;
    Coordinates outputs = pose.outputs;
    outputs[2] = phi->second;
    auto solved = mechanism.solveInverse(outputs, &pose);
    if (solved)
        return *solved;
    Pose start = pose; // not held at (x, y, phi_map): the cells still take φ from it
    start.outputs[2] = phi->second;
    return start;
}

MapSummary computeMap(const Mechanism &mechanism, const Actuators &actuators, MapQuantity quantity,
                      std::span<const Requirement> requirements, const Pose &near, const MapGrid &grid,
                      std::span<float> values, std::span<float> margins, SpecificationSummary *specification,
                      const std::atomic<bool> *cancel, const Progress &progress, int threads)
{
    MapSummary summary;
    summary.grid = grid;
    const ReportLayout *layout = layoutFor(actuators);
    const bool isSpecification = quantity == MapQuantity::Specification;
    const ReportEntry *entry = layout && !isSpecification ? layout->find(entryName(quantity)) : nullptr;
    SpecificationSummary met{0, 0.0, std::vector<std::size_t>(requirements.size(), 0)};
    if (specification)
        *specification = met;
    if (!layout || (!entry && !isSpecification) || grid.columns <= 0 || grid.rows <= 0 || values.size() < grid.cells()
        || mechanism.outputCount() < 2)
        return summary;
    const bool withMargins = margins.size() >= grid.cells();
    const std::size_t columns = std::size_t(grid.columns);
    // The kind's closed-form map says which cells are reachable (a few ns a cell): only those
    // are solved, so an unreachable cell costs no failed solve and the outline is the one
    // every other map of the design has.
    const PlanarWorkspace *closed = mechanism.planarWorkspace();
    // the kind's closed-form rows where it has them: the same cells, tens of times faster
    const std::vector<CellLimits> needed = rowsInClosedForm(mechanism, near)
        ? neededLimits(actuators, quantity, requirements) : std::vector<CellLimits>{};
    const bool closedRows = !needed.empty() || (isSpecification && requirements.empty() && rowsInClosedForm(mechanism, near));
    struct State {
        std::vector<double> report, delivered;
        std::vector<float> open; ///< the closed-form map of the row: NaN where unreachable
        SpecificationSummary met;
        std::vector<float> margins;   ///< the row's margins where the caller wants none
        std::vector<float> rows; ///< per requirement, its quantity over the row
    };
    const auto makeState = [&] {
        return State{std::vector<double>(std::size_t(mechanism.reportLayout().size)),
                     std::vector<double>(std::size_t(layout->size)), std::vector<float>(closed ? columns : 0),
                     SpecificationSummary{0, 0.0, std::vector<std::size_t>(requirements.size(), 0)},
                     std::vector<float>(closedRows ? columns : 0),
                     std::vector<float>(closedRows && isSpecification ? columns * needed.size() : 0)};
    };
    const auto fillClosedRow = [&](int r, solvedmap::Tally &tally, State &state) {
        const std::size_t first = std::size_t(r) * columns;
        const std::span<float> row = values.subspan(first, columns);
        const std::span<float> margin = withMargins ? margins.subspan(first, columns) : std::span<float>(state.margins);
        if (!isSpecification) {
            closed->fillCapabilityRow(needed[0], grid.y(r), grid.x(0), grid.dx(), row, margin);
        } else {
            // the reachable cells first (det J's outline), then each requirement's quantity
            closed->fillMapRow(MapQuantity::Determinant, grid.y(r), grid.x(0), grid.dx(), row, margin);
            for (std::size_t k = 0; k < needed.size(); ++k)
                closed->fillCapabilityRow(needed[k], grid.y(r), grid.x(0), grid.dx(),
                                          std::span<float>(state.rows).subspan(k * columns, columns), margin);
            for (std::size_t c = 0; c < columns; ++c) {
                if (std::isnan(row[c]))
                    continue;
                bool all = true;
                for (std::size_t k = 0; k < needed.size(); ++k) {
                    const Requirement &q = requirements[k];
                    const double v = state.rows[k * columns + c];
                    const bool holds = !std::isnan(v) && (q.atLeast ? v >= q.value : v <= q.value);
                    state.met.failing[k] += !holds;
                    all = all && holds;
                }
                state.met.metCells += all;
                row[c] = all ? 1.0f : 0.0f;
            }
        }
        // the tally with selects only, so that it vectorises as the row did
        constexpr float infinity = std::numeric_limits<float>::infinity();
        std::size_t reached = 0, nearSingular = 0;
        float low = infinity, high = -infinity;
        for (std::size_t c = 0; c < columns; ++c) {
            const float v = row[c];
            const bool reachable = v == v, finite = reachable & (v != infinity);
            reached += reachable;
            nearSingular += reachable & (margin[c] < float(nearSingularMargin));
            low = finite & (v < low) ? v : low;
            high = finite & (v > high) ? v : high;
        }
        tally.reachable += reached;
        tally.nearSingular += nearSingular;
        tally.min = std::min(tally.min, double(low));
        tally.max = std::max(tally.max, double(high));
    };
    const auto fillRow = [&](int r, solvedmap::Tally &tally, State &state) {
        if (closedRows)
            return fillClosedRow(r, tally, state);
        // every cell starts from the given pose (its modes, z and φ): the inverse kinematics is
        // closed form per working mode, so a neighbour is no better a start
        Coordinates outputs = near.outputs;
        if (closed)
            closed->fillMapRow(MapQuantity::Determinant, grid.y(r), grid.x(0), grid.dx(), state.open, {});
        for (std::size_t c = 0; c < columns; ++c) {
            const std::size_t i = std::size_t(r) * columns + c;
            float &cell = values[i];
            outputs[0] = grid.x(int(c));
            outputs[1] = grid.y(r);
            const auto pose = closed && std::isnan(state.open[c]) ? Result<Pose>(Failure{})
                                                                  : mechanism.solveInverse(outputs, &near);
            if (!pose) {
                cell = notReached;
                if (withMargins)
                    margins[i] = notReached;
                continue;
            }
            const Singularity singular = mechanism.evaluate(*pose, state.report);
            std::fill(state.delivered.begin(), state.delivered.end(), std::numeric_limits<double>::quiet_NaN());
            evaluate(mechanism, actuators, *pose, singular.type, state.delivered);
            if (withMargins)
                margins[i] = float(singular.margin);
            tally.nearSingular += singular.margin < nearSingularMargin;
            if (isSpecification) {
                bool all = true;
                for (std::size_t k = 0; k < requirements.size(); ++k) {
                    const bool holds = meets(requirements[k], *layout, state.delivered);
                    state.met.failing[k] += !holds;
                    all = all && holds;
                }
                state.met.metCells += all;
                cell = all ? 1.0f : 0.0f;
            } else {
                // undefined at a combined singularity (0 one way, ∞ the other): NaN would read
                // as unreachable, so such a cell shows as infinite
                const double v = state.delivered[std::size_t(entry->offset)];
                cell = std::isnan(v) ? std::numeric_limits<float>::infinity() : float(v);
            }
            tally.add(cell);
        }
    };
    const auto finish = [&](State &state) { // under solvedmap::run's lock
        met.metCells += state.met.metCells;
        for (std::size_t k = 0; k < met.failing.size(); ++k)
            met.failing[k] += state.met.failing[k];
    };
    summary = solvedmap::run(grid, threads, cancel, progress, makeState, fillRow, finish);
    met.metArea = double(met.metCells) * grid.cellArea();
    if (specification)
        *specification = std::move(met);
    return summary;
}

} // namespace pkm::capability
