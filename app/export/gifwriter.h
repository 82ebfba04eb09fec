#pragma once
/// Animated GIFs (giflib): the frames of a sweep, for lectures and slides, that every browser
/// and presentation program plays without a codec.

#include <QByteArray>
#include <QImage>
#include <QList>
#include <QSize>
#include <QString>

namespace pkm {

struct GifOptions {
    int frameMilliseconds = 40; ///< display time of each frame (GIF counts in hundredths)
    bool loop = true;           ///< play forever (the NETSCAPE2.0 extension), else once
};

/// An animated GIF written one frame at a time: each frame is quantised and compressed as it
/// comes, so that a long animation holds one frame in memory, not all of them (a 300-frame
/// 1280×720 GIF took 1.3 GB when the frames were kept).
class GifEncoder
{
public:
    GifEncoder();
    ~GifEncoder();
    GifEncoder(const GifEncoder &) = delete;
    GifEncoder &operator=(const GifEncoder &) = delete;

    /// Starts a GIF of frames of `size`; false (and `error`) if the size or giflib fails.
    bool begin(const QSize &size, const GifOptions &options, QString *error = nullptr);
    /// Appends one frame of the size given to begin(), quantised to its own 256 colours.
    bool addFrame(const QImage &frame, QString *error = nullptr);
    /// Ends the GIF: its bytes, or empty (and `error`) if giflib fails or no frame came.
    QByteArray finish(QString *error = nullptr);

private:
    struct State;
    State *m_state = nullptr;
};

/// Encodes `frames` (all of one size) as an animated GIF, each frame quantised to its own
/// palette of 256 colours. Returns an empty array and sets `error` if giflib fails.
QByteArray encodeGif(const QList<QImage> &frames, const GifOptions &options, QString *error = nullptr);

} // namespace pkm
