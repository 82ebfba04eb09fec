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

bool failWith(QString *error, const QString &why)
{
    if (error)
        *error = why;
    return false;
}

} // namespace

struct GifEncoder::State {
    QByteArray bytes;
    GifFile file;
    QSize size;
    GifOptions options;
    int frames = 0;
    std::vector<GifByteType> red, green, blue, indices;
};

GifEncoder::GifEncoder() = default;

GifEncoder::~GifEncoder()
{
    delete m_state;
}

bool GifEncoder::begin(const QSize &size, const GifOptions &options, QString *error)
{
    delete m_state;
    m_state = nullptr;
    if (size.isEmpty() || size.width() > 65535 || size.height() > 65535)
        return failWith(error, QCoreApplication::translate("pkm::GifWriter", "A GIF frame must be 1 to 65535 pixels on each side."));
    auto state = std::make_unique<State>();
    state->size = size;
    state->options = options;
    int code = 0;
    state->file.reset(EGifOpen(&state->bytes, appendToArray, &code));
    if (!state->file)
        return failWith(error, gifError(code));
    GifFileType *file = state->file.get();
    EGifSetGifVersion(file, true);
    if (EGifPutScreenDesc(file, size.width(), size.height(), 8, 0, nullptr) == GIF_ERROR)
        return failWith(error, gifError(file->Error));
    if (options.loop) {
        const char application[] = "NETSCAPE2.0";
        const GifByteType repeat[] = {0x01, 0x00, 0x00}; // sub-block 1: loop count 0 = forever
        if (EGifPutExtensionLeader(file, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR
            || EGifPutExtensionBlock(file, 11, application) == GIF_ERROR
            || EGifPutExtensionBlock(file, 3, repeat) == GIF_ERROR || EGifPutExtensionTrailer(file) == GIF_ERROR)
            return failWith(error, gifError(file->Error));
    }
    const std::size_t pixels = std::size_t(size.width()) * std::size_t(size.height());
    state->red.resize(pixels);
    state->green.resize(pixels);
    state->blue.resize(pixels);
    state->indices.resize(pixels);
    m_state = state.release();
    return true;
}

bool GifEncoder::addFrame(const QImage &frame, QString *error)
{
    if (!m_state)
        return failWith(error, QCoreApplication::translate("pkm::GifWriter", "giflib: out of memory."));
    State &s = *m_state;
    if (frame.size() != s.size)
        return failWith(error, QCoreApplication::translate("pkm::GifWriter", "All frames of a GIF must have the same size."));
    const QImage rgb = frame.convertToFormat(QImage::Format_RGB888);
    const int width = s.size.width();
    for (int y = 0; y < s.size.height(); ++y) {
        const uchar *line = rgb.constScanLine(y);
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            s.red[i] = line[3 * x];
            s.green[i] = line[3 * x + 1];
            s.blue[i] = line[3 * x + 2];
        }
    }
    int colours = 256;
    ColorMap map(GifMakeMapObject(colours, nullptr));
    if (!map)
        return failWith(error, QCoreApplication::translate("pkm::GifWriter", "giflib: out of memory."));
    if (GifQuantizeBuffer(width, s.size.height(), &colours, s.red.data(), s.green.data(), s.blue.data(), s.indices.data(),
                          map->Colors) == GIF_ERROR)
        return failWith(error, QCoreApplication::translate("pkm::GifWriter", "giflib could not reduce a frame to 256 colours."));
    GifFileType *file = s.file.get();
    const auto control = frameControl(s.options.frameMilliseconds);
    if (EGifPutExtension(file, GRAPHICS_EXT_FUNC_CODE, 4, control.data()) == GIF_ERROR
        || EGifPutImageDesc(file, 0, 0, width, s.size.height(), false, map.get()) == GIF_ERROR)
        return failWith(error, gifError(file->Error));
    for (int y = 0; y < s.size.height(); ++y) {
        if (EGifPutLine(file, s.indices.data() + std::size_t(y) * std::size_t(width), width) == GIF_ERROR)
            return failWith(error, gifError(file->Error));
    }
    ++s.frames;
    return true;
}

QByteArray GifEncoder::finish(QString *error)
{
    std::unique_ptr<State> state(m_state);
    m_state = nullptr;
    if (!state || state->frames == 0) {
        failWith(error, QCoreApplication::translate("pkm::GifWriter", "An animation needs at least one frame."));
        return {};
    }
    int code = 0;
    if (EGifCloseFile(state->file.release(), &code) == GIF_ERROR) {
        failWith(error, gifError(code));
        return {};
    }
    return std::move(state->bytes);
}

QByteArray encodeGif(const QList<QImage> &frames, const GifOptions &options, QString *error)
{
    if (frames.isEmpty()) {
        failWith(error, QCoreApplication::translate("pkm::GifWriter", "An animation needs at least one frame."));
        return {};
    }
    GifEncoder encoder;
    if (!encoder.begin(frames.first().size(), options, error))
        return {};
    for (const QImage &frame : frames) {
        if (!encoder.addFrame(frame, error))
            return {};
    }
    return encoder.finish(error);
}

} // namespace pkm
