#pragma once
/// Animated GIFs (giflib): the frames of a sweep, for lectures and slides, that every browser
/// and presentation program plays without a codec.

#include <QByteArray>
#include <QImage>
#include <QList>
#include <QString>

namespace pkm {

struct GifOptions {
    int frameMilliseconds = 40; ///< display time of each frame (GIF counts in hundredths)
    bool loop = true;           ///< play forever (the NETSCAPE2.0 extension), else once
};

/// Encodes `frames` (all of one size) as an animated GIF, each frame quantised to its own
/// palette of 256 colours. Returns an empty array and sets `error` if giflib fails.
QByteArray encodeGif(const QList<QImage> &frames, const GifOptions &options, QString *error = nullptr);

} // namespace pkm
