#include "export/videowriter.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/mem.h>
#include <libswscale/swscale.h>
}

#include <QCoreApplication>
#include <QFileInfo>
#include <QSaveFile>

#include <array>
#include <cstdio>

namespace pkm {

namespace {

QString ffmpegError(int code)
{
    std::array<char, AV_ERROR_MAX_STRING_SIZE> text {};
    av_strerror(code, text.data(), text.size());
    return QString::fromUtf8(text.data());
}

/// One encoder to try: FFmpeg's name, the codec in words, and its settings.
struct Candidate {
    const char *encoder;
    const char *name;
};

/// H.264 from x264 first (the reference quality), the Cisco encoder only if that is missing;
/// VP9 first for WebM, VP8 where libvpx was built without it.
std::array<Candidate, 2> candidates(VideoFormat format)
{
    if (format == VideoFormat::Mp4)
        return {{{"libx264", "H.264"}, {"libopenh264", "H.264"}}};
    return {{{"libvpx-vp9", "VP9"}, {"libvpx", "VP8"}}};
}

/// The encoder's settings for drawings: flat colour with thin lines, little motion. Constant
/// quality where the encoder has it, so a still frame costs almost nothing.
void encoderOptions(const char *encoder, AVCodecContext *codec, AVDictionary **options)
{
    const QByteArray name(encoder);
    if (name == "libx264") {
        av_dict_set(options, "preset", "fast", 0);
        av_dict_set(options, "tune", "animation", 0); // flat areas and sharp edges, as cartoons
        av_dict_set(options, "crf", "20", 0);
    } else if (name == "libvpx-vp9") {
        codec->bit_rate = 0; // with crf: constant quality
        av_dict_set(options, "crf", "24", 0);
        // "good" took four times as long as "realtime" for 10 % less file (720p: 7 against 30
        // frames/s on two cores); crf 24 keeps thin lines and text free of speckles.
        av_dict_set(options, "deadline", "realtime", 0);
        av_dict_set(options, "cpu-used", "6", 0);
        av_dict_set(options, "row-mt", "1", 0);
    } else {
        // VP8 and OpenH264 need a bit rate: 0.1 bit per pixel, plenty for line drawings.
        codec->bit_rate = static_cast<std::int64_t>(0.1 * codec->width * codec->height * videoFramesPerSecond);
        if (name == "libvpx") {
            av_dict_set(options, "crf", "10", 0);
            av_dict_set(options, "deadline", "good", 0);
            av_dict_set(options, "cpu-used", "4", 0);
        }
    }
}

} // namespace

std::optional<VideoFormat> videoFormatForPath(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("mp4"))
        return VideoFormat::Mp4;
    if (suffix == QLatin1String("webm"))
        return VideoFormat::WebM;
    return std::nullopt;
}

QString videoSizeProblem(QSize size)
{
    if (size.width() < minVideoSide || size.height() < minVideoSide || size.width() > maxVideoWidth
        || size.height() > maxVideoHeight || size.width() % 2 != 0 || size.height() % 2 != 0) {
        return VideoWriter::tr("A video is %1 to %2 pixels wide and %1 to %3 high, in even numbers (e.g. 1280x720 or "
                               "1920x1080), not %4x%5.")
            .arg(minVideoSide)
            .arg(maxVideoWidth)
            .arg(maxVideoHeight)
            .arg(size.width())
            .arg(size.height());
    }
    return {};
}

struct VideoWriter::Private {
    QString path;
    std::unique_ptr<QSaveFile> file;
    QString ioError; ///< the file's first write or seek failure
    AVFormatContext *format = nullptr;
    AVIOContext *io = nullptr;
    AVCodecContext *codec = nullptr;
    AVStream *stream = nullptr;
    SwsContext *scale = nullptr;
    AVFrame *frame = nullptr;
    AVPacket *packet = nullptr;
    QSize size;
    QString codecName;
    int frames = 0;

    /// The FFmpeg side, freed; the file is left to the caller.
    void release()
    {
        sws_freeContext(scale);
        scale = nullptr;
        av_frame_free(&frame);
        av_packet_free(&packet);
        avcodec_free_context(&codec);
        avformat_free_context(format); // the stream goes with it; the custom pb does not
        format = nullptr;
        stream = nullptr;
        if (io) {
            av_freep(&io->buffer);
            avio_context_free(&io);
        }
    }

    QString fileFailure(const QString &why) const
    {
        QString reason = why.trimmed();
        while (reason.endsWith(QLatin1Char('.')))
            reason.chop(1);
        return VideoWriter::tr("Cannot write '%1': %2.")
            .arg(path, reason.isEmpty() ? VideoWriter::tr("unknown error") : reason);
    }

    /// The failure of an FFmpeg call: the file's own reason when writing it failed.
    QString ffmpegFailure(int code) const
    {
        return ioError.isEmpty() ? fileFailure(ffmpegError(code)) : fileFailure(ioError);
    }

