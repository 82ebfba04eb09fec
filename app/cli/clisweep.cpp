#include "cli/clisweep.h"

#include "report/report.h"
#include "report/jsonwriter.h"
#include "report/numberformat.h"
#include "report/sweeprowformatter.h"

#include <QString>

#include <cstddef>
#include <string_view>
#include <vector>

namespace pkm::cli {

using namespace report;

namespace {

/// The rows are formatted into one buffer that is written out whenever it holds this much.
constexpr std::size_t flushBytes = std::size_t {1} << 20;

/// "75°", "500 mm", "0.4": a value in display units with its unit, for messages.
std::string withUnit(double displayValue, const Unit &unit)
{
    std::string text = numberText(displayValue);
    if (!unit.symbol.empty()) {
        if (unit.symbol != "°")
            text += ' ';
        text += unit.symbol;
    }
    return text;
}

bool writeAll(std::FILE *out, std::string_view text)
{
    return std::fwrite(text.data(), 1, text.size(), out) == text.size();
}

} // namespace

std::optional<Failure> Sweep::setVariable(const std::string &var)
{
    const Mechanism &mechanism = *m_design->mechanism;
    m_var = var;
    m_variable = mechanism.variableIndex(m_var);
    if (m_variable >= 0)
        m_unit = mechanism.variableInfo()[static_cast<std::size_t>(m_variable)].unit;
    else if ((m_parameter = mechanism.findParameter(m_var)))
        m_unit = m_parameter->unit;
    else
        return unknownSetName(mechanism, "--var " + m_var, m_var, m_design->origin);
    return std::nullopt;
}

std::string Sweep::stepContext(std::int64_t i) const
{
    return "sweep step " + std::to_string(i + 1) + " of " + std::to_string(m_steps) + " (" + m_var + " = "
        + withUnit(valueAt(i), m_unit) + ")";
}

Result<Sweep> Sweep::solve(const PreparedDesign &design, const Invocation &invocation)
{
    Sweep sweep(design);
    if (auto failure = sweep.setVariable(*invocation.var))
        return *failure;
    sweep.m_from = *invocation.from;
    sweep.m_to = *invocation.to;
    sweep.m_steps = *invocation.steps;
    sweep.m_json = invocation.json;

    // Solve every step before printing anything, so a failure leaves stdout empty. Only
    // whether each step solves is kept: write() solves them again, in the same order from the
    // same start, so memory stays constant whatever the number of steps.
    Pose near = design.pose;
    Step step;
    for (std::int64_t i = 0; i < sweep.m_steps; ++i) {
        if (const auto failure = sweep.solveStep(i, near, step))
            return inContext(*failure, sweep.stepContext(i));
        near = step.pose;
    }
    return sweep;
}

Result<SweepTable> Sweep::table(const PreparedDesign &design, const std::string &var, std::vector<double> values)
{
    Sweep sweep(design);
    if (auto failure = sweep.setVariable(var))
        return *failure;
    sweep.m_values = std::move(values);
    sweep.m_steps = static_cast<std::int64_t>(sweep.m_values.size());

    const SweepRowFormatter formatter(*design.mechanism, sweep.m_parameter != nullptr);
    SweepTable table;
    table.columns = formatter.columnNames();
    table.singularityColumn = formatter.singularityColumn();
    table.steps = sweep.m_values.size();
    table.values.resize(table.columns.size() * table.steps);
    // One pass: the table is the output, so nothing is saved by solving the steps twice.
    std::vector<double> buffer(formatter.valueCount());
    Pose near = design.pose;
    Step step;
    for (std::int64_t i = 0; i < sweep.m_steps; ++i) {
        if (const auto failure = sweep.solveStep(i, near, step))
            return inContext(*failure, sweep.stepContext(i));
        formatter.numberRow(table.values.data() + i, table.steps, *step.mechanism, step.pose, buffer);
        near = step.pose;
    }
    return table;
}

double Sweep::valueAt(std::int64_t i) const
{
    if (!m_values.empty())
        return m_values[static_cast<std::size_t>(i)];
    if (i == 0 || m_steps == 1)
        return m_from;
    if (i == m_steps - 1)
        return m_to;
    return m_from + (m_to - m_from) * (static_cast<double>(i) / static_cast<double>(m_steps - 1));
}

std::optional<Failure> Sweep::solveStep(std::int64_t i, const Pose &near, Step &step) const
{
    const double value = valueAt(i);
    if (!m_parameter) {
        auto solved = m_design->mechanism->solveWith(near, m_variable, m_unit.fromDisplay(value));
        if (!solved)
            return solved.failure();
        step.mechanism = m_design->mechanism.get();
        step.pose = *solved;
        return std::nullopt;
    }
    auto changed = designfile::setDisplayParameter(m_design->mechanism, QString::fromStdString(m_var), value);
    if (!changed)
        return changed.failure();
    const Mechanism &mechanism = **changed;
    auto solved = m_design->poseSets.empty() ? mechanism.solveInverse(m_design->pose.outputs, &near)
                                             : solvePoseSets(mechanism, near, m_design->poseSets);
    if (!solved)
        return solved.failure();
    step.owner = *changed;
    step.mechanism = step.owner.get();
    step.pose = *solved;
    return std::nullopt;
}

void Sweep::jsonHeader(std::string &out) const
{
    const Mechanism &mechanism = *m_design->mechanism;
    JsonWriter json(out, JsonWriter::Style::Pretty);
    json.beginObject();
    json.key("mechanism").string(mechanism.kind());
    writeParametersJson(json, mechanism, true);
    json.key("sweep");
    json.beginObject(true);
    json.key("var").string(m_var);
    json.key("group").string(m_parameter ? "parameters" : "pose");
    json.key("unit").string(m_unit.symbol);
    json.key("from").number(m_from);
    json.key("to").number(m_to);
    json.key("steps").integer(m_steps);
    json.endObject();
    json.key("rows");
    out += "[\n"; // the rows follow, one per line
}

Sweep::Outcome Sweep::write(std::FILE *out) const
{
    const SweepRowFormatter formatter(*m_design->mechanism, m_parameter != nullptr);
    // text[0, length) is formatted and not yet written. JSON rows are appended to it; CSV rows
    // are written through a pointer into room for one more row at its longest.
    std::string text;
    if (m_json)
        jsonHeader(text);
    else
        formatter.csvHeader(text);
    std::size_t length = text.size();
    if (m_json)
        text.reserve(2 * flushBytes);
    else
        text.resize(length + flushBytes + formatter.csvRowBound());
    const auto flush = [&] {
        const bool ok = writeAll(out, {text.data(), length});
        length = 0;
        if (m_json)
            text.clear();
        return ok;
    };

    std::vector<double> values(formatter.valueCount());
    Pose near = m_design->pose;
    Step step;
    for (std::int64_t i = 0; i < m_steps; ++i) {
        if (solveStep(i, near, step).has_value())
            return Outcome::NotDeterministic; // solve() solved it from the same pose
        if (m_json) {
            formatter.jsonRow(text, i, *step.mechanism, step.pose, values);
            length = text.size();
        } else {
            length = static_cast<std::size_t>(
                formatter.csvRow(text.data() + length, *step.mechanism, step.pose, values) - text.data());
        }
        if (length >= flushBytes && !flush())
            return Outcome::OutputError;
        near = step.pose;
    }
    if (m_json) {
        text += "\n]\n}\n";
        length = text.size();
    }
    return flush() ? Outcome::Written : Outcome::OutputError;
}

} // namespace pkm::cli
