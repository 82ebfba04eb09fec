#include "report/sweeprowformatter.h"

#include "report/report.h"
#include "report/jsonwriter.h"
#include "report/numberformat.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>
#include <cstring>
#include <set>
#include <string_view>

namespace pkm::report {

SweepRowFormatter::SweepRowFormatter(const Mechanism &mechanism, bool withParameters)
    : m_layout(mechanism.reportLayout())
    , m_actuators(capability::actuatorsOf(mechanism))
    , m_capabilityLayout(capability::layoutFor(m_actuators))
    , m_withParameters(withParameters)
{
    if (withParameters) {
        for (const ParameterInfo &info : mechanism.parameterInfo())
            m_parameters.push_back(&info);
    }
    std::set<std::string, std::less<>> used;
    for (const ParameterInfo *info : m_parameters)
        used.insert(info->name);
    // a group of the mechanism's layout, or (nullopt) the capability group, after it in the buffer
    const auto addEntries = [&](std::optional<ReportGroup> group) {
        const ReportLayout *from = group ? &m_layout : m_capabilityLayout;
        const int base = group ? 0 : m_layout.size;
        if (!from)
            return;
        for (const ReportEntry &entry : from->entries) {
            if (group && entry.group != *group)
                continue;
            const std::string prefix = group ? std::string(reportGroupKey(*group)) : std::string("capability");
            // Names are unique within a layout; a clash with a parameter or another group's
            // name gets the group prefix (a parameter stiffness and the capability's).
            const std::string name = used.count(entry.name) ? prefix + "." + entry.name : entry.name;
            used.insert(name);
            const bool scalar = entry.rows * entry.cols == 1;
            for (int r = 0; r < entry.rows; ++r) {
                for (int c = 0; c < entry.cols; ++c) {
                    m_columns.push_back({Column::Value, base + entry.offset + r * entry.cols + c, entry.unit,
                        scalar ? name : name + "[" + std::to_string(r) + "][" + std::to_string(c) + "]"});
                }
            }
        }
    };
    for (ReportGroup group : groupsBeforeSingularity)
        addEntries(group);
    m_columns.push_back({Column::SingularityType, 0, units::none, "singularity"});
    m_columns.push_back({Column::SingularityMargin, 0, units::none, "singularity_margin"});
    for (ReportGroup group : groupsAfterSingularity)
        addEntries(group);
    addEntries(std::nullopt);
    m_lastText.resize(m_columns.size());
}

std::optional<capability::Actuators> SweepRowFormatter::actuatorsOf(const Mechanism &mechanism) const
{
    if (!m_capabilityLayout)
        return std::nullopt;
    if (!m_withParameters)
        return m_actuators;
    capability::Actuators actuators = capability::actuatorsOf(mechanism);
    if (capability::layoutFor(actuators) != m_capabilityLayout)
        return std::nullopt; // a parameter step that changes the actuators: the columns stay empty
    return actuators;
}

SingularityType SweepRowFormatter::evaluateCapability(const Mechanism &mechanism, const Pose &pose,
    SingularityType type, std::span<double> values) const
{
    if (!m_capabilityLayout)
        return type;
    const std::span<double> mine = values.subspan(static_cast<std::size_t>(m_layout.size));
    if (const std::optional<capability::Actuators> actuators = actuatorsOf(mechanism))
        return capability::evaluate(mechanism, *actuators, pose, type, mine);
    std::fill(mine.begin(), mine.end(), std::nan(""));
    return type;
}

void SweepRowFormatter::csvHeader(std::string &out) const
{
    for (const ParameterInfo *info : m_parameters)
        out += info->name + ',';
    for (const Column &column : m_columns)
        out += column.name + ',';
    out.back() = '\n';
}

std::size_t SweepRowFormatter::csvRowBound() const
{
    return (m_parameters.size() + m_columns.size()) * static_cast<std::size_t>(maxNumberLength) + 16;
}

char *SweepRowFormatter::csvRow(char *out, const Mechanism &mechanism, const Pose &pose, std::span<double> values) const
{
    const Singularity singularity = mechanism.evaluate(pose, values);
    capability::settleNearSingular(
        m_layout, values, evaluateCapability(mechanism, pose, singularity.type, values), singularity.type);
    if (!m_parameters.empty()) {
        const ParameterSet parameters = mechanism.parameters();
        for (const ParameterInfo *info : m_parameters) {
            const auto it = parameters.find(info->name);
            if (it != parameters.end())
                out = writeNumber(out, info->unit.toDisplay(it->second));
            *out++ = ',';
        }
    }
    const LastText *before = nullptr; // the previous value column's, in this row
    for (std::size_t c = 0; c < m_columns.size(); ++c) {
        const Column &column = m_columns[c];
        if (column.kind == Column::Value) {
            const double value = column.unit.toDisplay(values[static_cast<std::size_t>(column.offset)]);
            if (std::isfinite(value)) { // else an empty field
                LastText &last = m_lastText[c];
                const auto bits = std::bit_cast<std::uint64_t>(value);
                if (bits != last.bits) {
                    // the column before often has the same value (force_worst and force_best of
                    // a one-output mechanism)
                    if (before && before->bits == bits)
                        last = *before;
                    else
                        last.length = static_cast<unsigned char>(writeNumber(last.text, value) - last.text);
                    last.bits = bits;
                }
                before = &last;
                std::memcpy(out, last.text, maxNumberLength); // whole, as writeNumber writes words
                out += last.length;
            }
        } else if (column.kind == Column::SingularityType) {
            const std::string_view name = singularityName(singularity.type);
            std::memcpy(out, name.data(), name.size());
            out += name.size();
        } else if (std::isfinite(singularity.margin)) {
            out = writeNumber(out, singularity.margin);
        }
        *out++ = ',';
    }
    out[-1] = '\n';
    return out;
}

std::vector<std::string> SweepRowFormatter::columnNames() const
{
    std::vector<std::string> names;
    names.reserve(m_parameters.size() + m_columns.size());
    for (const ParameterInfo *info : m_parameters)
        names.push_back(info->name);
    for (const Column &column : m_columns)
        names.push_back(column.name);
    return names;
}

std::size_t SweepRowFormatter::singularityColumn() const
{
    const auto found = std::find_if(
        m_columns.begin(), m_columns.end(), [](const Column &column) { return column.kind == Column::SingularityType; });
    return m_parameters.size() + static_cast<std::size_t>(found - m_columns.begin());
}

void SweepRowFormatter::numberRow(
    double *row, std::size_t stride, const Mechanism &mechanism, const Pose &pose, std::span<double> values) const
{
    const Singularity singularity = mechanism.evaluate(pose, values);
    capability::settleNearSingular(
        m_layout, values, evaluateCapability(mechanism, pose, singularity.type, values), singularity.type);
    const double nan = std::nan("");
    if (!m_parameters.empty()) {
        const ParameterSet parameters = mechanism.parameters();
        for (const ParameterInfo *info : m_parameters) {
            const auto it = parameters.find(info->name);
            *row = it != parameters.end() ? info->unit.toDisplay(it->second) : nan;
            row += stride;
        }
    }
    for (const Column &column : m_columns) {
        double number = nan;
        if (column.kind == Column::Value)
            number = column.unit.toDisplay(values[static_cast<std::size_t>(column.offset)]);
        else if (column.kind == Column::SingularityType)
            number = static_cast<double>(static_cast<int>(singularity.type));
        else
            number = singularity.margin;
        *row = std::isfinite(number) ? number : nan;
        row += stride;
    }
}

void SweepRowFormatter::jsonRow(
    std::string &out, std::int64_t index, const Mechanism &mechanism, const Pose &pose, std::span<double> values) const
{
    const Singularity singularity = mechanism.evaluate(pose, values);
    const SingularityType delivered = evaluateCapability(mechanism, pose, singularity.type, values);
    capability::settleNearSingular(m_layout, values, delivered, singularity.type);
    if (index > 0)
        out += ",\n";
    JsonWriter json(out, JsonWriter::Style::Compact);
    json.beginObject();
    if (!m_parameters.empty())
        writeParametersJson(json, mechanism, true);
    writeReportJson(json, m_layout, values, singularity, {}, delivered);
    if (m_capabilityLayout) {
        // the group as eval writes it, polygons included (a row without actuators has none)
        CapabilityReport group;
        group.layout = m_capabilityLayout;
        group.type = delivered;
        group.kindType = singularity.type;
        const auto mine = values.subspan(static_cast<std::size_t>(m_layout.size));
        group.values.assign(mine.begin(), mine.end());
        if (const std::optional<capability::Actuators> actuators = actuatorsOf(mechanism)) {
            group.hasPolygons = hasCapabilityPolygons(*actuators);
            if (group.hasPolygons)
                group.polygons = capability::polygonsAt(mechanism, *actuators, pose, singularity.type);
        }
        writeCapabilityJson(json, group);
    }
    json.endObject();
}

} // namespace pkm::report