    /// Hands `frame` (null: the end) to the encoder and every packet it gives to the muxer.
    bool encode(const AVFrame *input, QString *error)
    {
        int code = avcodec_send_frame(codec, input);
        while (code >= 0) {
            code = avcodec_receive_packet(codec, packet);
            if (code == AVERROR(EAGAIN) || code == AVERROR_EOF)
                return true;
            if (code < 0)
                break;
            if (packet->duration == 0)
                packet->duration = 1; // one frame: the last frame of an MP4 keeps its length
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            code = av_interleaved_write_frame(format, packet); // takes the packet's data
        }
        if (error)
            *error = ffmpegFailure(code);
        return false;
    }

#if LIBAVFORMAT_VERSION_MAJOR >= 61
    using WriteBuffer = const uint8_t *;
#else
    using WriteBuffer = uint8_t *;
#endif

    static int writeToFile(void *opaque, WriteBuffer data, int size)
    {
        auto *d = static_cast<Private *>(opaque);
        // A nearly full disk takes part of a write; the next one fails with the reason.
        const char *bytes = reinterpret_cast<const char *>(data);
        for (qint64 done = 0; done < size;) {
            const qint64 written = d->file->write(bytes + done, size - done);
            if (written <= 0) {
                if (d->ioError.isEmpty())
                    d->ioError = d->file->errorString();
                return AVERROR(EIO);
            }
            done += written;
        }
        return size;
    }

    /// The MP4 muxer goes back to the start to fill in the sizes once the index is written.
    static int64_t seekInFile(void *opaque, int64_t offset, int whence)
    {
        auto *d = static_cast<Private *>(opaque);
        if (whence & AVSEEK_SIZE)
            return d->file->size();
        qint64 target = 0;
        switch (whence & ~AVSEEK_FORCE) {
        case SEEK_SET:
            target = offset;
            break;
        case SEEK_CUR:
            target = d->file->pos() + offset;
            break;
        case SEEK_END:
            target = d->file->size() + offset;
            break;
        default:
            return AVERROR(EINVAL);
        }
        if (!d->file->seek(target)) {
            if (d->ioError.isEmpty())
                d->ioError = d->file->errorString();
            return AVERROR(EIO);
        }
        return target;
    }
};

VideoWriter::VideoWriter()
    : d(std::make_unique<Private>())
{
}

VideoWriter::~VideoWriter()
{
    discard();
}

void VideoWriter::discard()
{
    d->release();
    if (d->file) {
        d->file->cancelWriting();
        d->file.reset(); // QSaveFile removes its temporary file
    }
    d->frames = 0;
    d->ioError.clear();
}

