// `pkm list` and `pkm show`: the presets and kinds, and a design's parameters, variables and
// modes, as text for a person or JSON for a script (docs/cli.md). Split from cli.cpp, which
// keeps eval and the dispatch.

#include "cli/clishow.h"

#include "cli/cli.h"
#include "cli/clidesign.h"
#include "registry.h"
#include "report/jsonwriter.h"
#include "report/report.h"
#include "report/texttable.h"

#include <QString>

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <vector>

namespace pkm::cli {

using namespace report;

namespace {
constexpr std::array<ParameterGroup, 5> parameterGroups = {ParameterGroup::Geometry, ParameterGroup::Range,
    ParameterGroup::Actuator, ParameterGroup::Drawing, ParameterGroup::Mode};

} // namespace

std::string listOutput(bool json)
{
    const QList<PresetInfo> presets = designfile::presets();
    std::string out;
    if (json) {
        JsonWriter writer(out, JsonWriter::Style::Pretty);
        writer.beginObject();
        writer.key("presets");
        writer.beginArray();
        for (const PresetInfo &preset : presets) {
            writer.beginObject(true);
            writer.key("id").string(preset.id.toStdString());
            writer.key("mechanism").string(preset.kind.toStdString());
            writer.key("title").string(preset.title.toStdString());
            writer.endObject();
        }
        writer.endArray();
        writer.key("mechanisms");
        writer.beginArray();
        for (const MechanismKind &kind : mechanismKinds()) {
            writer.beginObject(true);
            writer.key("id").string(kind.id);
            writer.key("title").string(kind.title);
            writer.endObject();
        }
        writer.endArray();
        writer.endObject();
        out += '\n';
        return out;
    }
    TextTable table({false, false, false}, "");
    table.cells({"ID", "MECHANISM", "TITLE"});
    for (const PresetInfo &preset : presets)
        table.cells({preset.id.toStdString(), preset.kind.toStdString(), preset.title.toStdString()});
    table.render(out);
    return out;
}

std::string showJson(const PreparedDesign &prepared)
{
    const Mechanism &mechanism = *prepared.mechanism;
    const ParameterSet values = mechanism.parameters();
    std::string out;
    JsonWriter json(out, JsonWriter::Style::Pretty);
    json.beginObject();
    json.key("design").string(prepared.origin);
    json.key("title").string(prepared.design.title.toStdString());
    json.key("description").string(prepared.design.description.toStdString());
    json.key("mechanism").string(mechanism.kind());
    json.key("mechanism_title").string(kindTitle(mechanism.kind()));

    json.key("parameters");
    json.beginObject();
    for (const ParameterInfo &info : mechanism.parameterInfo()) {
        json.key(info.name);
        json.beginObject(true);
        json.key("value").number(parameterDisplayValue(values, info));
        json.key("unit").string(info.unit.symbol);
        json.key("min").number(info.unit.toDisplay(info.domain.min)); // ±∞ → null: unbounded
        json.key("max").number(info.unit.toDisplay(info.domain.max));
        json.key("min_open").boolean(info.openMin);
        json.key("max_open").boolean(info.openMax);
        json.key("stored").boolean(info.stored);
        json.key("group").string(parameterGroupKey(info.group));
        json.key("symbol").string(info.symbol);
        json.key("label").string(info.label);
        json.key("decimals").integer(info.decimals);
        json.endObject();
    }
    json.endObject();

    json.key("variables");
    json.beginObject();
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableInfo &info = variables[i];
        const Interval range = mechanism.variableRange(static_cast<int>(i));
        json.key(info.name);
        json.beginObject(true);
        json.key("value").number(info.unit.toDisplay(mechanism.variableValue(prepared.pose, static_cast<int>(i))));
        json.key("unit").string(info.unit.symbol);
        json.key("min").number(info.unit.toDisplay(range.min));
        json.key("max").number(info.unit.toDisplay(range.max));
        json.key("actuated").boolean(info.actuated);
        json.key("symbol").string(info.symbol);
        json.key("label").string(info.label);
        json.endObject();
    }
    json.endObject();

    json.key("quantities");
    json.beginObject();
    for (const ReportEntry &entry : mechanism.reportLayout().entries) {
        json.key(entry.name);
        json.beginObject(true);
        json.key("group").string(reportGroupKey(entry.group));
        json.key("unit").string(entry.unit.symbol);
        json.key("rows").integer(entry.rows);
        json.key("cols").integer(entry.cols);
        json.key("symbol").string(entry.symbol);
        json.key("label").string(entry.label);
        json.endObject();
    }
    json.endObject();

    json.key("warnings");
    json.beginArray();
    for (const std::string &warning : mechanism.designWarnings())
        json.string(warning);
    json.endArray();
    json.endObject();
    out += '\n';
    return out;
}

std::string showText(const PreparedDesign &prepared)
{
    const Mechanism &mechanism = *prepared.mechanism;
    const ParameterSet values = mechanism.parameters();
    std::string out = designHeading(prepared);
    if (!prepared.design.description.isEmpty())
        out += "About      " + prepared.design.description.toStdString() + '\n';
    out += '\n';

    TextTable table({false, false, true, false, false, false, false});
    table.cells({"NAME", "SYMBOL", "VALUE", "UNIT", "ALLOWED", "KIND", "LABEL"});
    for (ParameterGroup group : parameterGroups) {
        bool headed = false;
        for (const ParameterInfo &info : mechanism.parameterInfo()) {
            if (info.group != group)
                continue;
            if (!headed) {
                std::string title(parameterGroupKey(group));
                title.front() = static_cast<char>(title.front() - 'a' + 'A');
                table.heading(title + " parameters");
            }
            headed = true;
            table.cells({info.name, info.symbol, fixedText(parameterDisplayValue(values, info), info.decimals),
                std::string(info.unit.symbol),
                rangeText(info.unit.toDisplay(info.domain.min), info.unit.toDisplay(info.domain.max), info.openMin,
                    info.openMax),
                info.stored ? "stored" : "derived", info.label});
        }
    }
    table.heading("Pose variables");
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableInfo &info = variables[i];
        const int index = static_cast<int>(i);
        const Interval range = mechanism.variableRange(index);
        table.cells({info.name, info.symbol,
            fixedText(info.unit.toDisplay(mechanism.variableValue(prepared.pose, index)), info.decimals),
            std::string(info.unit.symbol),
            rangeText(info.unit.toDisplay(range.min), info.unit.toDisplay(range.max), false, false,
                std::max(info.decimals, 3)),
            info.actuated ? "input" : "output", info.label});
    }
    table.render(out);

    out += "\nQuantities of eval and sweep\n";
    TextTable quantities({false, false, false, false, false});
    for (const ReportEntry &entry : mechanism.reportLayout().entries) {
        const std::string shape = entry.rows * entry.cols == 1
            ? std::string()
            : std::to_string(entry.rows) + "×" + std::to_string(entry.cols);
        quantities.cells({entry.name, entry.symbol, std::string(entry.unit.symbol),
            std::string(reportGroupKey(entry.group)) + (shape.empty() ? "" : " " + shape), entry.label});
    }
    quantities.render(out);

    out += "\nWarnings\n";
    const std::vector<std::string> warnings = mechanism.designWarnings();
    for (const std::string &warning : warnings)
        out += "  " + warning + '\n';
    if (warnings.empty())
        out += "  none\n";
    return out;
}

/// The outputs of `pose` in display units, in the order of the variables.
} // namespace pkm::cli
