#include "cli/cli.h"

#include "cli/cliarguments.h"
#include "cli/clidesign.h"
#include "cli/clidrawing.h"
#include "cli/clihelp.h"
#include "cli/clishow.h"
#include "cli/clisweep.h"
#include "cli/clitolerance.h"
#include "cli/cliworkspace.h"
#include "registry.h"
#include "report/jsonwriter.h"
#include "report/report.h"
#include "report/texttable.h"
#include "text.h"

#include <QString>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <optional>
#include <span>
#include <vector>

// Everything `pkm` prints is built as UTF-8 std::string from core names and units, numbers
// are formatted locale-free (numberformat.h), and the text reaches the FILE* only once the
// command has succeeded. QString appears only at the designfile boundary.

namespace pkm {

int cliExitCode(const Failure &failure)
{
    switch (failure.kind) {
    case FailureKind::OutOfRange:
    case FailureKind::Unreachable:
    case FailureKind::Singular:
        return CliNoSolution;
    case FailureKind::InvalidParameter:
    case FailureKind::UnknownName:
        break;
    }
    return CliUsageError;
}

namespace cli {

using namespace report;

namespace {

/// An error message is one sentence, perhaps quoting a name or a value: longer than this, the
/// rest is cut ("…").
constexpr std::size_t maxMessageCharacters = 1000;


// -- eval ------------------------------------------------------------------------------------

std::vector<std::pair<std::string, double>> displayOutputs(const Mechanism &mechanism, const Pose &pose)
{
    std::vector<std::pair<std::string, double>> outputs;
    const auto &variables = mechanism.variableInfo();
    const int inputs = mechanism.inputCount();
    for (int i = inputs; i < static_cast<int>(variables.size()); ++i)
        outputs.emplace_back(variables[std::size_t(i)].name, variables[std::size_t(i)].unit.toDisplay(mechanism.variableValue(pose, i)));
    return outputs;
}

/// The kind's governing equations at the pose (core/equations.h), as the GUI's Equations
/// panel shows them: title and source, the formula, the numbers put in, and the note.
void addEquationRows(std::string &out, const Mechanism &mechanism, const Pose &pose)
{
    out += joinText({"\nEquations\n", equations::roundingNote(), "\n"});
    for (const Equation &equation : mechanismEquations(mechanism, pose)) {
        out += joinText({"\n", equation.title, " (", equation.source, ")\n  "});
        std::string text = equationText(equation);
        for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 3))
            text.replace(at, 1, "\n  ");
        out += joinText({text, "\n"});
        if (!equation.note.empty())
            out += joinText({"  note: ", equation.note, "\n"});
    }
}

std::string evalText(const PreparedDesign &prepared, bool allModes, bool equations)
{
    const Mechanism &mechanism = *prepared.mechanism;
    const ReportLayout &layout = mechanism.reportLayout();
    std::vector<double> mainValues(static_cast<std::size_t>(layout.size));
    const Singularity singularity = mechanism.evaluate(prepared.pose, mainValues);

    std::string out = designHeading(prepared);
    TextTable table({false, true, false, false});
    const auto label = [](const std::string &text, const std::string &symbol, const std::string &name) {
        return symbol == name ? text : text + " (" + name + ")"; // the name to use with --set and in JSON
    };

    table.heading("\nParameters");
    const ParameterSet parameters = mechanism.parameters();
    for (const ParameterInfo &info : mechanism.parameterInfo()) {
        table.cells({info.symbol, fixedText(parameterDisplayValue(parameters, info), info.decimals),
            std::string(info.unit.symbol), label(info.label, info.symbol, info.name)});
    }
    std::vector<std::string> undefined;
    const CapabilityReport capability = evaluateCapability(mechanism, prepared.pose, singularity.type);
    capability::settleNearSingular(layout, mainValues, capability.type, singularity.type);
    // a group of the mechanism's layout, or (nullopt) the capability group from its own layout
    const auto addGroup = [&](std::optional<ReportGroup> group, const char *title) {
        const ReportLayout *from = group ? &layout : capability.layout;
        if (!from)
            return;
        const std::span<const double> values = group ? std::span<const double>(mainValues) : capability.values;
        table.heading(title);
        for (const ReportEntry &entry : from->entries) {
            if (group && entry.group != *group)
                continue;
            if (!allFinite(entry, values))
                undefined.push_back(entry.name);
            const auto at = [&](int i) {
                return fixedText(
                    entry.unit.toDisplay(values[static_cast<std::size_t>(entry.offset + i)]), entry.decimals);
            };
            std::string text;
            if (entry.rows * entry.cols == 1) {
                text = at(0);
            } else {
                for (int r = 0; r < entry.rows; ++r) {
                    text += r == 0 ? "[[" : ", [";
                    for (int c = 0; c < entry.cols; ++c)
                        text += (c == 0 ? "" : ", ") + at(r * entry.cols + c);
                    text += "]";
                }
                text += "]";
            }
            table.cells(
                {entry.symbol, text, std::string(entry.unit.symbol), label(entry.label, entry.symbol, entry.name)});
        }
        for (const ReportText &word : mechanism.reportText(prepared.pose)) {
            if (group && word.group == *group)
                table.cells({word.name, word.text, "", word.label});
        }
    };
    addGroup(ReportGroup::Pose, "Pose");
    addGroup(ReportGroup::Jacobian, "Jacobian");
    addGroup(ReportGroup::Derived, "Derived");
    addGroup(std::nullopt, "Capability");
    if (const char *reason = capability::nearSingularReason(capability.type, capability.kindType))
        table.text(std::string("Jacobian and capability as at a singular pose, ") + reason);
    table.heading("Singularity");
    table.cells({"type", std::string(singularityName(singularity.type)), "", "singularity class"});
    table.cells({"margin", fixedText(singularity.margin, 4), "", "distance from the nearest singularity, 0 at it"});
    if (!undefined.empty()) {
        std::string names;
        for (const std::string &name : undefined)
            names += (names.empty() ? "" : ", ") + name;
        table.text("not finite at this pose: " + names);
    }
    addMobilityRows(table, mechanism, prepared.pose);
    if (allModes) {
        // every real solution of the direct kinematics at these inputs; * marks the pose's
        table.heading("Assembly modes at these inputs");
        const std::vector<Pose> modes = mechanism.assemblyModes(prepared.pose);
        for (std::size_t m = 0; m < modes.size(); ++m) {
            std::string text;
            for (const auto &[name, value] : displayOutputs(mechanism, modes[m]))
                text += (text.empty() ? "" : ", ") + name + " = " + fixedText(value, 3);
            const bool current = (modes[m].outputs - prepared.pose.outputs).norm()
                <= 1e-9 * std::max(1.0, prepared.pose.outputs.norm());
            table.cells({std::to_string(m + 1) + (current ? " *" : ""), text, "", ""});
        }
    }
    const std::vector<std::string> warnings = mechanism.designWarnings();
    if (!warnings.empty()) {
        table.heading("Warnings");
        for (const std::string &warning : warnings)
            table.text(warning);
    }
    table.render(out);
    if (equations)
        addEquationRows(out, mechanism, prepared.pose);
    return out;
}

// -- running -------------------------------------------------------------------------------

int fail(std::FILE *err, const Failure &failure)
{
    printError(err, failure.message);
    return cliExitCode(failure);
}

int finishOutput(std::FILE *out, std::FILE *err, bool ok)
{
    if (ok && std::fflush(out) == 0 && !std::ferror(out))
        return CliSuccess;
    printError(err, std::string("Cannot write the output: ") + std::strerror(errno) + ".");
    return CliOutputError;
}

int runSweep(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err)
{
    const auto sweep = Sweep::solve(prepared, invocation);
    if (!sweep)
        return fail(err, sweep.failure());
    const Sweep::Outcome outcome = sweep->write(out);
    if (outcome == Sweep::Outcome::NotDeterministic) {
        printError(err,
            "a sweep step solved in the first pass failed in the second: the mechanism is not "
            "deterministic (a bug).");
        return CliNoSolution;
    }
    return finishOutput(out, err, outcome == Sweep::Outcome::Written);
}

} // namespace

