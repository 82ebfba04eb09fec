#include "cli/clitolerance.h"

#include "cli/cli.h"
#include "report/jsonwriter.h"
#include "report/report.h"
#include "report/texttable.h"
#include "tolerancemap.h"

#include <cmath>
#include <limits>

// `pkm tolerance` (docs/cli.md): the first-order worst case, its parts per parameter, the Monte
// Carlo distribution and, with --grid, the worst case over the workspace (core/tolerance.h).
// Values are in display units: outputs in mm or degrees, each ∂x/∂p per display unit of p.

namespace pkm::cli {

using namespace report;

namespace {

/// "∞" for an unbounded value, "undefined" for NaN, else fixed decimals.
std::string valueText(double value, int decimals)
{
    if (std::isinf(value))
        return "∞";
    return fixedText(value, decimals);
}

struct Context {
    const PreparedDesign &prepared;
    const Invocation &invocation;
    const tolerance::Analysis &analysis;
    tolerance::FirstOrder first;
    std::optional<tolerance::MonteCarlo> monteCarlo;
    std::optional<MapSummary> map;
    std::vector<int> norm;
    Unit normUnit;
};

const VariableInfo &outputInfo(const Mechanism &m, int k)
{
    return m.variableInfo()[std::size_t(m.inputCount() + k)];
}

/// ∂x_k/∂p in display units of x per display unit of p.
double displayDerivative(const Mechanism &m, const tolerance::Contribution &c, int k)
{
    const ParameterInfo *info = m.findParameter(c.name);
    return outputInfo(m, k).unit.toDisplay(c.derivative[k]) / info->unit.toDisplay(1.0);
}

std::string normName(const Context &c)
{
    const Mechanism &m = c.analysis.mechanism();
    std::string names;
    for (const int k : c.norm)
        names += (names.empty() ? "" : ", ") + outputInfo(m, k).name;
    return "|Δ(" + names + ")|";
}

std::string tableText(const Context &c)
{
    const Mechanism &m = c.analysis.mechanism();
    const tolerance::FirstOrder &f = c.first;
    const bool normal = c.invocation.normal;
    std::string out = designHeading(c.prepared);
    TextTable table({false, true, false, false});
    table.heading("\nPose");
    for (int k = 0; k < m.outputCount(); ++k) {
        const VariableInfo &info = outputInfo(m, k);
        table.cells({info.symbol, fixedText(info.unit.toDisplay(c.prepared.pose.outputs[k]), 4),
                     std::string(info.unit.symbol), info.label});
    }
    table.heading("Tolerances (± in each parameter's display unit)");
    for (const auto &[name, tol] : c.analysis.tolerances()) {
        const ParameterInfo *info = m.findParameter(name);
        table.cells({info->symbol, "±" + fixedText(info->unit.toDisplay(tol), info->decimals + 2),
                     std::string(info->unit.symbol), info->label + " (" + name + ")"});
    }
    table.heading("First-order worst case (method: " + std::string(tolerance::methodName(f.method)) + ")");
    for (int k = 0; k < m.outputCount(); ++k) {
        const VariableInfo &info = outputInfo(m, k);
        table.cells({"Δ" + info.symbol, "±" + valueText(info.unit.toDisplay(f.worst[k]), 5), std::string(info.unit.symbol),
                     "worst case; σ " + valueText(info.unit.toDisplay(normal ? f.sigmaNormal[k] : f.sigmaUniform[k]), 5)
                         + (normal ? " (normal, tol = 3σ)" : " (uniform in ±tol)")});
    }
    table.cells({normName(c), valueText(c.normUnit.toDisplay(f.worstNorm), 5), std::string(c.normUnit.symbol),
                 "bound on the error of the position"});
    if (!f.finite)
        table.text(f.reason);
    table.heading("Contributions to " + normName(c));
    for (const tolerance::Contribution &p : f.parameters) {
        const ParameterInfo *info = m.findParameter(p.name);
        std::string derivatives;
        for (int k = 0; k < m.outputCount(); ++k) {
            derivatives += (k ? ", " : "") + ("∂" + outputInfo(m, k).symbol + "/∂" + info->symbol + " = ")
                + valueText(displayDerivative(m, p, k), 5);
        }
        table.cells({info->symbol, valueText(c.normUnit.toDisplay(p.contribution), 5), std::string(c.normUnit.symbol),
                     (std::isfinite(p.share) ? fixedText(100.0 * p.share, 1) + " %; " : std::string()) + derivatives});
    }
    if (c.monteCarlo) {
        const tolerance::MonteCarlo &mc = *c.monteCarlo;
        table.heading("Monte Carlo (" + std::to_string(mc.samples) + " samples, seed "
                      + std::to_string(c.invocation.seed.value_or(tolerance::defaultSeed)) + ", "
                      + (normal ? "normal, tol = 3σ" : "uniform in ±tol") + ")");
        if (mc.assembled() == 0) {
            table.text("no sample assembled: the statistics are undefined");
        } else {
            for (int k = 0; k < m.outputCount(); ++k) {
                const VariableInfo &info = outputInfo(m, k);
                const Unit u = info.unit;
                table.cells({"Δ" + info.symbol, fixedText(u.toDisplay(mc.mean[k]), 5), std::string(u.symbol),
                             "mean; σ " + fixedText(u.toDisplay(mc.deviation[k]), 5) + ", max |Δ| "
                                 + fixedText(u.toDisplay(mc.maxAbs[k]), 5)});
            }
            table.cells({normName(c), fixedText(c.normUnit.toDisplay(mc.normMean), 5), std::string(c.normUnit.symbol),
                         "mean; σ " + fixedText(c.normUnit.toDisplay(mc.normDeviation), 5) + ", max "
                             + fixedText(c.normUnit.toDisplay(mc.normMax), 5)});
        }
        table.cells({"failed", std::to_string(mc.failed), "", "samples that do not assemble in this mode ("
                         + fixedText(100.0 * mc.failedFraction(), 1) + " %)"});
    }
    if (c.map) {
        const MapSummary &s = *c.map;
        table.heading("Worst case over the workspace (grid " + std::to_string(s.grid.columns) + " × "
                      + std::to_string(s.grid.rows) + ")");
        table.cells({"cells", std::to_string(s.reachableCells), "", "reachable cells"});
        table.cells({"min", fixedText(c.normUnit.toDisplay(s.min), 5), std::string(c.normUnit.symbol), "least finite bound"});
        table.cells({"max", fixedText(c.normUnit.toDisplay(s.max), 5), std::string(c.normUnit.symbol), "greatest finite bound"});
    }
    table.render(out);
    return out;
}

void writeOutputs(JsonWriter &json, const Mechanism &m, const Coordinates &values)
{
    json.beginObject(true);
    for (int k = 0; k < m.outputCount(); ++k)
        json.key(outputInfo(m, k).name).number(outputInfo(m, k).unit.toDisplay(values[k]));
    json.endObject();
}

std::string jsonText(const Context &c)
{
    const Mechanism &m = c.analysis.mechanism();
    const tolerance::FirstOrder &f = c.first;
    std::string out;
    JsonWriter json(out, JsonWriter::Style::Pretty);
    json.beginObject();
    json.key("design").string(c.prepared.origin);
    json.key("mechanism").string(m.kind());
    writeParametersJson(json, m, true);
    json.key("pose");
    writeOutputs(json, m, c.prepared.pose.outputs);
    json.key("tolerances");
    json.beginObject(true);
    for (const auto &[name, tol] : c.analysis.tolerances())
        json.key(name).number(m.findParameter(name)->unit.toDisplay(tol));
    json.endObject();
    json.key("norm");
    json.beginObject(true);
    json.key("outputs");
    json.beginArray(true);
    for (const int k : c.norm)
        json.string(outputInfo(m, k).name);
    json.endArray();
    json.key("unit").string(c.normUnit.symbol);
    json.endObject();
    json.key("first_order");
    json.beginObject();
    json.key("method").string(tolerance::methodName(f.method));
    json.key("singularity").string(singularityName(f.singularity));
    json.key("finite").boolean(f.finite);
    if (f.finite)
        json.key("reason").null();
    else
        json.key("reason").string(f.reason);
    json.key("worst");
    writeOutputs(json, m, f.worst);
    json.key("worst_norm").number(c.normUnit.toDisplay(f.worstNorm));
    json.key("sigma");
    writeOutputs(json, m, c.invocation.normal ? f.sigmaNormal : f.sigmaUniform);
    json.key("contributions");
    json.beginArray();
    for (const tolerance::Contribution &p : f.parameters) {
        json.beginObject(true);
        json.key("name").string(p.name);
        json.key("tolerance").number(m.findParameter(p.name)->unit.toDisplay(p.tolerance));
        json.key("derivative");
        json.beginObject(true);
        for (int k = 0; k < m.outputCount(); ++k)
            json.key(outputInfo(m, k).name).number(displayDerivative(m, p, k));
        json.endObject();
        json.key("contribution").number(c.normUnit.toDisplay(p.contribution));
        json.key("share").number(p.share);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    json.key("monte_carlo");
    if (!c.monteCarlo) {
        json.null();
    } else {
        const tolerance::MonteCarlo &mc = *c.monteCarlo;
        json.beginObject();
        json.key("samples").integer(mc.samples);
        json.key("seed").string(std::to_string(c.invocation.seed.value_or(tolerance::defaultSeed)));
        json.key("distribution").string(c.invocation.normal ? "normal" : "uniform");
        json.key("failed").integer(mc.failed);
        json.key("failed_fraction").number(mc.failedFraction());
        if (mc.assembled() == 0)
            json.key("reason").string("no sample assembled in the mode of the pose: the statistics are undefined");
        else
            json.key("reason").null();
        json.key("mean");
        writeOutputs(json, m, mc.mean);
        json.key("std");
        writeOutputs(json, m, mc.deviation);
        json.key("max_abs");
        writeOutputs(json, m, mc.maxAbs);
        json.key("norm");
        json.beginObject(true);
        json.key("mean").number(c.normUnit.toDisplay(mc.normMean));
        json.key("std").number(c.normUnit.toDisplay(mc.normDeviation));
        json.key("max").number(c.normUnit.toDisplay(mc.normMax));
        json.endObject();
        json.endObject();
    }
    if (c.map) {
        const MapSummary &s = *c.map;
        json.key("map");
        json.beginObject(true);
        json.key("columns").integer(s.grid.columns);
        json.key("rows").integer(s.grid.rows);
        json.key("reachable_cells").integer(std::int64_t(s.reachableCells));
        json.key("min").number(c.normUnit.toDisplay(s.min));
        json.key("max").number(c.normUnit.toDisplay(s.max));
        json.key("seconds").number(s.seconds);
        json.endObject();
    }
    json.endObject();
    out += "\n";
    return out;
}

} // namespace

Result<ParameterSet> tolerancesOf(const PreparedDesign &prepared, const Invocation &invocation,
                                  const std::string &command)
{
    const Mechanism &m = *prepared.mechanism;
    ParameterSet tolerances = prepared.design.tolerances;
    for (const ToleranceSetting &setting : invocation.tolerances) {
        const std::string context = "--tol " + setting.text;
        auto info = tolerance::checkParameter(m, setting.name);
        if (!info)
            return inContext(info.failure(), context);
        const double value = (*info)->unit.fromDisplay(setting.value);
        if (value == 0.0) {
            tolerances.erase(setting.name);
            continue;
        }
        if (auto checked = tolerance::checkTolerance(m, setting.name, value); !checked)
            return inContext(checked.failure(), context);
        tolerances[setting.name] = value;
    }
    if (tolerances.empty()) {
        return usageFailure("--tol", command + " needs at least one --tol NAME=±VALUE (or a design file with "
                                               "tolerances) (see 'pkm tolerance --help').");
    }
    return tolerances;
}

int runToleranceCommand(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err)
{
    const Mechanism &m = *prepared.mechanism;
    const auto fail = [&](const Failure &failure) {
        printError(err, failure.message);
        return cliExitCode(failure);
    };
    auto tolerances = tolerancesOf(prepared, invocation, "'pkm tolerance'");
    if (!tolerances)
        return fail(tolerances.failure());
    auto analysis = tolerance::Analysis::make(prepared.mechanism, *tolerances);
    if (!analysis)
        return fail(analysis.failure());
    Context c{prepared, invocation, *analysis, analysis->firstOrder(prepared.pose), std::nullopt, std::nullopt,
              tolerance::normOutputs(m), tolerance::normUnit(m)};
    const int samples = invocation.samples.value_or(defaultToleranceSamples);
    if (samples > 0) {
        tolerance::MonteCarloOptions options;
        options.samples = samples;
        options.seed = invocation.seed.value_or(tolerance::defaultSeed);
        options.distribution = invocation.normal ? tolerance::Distribution::Normal : tolerance::Distribution::Uniform;
        c.monteCarlo = analysis->monteCarlo(prepared.pose, options);
    }
    if (invocation.grid) {
        const PlanarWorkspace *workspace = m.planarWorkspace();
        if (!workspace) {
            return fail(usageFailure("--grid", "--grid: the " + std::string(m.kind())
                                                   + " has no planar workspace to map the worst case over."));
        }
        if (*invocation.grid > tolerance::maxMapGrid) {
            return fail(usageFailure("--grid", "--grid " + std::to_string(*invocation.grid)
                                                   + ": the worst-case map takes at most "
                                                   + std::to_string(tolerance::maxMapGrid) + " cells per side."));
        }
        const MapGrid grid = squareGrid(workspace->workspaceBounds(), *invocation.grid);
        std::vector<float> values(grid.cells());
        c.map = tolerance::computeMap(*analysis, prepared.pose, grid, values);
    }
    return printOutput(out, err, invocation.json ? jsonText(c) : tableText(c));
}

} // namespace pkm::cli
