#include "export/animation.h"

#include "export/scenepicture.h"
#include "export/gifwriter.h"
#include "export/videowriter.h"
#include "quantityformat.h"
#include "scenepainter.h"
#include "text.h"

#include <QCoreApplication>
#include <QPainter>

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace pkm {

namespace {
/// A message for the GUI's status bar and the CLI's stderr (English there: no catalogue).
std::string message(const QString &text)
{
    return text.toStdString();
}

/// A number in a sentence: the locale's decimal point in the GUI, '.' in the CLI.
QString numberText(double value, int decimals)
{
    return toQString(text::number(value, decimals));
}
} // namespace

Result<std::vector<Pose>> animationPoses(const Mechanism &mechanism, const Pose &start,
                                         const AnimationSettings &settings)
{
    const auto &variables = mechanism.variableInfo();
    if (settings.variable < 0 || settings.variable >= static_cast<int>(variables.size()))
        return Failure{FailureKind::UnknownName, {},
                       message(QCoreApplication::translate("pkm::Animation",
                                                           "The animation needs a pose variable of the mechanism."))};
    const VariableInfo &info = variables[settings.variable];
    if (settings.frames < minAnimationFrames || settings.frames > maxAnimationFrames) {
        return Failure{FailureKind::InvalidParameter, "frames",
                       message(QCoreApplication::translate("pkm::Animation", "An animation has %1 to %2 frames, not %3.")
                                   .arg(numberText(minAnimationFrames, 0), numberText(maxAnimationFrames, 0),
                                        numberText(settings.frames, 0)))};
    }
    const double pixels = double(animationFrameCount(settings.frames, settings.bounce)) * settings.size.width()
        * settings.size.height();
    if (pixels > maxAnimationPixels) {
        return Failure{FailureKind::InvalidParameter, "pixels",
                       message(QCoreApplication::translate("pkm::Animation",
                                                           "An animation draws at most %1 million pixels (frames × "
                                                           "width × height); %2 frames of %3 × %4 would be %5 million: "
                                                           "take fewer steps or a smaller size.")
                                   .arg(numberText(maxAnimationPixels / 1e6, 0))
                                   .arg(animationFrameCount(settings.frames, settings.bounce))
                                   .arg(settings.size.width())
                                   .arg(settings.size.height())
                                   .arg(numberText(pixels / 1e6, 0)))};
    }
    std::vector<Pose> poses;
    poses.reserve(settings.frames);
    Pose near = start;
    for (int i = 0; i < settings.frames; ++i) {
        const double t = static_cast<double>(i) / (settings.frames - 1);
        const double value = i + 1 == settings.frames ? settings.to : settings.from + t * (settings.to - settings.from);
        auto solved = mechanism.solveWith(near, settings.variable, value);
        if (!solved) {
            Failure failure = solved.failure();
            const QString unit = toQString(text::label(info.unit.symbol));
            const QString shown = numberText(info.unit.toDisplay(value), info.decimals)
                + (unit.isEmpty() || unit.startsWith(QChar(0x00B0)) ? QString() : QStringLiteral(" ")) + unit;
            failure.message = message(QCoreApplication::translate("pkm::Animation", "Frame %1 (%2 = %3): %4")
                                          .arg(numberText(i + 1, 0), toQString(info.name), shown,
                                               toQString(failure.message)));
            return failure;
        }
        near = *solved;
        poses.push_back(near);
    }
    return poses;
}

Interval animationRange(const Mechanism &mechanism, const Pose &start, int variable)
{
    const Interval range = mechanism.variableRange(variable);
    const double here = std::clamp(mechanism.variableValue(start, variable), range.min, range.max);
    // Small steps, each solved from the last: the solver refuses a step that changes a mode or
    // crosses a singularity, and the range ends one step before the first refused.
    constexpr int steps = 400;
    const double step = (range.max - range.min) / steps;
    if (!(step > 0))
        return range;
    const auto reach = [&](double direction, double limit) {
        Pose near = start;
        double reached = here, previous = here;
        for (int i = 1; i <= steps; ++i) {
            const double value = direction > 0 ? std::min(limit, here + i * step) : std::max(limit, here - i * step);
            auto solved = mechanism.solveWith(near, variable, value);
            if (!solved)
                return previous; // a step short of the first pose refused
            near = *solved;
            previous = reached;
            reached = value;
            if (value == limit)
                return value;
        }
        return reached;
    };
    return {reach(-1.0, range.min), reach(1.0, range.max)};
}

int animationFrameCount(int poses, bool bounce)
{
    return bounce && poses > 2 ? 2 * poses - 2 : poses;
}

namespace {
/// The poses in playing order: back again without repeating the turning points, so the loop
/// runs smoothly.
std::vector<const Pose *> frameOrder(const std::vector<Pose> &poses, bool bounce)
{
    std::vector<const Pose *> order;
    for (const Pose &pose : poses)
        order.push_back(&pose);
    if (bounce && poses.size() > 2) {
        for (auto it = poses.rbegin() + 1; it + 1 != poses.rend(); ++it)
            order.push_back(&*it);
    }
    return order;
}

/// Where the labels stood, pose by pose, as an animation's frames are drawn: on the way forth
/// each frame starts from the frame before's places, so that a label keeps its side while it
/// can; on the way back each pose is drawn from its own places of the way forth, so that a
/// bounced animation passes the same pictures back and closes its loop on the first.
class FrameLabels
{
public:
    explicit FrameLabels(const std::vector<Pose> &poses)
        : m_poses(poses)
        , m_byPose(poses.size())
    {
    }
    /// The places to draw `pose` (one of the poses) from; the drawing leaves its own there.
    std::vector<std::pair<QString, QPointF>> *before(const Pose *pose)
    {
        m_index = std::size_t(pose - m_poses.data());
        m_buffer = m_byPose[m_index] ? *m_byPose[m_index] : m_last;
        return &m_buffer;
    }
    /// After the frame of before()'s pose is drawn.
    void after()
    {
        if (!m_byPose[m_index]) {
            m_byPose[m_index] = m_buffer;
            m_last = m_buffer;
        }
    }

private:
    const std::vector<Pose> &m_poses;
    std::vector<std::optional<std::vector<std::pair<QString, QPointF>>>> m_byPose;
    std::vector<std::pair<QString, QPointF>> m_last, m_buffer;
    std::size_t m_index = 0;
};
} // namespace

Eigen::AlignedBox3d sweptExtent(const Mechanism &mechanism, const std::vector<Pose> &poses)
{
    Eigen::AlignedBox3d swept, whole;
    for (const Pose &pose : poses) {
        const Scene scene = mechanism.scene(pose);
        if (scene.poseExtent.isEmpty())
            return {}; // a kind whose range of motion is its pose's size
        swept.extend(scene.poseExtent);
        whole = scene.extent;
    }
    const auto area = [](const Eigen::AlignedBox3d &box) { return box.sizes().x() * box.sizes().y(); };
    if (swept.isEmpty() || whole.isEmpty() || area(swept) >= 0.5 * area(whole))
        return {};
    return swept;
}

QImage animationFrame(const Mechanism &mechanism, const Pose &pose, const AnimationSettings &settings,
                      std::vector<std::pair<QString, QPointF>> *labelPlaces)
{
    const SceneStyle style;
    QImage image(settings.size, QImage::Format_RGB32);
    image.fill(style.background);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing, true);
    // Beside a plot the scene has half the width: the pose alone, which the caption is for.
    const QString caption = settings.caption
        ? pictures::poseCaption(mechanism, pose, settings.beside ? QString() : settings.name)
        : QString();
    QRect scene = image.rect();
    if (settings.beside) {
        // The mechanism at the left, the plot at the right: half each, the plot's side even.
        const int plotWidth = (image.width() / 2) & ~1;
        scene.setWidth(image.width() - plotWidth);
        const QImage plot = settings.beside(pose, QSize(plotWidth, image.height()));
        painter.drawImage(QRect(scene.right() + 1, 0, plotWidth, image.height()), plot);
        painter.setPen(QColor(0xc8, 0xcf, 0xd9));
        painter.drawLine(scene.topRight(), scene.bottomRight());
    }
    Scene drawn = mechanism.scene(pose);
    if (!settings.extent.isEmpty())
        drawn.extent = settings.extent;
    pictures::paintScenePicture(painter, QRectF(scene), drawn, style, caption, pictures::PictureFit::MotionRange,
                                labelPlaces);
    painter.end();
    return image;
}

