#include "cli/clidxf.h"

#include "cli/cli.h"
#include "cli/cliarguments.h"
#include "cli/clidesign.h"
#include "cli/clihelp.h"
#include "cli/clirender.h"
#include "document/savefile.h"
#include "export/dxfwriter.h"
#include "report/texttable.h"

#include <QString>

#include <algorithm>
#include <optional>

namespace pkm::cli {

using namespace report;

namespace {

constexpr std::string_view quotedCommand = "'pkm dxf'";
constexpr std::string_view seeHelp = " (see 'pkm dxf --help')";

bool isHelp(const std::string &argument)
{
    return argument == "-h" || argument == "--help";
}

/// The command line of `pkm dxf`.
struct DxfInvocation {
    bool help = false;
    std::optional<std::string> design;
    std::vector<Setting> sets;
    std::optional<std::string> output;
};

/// One --set NAME=VALUE, read exactly as every other command reads it: parseArguments()
/// parses it on a `pkm show` line (same numbers, same mode words, same messages).
Result<Setting> parseSetting(const std::string &value)
{
    const auto equals = value.find('=');
    if (equals == std::string::npos || equals == 0)
        return usageFailure(value, "--set needs NAME=VALUE, not '" + value + "'" + std::string(seeHelp) + ".");
    const auto parsed = parseArguments({"show", "-", "--set", value});
    if (!parsed)
        return parsed.failure();
    if (parsed->sets.size() != 1)
        return usageFailure(value, "--set needs NAME=VALUE, not '" + value + "'" + std::string(seeHelp) + ".");
    return parsed->sets.front();
}

Result<DxfInvocation> parseDxfArguments(const std::vector<std::string> &arguments)
{
    DxfInvocation invocation;
    if (arguments.front() == "help" || std::any_of(arguments.begin() + 1, arguments.end(), isHelp)) {
        invocation.help = true; // help wins over any other mistake on the line, as elsewhere
        return invocation;
    }
    bool optionsEnded = false;
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        const std::string &argument = arguments[i];
        if (optionsEnded || !argument.starts_with('-') || argument == "-") {
            if (invocation.design)
                return usageFailure(argument, "Unexpected argument '" + argument + "'" + std::string(seeHelp) + ".");
            invocation.design = argument;
            continue;
        }
        if (argument == "--") {
            optionsEnded = true;
            continue;
        }
        std::string option = argument;
        std::optional<std::string> inlineValue;
        if (const auto equals = argument.find('='); argument.starts_with("--") && equals != std::string::npos) {
            option = argument.substr(0, equals);
            inlineValue = argument.substr(equals + 1);
        }
        const bool output = option == "-o" || option == "--output";
        if (option != "--set" && !output) {
            return usageFailure(option,
                "'" + option + "' is not an option of " + std::string(quotedCommand) + std::string(seeHelp) + ".");
        }
        std::string value;
        if (inlineValue)
            value = *inlineValue;
        else if (i + 1 < arguments.size())
            value = arguments[++i];
        else
            return usageFailure(option, "'" + option + "' needs a value" + std::string(seeHelp) + ".");
        if (output) {
            if (value.empty() || fileExtension(value) != "dxf") {
                return usageFailure(value,
                    option + " " + value + ": " + std::string(quotedCommand)
                        + " writes a .dxf file, so the name must end in .dxf" + std::string(seeHelp) + ".");
            }
            invocation.output = value;
            continue;
        }
        auto setting = parseSetting(value);
        if (!setting)
            return setting.failure();
        invocation.sets.push_back(*setting);
    }
    if (!invocation.design) {
        return usageFailure("DESIGN",
            std::string(quotedCommand) + " needs a DESIGN: a preset id (see 'pkm list') or a .pkm.json file"
                + std::string(seeHelp) + ".");
    }
    if (!invocation.output)
        return usageFailure(
            "-o", std::string(quotedCommand) + " needs -o FILE, a .dxf file" + std::string(seeHelp) + ".");
    return invocation;
}

/// "160.0 × 95.5 mm"
std::string sizeText(const Eigen::AlignedBox2d &box)
{
    if (box.isEmpty())
        return "empty";
    const Eigen::Vector2d size = box.sizes();
    return fixedText(size.x(), 1) + " × " + fixedText(size.y(), 1) + " mm";
}

} // namespace

int runDxfCommand(const std::vector<std::string> &arguments, std::FILE *out, std::FILE *err)
{
    const auto parsed = parseDxfArguments(arguments);
    if (!parsed) {
        printError(err, parsed.failure().message);
        return cliExitCode(parsed.failure());
    }
    if (parsed->help)
        return printOutput(out, err, dxfHelpText());

    const auto prepared = prepareDesign(*parsed->design, parsed->sets);
    if (!prepared) {
        printError(err, prepared.failure().message);
        return cliExitCode(prepared.failure());
    }
    if (!prepared->note.empty())
        printError(err, "note: " + prepared->note);

    dxf::DrawingOptions options;
    options.caption = renderCaption(*prepared).toStdString();
    const dxf::Drawing drawing = dxf::sceneDrawing(prepared->mechanism->scene(prepared->pose), options);
    const std::string &path = *parsed->output;
    if (const auto failure = files::saveFile(path, [&](const files::ChunkWriter &write) { return write(drawing.dxf); })) {
        printError(err, *failure);
        return CliOutputError;
    }
    if (drawing.skipped > 0) {
        printError(err,
            "note: " + std::to_string(drawing.skipped)
                + " element(s) of the drawing were left out: a coordinate is not finite in this pose.");
    }
    std::string line("Wrote ");
    line.append(path)
        .append(" (AutoCAD R12 DXF, mm, ")
        .append(std::to_string(drawing.entities))
        .append(" entities, ")
        .append(sizeText(drawing.extents))
        .append(")\n");
    return printOutput(out, err, line);
}

} // namespace pkm::cli
