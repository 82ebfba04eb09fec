#pragma once
/// The command line of `pkm`, parsed: which command, its options and the --set values. Only
/// the syntax is checked here; names are checked against the design (clidesign.h).

#include "result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pkm::cli {

enum class Command { List, Show, Eval, Sweep, Workspace, Map, Render, Sheet, Tolerance };

/// "list", "show", "eval", "sweep", "workspace", "map", "render", "sheet", "tolerance".
std::string_view commandName(Command command);

/// --grid K of workspace and map: K cells along the longer side of the workspace.
inline constexpr int defaultGrid = 400;
inline constexpr int minGrid = 10;
inline constexpr int maxGrid = 4000; ///< 16 million cells, 128 MB of map and margins

/// --size WxH of render: pixels per side.
inline constexpr int defaultPictureWidth = 1600;
inline constexpr int defaultPictureHeight = 1200;
inline constexpr int minPictureSide = 16;
inline constexpr int maxPictureSide = 8000;
/// render -o FILE.gif: the frames of the animation (--steps), and its default size.
inline constexpr int minAnimationSteps = 2;
inline constexpr int maxAnimationSteps = 1000;
inline constexpr int defaultAnimationWidth = 960;
inline constexpr int defaultAnimationHeight = 720;
/// A video's default size (-o FILE.mp4|.webm): 720p, the projector's; the limits are the
/// encoder's (export/videowriter.h), checked when the video is opened.
inline constexpr int defaultVideoWidth = 1280;
inline constexpr int defaultVideoHeight = 720;

/// One --set NAME=VALUE.
struct Setting {
    std::string text; ///< as typed, "theta=30", for messages
    std::string name;
    double value = 0.0;
    /// The value when it is not a number ("X" in mode=X): a mode's name, resolved against the
    /// design's parameters (value is NaN then).
    std::string word;
};

/// One --tol NAME=±VALUE (tolerance): the half-width in the parameter's display units.
struct ToleranceSetting {
    std::string text; ///< as typed, "l1=±0.05", for messages
    std::string name;
    double value = 0.0;
};

/// --samples N (tolerance): Monte Carlo samples, 0 for the first order alone.
inline constexpr int defaultToleranceSamples = 2000;
inline constexpr int maxToleranceSamples = 100000;

struct Invocation {
    std::optional<Command> command; ///< none for `pkm --help` and `pkm --version`
    bool help = false;
    bool version = false;
    bool json = false;
    bool csv = false;
    bool allModes = false; ///< --all-modes (eval): every assembly mode at the inputs
    bool equations = false; ///< --equations (eval): the governing equations with the pose's numbers
    std::optional<std::string> design;
    std::vector<Setting> sets;
    std::optional<std::string> var;
    std::optional<double> from;
    std::optional<double> to;
    std::optional<std::int64_t> steps;
    std::optional<int> grid; ///< --grid K (workspace, map): cells along the longer side
    std::optional<std::string> quantity; ///< --quantity det|cond|range|force_worst|…|spec (map)
    std::vector<std::string> requirements; ///< --require NAME>=VALUE (workspace, map), as given
    std::optional<std::string> output; ///< -o FILE (workspace, map, render, sheet), its extension checked
    std::optional<std::string> view; ///< --view 2d|3d (render)
    std::optional<std::string> camera; ///< --camera front|top|side|iso (render, 3d only)
    bool orthographic = false; ///< --orthographic (render, 3d only)
    bool caption = true; ///< false with --no-caption (render)
    bool oneWay = false; ///< --one-way (render -o FILE.gif): no way back to the start
    std::optional<std::string> plot; ///< --plot QUANTITY (render -o FILE.gif|.mp4|.webm): a plot beside the view
    int width = defaultPictureWidth; ///< --size WxH (render), pixels
    int height = defaultPictureHeight;
    bool sizeGiven = false; ///< --size was given (an animation's default size is smaller)
    std::optional<std::string> language; ///< --lang CODE (sheet), checked by the command (clisheet.h)
    std::vector<ToleranceSetting> tolerances; ///< --tol NAME=±V (tolerance), in order
    std::optional<int> samples; ///< --samples N (tolerance)
    std::optional<std::uint64_t> seed; ///< --seed S (tolerance)
    bool normal = false; ///< --normal (tolerance): normal samples with tol = 3σ
};

/// The lower-case extension of `path` without the dot ("png"), empty without one.
std::string fileExtension(std::string_view path);

/// Parses `arguments` (without the program name). A command that needs a DESIGN has one,
/// sweep has all of --var, --from, --to and --steps, --grid is a whole number from 10 to 4000,
/// --quantity is det or cond, -o names a file of a type the command writes (render needs one),
/// --view is 2d or 3d, --camera one of front, top, side, iso and only with --view 3d (as
/// --orthographic), and --size is WxH with whole numbers from 16 to 8000.
Result<Invocation> parseArguments(const std::vector<std::string> &arguments);

/// A mistake on the command line: exit status 2.
Failure usageFailure(std::string culprit, std::string message);

/// Prefixes a core message with the argument that caused it ("--set theta=75: θ = 75° is …"),
/// so the sentence names the culprit as the user typed it.
Failure inContext(Failure failure, const std::string &context);

} // namespace pkm::cli
