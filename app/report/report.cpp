#include "report/report.h"

#include "mobility.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>

namespace pkm::report {

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

bool anyInfinite(const ReportEntry &entry, std::span<const double> values)
{
    for (int i = 0; i < entry.rows * entry.cols; ++i) {
        if (std::isinf(values[static_cast<std::size_t>(entry.offset + i)]))
            return true;
    }
    return false;
}

/// Why quantities are null at a singular pose (the JSON's singularity.reason); null: regular.
const char *singularityReason(SingularityType type)
{
    switch (type) {
    case SingularityType::None:
        return nullptr;
    case SingularityType::Inverse:
        return "inverse singularity: J_q is singular, so what divides by det J_q (J, det J, the condition "
               "number) is unbounded";
    case SingularityType::Direct:
        return "direct singularity: J_x is singular, so det J is 0 and what divides by det J_x is unbounded";
    case SingularityType::Combined:
        return "combined singularity: J_q and J_x are both singular; a quantity that is 0 by one and "
               "unbounded by the other is undefined";
    }
    return nullptr;
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
    const Singularity &singularity, const std::vector<ReportText> &text, std::optional<SingularityType> settled)
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
    // of those, the ones that are unbounded at the pose (∞) rather than undefined (0/0)
    json.key("infinite");
    json.beginArray(true);
    for (const ReportEntry &entry : layout.entries) {
        if (anyInfinite(entry, values))
            json.string(entry.name);
    }
    json.endArray();
    json.key("reason");
    const char *reason = singularityReason(singularity.type);
    if (settled && *settled != singularity.type)
        reason = capability::nearSingularReason(*settled, singularity.type);
    if (reason)
        json.string(reason);
    else
        json.null();
    json.endObject();
    for (ReportGroup group : groupsAfterSingularity)
        writeGroupJson(json, layout, group, values, text);
}

CapabilityReport evaluateCapability(const Mechanism &mechanism, const Pose &pose, SingularityType type)
{
    CapabilityReport report;
    const capability::Actuators actuators = capability::actuatorsOf(mechanism);
    report.layout = capability::layoutFor(actuators);
    if (!report.layout)
        return report;
    report.values.assign(static_cast<std::size_t>(report.layout->size), std::nan(""));
    report.kindType = type;
    report.type = capability::evaluate(mechanism, actuators, pose, type, report.values);
    report.hasPolygons = hasCapabilityPolygons(actuators);
    if (report.hasPolygons)
        report.polygons = capability::polygonsAt(mechanism, actuators, pose, type);
    return report;
}

bool hasCapabilityPolygons(const capability::Actuators &actuators)
{
    return actuators.count >= 2 && actuators.outputs >= 2 && !actuators.rotaryOutput;
}

void writeCapabilityJson(JsonWriter &json, const CapabilityReport &capability)
{
    json.key("capability");
    if (!capability.layout) {
        json.null();
        return;
    }
    json.beginObject();
    for (const ReportEntry &entry : capability.layout->entries)
        writeEntryJson(json, entry, capability.values);
    const std::array<std::pair<const char *, const capability::Shape *>, 2> polygons = {
        std::pair{"velocity_polygon", &capability.polygons.velocity},
        std::pair{"force_polygon", &capability.polygons.force}};
    if (capability.hasPolygons) {
        for (const auto &[name, shape] : polygons) {
            json.key(name);
            if (shape->polygon.empty()) {
                json.null();
                continue;
            }
            json.beginArray(true);
            for (const Eigen::Vector2d &p : shape->polygon) {
                json.beginArray(true);
                json.number(p.x());
                json.number(p.y());
                json.endArray();
            }
            json.endArray();
        }
    }
    // as the values: "undefined" names every null, "infinite" those that are unbounded
    const auto namesWhere = [&](const char *key, auto notFinite, bool unboundedOnly) {
        json.key(key);
        json.beginArray(true);
        for (const ReportEntry &entry : capability.layout->entries) {
            if (notFinite(entry, capability.values))
                json.string(entry.name);
        }
        for (const auto &[name, shape] : polygons) {
            if (capability.hasPolygons && shape->polygon.empty() && (shape->unbounded || !unboundedOnly))
                json.string(name);
        }
        json.endArray();
    };
    namesWhere("undefined", [](const ReportEntry &e, std::span<const double> v) { return !allFinite(e, v); }, false);
    namesWhere("infinite", [](const ReportEntry &e, std::span<const double> v) { return anyInfinite(e, v); }, true);
    json.key("singular").string(singularityName(capability.type));
    json.key("reason");
    if (const char *reason = capability::nearSingularReason(capability.type, capability.kindType))
        json.string(reason);
    else
        json.null();
    json.endObject();
}

