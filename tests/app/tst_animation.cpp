// Animated GIFs of a sweep: the poses follow the swept variable, the frames are drawn, the GIF
// decodes (with an independent reader, Qt's) to the right number of frames, size and timing,
// and the GUI writes one without blocking.
#include "export/animation.h"
#include "cli/cli.h"
#include "cli/drawingcommands.h"
#include "document/document.h"
#include "export/gifwriter.h"
#include "document/designfile.h"
#include "gui/animationdialog.h"
#include "gui/mainwindow.h"
#include "registry.h"

#include <QBuffer>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QImageReader>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>

using namespace pkm;

namespace {
/// The process's resident memory (/proc/self/statm), MB.
double residentMegabytes()
{
    QFile statm(QStringLiteral("/proc/self/statm"));
    if (!statm.open(QIODevice::ReadOnly))
        return 0.0;
    const QList<QByteArray> fields = statm.readAll().split(' ');
    return fields.size() > 1 ? fields[1].toDouble() * 4096.0 / (1024.0 * 1024.0) : 0.0;
}

/// The four-bar's crank α through one turn in `frames` frames of `size`.
AnimationSettings crankTurn(int frames, QSize size)
{
    AnimationSettings settings;
    settings.variable = 0; // α
    settings.from = 0.0;
    settings.to = 6.283185307179586;
    settings.frames = frames;
    settings.size = size;
    return settings;
}

struct Decoded {
    int frames = 0;
    QSize size;
    int loops = 0;
    int delay = 0;
    QList<QImage> images;
};

Decoded decode(const QByteArray &gif)
{
    QBuffer buffer;
    buffer.setData(gif);
    buffer.open(QIODevice::ReadOnly);
    QImageReader reader(&buffer, "gif");
    Decoded decoded;
    decoded.size = reader.size();
    decoded.loops = reader.loopCount();
    QImage image;
    while (reader.read(&image)) {
        decoded.delay = reader.nextImageDelay();
        decoded.images.append(image);
        ++decoded.frames;
    }
    return decoded;
}

MechanismPtr prototype()
{
    return createMechanism("pjoint", {}).value();
}
} // namespace

