// Videos of a sweep: `pkm render … -o FILE.mp4|.webm` and the GUI's export write files that an
// independent reader — libavformat and libavcodec opening them again — finds to be MP4 with
// H.264 or WebM with VP9, of the size asked, one frame per step at 30 frames/s; a bad size is
// refused with its message; a cancel or a failure leaves no file, not even a temporary one.
#include "cli/cli.h"
#include "cli/drawingcommands.h"
#include "export/animation.h"
#include "export/videowriter.h"
#include "gui/animationdialog.h"
#include "gui/mainwindow.h"
#include "registry.h"
#include "support/cliinprocess.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
}

#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QProgressDialog>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>


using namespace pkm;

namespace {

/// What libavformat reads back from a video file.
struct Probe {
    QString error; ///< empty when the file opened
    QString container; ///< libavformat's demuxer, e.g. "mov,mp4,m4a,3gp,3g2,mj2"
    QString codec; ///< "h264", "vp9"
    QSize size;
    QString pixelFormat;
    int frames = 0; ///< decoded frames
    AVRational rate {0, 1};
};

Probe probe(const QString &path)
{
    Probe result;
    AVFormatContext *format = nullptr;
    if (avformat_open_input(&format, QFile::encodeName(path).constData(), nullptr, nullptr) < 0) {
        result.error = QStringLiteral("cannot open");
        return result;
    }
    AVCodecContext *codec = nullptr;
    AVPacket *packet = av_packet_alloc();
    AVFrame *frame = av_frame_alloc();
    const int index = avformat_find_stream_info(format, nullptr) < 0
        ? -1
        : av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (index < 0) {
        result.error = QStringLiteral("no video stream");
    } else {
        const AVStream *stream = format->streams[index];
        result.container = QString::fromLatin1(format->iformat->name);
        result.codec = QString::fromLatin1(avcodec_get_name(stream->codecpar->codec_id));
        result.size = QSize(stream->codecpar->width, stream->codecpar->height);
        result.pixelFormat
            = QString::fromLatin1(av_get_pix_fmt_name(static_cast<AVPixelFormat>(stream->codecpar->format)));
        result.rate = stream->avg_frame_rate;
        const AVCodec *decoder = avcodec_find_decoder(stream->codecpar->codec_id);
        codec = decoder ? avcodec_alloc_context3(decoder) : nullptr;
        if (!codec || avcodec_parameters_to_context(codec, stream->codecpar) < 0
            || avcodec_open2(codec, decoder, nullptr) < 0) {
            result.error = QStringLiteral("no decoder");
        } else {
            // Decoding counts what a player shows (VP9's hidden frames are not frames).
            const auto drain = [&] {
                while (avcodec_receive_frame(codec, frame) == 0)
                    ++result.frames;
            };
            while (av_read_frame(format, packet) >= 0) {
                if (packet->stream_index == index && avcodec_send_packet(codec, packet) >= 0)
                    drain();
                av_packet_unref(packet);
            }
            avcodec_send_packet(codec, nullptr);
            drain();
        }
    }
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
    return result;
}

using Run = test::CliRun;
const auto run = test::runCliInProcess;

/// `pkm render fourbar-example --var alpha --from 0 --to 90 --steps K …`
QStringList crank(int steps, const QString &path, const QStringList &more = {})
{
    return QStringList {QStringLiteral("render"), QStringLiteral("fourbar-example"), QStringLiteral("--var"),
               QStringLiteral("alpha"), QStringLiteral("--from"), QStringLiteral("0"), QStringLiteral("--to"),
               QStringLiteral("90"), QStringLiteral("--steps"), QString::number(steps), QStringLiteral("-o"), path}
    + more;
}

AnimationSettings sweep(const Mechanism &mechanism, int frames)
{
    AnimationSettings settings;
    settings.variable = mechanism.variableIndex("alpha");
    settings.from = 0.0;
    settings.to = 1.5;
    settings.frames = frames;
    settings.size = QSize(160, 120);
    return settings;
}

} // namespace