bool VideoWriter::open(const QString &path, VideoFormat format, QSize size, QString *error)
{
    discard();
    const auto fail = [this, error](const QString &why) {
        discard();
        if (error)
            *error = why;
        return false;
    };
    if (const QString problem = videoSizeProblem(size); !problem.isEmpty())
        return fail(problem);
    // The encoders' chatter (x264's statistics, VP9's warnings) would break the one line the
    // CLI prints; every failure comes back as a return code and is told in a sentence.
    av_log_set_level(AV_LOG_QUIET);
    d->path = path;
    d->size = size;
    const QString container = format == VideoFormat::Mp4 ? QStringLiteral("MP4") : QStringLiteral("WebM");
    const AVOutputFormat *output = av_guess_format(format == VideoFormat::Mp4 ? "mp4" : "webm", nullptr, nullptr);
    if (!output)
        return fail(VideoWriter::tr("This build of FFmpeg's libavformat cannot write %1 files.").arg(container));

    QString tried;
    int openCode = 0;
    for (const Candidate &candidate : candidates(format)) {
        const AVCodec *encoder = avcodec_find_encoder_by_name(candidate.encoder);
        if (!encoder)
            continue;
        AVCodecContext *codec = avcodec_alloc_context3(encoder);
        if (!codec)
            return fail(VideoWriter::tr("FFmpeg is out of memory."));
        codec->width = size.width();
        codec->height = size.height();
        codec->time_base = AVRational {1, videoFramesPerSecond};
        codec->framerate = AVRational {videoFramesPerSecond, 1};
        codec->sample_aspect_ratio = AVRational {1, 1};
        codec->pix_fmt = AV_PIX_FMT_YUV420P; // what every player decodes
        codec->gop_size = 2 * videoFramesPerSecond; // a key frame every 2 s, for seeking
        // HD video is BT.709; the frames are converted with the same matrix below.
        codec->colorspace = AVCOL_SPC_BT709;
        codec->color_primaries = AVCOL_PRI_BT709;
        codec->color_trc = AVCOL_TRC_BT709;
        codec->color_range = AVCOL_RANGE_MPEG;
        if (output->flags & AVFMT_GLOBALHEADER)
            codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        AVDictionary *options = nullptr;
        encoderOptions(candidate.encoder, codec, &options);
        openCode = avcodec_open2(codec, encoder, &options);
        av_dict_free(&options);
        if (openCode >= 0) {
            d->codec = codec;
            d->codecName = QString::fromLatin1(candidate.name);
            break;
        }
        avcodec_free_context(&codec); // unusable here (e.g. no VP9 in this libvpx): the next one
        tried += (tried.isEmpty() ? QString() : QStringLiteral(", ")) + QString::fromLatin1(candidate.encoder);
    }
    if (!d->codec) {
        if (!tried.isEmpty()) {
            return fail(VideoWriter::tr("FFmpeg could not start the %1 encoder (%2): %3.")
                            .arg(container, tried, ffmpegError(openCode)));
        }
        return fail(format == VideoFormat::Mp4
                ? VideoWriter::tr(
                    "FFmpeg's libavcodec here has no H.264 encoder: MP4 needs libx264 (Debian's libavcodec has it).")
                : VideoWriter::tr("FFmpeg's libavcodec here has no VP9 or VP8 encoder: WebM needs libvpx (Debian's "
                                  "libavcodec has it)."));
    }

    if (avformat_alloc_output_context2(&d->format, output, nullptr, nullptr) < 0 || !d->format)
        return fail(VideoWriter::tr("FFmpeg is out of memory."));
    d->stream = avformat_new_stream(d->format, nullptr);
    d->frame = av_frame_alloc();
    d->packet = av_packet_alloc();
    if (!d->stream || !d->frame || !d->packet)
        return fail(VideoWriter::tr("FFmpeg is out of memory."));
    d->stream->time_base = d->codec->time_base;
    d->stream->avg_frame_rate = d->codec->framerate;
    if (const int code = avcodec_parameters_from_context(d->stream->codecpar, d->codec); code < 0)
        return fail(ffmpegError(code));

    d->frame->format = d->codec->pix_fmt;
    d->frame->width = size.width();
    d->frame->height = size.height();
    if (const int code = av_frame_get_buffer(d->frame, 0); code < 0)
        return fail(ffmpegError(code));
    // QImage::Format_RGB32 is 0xffRRGGBB in native byte order: FFmpeg's RGB32.
    d->scale = sws_getContext(size.width(), size.height(), AV_PIX_FMT_RGB32, size.width(), size.height(),
        AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
    if (!d->scale)
        return fail(VideoWriter::tr("FFmpeg's libswscale cannot convert the frames to YUV 4:2:0."));
    sws_setColorspaceDetails(
        d->scale, sws_getCoefficients(SWS_CS_DEFAULT), 1, sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16);

    d->file = std::make_unique<QSaveFile>(path);
    // Unbuffered: libavformat buffers already, and a full disk then fails the write that hit
    // it, with the system's reason, rather than a later flush without one.
    if (!d->file->open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return fail(d->fileFailure(d->file->errorString()));
    constexpr int bufferSize = 1 << 16;
    auto *buffer = static_cast<unsigned char *>(av_malloc(bufferSize));
    d->io = buffer
        ? avio_alloc_context(buffer, bufferSize, 1, d.get(), nullptr, Private::writeToFile, Private::seekInFile)
        : nullptr;
    if (!d->io) {
        av_free(buffer);
        return fail(VideoWriter::tr("FFmpeg is out of memory."));
    }
    d->format->pb = d->io;
    d->format->flags |= AVFMT_FLAG_CUSTOM_IO;
    if (const int code = avformat_write_header(d->format, nullptr); code < 0)
        return fail(d->ffmpegFailure(code));
    return true;
}

bool VideoWriter::addFrame(const QImage &frame, QString *error)
{
    if (!d->codec) {
        if (error)
            *error = VideoWriter::tr("The video is not open.");
        return false;
    }
    const QImage sized
        = frame.size() == d->size ? frame : frame.scaled(d->size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    const QImage rgb = sized.convertToFormat(QImage::Format_RGB32);
    if (const int code = av_frame_make_writable(d->frame); code < 0) {
        if (error)
            *error = ffmpegError(code);
        return false;
    }
    const uint8_t *source[1] = {rgb.constBits()};
    const int stride[1] = {static_cast<int>(rgb.bytesPerLine())};
    sws_scale(d->scale, source, stride, 0, d->size.height(), d->frame->data, d->frame->linesize);
    d->frame->pts = d->frames;
    if (!d->encode(d->frame, error))
        return false;
    ++d->frames;
    return true;
}

bool VideoWriter::finish(QString *error)
{
    const auto fail = [this, error](const QString &why) {
        discard();
        if (error)
            *error = why;
        return false;
    };
    if (!d->codec)
        return fail(VideoWriter::tr("The video is not open."));
    if (d->frames == 0)
        return fail(VideoWriter::tr("A video needs at least one frame."));
    QString why;
    if (!d->encode(nullptr, &why))
        return fail(why);
    if (const int code = av_write_trailer(d->format); code < 0)
        return fail(d->ffmpegFailure(code));
    avio_flush(d->io);
    if (d->io->error < 0 || !d->ioError.isEmpty())
        return fail(d->ffmpegFailure(d->io->error));
    const int frames = d->frames;
    d->release();
    if (!d->file->commit()) {
        const QString reason = d->file->errorString();
        return fail(d->fileFailure(reason));
    }
    d->file.reset();
    d->frames = frames;
    return true;
}

QString VideoWriter::codecName() const
{
    return d->codecName;
}

int VideoWriter::framesWritten() const
{
    return d->frames;
}

} // namespace pkm
