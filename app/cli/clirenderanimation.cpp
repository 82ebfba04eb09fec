// `pkm render … --var N --from A --to B --steps K -o FILE.gif|.mp4|.webm`: the sweep's poses
// solved one from the other, each drawn as the 2D picture, then an animated GIF (all frames
// at once, giflib wants them) or a video (one frame at a time, FFmpeg encodes as it goes).

#include "cli/cli.h"
#include "cli/clirender.h"
#include "document/savefile.h"
#include "export/animation.h"
#include "export/animationplot.h"
#include "export/videowriter.h"
#include "report/texttable.h"
#include "text.h"

#include <QFileInfo>
#include <QSize>

#include <cstdio>
#include <string>

namespace pkm::cli {

namespace {
/// The option a failure of the animation is about: --steps for its frames, --steps and
/// --size for its pixels, else the swept variable.
std::string culpritOf(const Failure &failure, const std::string &variable)
{
    if (failure.culprit == "frames")
        return "--steps";
    if (failure.culprit == "pixels")
        return "--steps and --size";
    return "--var " + variable;
}
} // namespace

namespace {

/// "40 frames of 1280 × 720 pixels"
std::string framesText(int frames, const Invocation &invocation)
{
    std::string text(std::to_string(frames));
    text.append(" frames of ")
        .append(std::to_string(invocation.width))
        .append(" × ")
        .append(std::to_string(invocation.height))
        .append(" pixels");
    return text;
}

/// "1.3 s" at 30 frames/s.
std::string durationText(int frames)
{
    return report::fixedText(static_cast<double>(frames) / videoFramesPerSecond, 1) + " s";
}

} // namespace

int runRenderAnimation(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err)
{
    const Mechanism &mechanism = *prepared.mechanism;
    const std::string &name = *invocation.var;
    const int variable = mechanism.variableIndex(name);
    if (variable < 0) {
        printError(err,
            joinText({"--var ", name, ": an animation moves a pose variable of the ", std::string(mechanism.kind()),
                " (see 'pkm show ", prepared.origin, "')."}));
        return CliUsageError;
    }
    const QString path = QString::fromStdString(*invocation.output);
    const std::optional<VideoFormat> video = videoFormatForPath(path);
    const QSize size(invocation.width, invocation.height);
    if (video) {
        if (const QString problem = videoSizeProblem(size); !problem.isEmpty()) {
            printError(err,
                "--size " + std::to_string(size.width()) + "x" + std::to_string(size.height()) + ": "
                    + problem.toStdString());
            return CliUsageError;
        }
    }
    if (!prepared.note.empty())
        printError(err, "note: " + prepared.note);
    const Unit &unit = mechanism.variableInfo()[variable].unit;
    AnimationSettings settings;
    settings.variable = variable;
    settings.from = unit.fromDisplay(*invocation.from);
    settings.to = unit.fromDisplay(*invocation.to);
    settings.frames = static_cast<int>(*invocation.steps);
    settings.bounce = !invocation.oneWay;
    settings.size = size;
    settings.caption = invocation.caption;
    settings.name = QFileInfo(QString::fromStdString(prepared.origin)).fileName();
    const std::string way = settings.bounce ? "forth and back)\n" : "one way)\n";
    if (invocation.plot) {
        // Solved once for the whole animation; each frame then draws it with its cursor.
        auto plot = animationPlot(mechanism, prepared.pose, settings, *invocation.plot);
        if (!plot) {
            printError(err, "--plot " + text::printable(*invocation.plot, 40) + ": " + plot.failure().message);
            return CliUsageError;
        }
        settings.beside = [plot = std::move(*plot), &mechanism](const Pose &pose, const QSize &side) {
            return animationPlotImage(plot, mechanism, pose, side);
        };
    }

    std::string line("Wrote ");
    line.append(*invocation.output);
    if (video) {
        auto poses = animationPoses(mechanism, prepared.pose, settings);
        if (!poses) {
            printError(err, culpritOf(poses.failure(), name) + ": " + poses.failure().message);
            return cliExitCode(poses.failure());
        }
        const VideoExport written = writeAnimationVideo(mechanism, *poses, settings, path);
        if (!written.ok()) {
            printError(err, written.error.toStdString());
            return CliOutputError;
        }
        line.append(*video == VideoFormat::Mp4 ? " (MP4 video, " : " (WebM video, ")
            .append(written.codec.toStdString())
            .append(", ")
            .append(framesText(written.frames, invocation))
            .append(" at ")
            .append(std::to_string(videoFramesPerSecond))
            .append(" frames/s, ")
            .append(durationText(written.frames))
            .append(", ")
            .append(way);
        return printOutput(out, err, line);
    }

    auto gif = renderAnimation(mechanism, prepared.pose, settings);
    if (!gif) {
        printError(err, culpritOf(gif.failure(), name) + ": " + gif.failure().message);
        return cliExitCode(gif.failure());
    }
    if (const auto failure = files::saveBytes(*invocation.output, *gif)) {
        printError(err, *failure);
        return CliOutputError;
    }
    line.append(" (animated GIF, ")
        .append(framesText(animationFrameCount(settings.frames, settings.bounce), invocation))
        .append(", ")
        .append(way);
    return printOutput(out, err, line);
}

} // namespace pkm::cli