std::string kindTitle(std::string_view kind)
{
    const MechanismKind *found = findMechanismKind(kind);
    return found ? std::string(found->title) : std::string(kind);
}

std::string designHeading(const PreparedDesign &prepared)
{
    const std::string title = prepared.design.title.toStdString();
    const std::string_view kind = prepared.mechanism->kind();
    return "Design     " + (title.empty() ? prepared.origin : prepared.origin + ": " + title) + "\nMechanism  "
        + std::string(kind) + " (" + kindTitle(kind) + ")\n";
}

void printError(std::FILE *err, const std::string &message)
{
    // a message may quote a file or an argument: no control character reaches the terminal
    // (ESC sequences, a newline faking a line) and a quoted megabyte does not make a sentence
    const std::string line = "pkm: " + text::printable(message, maxMessageCharacters) + "\n";
    std::fwrite(line.data(), 1, line.size(), err);
    std::fflush(err);
}

int printOutput(std::FILE *out, std::FILE *err, std::string_view text)
{
    return finishOutput(out, err, std::fwrite(text.data(), 1, text.size(), out) == text.size());
}

std::string evalJson(const Mechanism &mechanism, const Pose &pose, bool allModes, bool equations)
{
    const ReportLayout &layout = mechanism.reportLayout();
    std::vector<double> values(static_cast<std::size_t>(layout.size));
    const Singularity singularity = mechanism.evaluate(pose, values);
    const CapabilityReport capability = evaluateCapability(mechanism, pose, singularity.type);
    capability::settleNearSingular(layout, values, capability.type, singularity.type);
    std::string out;
    JsonWriter json(out, JsonWriter::Style::Pretty);
    json.beginObject();
    json.key("mechanism").string(mechanism.kind());
    writeParametersJson(json, mechanism, false);
    writeReportJson(json, layout, values, singularity, mechanism.reportText(pose), capability.type);
    writeCapabilityJson(json, capability);
    writeMobilityJson(json, mechanism, pose);
    if (allModes) {
        json.key("assembly_modes");
        json.beginArray();
        for (const Pose &mode : mechanism.assemblyModes(pose)) {
            json.beginObject(true);
            for (const auto &[name, value] : displayOutputs(mechanism, mode))
                json.key(name).number(value);
            json.endObject();
        }
        json.endArray();
    }
    if (equations) {
        json.key("equations");
        json.beginArray();
        for (const Equation &equation : mechanismEquations(mechanism, pose)) {
            json.beginObject();
            json.key("title").string(equation.title);
            json.key("symbolic").string(equation.symbolic);
            json.key("substituted").string(fillEquation(equation, plainEquationNumber));
            json.key("result").number(equation.result.unit.toDisplay(equation.result.value));
            json.key("unit").string(equation.result.unit.symbol);
            json.key("source").string(equation.source);
            json.key("note").string(equation.note);
            json.endObject();
        }
        json.endArray();
    }
    json.endObject();
    return out;
}

} // namespace cli