QList<QImage> animationFrames(const Mechanism &mechanism, const std::vector<Pose> &poses,
                              const AnimationSettings &settings, const std::atomic<bool> *cancel)
{
    AnimationSettings fitted = settings;
    fitted.extent = sweptExtent(mechanism, poses);
    const std::vector<const Pose *> order = frameOrder(poses, settings.bounce);
    QList<QImage> frames;
    frames.reserve(static_cast<qsizetype>(order.size()));
    FrameLabels labels(poses);
    for (const Pose *pose : order) {
        if (cancel && cancel->load())
            return {};
        frames.append(animationFrame(mechanism, *pose, fitted, labels.before(pose)));
        labels.after();
    }
    return frames;
}

VideoExport writeAnimationVideo(const Mechanism &mechanism, const std::vector<Pose> &poses,
                                const AnimationSettings &settings, const QString &path,
                                const std::atomic<bool> *cancel, const AnimationProgress &progress)
{
    VideoExport result;
    const auto format = videoFormatForPath(path);
    if (!format) {
        result.error = QCoreApplication::translate("pkm::Animation", "A video file's name ends in .mp4 or .webm: %1.")
                           .arg(path);
        return result;
    }
    VideoWriter writer;
    if (!writer.open(path, *format, settings.size, &result.error))
        return result;
    result.codec = writer.codecName();
    AnimationSettings fitted = settings;
    fitted.extent = sweptExtent(mechanism, poses);
    const std::vector<const Pose *> order = frameOrder(poses, settings.bounce);
    const int total = static_cast<int>(order.size());
    FrameLabels labels(poses);
    for (int i = 0; i < total; ++i) {
        if (cancel && cancel->load()) {
            result.cancelled = true;
            return result; // the writer discards its temporary file
        }
        if (!writer.addFrame(animationFrame(mechanism, *order[i], fitted, labels.before(order[i])), &result.error))
            return result;
        labels.after();
        if (progress)
            progress(i + 1, total);
    }
    if (cancel && cancel->load()) {
        result.cancelled = true;
        return result;
    }
    if (writer.finish(&result.error))
        result.frames = writer.framesWritten();
    return result;
}

