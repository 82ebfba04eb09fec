// libFuzzer target: the command line of `pkm` — the argument parser, the --set, --var, --tol
// and --require parsers, the design after --set (clidesign.h) and the commands that print:
// show, eval, sweep, workspace, map and tolerance — through runCli(), as a user types them.
//
// The input is the argument list, one argument per line. Arguments that would touch the file
// system (-o, a design file path) are not run: the target reads only presets and writes only
// to memory. Sizes are capped (largest()) and a map needs a small --grid, so that one input
// stays within seconds under the sanitizers.
//
// Checks: stderr is one printable line per failure; the exit status is one of docs/cli.md's;
// a --json output parses and holds no NaN or infinity.
#include "fuzzcheck.h"

#include "cli/cli.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

bool takesNumber(std::string_view option)
{
    return option == "--steps" || option == "--grid" || option == "--samples";
}

/// The largest value of --steps, --samples and --grid run: under the sanitizers a map costs
/// some 50 times what it does in a release build, and a Monte Carlo sample rebuilds the design.
double largest(std::string_view option)
{
    return option == "--grid" ? 40 : option == "--samples" ? 30 : 300;
}

/// The arguments, one per line; false when one of them is not for an in-memory run.
bool splitArguments(std::string_view input, QStringList &arguments)
{
    bool previousTakesNumber = false;
    std::string_view previous; // the option whose value comes next
    bool grid = false, maps = false, turning = false, monteCarlo = false, samples = false;
    while (!input.empty() && arguments.size() < 40) {
        const auto end = input.find('\n');
        const std::string_view argument = input.substr(0, end);
        input = end == std::string_view::npos ? std::string_view() : input.substr(end + 1);
        // files: no output file, no design file (only presets, which have no '/' or ".json")
        if (argument == "-o" || argument.starts_with("--output") || argument.find('/') != std::string_view::npos ||
            argument.find(".json") != std::string_view::npos)
            return false;
        // time: bounded sweeps, grids and samples ("--grid 300" or "--grid=300")
        std::string_view option = argument, value;
        if (const auto equals = argument.find('='); argument.starts_with("--") && equals != std::string_view::npos) {
            option = argument.substr(0, equals);
            value = argument.substr(equals + 1);
        } else if (previousTakesNumber) {
            value = argument;
        }
        if (!value.empty() && (previousTakesNumber || takesNumber(option)) &&
            !(std::strtod(std::string(value).c_str(), nullptr) <= largest(previousTakesNumber ? previous : option)))
            return false;
        previousTakesNumber = value.empty() && takesNumber(option);
        if (previousTakesNumber)
            previous = option;
        grid = grid || option == "--grid";
        turning = turning || argument.starts_with("pp-3"); // a platform that turns: 3-DOF presets
        maps = maps || argument == "workspace" || argument == "map";
        monteCarlo = monteCarlo || argument == "tolerance";
        samples = samples || option == "--samples";
        arguments << QString::fromUtf8(argument.data(), qsizetype(argument.size()));
    }
    // A map only on a small grid given, and not of a 3-DOF design: it maps each of its eight
    // working modes, some 15 s for a 20² grid under the sanitizers, a tenth of the target's
    // speed for the whole run (its maps are tested in tst_climapcapability and tst_cli).
    // Monte Carlo only with a few samples given: each rebuilds the design (the default 2000
    // take a second in a release build, a minute under the sanitizers).
    return (!maps || (grid && !turning)) && (!monteCarlo || samples);

}

std::string_view contents(char *buffer, std::size_t size) { return {buffer ? buffer : "", size}; }

} // namespace

// runCli() translates through QCoreApplication, as pkm's main() sets it up.
extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static QCoreApplication application(*argc, *argv);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size > 4096)
        return 0;
    QStringList arguments;
    if (!splitArguments({reinterpret_cast<const char *>(data), size}, arguments))
        return 0;

    char *outBuffer = nullptr, *errBuffer = nullptr;
    std::size_t outSize = 0, errSize = 0;
    std::FILE *out = open_memstream(&outBuffer, &outSize);
    std::FILE *err = open_memstream(&errBuffer, &errSize);
    const int status = pkm::runCli(arguments, out, err);
    std::fclose(out);
    std::fclose(err);
    const std::string_view output = contents(outBuffer, outSize);
    const std::string_view errors = contents(errBuffer, errSize);

    if (status < pkm::CliSuccess || status > pkm::CliNoSolution)
        pkm::fuzz::fail("an exit status docs/cli.md does not list", errors);
    if (status != pkm::CliSuccess) {
        // one sentence on one line, nothing on stdout
        if (!errors.starts_with("pkm: ") || errors.find('\n') != errors.size() - 1)
            pkm::fuzz::fail("a failure is not one 'pkm: …' line", errors);
        pkm::fuzz::checkMessage(errors);
        if (!output.empty())
            pkm::fuzz::fail("a failed command wrote to stdout", output);
    } else if (arguments.contains(QStringLiteral("--json")) && !arguments.contains(QStringLiteral("--help")) &&
               !arguments.contains(QStringLiteral("-h")) && arguments.first() != QStringLiteral("--version") &&
               arguments.first() != QStringLiteral("-V") && arguments.first() != QStringLiteral("help")) {
        // (help anywhere, and the help command or --version first, win over every other option
        // and print text: `pkm help eval --json` is eval's usage)
        pkm::fuzz::checkJson(QByteArray(output.data(), qsizetype(output.size())));
    }
    std::free(outBuffer);
    std::free(errBuffer);
    return 0;
}
