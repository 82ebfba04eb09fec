#pragma once
/// Animations of a sweep: one pose variable moved evenly from one value to another, each pose
/// drawn as the 2D picture `pkm render` makes, for an animated GIF (gifwriter.h) or a video
/// (videowriter.h). Shared by `pkm render … -o FILE.gif|.mp4|.webm` and the GUI's File →
/// Export Animation.

#include "mechanism.h"

#include <QImage>
#include <QList>
#include <QPointF>
#include <QSize>
#include <QString>

#include <atomic>
#include <functional>
#include <utility>
#include <vector>

namespace pkm {

struct AnimationSettings {
    int variable = 0;    ///< index into variableInfo()
    double from = 0.0;   ///< core units
    double to = 0.0;
    int frames = 60;     ///< poses from `from` to `to`, both included (≥ 2)
    bool bounce = true;  ///< play back to the start, so that a loop has no jump
    QSize size {960, 720};
    int frameMilliseconds = 50; ///< GIF only: a video has videoFramesPerSecond
    bool caption = true; ///< the pose under each frame
    QString name;        ///< the design's name in the caption
    /// A picture beside the mechanism, at the right half of each frame (none when empty): the
    /// plot of a quantity (animationplot.h) or, in the GUI, the plot on screen. Called for
    /// every frame from the thread that draws it, with the pose and the size it is to fill.
    std::function<QImage(const Pose &pose, const QSize &size)> beside;
    /// The box every frame is fitted to (mm), so that all share one scale: empty for the
    /// scene's range of motion; animationFrames() and the writers set it to the sweep's
    /// (sweptExtent()).
    Eigen::AlignedBox3d extent;
};

/// The box of the poses `poses` reach (their scenes' poseExtent), where it is less than half
/// the range of motion (the 3-RP̲R's platform, a five-bar's cranks); else empty. A video of a
/// small motion then shows the mechanism large, where the whole range left it small.
Eigen::AlignedBox3d sweptExtent(const Mechanism &mechanism, const std::vector<Pose> &poses);

inline constexpr int minAnimationFrames = 2;
inline constexpr int maxAnimationFrames = 1000;
/// Frames drawn × width × height: the time of an export grows with it (about 16 s at the
/// limit on the 2-core build machine), so a larger one is refused before a frame is drawn.
inline constexpr double maxAnimationPixels = 1e9;

/// The poses of the sweep, each solved from the one before (so the mechanism stays in its
/// mode), starting from `start`. The failure names the first value without a pose.
Result<std::vector<Pose>> animationPoses(const Mechanism &mechanism, const Pose &start,
                                         const AnimationSettings &settings);

/// The part of variable `variable`'s range that the mechanism sweeps from `start` without
/// leaving its modes or meeting a singular pose (core units): what an animation offers by
/// default. A five-bar's crank may turn from −180° to 180° on paper, yet its leg stretches on
/// the way; this range stops a step short of that, as Play does.
Interval animationRange(const Mechanism &mechanism, const Pose &start, int variable);

/// How many frames `poses` poses make: forth and back without repeating the turning points.
int animationFrameCount(int poses, bool bounce);

/// The picture of one pose, as every frame of GIF and video is drawn; thread-safe.
/// `labelPlaces` carries where the labels stood from one frame to the next, so that a label
/// keeps its side while that stays free (null: each frame laid out afresh).
QImage animationFrame(const Mechanism &mechanism, const Pose &pose, const AnimationSettings &settings,
                      std::vector<std::pair<QString, QPointF>> *labelPlaces = nullptr);

/// The frames of the poses (bounced if asked); thread-safe (QImage and QPainter only). Stops
/// early, returning no frames, once `*cancel` becomes true.
QList<QImage> animationFrames(const Mechanism &mechanism, const std::vector<Pose> &poses,
                              const AnimationSettings &settings, const std::atomic<bool> *cancel = nullptr);

/// Poses, frames and GIF in one: the GIF's bytes, or the failure.
Result<QByteArray> renderAnimation(const Mechanism &mechanism, const Pose &start, const AnimationSettings &settings,
                                   const std::atomic<bool> *cancel = nullptr);

/// What writeAnimationVideo() did.
struct VideoExport {
    QString error;          ///< one sentence; empty when the file was written (or cancelled)
    bool cancelled = false; ///< `*cancel` became true: no file was written
    QString codec;          ///< "H.264", "VP9" or "VP8"
    int frames = 0;         ///< frames written
    bool ok() const { return error.isEmpty() && !cancelled; }
};

/// Frames done so far and the total; called from the thread that encodes.
using AnimationProgress = std::function<void(int done, int total)>;

/// Writes the video of `poses` to `path` (MP4 or WebM by its extension, settings.size, 30
/// frames/s): each frame is drawn and encoded before the next is drawn, so memory stays that
/// of one frame whatever the length; the file appears only once complete. Thread-safe.
VideoExport writeAnimationVideo(const Mechanism &mechanism, const std::vector<Pose> &poses,
                                const AnimationSettings &settings, const QString &path,
                                const std::atomic<bool> *cancel = nullptr, const AnimationProgress &progress = {});

} // namespace pkm
