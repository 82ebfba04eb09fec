#include "export/gifwriter.h"

#include <gif_lib.h>

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

namespace pkm {

namespace {

int appendToArray(GifFileType *file, const GifByteType *data, int length)
{
    static_cast<QByteArray *>(file->UserData)->append(reinterpret_cast<const char *>(data), length);
    return length;
}

struct GifCloser {
    void operator()(GifFileType *file) const
    {
        int error = 0;
        EGifCloseFile(file, &error);
    }
};
using GifFile = std::unique_ptr<GifFileType, GifCloser>;

struct ColorMapDeleter {
    void operator()(ColorMapObject *map) const { GifFreeMapObject(map); }
};
using ColorMap = std::unique_ptr<ColorMapObject, ColorMapDeleter>;

QString gifError(int code)
{
    const char *text = GifErrorString(code);
    return QStringLiteral("giflib: %1").arg(QString::fromLatin1(text ? text : "unknown error"));
}

/// The Graphics Control Extension of one frame: its delay, no transparency.
std::array<GifByteType, 4> frameControl(int milliseconds)
{
    const int hundredths = std::clamp((milliseconds + 5) / 10, 2, 65535); // below 2, players slow down
    return {GifByteType(0x04) /* disposal 1: keep the frame */, GifByteType(hundredths & 0xff),
            GifByteType(hundredths >> 8), GifByteType(0)};
}

} // namespace

QByteArray encodeGif(const QList<QImage> &frames, const GifOptions &options, QString *error)
{
    const auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return QByteArray();
    };
    if (frames.isEmpty())
        return fail(QCoreApplication::translate("pkm::GifWriter", "An animation needs at least one frame."));
    const QSize size = frames.first().size();
    if (size.isEmpty() || size.width() > 65535 || size.height() > 65535)
        return fail(QCoreApplication::translate("pkm::GifWriter", "A GIF frame must be 1 to 65535 pixels on each side."));

    QByteArray bytes;
    int code = 0;
    GifFile file(EGifOpen(&bytes, appendToArray, &code));
    if (!file)
        return fail(gifError(code));
    EGifSetGifVersion(file.get(), true);
    if (EGifPutScreenDesc(file.get(), size.width(), size.height(), 8, 0, nullptr) == GIF_ERROR)
        return fail(gifError(file->Error));
    if (options.loop) {
        const char application[] = "NETSCAPE2.0";
        const GifByteType repeat[] = {0x01, 0x00, 0x00}; // sub-block 1: loop count 0 = forever
        if (EGifPutExtensionLeader(file.get(), APPLICATION_EXT_FUNC_CODE) == GIF_ERROR
            || EGifPutExtensionBlock(file.get(), 11, application) == GIF_ERROR
            || EGifPutExtensionBlock(file.get(), 3, repeat) == GIF_ERROR
            || EGifPutExtensionTrailer(file.get()) == GIF_ERROR)
            return fail(gifError(file->Error));
    }

    const int pixels = size.width() * size.height();
    std::vector<GifByteType> red(pixels), green(pixels), blue(pixels), indices(pixels);
    for (const QImage &frame : frames) {
        if (frame.size() != size)
            return fail(QCoreApplication::translate("pkm::GifWriter", "All frames of a GIF must have the same size."));
        const QImage rgb = frame.convertToFormat(QImage::Format_RGB888);
        for (int y = 0; y < size.height(); ++y) {
            const uchar *line = rgb.constScanLine(y);
            for (int x = 0; x < size.width(); ++x) {
                const int i = y * size.width() + x;
                red[i] = line[3 * x];
                green[i] = line[3 * x + 1];
                blue[i] = line[3 * x + 2];
            }
        }
        int colours = 256;
        ColorMap map(GifMakeMapObject(colours, nullptr));
        if (!map)
            return fail(QCoreApplication::translate("pkm::GifWriter", "giflib: out of memory."));
        if (GifQuantizeBuffer(size.width(), size.height(), &colours, red.data(), green.data(), blue.data(),
                              indices.data(), map->Colors) == GIF_ERROR)
            return fail(QCoreApplication::translate("pkm::GifWriter", "giflib could not reduce a frame to 256 colours."));
        const auto control = frameControl(options.frameMilliseconds);
        if (EGifPutExtension(file.get(), GRAPHICS_EXT_FUNC_CODE, 4, control.data()) == GIF_ERROR
            || EGifPutImageDesc(file.get(), 0, 0, size.width(), size.height(), false, map.get()) == GIF_ERROR)
            return fail(gifError(file->Error));
        for (int y = 0; y < size.height(); ++y) {
            if (EGifPutLine(file.get(), indices.data() + y * size.width(), size.width()) == GIF_ERROR)
                return fail(gifError(file->Error));
        }
    }
    GifFileType *open = file.release();
    if (EGifCloseFile(open, &code) == GIF_ERROR)
        return fail(gifError(code));
    return bytes;
}

} // namespace pkm
