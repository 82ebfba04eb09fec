#include "cli/cliworkspace.h"

#include "cli/cli.h"
#include "cli/clicapabilitymap.h"
#include "cli/clitolerance.h"
#include "cli/cliworkspaceparts.h"
#include "document/savefile.h"
#include "registry.h"
#include "report/jsonwriter.h"
#include "report/numberformat.h"
#include "report/report.h"
#include "report/texttable.h"
#include "report/workspaceoutline.h"
#include "tolerancemap.h"
#include "units.h"

#include <QByteArray>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <vector>

namespace pkm::cli {

using namespace report;

namespace {

using Clock = std::chrono::steady_clock;

WorkspacePictureWriters &pictureWriters()
{
    static WorkspacePictureWriters writers;
    return writers;
}

/// A picture the drawing half of the command line writes; refused where it is not linked in.
template <typename Writer, typename... Arguments>
std::optional<std::string> writePicture(Writer writer, const std::string &path, const Arguments &...arguments)
{
    if (!writer)
        return "Cannot write '" + path + "': pictures are drawn by pkm-draw, which was not found beside this program.";
    return writer(path, arguments...);
}

// -- numbers and names ---------------------------------------------------------------------

/// "Active П-joint" → "active П-joint"; "MOMA …" stays.
std::string inSentence(std::string title)
{
    if (title.size() > 1 && title[0] >= 'A' && title[0] <= 'Z' && title[1] >= 'a' && title[1] <= 'z')
        title[0] = static_cast<char>(title[0] - 'A' + 'a');
    return title;
}


} // namespace

namespace {

// -- the commands --------------------------------------------------------------------------

struct Context {
    const PreparedDesign &prepared;
    const Invocation &invocation;
    std::FILE *out;
    std::FILE *err;
    int resolution = defaultGrid;
};

int failWith(std::FILE *err, const Failure &failure)
{
    printError(err, failure.message);
    return cliExitCode(failure);
}

/// The singular curves drawn over a picture of a map of `quantity`, as the map view draws them:
/// none over the orientation range, which is not a slice at one platform angle.
std::vector<SingularCurve> singularCurves(const Mechanism &mechanism, MapQuantity quantity)
{
    const PlanarWorkspace *workspace = mechanism.planarWorkspace();
    if (!workspace || quantity == MapQuantity::OrientationRange)
        return {};
    return workspace->singularCurves();
}

/// The design's modes for headings: " (branch1 = -1, …)" or "".
std::string modeSuffix(const Mechanism &mechanism)
{
    const std::string modes = modeText(modeParameters(mechanism), mechanism.parameters());
    return modes.empty() ? std::string() : " (" + modes + ")";
}

std::optional<Failure> emptyWorkspace(const PreparedDesign &prepared, const MapSummary &summary)
{
    if (summary.reachableCells > 0)
        return std::nullopt;
    const MapGrid &grid = summary.grid;
    return Failure {FailureKind::Unreachable, prepared.origin,
        "The workspace of " + prepared.origin + modeSuffix(*prepared.mechanism)
            + " has no reachable cell on the " + std::to_string(grid.columns) + " × " + std::to_string(grid.rows)
            + " grid over " + intervalText(grid.bounds.min().x(), grid.bounds.max().x()) + " × "
            + intervalText(grid.bounds.min().y(), grid.bounds.max().y())
            + " mm: it is empty or thinner than a cell (try a larger --grid)."};
}

int runWorkspace(const Context &context)
{
    const Mechanism &mechanism = *context.prepared.mechanism;
    const auto computed = computeCommandWorkspace(context.prepared, context.invocation);
    if (!computed)
        return failWith(context.err, computed.failure());
    const auto &[map, box, modes, areas, united, named, requirements, region, specification, seconds] = *computed;

    const std::string suffix = modeSuffix(mechanism);
    if (const auto &path = context.invocation.output) {
        std::optional<std::string> failure;
        if (fileExtension(*path) == "svg") {
            const std::string title
                = "Workspace of " + context.prepared.origin + suffix + ": " + fixedText(map.summary.area, 1) + " mm²";
            failure = files::saveBytes(*path, QByteArray::fromStdString(workspaceSvg(map.grid, map.values, title)));
        } else if (!context.invocation.requirements.empty()) {
            // asked on the command line: the workspace light, where every requirement holds dark
            // (a design file's own requirements leave the picture of the modes as it is)
            report::ModeRegions met {region.grid, {std::vector<char>(region.values.size()), std::vector<char>(region.values.size())},
                {false, true}, region.summary.reachableCells, region.summary.area};
            for (std::size_t i = 0; i < region.values.size(); ++i) {
                met.reached[0][i] = !std::isnan(region.values[i]);
                met.reached[1][i] = region.values[i] == 1.0f;
            }
            failure = writePicture(pictureWriters().regions, *path, met,
                "Where " + context.prepared.origin + suffix + " meets the requirements (darker): "
                    + fixedText(specification.metArea, 1) + " of " + fixedText(region.summary.area, 1) + " mm²");
        } else if (!named.empty() && united.reached.size() > 1) {
            failure = writePicture(pictureWriters().regions, *path, united,
                "Workspaces of the modes of " + context.prepared.origin + suffix
                    + " (the design's own darker), their union outlined");
        } else {
            const std::vector<SingularCurve> curves = singularCurves(mechanism, MapQuantity::Determinant);
            failure = writePicture(pictureWriters().workspace, *path, map.grid, std::span<const float>(map.values),
                std::span<const SingularCurve>(curves), "Workspace of " + context.prepared.origin + suffix);
        }
        if (failure) {
            printError(context.err, *failure);
            return CliOutputError;
        }
    }

    std::string out;
    if (context.invocation.json) {
        out = workspaceJson(context.prepared, *computed, context.resolution);
    } else {
        out = designHeading(context.prepared);
        TextTable table({false, true, false});
        table.heading("\nWorkspace" + suffix);
        const PlanarWorkspace *planar = mechanism.planarWorkspace();
        const std::vector<ExactArea> exact = planar ? planar->exactAreas() : std::vector<ExactArea> {};
        // where the area is known in closed form, that is the area, and the grid's an estimate
        for (const ExactArea &known : exact)
            table.cells({known.key + " (exact)", fixedText(known.area, 1), "mm²"});
        table.cells({exact.empty() ? "area" : "area (grid)", fixedText(map.summary.area, 1), "mm²"});
        if (const auto travel = carriedTravel(mechanism)) {
            // of the exact area where it is known, as the area above it
            double area = map.summary.area;
            for (const ExactArea &known : exact)
                area = known.key == "area" ? known.area : area;
            table.cells({"volume", fixedText(area * *travel, 0), "mm³"});
            table.cells({"", "(the area extruded over the travel of " + fixedText(*travel, 1) + " mm)", ""});
        }
        addGridRows(table, map.grid, context.resolution, box, map.summary.reachableCells);
        table.cells({"time", fixedText(seconds, 3), "s"});
        table.render(out);
        if (!areas.empty()) {
            out += "\nArea per mode\n";
            std::vector<bool> alignment(modes.size(), true);
            alignment.push_back(true);
            alignment.push_back(false);
            TextTable modeTable(alignment);
            std::vector<std::string> header;
            for (const ParameterInfo *info : modes)
                header.push_back(info->name);
            header.push_back("area (mm²)");
            header.push_back("");
            modeTable.cells(header);
            for (const ModeArea &mode : areas) {
                std::vector<std::string> row;
                for (std::size_t i = 0; i < modes.size(); ++i)
                    row.push_back(modeValueText(*modes[i], mode.values[i]));
                row.push_back(fixedText(mode.area, 1));
                row.push_back(mode.current ? "current" : mode.empty ? "no workspace in this mode" : mode.note);
                modeTable.cells(row);
            }
            modeTable.render(out);
            out.append("Union of the modes: ").append(fixedText(united.unionArea, 1)).append(" mm²\n");
        }
        if (!requirements.empty()) {
            TextTable spec({false, true, false});
            spec.heading("\nSpecification (what the actuators deliver, on the same grid)");
            addSpecificationRows(spec, mechanism, requirements, specification, region.summary);
            spec.render(out);
        }
        if (const auto &path = context.invocation.output)
            out += "\nWrote " + *path + '\n';
    }
    return printOutput(context.out, context.err, out);
}

int runMap(const Context &context)
{
    const Mechanism &mechanism = *context.prepared.mechanism;
    const auto &path = context.invocation.output;
    auto computed = computeCommandMap(context.prepared, context.invocation, path.has_value());
    if (!computed)
        return failWith(context.err, computed.failure());
    const MapQuantity quantity = computed->quantity;
    const ComputedMap &map = computed->map;
    const std::vector<capability::Requirement> &requirements = computed->requirements;
    const capability::SpecificationSummary &specification = computed->specification;
    const Eigen::AlignedBox2d &box = computed->box;

    const bool png = path && fileExtension(*path) == "png";
    double limit = 0.0;
    if (path) {
        std::optional<std::string> failure;
        if (png) {
            limit = mapColourLimit(map.values, quantity);
            const std::vector<SingularCurve> curves = singularCurves(mechanism, quantity);
            failure = writePicture(pictureWriters().map, *path, map.grid, std::span<const float>(map.values), quantity,
                limit, std::span<const SingularCurve>(curves),
                quantityTitle(mechanism, quantity) + " of " + context.prepared.origin + modeSuffix(mechanism));
        } else {
            failure = saveMapCsv(*path, map);
        }
        if (failure) {
            printError(context.err, *failure);
            return CliOutputError;
        }
    }
    const double colourMin = quantity == MapQuantity::Condition ? 1.0
        : quantity == MapQuantity::Determinant                  ? -limit
                                                                : 0.0;

    std::string out;
    if (context.invocation.json) {
        JsonWriter json(out, JsonWriter::Style::Pretty);
        json.beginObject();
        json.key("design").string(context.prepared.origin);
        json.key("mechanism").string(mechanism.kind());
        writeParametersJson(json, mechanism, true);
        json.key("quantity").string(quantityKey(quantity));
        if (const std::string unit = capabilityUnit(mechanism, quantity); !unit.empty())
            json.key("unit").string(unit);
        writeGridJson(json, map.grid, context.resolution);
        json.key("bounds");
        json.beginObject(true);
        writeBoxJson(json, box);
        json.endObject();
        json.key("reachable_cells").integer(static_cast<std::int64_t>(map.summary.reachableCells));
        json.key("area").number(map.summary.area);
        json.key("min").number(map.summary.min);
        json.key("max").number(map.summary.max);
        json.key("near_singular_cells").integer(static_cast<std::int64_t>(map.summary.nearSingularCells));
        json.key("near_singular_margin").number(nearSingularMargin);
        if (quantity == MapQuantity::Specification)
            writeSpecificationJson(json, mechanism, requirements, specification, map.summary);
        if (quantity == MapQuantity::ToleranceWorst) {
            json.key("tolerances"); // in the parameters' display units, as --tol takes them
            json.beginObject(true);
            for (const auto &[name, value] : computed->tolerances) {
                const ParameterInfo *info = mechanism.findParameter(name);
                json.key(name).number(info ? info->unit.toDisplay(value) : value);
            }
            json.endObject();
        }
        if (png) {
            json.key("colour_scale");
            json.beginObject(true);
            json.key("min").number(colourMin);
            json.key("max").number(limit);
            json.key("log").boolean(quantity == MapQuantity::Condition);
            json.endObject();
        }
        json.key("seconds").number(map.summary.seconds);
        json.endObject();
        out += '\n';
    } else {
        out = designHeading(context.prepared);
        TextTable table({false, true, false});
        table.heading("\nMap of " + quantityTitle(mechanism, quantity) + modeSuffix(mechanism));
        addGridRows(table, map.grid, context.resolution, box, map.summary.reachableCells);
        table.cells({"area", fixedText(map.summary.area, 1), "mm²"});
        table.cells({"min", shortNumber(map.summary.min), "over the finite cells"});
        table.cells({"max", shortNumber(map.summary.max), ""});
        table.cells({"near-singular cells", std::to_string(map.summary.nearSingularCells),
            "margin < " + numberText(nearSingularMargin)});
        if (quantity == MapQuantity::Specification)
            addSpecificationRows(table, mechanism, requirements, specification, map.summary);
        if (png) {
            std::string scale("[");
            scale += shortNumber(colourMin) + ", " + shortNumber(limit) + "]";
            table.cells({"colours", scale, quantity == MapQuantity::Condition ? "log scale"
                                               : quantity == MapQuantity::OrientationRange ? "linear"
                                               : quantity == MapQuantity::Specification    ? "met or not"
                                                                                           : "linear, clipped"});
        }
        table.cells({"time", fixedText(map.summary.seconds, 3), "s"});
        table.render(out);
        if (path)
            out += "\nWrote " + *path + '\n';
    }
    return printOutput(context.out, context.err, out);
}

} // namespace

void setWorkspacePictureWriters(const WorkspacePictureWriters &writers)
{
    pictureWriters() = writers;
}

bool writesPicture(const Invocation &invocation)
{
    if (!invocation.output || invocation.help)
        return false;
    const std::string extension = fileExtension(*invocation.output);
    if (invocation.command == Command::Workspace)
        return extension != "svg";
    return invocation.command == Command::Map && extension == "png";
}

Result<const PlanarWorkspace *> planarWorkspaceOf(const PreparedDesign &prepared, Command command)
{
    const Mechanism &mechanism = *prepared.mechanism;
    if (const PlanarWorkspace *workspace = mechanism.planarWorkspace())
        return workspace;
    const std::string kinds = planarKinds();
    return usageFailure(prepared.origin,
        "The " + inSentence(kindTitle(mechanism.kind())) + " has no planar workspace: 'pkm " + std::string(commandName(command))
            + " " + prepared.origin + "' needs a mechanism whose output is a point of the plane"
            + (kinds.empty() ? std::string() : " (" + kinds + ")") + ".");
}

Result<CommandWorkspace> computeCommandWorkspace(const PreparedDesign &prepared, const Invocation &invocation)
{
    const auto workspace = planarWorkspaceOf(prepared, Command::Workspace);
    if (!workspace)
        return workspace.failure();
    const Mechanism &mechanism = *prepared.mechanism;
    const int resolution = invocation.grid.value_or(defaultGrid);
    CommandWorkspace computed;
    auto &[map, box, modes, areas, united, named, requirements, region, specification, seconds] = computed;
    const auto start = Clock::now();
    map.summary = computeInto(**workspace, MapQuantity::Determinant, resolution, map.values, nullptr);
    map.grid = map.summary.grid;
    if (auto empty = emptyWorkspace(prepared, map.summary))
        return *empty;
    box = reachableBounds(map.grid, map.values);
    modes = modeParameters(mechanism);
    MapCells buffer;
    areas = modeAreas(mechanism, modes, map.summary, resolution, buffer);
    if (!modes.empty())
        united = modeRegions(mechanism, modes, resolution);
    named = namedModeAreas(modes, areas);
    // --require: where in the workspace the actuators deliver what is asked
    auto required = requirementsOf(prepared, invocation);
    if (!required)
        return required.failure();
    requirements = std::move(*required);
    if (!requirements.empty()) {
        region.summary = computeCapabilityInto(mechanism, prepared.pose, MapQuantity::Specification, requirements,
                                               resolution, region.values, region.margins, &specification);
        region.grid = region.summary.grid;
    }
    seconds = std::chrono::duration<double>(Clock::now() - start).count();

    return computed;
}

Result<CommandMap> computeCommandMap(const PreparedDesign &prepared, const Invocation &invocation, bool keepCells)
{
    const auto workspace = planarWorkspaceOf(prepared, Command::Map);
    if (!workspace)
        return workspace.failure();
    const Mechanism &mechanism = *prepared.mechanism;
    // --require alone maps where the requirements hold, --tol alone the worst-case error
    const bool required = !invocation.requirements.empty();
    CommandMap computed;
    // checked by the argument parser: a key of quantityOf()
    computed.quantity = quantityOf(invocation.quantity.value_or(required                          ? "spec"
                                                                : !invocation.tolerances.empty() ? "tolerance"
                                                                                                 : "det"))
                            .value_or(MapQuantity::Determinant);
    const MapQuantity quantity = computed.quantity;
    if (auto failure = capabilityMapFailure(prepared, invocation, **workspace, quantity))
        return *failure;
    auto requirements = requirementsOf(prepared, invocation);
    if (!requirements)
        return requirements.failure();
    computed.requirements = std::move(*requirements);
    ComputedMap &map = computed.map;
    const int resolution = invocation.grid.value_or(defaultGrid);
    if (quantity == MapQuantity::ToleranceWorst) {
        auto tolerances = tolerancesOf(prepared, invocation, "'pkm map --quantity tolerance'");
        if (!tolerances)
            return tolerances.failure();
        if (resolution > tolerance::maxMapGrid) {
            return usageFailure("--grid", "--grid " + std::to_string(resolution) + ": the worst-case map takes at most "
                                              + std::to_string(tolerance::maxMapGrid) + " cells per side.");
        }
        auto analysis = tolerance::Analysis::make(prepared.mechanism, *tolerances);
        if (!analysis)
            return analysis.failure();
        // the margins are det J's on the same grid: where the mechanism is near a singularity
        const MapSummary closed = computeInto(**workspace, MapQuantity::Determinant, resolution, map.values, &map.margins);
        map.summary = tolerance::computeMap(*analysis, capability::mapStart(mechanism, prepared.pose), closed.grid,
                                            map.values);
        map.summary.nearSingularCells = closed.nearSingularCells;
        computed.tolerances = std::move(*tolerances);
    } else if (isCapability(quantity)) {
        map.summary = computeCapabilityInto(mechanism, prepared.pose, quantity, computed.requirements, resolution,
                                            map.values, map.margins, &computed.specification);
    } else if (keepCells) {
        map.summary = computeInto(**workspace, quantity, resolution, map.values, &map.margins);
    } else {
        map.summary = summariseMap(**workspace, quantity, squareGrid((*workspace)->workspaceBounds(), resolution));
    }
    map.grid = map.summary.grid;
    // a planar workspace's map gives the box with its summary; the others are scanned
    const bool boxed = map.values.empty() || !map.summary.reachableBox.isEmpty() || map.summary.reachableCells == 0;
    computed.box = boxed ? map.summary.reachableBox : reachableBounds(map.grid, map.values);
    if (quantity == MapQuantity::OrientationRange) {
        // the core maps radians; the command line gives angles in degrees, as everywhere
        for (float &value : map.values)
            value = static_cast<float>(value / units::degree);
        map.summary.min /= units::degree;
        map.summary.max /= units::degree;
    }
    if (auto empty = emptyWorkspace(prepared, map.summary))
        return *empty;
    return computed;
}

int runWorkspaceCommand(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err)
{
    const auto workspace = planarWorkspaceOf(prepared, *invocation.command);
    if (!workspace)
        return failWith(err, workspace.failure());
    Context context {prepared, invocation, out, err, invocation.grid.value_or(defaultGrid)};
    return invocation.command == Command::Map ? runMap(context) : runWorkspace(context);
}

} // namespace pkm::cli