Result<QByteArray> renderAnimation(const Mechanism &mechanism, const Pose &start, const AnimationSettings &settings,
                                   const std::atomic<bool> *cancel)
{
    auto poses = animationPoses(mechanism, start, settings);
    if (!poses)
        return poses.failure();
    // Drawn and encoded one frame at a time: memory holds one frame and the compressed GIF,
    // whatever the number of frames.
    QString error;
    GifOptions options;
    options.frameMilliseconds = settings.frameMilliseconds;
    GifEncoder encoder;
    AnimationSettings fitted = settings;
    fitted.extent = sweptExtent(mechanism, *poses);
    if (!encoder.begin(settings.size, options, &error))
        return Failure{FailureKind::InvalidParameter, {}, error.toStdString()};
    FrameLabels labels(*poses);
    for (const Pose *pose : frameOrder(*poses, settings.bounce)) {
        if (cancel && cancel->load())
            return Failure{FailureKind::InvalidParameter, {},
                           message(QCoreApplication::translate("pkm::Animation", "The animation was cancelled."))};
        if (!encoder.addFrame(animationFrame(mechanism, *pose, fitted, labels.before(pose)), &error))
            return Failure{FailureKind::InvalidParameter, {}, error.toStdString()};
        labels.after();
    }
    const QByteArray gif = encoder.finish(&error);
    if (gif.isEmpty())
        return Failure{FailureKind::InvalidParameter, {}, error.toStdString()};
    return gif;
}

} // namespace pkm