int runCli(const QStringList &arguments, std::FILE *out, std::FILE *err)
{
    using namespace cli;
    std::vector<std::string> args;
    args.reserve(static_cast<std::size_t>(arguments.size()));
    for (const QString &argument : arguments)
        args.push_back(argument.toStdString());
    if (isDxfCommand(args)) { // its own options (clidxf.h)
        if (!drawingCommands().dxf)
            return fail(err, usageFailure("dxf", cannotDrawMessage("dxf")));
        return drawingCommands().dxf(args, out, err);
    }

    const auto parsed = parseArguments(args);
    if (!parsed)
        return fail(err, parsed.failure());
    const Invocation &invocation = *parsed;
    if (invocation.version)
        return printOutput(out, err, std::string("pkm ") + PKM_VERSION + "\n");
    if (invocation.help)
        return printOutput(out, err, helpText(invocation.command));
    if (invocation.command == Command::List)
        return printOutput(out, err, listOutput(invocation.json));

    const auto prepared = prepareDesign(*invocation.design, invocation.sets);
    if (!prepared)
        return fail(err, prepared.failure());
    const DrawingCommands &drawing = drawingCommands();
    if (invocation.command == Command::Render) {
        if (!drawing.render)
            return fail(err, usageFailure("render", cannotDrawMessage("render")));
        return drawing.render(*prepared, invocation, out, err); // it prints the note where it draws
    }
    if (invocation.command == Command::Sheet && !drawing.sheet)
        return fail(err, usageFailure("sheet", cannotDrawMessage("sheet")));
    if (!prepared->note.empty())
        printError(err, "note: " + prepared->note);

    if (invocation.command == Command::Show)
        return printOutput(out, err, invocation.json ? showJson(*prepared) : showText(*prepared));
    if (invocation.command == Command::Eval) {
        return printOutput(
            out, err, invocation.json ? evalJson(*prepared->mechanism, prepared->pose, invocation.allModes, invocation.equations) + "\n"
                                : evalText(*prepared, invocation.allModes, invocation.equations));
    }
    if (invocation.command == Command::Workspace || invocation.command == Command::Map)
        return runWorkspaceCommand(*prepared, invocation, out, err);
    if (invocation.command == Command::Sheet)
        return drawing.sheet(*prepared, invocation, out, err);
    if (invocation.command == Command::Tolerance)
        return runToleranceCommand(*prepared, invocation, out, err);
    return runSweep(*prepared, invocation, out, err);
}

} // namespace pkm