class TestVideo : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        cli::registerDrawingCommands(); // runCli() in-process runs `pkm render`, as pkm-draw does
    }

    void sizesAreChecked()
    {
        QVERIFY(videoSizeProblem(defaultVideoSize).isEmpty());
        QVERIFY(videoSizeProblem(fullHdVideoSize).isEmpty());
        for (const QSize size : {QSize(321, 240), QSize(320, 241), QSize(3842, 2160), QSize(30, 30)}) {
            const QString problem = videoSizeProblem(size);
            QVERIFY2(problem.contains(QStringLiteral("%1x%2").arg(size.width()).arg(size.height()))
                    && problem.contains(QStringLiteral("even")),
                qPrintable(problem));
        }
    }

    void commandLineWritesMp4()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("crank.mp4"));
        const Run written = run(crank(4, path, {QStringLiteral("--size"), QStringLiteral("320x240")}));
        QVERIFY2(written.status == 0, qPrintable(written.err));
        QVERIFY2(written.out.startsWith(QStringLiteral("Wrote %1 (MP4 video, H.264, 6 frames of 320 × 240 pixels at "
                                                       "30 frames/s, 0.2 s, forth and back)")
                                            .arg(path)),
            qPrintable(written.out));
        QVERIFY(written.err.isEmpty());
        const Probe video = probe(path);
        QVERIFY2(video.error.isEmpty(), qPrintable(video.error));
        QVERIFY2(video.container.contains(QStringLiteral("mp4")), qPrintable(video.container));
        QCOMPARE(video.codec, QStringLiteral("h264"));
        QCOMPARE(video.size, QSize(320, 240));
        QCOMPARE(video.pixelFormat, QStringLiteral("yuv420p"));
        QCOMPARE(video.frames, 4 + 2); // forth and back, the turning points once
        QCOMPARE(av_q2d(video.rate), 30.0);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList {QStringLiteral("crank.mp4")});
    }

    void commandLineWritesWebm()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("crank.webm"));
        const Run written
            = run(crank(3, path, {QStringLiteral("--one-way"), QStringLiteral("--size"), QStringLiteral("320x240")}));
        QVERIFY2(written.status == 0, qPrintable(written.err));
        QVERIFY2(written.out.contains(QStringLiteral("(WebM video, VP9, 3 frames of 320 × 240 pixels")),
            qPrintable(written.out));
        const Probe video = probe(path);
        QVERIFY2(video.error.isEmpty(), qPrintable(video.error));
        QVERIFY2(video.container.contains(QStringLiteral("webm")), qPrintable(video.container));
        QCOMPARE(video.codec, QStringLiteral("vp9"));
        QCOMPARE(video.size, QSize(320, 240));
        QCOMPARE(video.frames, 3);
        QCOMPARE(av_q2d(video.rate), 30.0);
    }

    void commandLineVideoIs720pByDefault()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("short.mp4"));
        const Run written = run(crank(2, path, {QStringLiteral("--one-way")}));
        QVERIFY2(written.status == 0, qPrintable(written.err));
        const Probe video = probe(path);
        QCOMPARE(video.size, QSize(1280, 720));
        QCOMPARE(video.frames, 2);
    }

    void commandLineRefusesBadSizes()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.mp4"));
        for (const QString &size : {QStringLiteral("321x240"), QStringLiteral("4000x2000")}) {
            const Run refused = run(crank(3, path, {QStringLiteral("--size"), size}));
            QCOMPARE(refused.status, 2);
            QVERIFY(refused.out.isEmpty());
            QVERIFY2(refused.err.contains(QStringLiteral("--size ") + size)
                    && refused.err.contains(QStringLiteral("even")) && refused.err.count(QLatin1Char('\n')) == 1,
                qPrintable(refused.err));
        }
        // --view 3d has no video
        const Run view = run(crank(3, path, {QStringLiteral("--view"), QStringLiteral("3d")}));
        QCOMPARE(view.status, 2);
        QVERIFY2(view.err.contains(QStringLiteral("video")), qPrintable(view.err));
        QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    }

    void cancelLeavesNoFile()
    {
        const MechanismPtr mechanism = createMechanism("fourbar", {}).value();
        const AnimationSettings settings = sweep(*mechanism, 20);
        auto poses = animationPoses(*mechanism, mechanism->homePose(), settings);
        QVERIFY(poses.ok());
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("cancelled.webm"));
        QFile old(path); // an older file at the path survives
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("older");
        old.close();
        std::atomic<bool> cancel {false};
        int reported = 0;
        const VideoExport written
            = writeAnimationVideo(*mechanism, *poses, settings, path, &cancel, [&](int done, int total) {
                  reported = done;
                  QCOMPARE(total, 20 + 18);
                  if (done == 5)
                      cancel = true;
              });
        QVERIFY(written.cancelled);
        QVERIFY(!written.ok());
        QCOMPARE(reported, 5);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList {QStringLiteral("cancelled.webm")});
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), QByteArray("older"));
    }

    void failureIsOneSentenceAndNoFile()
    {
        const MechanismPtr mechanism = createMechanism("fourbar", {}).value();
        AnimationSettings settings = sweep(*mechanism, 3);
        auto poses = animationPoses(*mechanism, mechanism->homePose(), settings);
        QVERIFY(poses.ok());
        QTemporaryDir dir;
        const QString missing = dir.filePath(QStringLiteral("no/such/folder/x.mp4"));
        VideoExport written = writeAnimationVideo(*mechanism, *poses, settings, missing);
        QVERIFY2(written.error.startsWith(QStringLiteral("Cannot write '%1'").arg(missing)), qPrintable(written.error));
        settings.size = QSize(161, 120);
        written = writeAnimationVideo(*mechanism, *poses, settings, dir.filePath(QStringLiteral("odd.mp4")));
        QVERIFY2(written.error.contains(QStringLiteral("161x120")), qPrintable(written.error));
        QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot).isEmpty());
    }

    void dialogOffersTheVideoSizes()
    {
        const MechanismPtr mechanism = createMechanism("fourbar", {}).value();
        AnimationDialog dialog(*mechanism, 0);
        QCOMPARE(dialog.fileExtension(), QStringLiteral("gif"));
        QComboBox *format = dialog.formatBox();
        QCOMPARE(format->count(), 3);
        format->setCurrentIndex(format->findData(QStringLiteral("mp4")));
        QCOMPARE(dialog.fileExtension(), QStringLiteral("mp4"));
        QList<QSize> sizes;
        for (int i = 0; i < dialog.sizeBox()->count(); ++i)
            sizes.append(dialog.sizeBox()->itemData(i).toSize());
        QCOMPARE(sizes, (QList<QSize> {QSize(1280, 720), QSize(1920, 1080)}));
        QCOMPARE(dialog.settings().size, QSize(1280, 720));
        dialog.sizeBox()->setCurrentIndex(1);
        format->setCurrentIndex(format->findData(QStringLiteral("webm")));
        QCOMPARE(dialog.settings().size, QSize(1920, 1080)); // kept from one video format to the other
        format->setCurrentIndex(format->findData(QStringLiteral("gif")));
        QCOMPARE(dialog.settings().size, QSize(960, 720)); // the GIF's default again
    }

    void guiExportWritesAndCancels()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sweep.mp4"));
        MainWindow window;
        QVERIFY(window.openDesign(QStringLiteral("fourbar-example")));
        AnimationSettings settings;
        settings.variable = 0; // α
        settings.from = 0.0;
        settings.to = 3.0;
        settings.frames = 6;
        settings.size = QSize(320, 240);
        window.exportAnimationTo(path, settings);
        QVERIFY(!QFile::exists(path)); // encoded off the GUI thread: not there yet
        QTRY_VERIFY2_WITH_TIMEOUT(
            window.lastStatus().startsWith(QStringLiteral("Wrote")), qPrintable(window.lastStatus()), 60000);
        const Probe video = probe(path);
        QCOMPARE(video.codec, QStringLiteral("h264"));
        QCOMPARE(video.frames, 6 + 4);

        // Cancel in the progress dialog: the export stops and leaves no file.
        const QString stopped = dir.filePath(QStringLiteral("stopped.webm"));
        settings.frames = 200;
        const auto before = window.findChildren<QProgressDialog *>();
        window.exportAnimationTo(stopped, settings);
        QProgressDialog *progress = nullptr;
        for (QProgressDialog *dialog : window.findChildren<QProgressDialog *>()) {
            if (!before.contains(dialog))
                progress = dialog; // this export's
        }
        QVERIFY(progress);
        // The bar counts the frames (forth and back: 200 + 198), filled as they are encoded.
        QTRY_COMPARE_WITH_TIMEOUT(progress->maximum(), 200 + 198, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(progress->value() > 0, 30000);
        auto *cancelButton = progress->findChild<QPushButton *>();
        QVERIFY(cancelButton);
        cancelButton->click(); // as the user does: QProgressDialog says "canceled"
        QTRY_VERIFY2_WITH_TIMEOUT(window.lastStatus() == QStringLiteral("Animation export cancelled."),
            qPrintable(window.lastStatus()), 60000);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList {QStringLiteral("sweep.mp4")});
    }
};

QTEST_MAIN(TestVideo)
#include "tst_video.moc"