void writeMobilityJson(JsonWriter &json, const Mechanism &mechanism, const Pose &pose)
{
    const KinematicChain chain = mechanism.kinematicChain(pose);
    const MobilityReport r = analyseMobility(chain);
    const auto integer = [&](const char *key, std::optional<int> value) {
        json.key(key);
        if (r.valid && value)
            json.integer(*value);
        else
            json.null();
    };
    const auto flag = [&](const char *key, bool value) {
        json.key(key);
        if (r.valid)
            json.boolean(value);
        else
            json.null();
    };
    json.key("mobility");
    json.beginObject();
    integer("moving_links", r.movingLinks);
    json.key("pairs");
    json.beginObject(true);
    for (int c = 5; c >= 1; --c)
        integer(c == 5 ? "P5" : c == 4 ? "P4" : c == 3 ? "P3" : c == 2 ? "P2" : "P1", r.pairsByClass[std::size_t(c)]);
    json.endObject();
    integer("loops", r.loops);
    integer("freedoms", r.freedoms);
    integer("chebyshev", r.chebyshev);
    integer("somov_malyshev", r.somovMalyshev);
    integer("rank", r.rank);
    integer("numerical", r.numerical);
    integer("finite", r.mobility);
    flag("singular", r.singular);
    integer("redundant_constraints", r.redundantConstraints);
    integer("planar_redundant_constraints", r.planarRedundantConstraints);
    integer("idle_freedoms", r.idleFreedoms);
    integer("actuators", r.actuators);
    integer("locked_freedoms", r.lockedMobility);
    flag("fully_actuated", r.fullyActuated);
    flag("chebyshev_fails", r.chebyshevFails);
    flag("somov_malyshev_fails", r.somovMalyshevFails);
    flag("formula_fails", r.formulaFails);
    json.key("chain").string(chain.description);
    json.key("verdict").string(r.verdict);
    json.endObject();
}

void addMobilityRows(TextTable &table, const Mechanism &mechanism, const Pose &pose)
{
    const KinematicChain chain = mechanism.kinematicChain(pose);
    const MobilityReport r = analyseMobility(chain);
    table.heading("Mobility");
    if (!chain.description.empty())
        table.text(chain.description);
    if (r.valid) {
        const auto row = [&](const char *symbol, int value, const char *label) {
            table.cells({symbol, std::to_string(value), "", label});
        };
        row("n", r.movingLinks, "moving links");
        static constexpr std::array<const char *, 6> classes = {"", "P₁", "P₂", "P₃", "P₄", "P₅"};
        static constexpr std::array<const char *, 6> labels
            = {"", "pairs of class 1 (5 freedoms: point contact)", "pairs of class 2 (4 freedoms: line contact)",
                "pairs of class 3 (3 freedoms: spherical)", "pairs of class 4 (2 freedoms: cylindrical, planar cam)",
                "pairs of class 5 (1 freedom: revolute, prismatic, screw)"};
        for (std::size_t c = 5; c >= 1; --c)
            row(classes[c], r.pairsByClass[c], labels[c]);
        row("L", r.loops, "independent loops");
        if (r.chebyshev)
            row("W", *r.chebyshev, "Chebyshev: W = 3n − 2P₅ − P₄");
        row("W", r.somovMalyshev, "Somov–Malyshev: W = 6n − 5P₅ − 4P₄ − 3P₃ − 2P₂ − P₁");
        row("M", r.numerical, "numerical: freedoms − rank of the constraint Jacobian at this pose");
        if (r.singular)
            row("M", r.mobility, "finite mobility, at the regular poses next to this singular one");
        row("q", r.redundantConstraints, "redundant loop equations (overconstraints): 6L − rank");
        row("A", r.actuators, "actuated freedoms");
    }
    table.text(r.verdict);
}

} // namespace pkm::report
