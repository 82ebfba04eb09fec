#include "cli/cliarguments.h"

#include "cli/cliargumentvalues.h"
#include "cli/clicapabilitymap.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

namespace pkm::cli {

namespace {

enum OptionFlag : unsigned {
    OptionJson = 1u << 0,
    OptionCsv = 1u << 1,
    OptionSet = 1u << 2,
    OptionSweep = 1u << 3, ///< --var, --from, --to, --steps
    OptionDesign = 1u << 4, ///< takes a DESIGN argument
    OptionGrid = 1u << 5,
    OptionQuantity = 1u << 6,
    OptionOutput = 1u << 7, ///< -o FILE
    OptionPicture = 1u << 8, ///< --view, --size, --camera, --orthographic, --no-caption, --one-way, --plot
    OptionLanguage = 1u << 9, ///< --lang CODE
    OptionModes = 1u << 10, ///< --all-modes
    OptionEquations = 1u << 11, ///< --equations
    OptionTolerance = 1u << 12, ///< --tol, --samples, --seed, --normal
    OptionRequire = 1u << 13, ///< --require NAME>=VALUE (workspace, map)
    OptionTol = 1u << 14, ///< --tol NAME=±V (tolerance; map --quantity tolerance)
};

struct CommandSpec {
    Command command;
    std::string_view name;
    unsigned options;
    std::array<std::string_view, 6> outputTypes {}; ///< the extensions -o takes (empty: unused)
    bool needsOutput = false; ///< -o FILE is required
};

constexpr std::array<CommandSpec, 9> commandSpecs = {{
    {Command::List, "list", OptionJson},
    {Command::Show, "show", OptionDesign | OptionJson | OptionSet},
    {Command::Eval, "eval", OptionDesign | OptionJson | OptionSet | OptionModes | OptionEquations},
    {Command::Sweep, "sweep", OptionDesign | OptionJson | OptionCsv | OptionSet | OptionSweep},
    {Command::Workspace, "workspace", OptionDesign | OptionJson | OptionSet | OptionGrid | OptionOutput | OptionRequire,
        {"png", "svg"}},
    {Command::Map, "map",
        OptionDesign | OptionJson | OptionSet | OptionGrid | OptionQuantity | OptionOutput | OptionRequire | OptionTol,
        {"png", "csv"}},
    {Command::Render, "render", OptionDesign | OptionSet | OptionOutput | OptionPicture | OptionSweep,
        {"png", "svg", "pdf", "gif", "mp4", "webm"}, true},
    {Command::Sheet, "sheet", OptionDesign | OptionSet | OptionOutput | OptionLanguage, {"pdf", "json", "csv"}, true},
    {Command::Tolerance, "tolerance", OptionDesign | OptionJson | OptionSet | OptionTolerance | OptionTol | OptionGrid},
}};

const CommandSpec *findCommand(std::string_view name)
{
    for (const CommandSpec &spec : commandSpecs) {
        if (spec.name == name)
            return &spec;
    }
    return nullptr;
}

/// The flag of an option ("--json"), 0 for an unknown one.
unsigned optionFlag(std::string_view option)
{
    if (option == "--json")
        return OptionJson;
    if (option == "--csv")
        return OptionCsv;
    if (option == "--set")
        return OptionSet;
    if (option == "--var" || option == "--from" || option == "--to" || option == "--steps")
        return OptionSweep;
    if (option == "--grid")
        return OptionGrid;
    if (option == "--quantity")
        return OptionQuantity;
    if (option == "-o" || option == "--output")
        return OptionOutput;
    if (option == "--view" || option == "--size" || option == "--camera" || option == "--orthographic"
        || option == "--no-caption" || option == "--one-way" || option == "--plot")
        return OptionPicture;
    if (option == "--lang")
        return OptionLanguage;
    if (option == "--all-modes")
        return OptionModes;
    if (option == "--equations")
        return OptionEquations;
    if (option == "--tol")
        return OptionTol;
    if (option == "--samples" || option == "--seed" || option == "--normal")
        return OptionTolerance;
    if (option == "--require")
        return OptionRequire;
    return 0;
}

bool isHelp(const std::string &argument)
{
    return argument == "-h" || argument == "--help";
}

} // namespace

std::string_view commandName(Command command)
{
    for (const CommandSpec &spec : commandSpecs) {
        if (spec.command == command)
            return spec.name;
    }
    return {};
}

std::string fileExtension(std::string_view path)
{
    const std::size_t slash = path.find_last_of('/');
    const std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
    const std::size_t dot = name.find_last_of('.');
    if (dot == std::string_view::npos || dot == 0)
        return {};
    std::string extension(name.substr(dot + 1));
    for (char &c : extension) {
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    }
    return extension;
}

Failure usageFailure(std::string culprit, std::string message)
{
    return Failure {FailureKind::InvalidParameter, std::move(culprit), std::move(message)};
}

Failure inContext(Failure failure, const std::string &context)
{
    failure.message = context + ": " + failure.message;
    return failure;
}

Result<Invocation> parseArguments(const std::vector<std::string> &arguments)
{
    Invocation invocation;
    if (arguments.empty())
        return usageFailure({}, "No command given: try 'pkm --help'.");

    const std::string &first = arguments.front();
    if (isHelp(first) || first == "help") {
        invocation.help = true;
        if (first == "help" && arguments.size() > 1) {
            const CommandSpec *spec = findCommand(arguments[1]);
            if (!spec)
                return usageFailure(arguments[1], "Unknown command '" + arguments[1] + "': try 'pkm --help'.");
            invocation.command = spec->command;
        }
        return invocation;
    }
    if (first == "--version" || first == "-V") {
        invocation.version = true;
        return invocation;
    }
    if (first.starts_with('-'))
        return usageFailure(first, "Unknown option '" + first + "' before the command: try 'pkm --help'.");
    const CommandSpec *spec = findCommand(first);
    if (!spec)
        return usageFailure(first, "Unknown command '" + first + "': try 'pkm --help'.");
    const CommandSpec &command = *spec;
    invocation.command = command.command;
    // Help wins over any other mistake on the line, even after "--".
    if (std::any_of(arguments.begin() + 1, arguments.end(), isHelp)) {
        invocation.help = true;
        return invocation;
    }

    const std::string quotedCommand = "'pkm " + std::string(command.name) + "'";
    const std::string seeHelp = " (see 'pkm " + std::string(command.name) + " --help')";
    bool optionsEnded = false;
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        const std::string &argument = arguments[i];
        if (optionsEnded || !argument.starts_with('-') || argument == "-") {
            if (!(command.options & OptionDesign) || invocation.design)
                return usageFailure(argument, "Unexpected argument '" + argument + "'" + seeHelp + ".");
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
        const unsigned flag = optionFlag(option);
        if (!(flag & command.options)) {
            return usageFailure(option, "'" + option + "' is not an option of " + quotedCommand + seeHelp + ".");
        }
        if (flag == OptionJson || flag == OptionCsv || flag == OptionModes || flag == OptionEquations) {
            if (inlineValue)
                return usageFailure(option, "'" + option + "' takes no value" + seeHelp + ".");
            (flag == OptionJson        ? invocation.json
             : flag == OptionCsv       ? invocation.csv
             : flag == OptionModes     ? invocation.allModes
                                       : invocation.equations) = true;
            continue;
        }
        if (option == "--normal") {
            if (inlineValue)
                return usageFailure(option, "'" + option + "' takes no value" + seeHelp + ".");
            invocation.normal = true;
            continue;
        }
        if (option == "--orthographic" || option == "--no-caption" || option == "--one-way") {
            if (inlineValue)
                return usageFailure(option, "'" + option + "' takes no value" + seeHelp + ".");
            if (option == "--orthographic")
                invocation.orthographic = true;
            else if (option == "--one-way")
                invocation.oneWay = true;
            else
                invocation.caption = false;
            continue;
        }
        // The remaining options take a value, which may look like a negative number.
        std::string value;
        if (inlineValue) {
            value = *inlineValue;
        } else if (i + 1 < arguments.size()) {
            value = arguments[++i];
        } else {
            return usageFailure(option, "'" + option + "' needs a value" + seeHelp + ".");
        }
        const std::string context = option + " " + value;
        if (option == "--set") {
            const auto equals = value.find('=');
            if (equals == std::string::npos || equals == 0)
                return usageFailure(value, "--set needs NAME=VALUE, not '" + value + "'" + seeHelp + ".");
            const std::string name = value.substr(0, equals);
            const std::string_view number = std::string_view(value).substr(equals + 1);
            const auto parsed = parseNumber(number);
            const bool word = !number.empty()
                && std::all_of(number.begin(), number.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); });
            if (!parsed && !word)
                return notANumber(context, name, number);
            if (parsed)
                invocation.sets.push_back({value, name, *parsed, {}});
            else
                invocation.sets.push_back({value, name, std::nan(""), std::string(number)});
        } else if (option == "--tol") {
            const auto equals = value.find('=');
            if (equals == std::string::npos || equals == 0)
                return usageFailure(value, "--tol needs NAME=±VALUE, not '" + value + "'" + seeHelp + ".");
            const std::string name = value.substr(0, equals);
            std::string_view number = std::string_view(value).substr(equals + 1);
            // "±0.05", "+-0.05" and "0.05" all mean the same half-width
            for (const std::string_view sign : {std::string_view("±"), std::string_view("+-"), std::string_view("+/-")}) {
                if (number.starts_with(sign)) {
                    number.remove_prefix(sign.size());
                    break;
                }
            }
            const auto parsed = parseNumber(number);
            if (!parsed)
                return notANumber(context, name, number);
            if (*parsed < 0)
                return usageFailure(name, context + ": a tolerance is a half-width ±VALUE with VALUE ≥ 0.");
            invocation.tolerances.push_back({value, name, *parsed});
        } else if (option == "--samples") {
            const auto number = parseNumber(value);
            if (!number || *number < 0 || *number > maxToleranceSamples || *number != std::floor(*number)) {
                return usageFailure("--samples", context + ": the number of Monte Carlo samples must be a whole number "
                                                           "from 0 (first order only) to "
                        + std::to_string(maxToleranceSamples) + ".");
            }
            invocation.samples = static_cast<int>(*number);
        } else if (option == "--seed") {
            std::uint64_t seed = 0;
            const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), seed);
            if (value.empty() || error != std::errc() || end != value.data() + value.size())
                return usageFailure("--seed", context + ": the seed must be a whole number from 0 to 18446744073709551615.");
            invocation.seed = seed;
        } else if (option == "--var") {
            invocation.var = value;
        } else if (option == "--plot") {
            invocation.plot = value; // checked against the design's quantities by the command
        } else if (option == "--lang") {
            invocation.language = value;
        } else if (option == "--grid") {
            const auto number = parseNumber(value);
            if (!number || *number < minGrid || *number > maxGrid || *number != std::floor(*number)) {
                return usageFailure("--grid",
                    context + ": the grid must be a whole number of cells from " + std::to_string(minGrid) + " to "
                        + std::to_string(maxGrid) + " (along the longer side of the workspace).");
            }
            invocation.grid = static_cast<int>(*number);
        } else if (option == "--quantity") {
            if (!quantityOf(value)) {
                return usageFailure("--quantity",
                    context + ": the quantity must be 'det' (det J), 'cond' (the condition number of J), 'range' (the "
                              "orientation range of a platform that turns), one of what the actuators deliver "
                              "('force_worst', 'speed_worst', 'resolution_worst', 'stiffness_worst'), 'spec' (where "
                              "every --require holds) or 'tolerance' (the worst-case error from --tol).");
            }
            invocation.quantity = value;
        } else if (option == "--require") {
            // checked against the design's actuators by the command (capabilitymap.h)
            invocation.requirements.push_back(value);
        } else if (flag == OptionOutput) {
            const std::string extension = fileExtension(value);
            const auto &types = command.outputTypes;
            if (value.empty() || extension.empty() || std::find(types.begin(), types.end(), extension) == types.end()) {
                return usageFailure(value,
                    option + " " + value + ": " + quotedCommand + " writes " + fileTypes(types)
                        + ", so the name must end in one of these" + seeHelp + ".");
            }
            invocation.output = value;
        } else if (option == "--view") {
            if (value != "2d" && value != "3d") {
                return usageFailure("--view",
                    context + ": the view must be '2d' (the drawing of the mechanism plane) or '3d' (the solid model)"
                        + seeHelp + ".");
            }
            invocation.view = value;
        } else if (option == "--camera") {
            if (value != "front" && value != "top" && value != "side" && value != "iso") {
                return usageFailure(
                    "--camera", context + ": the camera must be 'front', 'top', 'side' or 'iso'" + seeHelp + ".");
            }
            invocation.camera = value;
        } else if (option == "--size") {
            const auto size = parseSize(value);
            const auto valid = [](double side) {
                return side >= minPictureSide && side <= maxPictureSide && side == std::floor(side);
            };
            if (!size || !valid(size->first) || !valid(size->second)) {
                std::string message(context);
                message.append(": the size must be WIDTHxHEIGHT in pixels, whole numbers from ")
                    .append(std::to_string(minPictureSide))
                    .append(" to ")
                    .append(std::to_string(maxPictureSide))
                    .append(", e.g. 1600x1200")
                    .append(seeHelp)
                    .append(".");
                return usageFailure("--size", message);
            }
            invocation.width = static_cast<int>(size->first);
            invocation.height = static_cast<int>(size->second);
            invocation.sizeGiven = true;
        } else if (option == "--steps") {
            const auto number = parseNumber(value);
            // 10^9 rows are ~300 GB of CSV: far beyond any use.
            if (!number || *number < 1 || *number > 1e9 || *number != std::floor(*number)) {
                return usageFailure("--steps",
                    context
                        + ": the number of steps must be a whole number from 1 to "
                          "1000000000.");
            }
            invocation.steps = static_cast<std::int64_t>(*number);
        } else {
            const auto number = parseNumber(value);
            if (!number)
                return notANumber(context, option, value);
            (option == "--from" ? invocation.from : invocation.to) = *number;
        }
    }

    if ((command.options & OptionDesign) && !invocation.design) {
        return usageFailure("DESIGN",
            quotedCommand + " needs a DESIGN: a preset id (see 'pkm list') or a .pkm.json file" + seeHelp + ".");
    }
    if (command.needsOutput && !invocation.output) {
        return usageFailure("-o", quotedCommand + " needs -o FILE, " + fileTypes(command.outputTypes) + seeHelp + ".");
    }
    if (invocation.view.value_or("2d") != "3d") {
        if (invocation.camera)
            return usageFailure("--camera", "--camera " + *invocation.camera + " needs --view 3d" + seeHelp + ".");
        if (invocation.orthographic)
            return usageFailure("--orthographic", "--orthographic needs --view 3d" + seeHelp + ".");
    }
    if (invocation.json && invocation.csv)
        return usageFailure("--csv", "--csv and --json exclude each other: give one.");
    const std::string outputType = invocation.output ? fileExtension(*invocation.output) : std::string();
    const bool video = outputType == "mp4" || outputType == "webm";
    const bool animation = invocation.command == Command::Render && (outputType == "gif" || video);
    if (invocation.command == Command::Render && !animation) {
        const std::optional<std::string> &sweepOption = invocation.var ? std::optional<std::string>("--var")
            : invocation.from                                          ? std::optional<std::string>("--from")
            : invocation.to                                            ? std::optional<std::string>("--to")
            : invocation.steps ? std::optional<std::string>("--steps")
            : invocation.oneWay ? std::optional<std::string>("--one-way")
            : invocation.plot   ? std::optional<std::string>("--plot")
                                : std::nullopt;
        if (sweepOption) {
            return usageFailure(*sweepOption,
                *sweepOption + " makes an animation: it needs -o FILE.gif, FILE.mp4 or FILE.webm" + seeHelp + ".");
        }
    }
    if (animation) {
        if (!invocation.sizeGiven) {
            // A plot beside the mechanism takes half the frame: a GIF gets the video's wide frame.
            const bool wide = video || invocation.plot;
            invocation.width = wide ? defaultVideoWidth : defaultAnimationWidth;
            invocation.height = wide ? defaultVideoHeight : defaultAnimationHeight;
        }
        if (invocation.view.value_or("2d") != "2d") {
            return usageFailure("--view", std::string(video ? "A video" : "An animated GIF")
                    + " is drawn from the 2D view: leave out --view 3d.");
        }
        if (invocation.steps && (*invocation.steps < minAnimationSteps || *invocation.steps > maxAnimationSteps)) {
            return usageFailure("--steps",
                "--steps " + std::to_string(*invocation.steps) + ": an animation has "
                    + std::to_string(minAnimationSteps) + " to " + std::to_string(maxAnimationSteps) + " frames.");
        }
    }
    if ((command.options & OptionSweep) && (invocation.command != Command::Render || animation)) {
        const auto missing = [&](const char *option, const char *what) {
            return usageFailure(option, quotedCommand + " needs " + option + " " + what + seeHelp + ".");
        };
        if (!invocation.var)
            return missing("--var", "NAME (a pose variable or a parameter)");
        if (!invocation.from)
            return missing("--from", "A (the first value)");
        if (!invocation.to)
            return missing("--to", "B (the last value)");
        if (!invocation.steps)
            return missing("--steps", animation ? "K (the number of frames)" : "K (the number of rows)");
    }
    return invocation;
}

} // namespace pkm::cli
