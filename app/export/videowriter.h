#pragma once
/// Videos of a sweep (Debian's FFmpeg libraries: libavformat, libavcodec, libswscale): MP4 with
/// H.264 and WebM with VP9 (VP8 where VP9 cannot be had), 30 frames per second, for slides and
/// the lecture hall's projector where a GIF's 256 colours and its size fall short.
///
/// Frames go in one at a time and are encoded at once, so memory does not grow with the length
/// of the video. The file is written atomically: into a temporary file (QSaveFile) that takes
/// the path's place only when finish() succeeds; a failure, a cancel or a writer dropped before
/// finish() leaves no file and an existing one as it was.

#include <QCoreApplication>
#include <QImage>
#include <QSize>
#include <QString>

#include <memory>
#include <optional>

namespace pkm {

enum class VideoFormat {
    Mp4, ///< MP4 with H.264 (libx264), yuv420p: plays everywhere, presentation programs included
    WebM, ///< WebM with VP9 (libvpx-vp9), or VP8 (libvpx): free codecs, for web pages
};

/// The format a file name asks for by its extension (.mp4, .webm, any case), if any.
std::optional<VideoFormat> videoFormatForPath(const QString &path);

inline constexpr int videoFramesPerSecond = 30;
inline constexpr QSize defaultVideoSize {1280, 720};
inline constexpr QSize fullHdVideoSize {1920, 1080};
/// The sides a video may have: 4:2:0 chroma halves each side, so both must be even; the upper
/// limit is 4K UHD, past which H.264's levels (and most players) stop.
inline constexpr int minVideoSide = 32;
inline constexpr int maxVideoWidth = 3840;
inline constexpr int maxVideoHeight = 2160;

/// Why `size` cannot be a video's (one sentence), or an empty string when it can.
QString videoSizeProblem(QSize size);

class VideoWriter
{
    Q_DECLARE_TR_FUNCTIONS(pkm::VideoWriter)

public:
    VideoWriter();
    /// Discards the file unless finish() succeeded.
    ~VideoWriter();
    VideoWriter(const VideoWriter &) = delete;
    VideoWriter &operator=(const VideoWriter &) = delete;

    /// Opens the temporary file beside `path` and the encoder for frames of `size`. On failure
    /// returns false with one sentence in `error` (the size, the codec or the file named).
    bool open(const QString &path, VideoFormat format, QSize size, QString *error);
    /// Encodes the next frame (any QImage format, scaled to the video's size if it differs).
    bool addFrame(const QImage &frame, QString *error);
    /// Drains the encoder, writes the container's index and renames the file into place.
    bool finish(QString *error);
    /// Drops everything written so far: no file is left.
    void discard();

    /// The codec in words, e.g. "H.264" or "VP9" (after open()).
    QString codecName() const;
    int framesWritten() const;

private:
    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace pkm
