#include "clireport.h"

#include <cmath>
#include <cstddef>

namespace pkm::cli {

namespace {

void writeEntryJson(JsonWriter &json, const ReportEntry &entry, std::span<const double> values)
{
    json.key(entry.name);
    const auto at = [&](int i) { return entry.unit.toDisplay(values[static_cast<std::size_t>(entry.offset + i)]); };
    if (entry.rows * entry.cols == 1) {
        json.number(at(0));
        return;
    }
    json.beginArray(true); // row-major nested arrays, whatever the shape
    for (int r = 0; r < entry.rows; ++r) {
        json.beginArray(true);
        for (int c = 0; c < entry.cols; ++c)
            json.number(at(r * entry.cols + c));
        json.endArray();
    }
    json.endArray();
}

void writeGroupJson(JsonWriter &json, const ReportLayout &layout, ReportGroup group, std::span<const double> values,
    const std::vector<ReportText> &text)
{
    json.key(reportGroupKey(group));
    json.beginObject();
    for (const ReportEntry &entry : layout.entries) {
        if (entry.group == group)
            writeEntryJson(json, entry, values);
    }
    for (const ReportText &word : text) {
        if (word.group == group)
            json.key(word.name).string(word.text);
    }
    json.endObject();
}

} // namespace

std::string_view reportGroupKey(ReportGroup group)
{
    switch (group) {
    case ReportGroup::Pose:
        return "pose";
    case ReportGroup::Jacobian:
        return "jacobian";
    case ReportGroup::Derived:
        return "derived";
    }
    return "derived";
}

bool allFinite(const ReportEntry &entry, std::span<const double> values)
{
    for (int i = 0; i < entry.rows * entry.cols; ++i) {
        if (!std::isfinite(values[static_cast<std::size_t>(entry.offset + i)]))
            return false;
    }
    return true;
}

double parameterDisplayValue(const ParameterSet &values, const ParameterInfo &info)
{
    const auto it = values.find(info.name);
    return it != values.end() ? info.unit.toDisplay(it->second) : std::nan("");
}

void writeParametersJson(JsonWriter &json, const Mechanism &mechanism, bool inlined)
{
    const ParameterSet values = mechanism.parameters();
    json.key("parameters");
    json.beginObject(inlined);
    for (const ParameterInfo &info : mechanism.parameterInfo())
        json.key(info.name).number(parameterDisplayValue(values, info));
    json.endObject();
}

void writeReportJson(JsonWriter &json, const ReportLayout &layout, std::span<const double> values,
    const Singularity &singularity, const std::vector<ReportText> &text)
{
    for (ReportGroup group : groupsBeforeSingularity)
        writeGroupJson(json, layout, group, values, text);
    json.key("singularity");
    json.beginObject();
    json.key("type").string(singularityName(singularity.type));
    json.key("margin").number(singularity.margin);
    json.key("undefined");
    json.beginArray(true);
    for (const ReportEntry &entry : layout.entries) {
        if (!allFinite(entry, values))
            json.string(entry.name);
    }
    json.endArray();
    json.endObject();
    for (ReportGroup group : groupsAfterSingularity)
        writeGroupJson(json, layout, group, values, text);
}

} // namespace pkm::cli