class TestAnimation : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void encodesFramesThatDecode()
    {
        QList<QImage> frames;
        for (int i = 0; i < 5; ++i) {
            QImage frame(64, 48, QImage::Format_RGB32);
            frame.fill(QColor::fromHsv(i * 60, 200, 220));
            frames.append(frame);
        }
        GifOptions options;
        options.frameMilliseconds = 120;
        QString error;
        const QByteArray gif = encodeGif(frames, options, &error);
        QVERIFY2(!gif.isEmpty(), qPrintable(error));
        QVERIFY(gif.startsWith("GIF89a"));
        const Decoded decoded = decode(gif);
        QCOMPARE(decoded.frames, 5);
        QCOMPARE(decoded.size, QSize(64, 48));
        QCOMPARE(decoded.delay, 120);
        QCOMPARE(decoded.loops, -1); // forever
        // Flat colours survive the palette (giflib keeps 5 bits per primary).
        for (int i = 0; i < 5; ++i) {
            const QColor expected = frames[i].pixelColor(10, 10);
            const QColor got = decoded.images[i].pixelColor(10, 10);
            QVERIFY2(std::abs(expected.red() - got.red()) <= 8 && std::abs(expected.green() - got.green()) <= 8
                         && std::abs(expected.blue() - got.blue()) <= 8,
                     qPrintable(QStringLiteral("frame %1: %2 → %3").arg(i).arg(expected.name(), got.name())));
        }
    }

    void refusesBadFrames()
    {
        QString error;
        QVERIFY(encodeGif({}, {}, &error).isEmpty());
        QVERIFY(!error.isEmpty());
        QImage a(10, 10, QImage::Format_RGB32), b(12, 10, QImage::Format_RGB32);
        a.fill(Qt::white);
        b.fill(Qt::white);
        QVERIFY(encodeGif({a, b}, {}, &error).isEmpty());
        QVERIFY(error.contains(QStringLiteral("same size")));
    }

    /// Frames are encoded as they are drawn: 200 frames of 800 × 600 pixels (over 380 MB had
    /// they been kept) raise the process's peak memory by a small fraction of that.
    void memoryDoesNotGrowWithFrames()
    {
        const auto peakKilobytes = [] {
            QFile status(QStringLiteral("/proc/self/status"));
            if (!status.open(QIODevice::ReadOnly))
                return -1LL;
            for (const QByteArray &line : status.readAll().split('\n')) {
                if (line.startsWith("VmHWM:"))
                    return line.mid(6).trimmed().split(' ').first().toLongLong();
            }
            return -1LL;
        };
        auto mechanism = createMechanism("fourbar", {});
        QVERIFY(mechanism);
        AnimationSettings settings;
        settings.variable = 0;
        settings.from = 0.0;
        settings.to = 2 * 3.141592653589793;
        settings.frames = 101;
        settings.bounce = true; // 200 frames
        settings.size = QSize(800, 600);
        const long long before = peakKilobytes();
        QVERIFY(before > 0);
        auto gif = renderAnimation(**mechanism, (*mechanism)->homePose(), settings);
        QVERIFY2(gif, gif ? "" : gif.failure().message.c_str());
        const long long grown = peakKilobytes() - before;
        QVERIFY2(grown < 60 * 1024, qPrintable(QStringLiteral("peak memory grew by %1 MB").arg(grown / 1024)));
    }

    void posesFollowTheVariable()
    {
        const MechanismPtr mechanism = prototype();
        AnimationSettings settings;
        settings.variable = mechanism->variableIndex("theta");
        settings.from = -0.5;
        settings.to = 0.5;
        settings.frames = 11;
        auto poses = animationPoses(*mechanism, mechanism->homePose(), settings);
        QVERIFY(poses.ok());
        QCOMPARE(int(poses->size()), 11);
        for (int i = 0; i < 11; ++i)
            QVERIFY(std::abs(mechanism->variableValue((*poses)[i], settings.variable) - (-0.5 + 0.1 * i)) < 1e-12);
        // Bounced: forth and back without repeating the ends.
        settings.size = QSize(160, 120);
        const QList<QImage> frames = animationFrames(*mechanism, *poses, settings);
        QCOMPARE(frames.size(), 11 + 9);
        QCOMPARE(frames.first().size(), QSize(160, 120));
        QVERIFY(frames[1] != frames[2]); // the linkage moved
        QCOMPARE(frames[9], frames[11]); // the way back passes the same poses
    }

    /// A video of the 3-RP̲R's q₁ from 10 to 20 mm showed the platform small in its half
    /// frame, fitted to the whole range of motion, about three times its size: the frames now
    /// share the sweep's box, which holds every pose's joints. The П-joint's range of motion is
    /// its pose's size: it keeps it.
    void framesFitTheSweep()
    {
        auto design = designfile::load(QStringLiteral("pp-3rpr"));
        QVERIFY(design);
        const Mechanism &mechanism = *design->mechanism;
        AnimationSettings settings;
        settings.variable = mechanism.variableIndex("q1");
        settings.from = 10.0;
        settings.to = 20.0;
        settings.frames = 6;
        auto poses = animationPoses(mechanism, design->pose, settings);
        QVERIFY(poses.ok());
        const Eigen::AlignedBox3d swept = sweptExtent(mechanism, *poses);
        QVERIFY(!swept.isEmpty());
        const Eigen::AlignedBox3d whole = mechanism.scene(design->pose).extent;
        QVERIFY2(swept.sizes().x() * swept.sizes().y() < 0.5 * whole.sizes().x() * whole.sizes().y(),
                 qPrintable(QStringLiteral("%1 × %2 mm of %3 × %4").arg(swept.sizes().x()).arg(swept.sizes().y())
                                .arg(whole.sizes().x()).arg(whole.sizes().y())));
        for (const Pose &pose : *poses) {
            for (const SceneJoint &joint : mechanism.scene(pose).joints) {
                if (joint.position.allFinite())
                    QVERIFY(swept.contains(joint.position));
            }
        }
        const MechanismPtr pjoint = prototype();
        settings.variable = pjoint->variableIndex("theta");
        settings.from = -0.5;
        settings.to = 0.5;
        auto pjointPoses = animationPoses(*pjoint, pjoint->homePose(), settings);
        QVERIFY(pjointPoses.ok());
        QVERIFY(sweptExtent(*pjoint, *pjointPoses).isEmpty());
    }

    void unreachableFrameIsNamed()
    {
        const MechanismPtr mechanism = prototype();
        AnimationSettings settings;
        settings.variable = mechanism->variableIndex("theta");
        settings.from = 0.0;
        settings.to = 2.0; // past θ_max = 60°
        settings.frames = 5;
        auto poses = animationPoses(*mechanism, mechanism->homePose(), settings);
        QVERIFY(!poses.ok());
        const QString message = QString::fromStdString(poses.failure().message);
        QVERIFY2(message.startsWith(QStringLiteral("Frame ")) && message.contains(QStringLiteral("theta")),
                 qPrintable(message));
        settings.frames = 1;
        QVERIFY(!animationPoses(*mechanism, mechanism->homePose(), settings).ok());
    }

    /// A five-bar's crank may turn −180…180° on paper, yet its leg stretches on the way: the
    /// range offered stops short of that, and an export over it runs to its end, in both
    /// directions. The export dialog offers it, and keeps the choices of the last export.
    void offeredRangeRunsToItsEnd()
    {
        const Design design = designfile::load(QStringLiteral("fivebar-example")).value();
        const Mechanism &m = *design.mechanism;
        AnimationSettings settings;
        settings.variable = m.variableIndex("theta1");
        const Interval whole = m.variableRange(settings.variable);
        settings.from = whole.min;
        settings.to = whole.max;
        QVERIFY(!animationPoses(m, design.pose, settings).ok()); // frame 43 once
        const Interval offered = animationRange(m, design.pose, settings.variable);
        const double here = m.variableValue(design.pose, settings.variable);
        QVERIFY2(offered.min <= here && here <= offered.max && offered.max - offered.min > 0.5
                     && offered.max - offered.min < whole.max - whole.min,
                 qPrintable(QStringLiteral("%1 … %2 rad").arg(offered.min).arg(offered.max)));
        for (bool forward : {true, false}) {
            settings.from = forward ? offered.min : offered.max;
            settings.to = forward ? offered.max : offered.min;
            auto poses = animationPoses(m, design.pose, settings);
            QVERIFY2(poses.ok(), poses.ok() ? "" : poses.failure().message.c_str());
        }
        // a range that is whole stays whole: the П-joint's θ over ±60°
        const MechanismPtr pjoint = prototype();
        const int theta = pjoint->variableIndex("theta");
        const Interval full = animationRange(*pjoint, pjoint->homePose(), theta);
        QCOMPARE(full.min, pjoint->variableRange(theta).min);
        QCOMPARE(full.max, pjoint->variableRange(theta).max);

        QSettings().clear();
        AnimationDialog dialog(m, settings.variable);
        dialog.setStart(design.pose);
        const AnimationSettings chosen = dialog.settings();
        QVERIFY(chosen.from >= offered.min - 1e-9 && chosen.to <= offered.max + 1e-9);
        QVERIFY(animationPoses(m, design.pose, chosen).ok());
        dialog.framesBox()->setValue(90);
        dialog.formatBox()->setCurrentIndex(1);
        dialog.rememberChoices();
        AnimationDialog again(m, 0);
        again.restoreChoices();
        QCOMPARE(again.framesBox()->value(), 90);
        QCOMPARE(again.formatBox()->currentIndex(), 1);
        QSettings().clear();
    }

    void commandLineWritesAGif()
    {
        cli::registerDrawingCommands(); // runCli() in-process runs `pkm render`, as pkm-draw does
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("crank.gif"));
        const auto run = [](const QStringList &arguments) {
            std::FILE *out = std::tmpfile();
            std::FILE *err = std::tmpfile();
            const int status = runCli(arguments, out, err);
            std::fclose(out);
            std::fclose(err);
            return status;
        };
        QCOMPARE(run({QStringLiteral("render"), QStringLiteral("fourbar-example"), QStringLiteral("--var"),
                      QStringLiteral("alpha"), QStringLiteral("--from"), QStringLiteral("0"), QStringLiteral("--to"),
                      QStringLiteral("90"), QStringLiteral("--steps"), QStringLiteral("5"), QStringLiteral("--size"),
                      QStringLiteral("200x150"), QStringLiteral("-o"), path}),
                 0);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const Decoded decoded = decode(file.readAll());
        QCOMPARE(decoded.frames, 5 + 3);
        QCOMPARE(decoded.size, QSize(200, 150));

        // --var without a GIF, a pose past the limit, a parameter: refused, nothing written.
        const QString other = dir.filePath(QStringLiteral("other.gif"));
        QCOMPARE(run({QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("--var"),
                      QStringLiteral("theta"), QStringLiteral("-o"), dir.filePath(QStringLiteral("x.png"))}),
                 2);
        QCOMPARE(run({QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("--var"),
                      QStringLiteral("theta"), QStringLiteral("--from"), QStringLiteral("0"), QStringLiteral("--to"),
                      QStringLiteral("90"), QStringLiteral("--steps"), QStringLiteral("4"), QStringLiteral("-o"), other}),
                 3);
        QCOMPARE(run({QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("--var"),
                      QStringLiteral("a"), QStringLiteral("--from"), QStringLiteral("100"), QStringLiteral("--to"),
                      QStringLiteral("200"), QStringLiteral("--steps"), QStringLiteral("4"), QStringLiteral("-o"), other}),
                 2);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("crank.gif")});
    }

    void guiExportWritesAGif()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sweep.gif"));
        MainWindow window;
        QVERIFY(window.openDesign(QStringLiteral("fourbar-example")));
        AnimationSettings settings = crankTurn(24, QSize(320, 240));
        window.exportAnimationTo(path, settings);
        // Drawn off the GUI thread: the call returns at once, and the window hears of the
        // result only through its event loop (the file itself may already be there when the
        // worker was quick and this thread slow, so it is not what is checked).
        QVERIFY(!window.lastStatus().startsWith(QStringLiteral("Wrote")));
        QTRY_VERIFY2_WITH_TIMEOUT(window.lastStatus().startsWith(QStringLiteral("Wrote")), qPrintable(window.lastStatus()),
                                  60000);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const Decoded decoded = decode(file.readAll());
        QCOMPARE(decoded.frames, 24 + 22);
        QCOMPARE(decoded.size, QSize(320, 240));
    }

    /// Exporting gives the memory back: after one export has loaded what every export needs,
    /// two more of 150 frames at 1000×750 (two such GIFs grew the window from 236 to 891 MB
    /// when the frames were kept) leave the process within 10 % of where it stood.
    void guiExportsGiveTheirMemoryBack()
    {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(window.openDesign(QStringLiteral("fourbar-example")));
        AnimationSettings settings = crankTurn(20, QSize(1000, 750));
        const auto exportOnce = [&](int index, int frames) {
            settings.frames = frames;
            const QString path = dir.filePath(QStringLiteral("sweep%1.gif").arg(index));
            window.exportAnimationTo(path, settings);
            QTRY_VERIFY_WITH_TIMEOUT(window.lastStatus().startsWith(QStringLiteral("Wrote")) &&
                                         window.lastStatus().contains(QStringLiteral("sweep%1.gif").arg(index)),
                                     120000);
            QFile::remove(path);
        };
        exportOnce(0, 20);
        QTest::qWait(200);
        const double start = residentMegabytes();
        for (int i = 1; i <= 2; ++i) {
            exportOnce(i, 150);
            if (QTest::currentTestFailed())
                return;
        }
        // Given back once the export's worker and its frames are gone: on a loaded machine that
        // is a little after the status says "Wrote" (CI once measured 137 MB 200 ms after it).
        QTRY_VERIFY_WITH_TIMEOUT(residentMegabytes() <= 1.10 * start, 10000);
        const double end = residentMegabytes();
        qInfo("resident memory: %.0f MB after the first export, %.0f MB after two more", start, end);
        QVERIFY2(end <= 1.10 * start, qPrintable(QStringLiteral("%1 MB → %2 MB").arg(start).arg(end)));
    }
};

QTEST_MAIN(TestAnimation)
#include "tst_animation.moc"
