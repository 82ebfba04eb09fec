// The plot beside an animation's mechanism: `pkm render … --plot QUANTITY` and the GUI's
// export with a quantity or the plot on screen beside the view. The curve is the quantity
// along the animation's path (the П-joint's d(θ) against eq. (2) in closed form), the cursor
// follows each frame's pose, a singular pose reads ∞ rather than a huge number, and the frames
// really carry the plot at their right half.
#include "cli/cli.h"
#include "cli/drawingcommands.h"
#include "document/designfile.h"
#include "document/document.h"
#include "document/language.h"
#include "export/animation.h"
#include "export/animationplot.h"
#include "gui/animationdialog.h"
#include "gui/mainwindow.h"
#include "kinds/kindpanel.h"
#include "plotfocus.h"
#include "plotstyle.h"
#include "registry.h"
#include "support/cliinprocess.h"

#include <QComboBox>
#include <QImageReader>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace pkm;

namespace {

using Run = test::CliRun;
const auto run = test::runCliInProcess;

/// Pixels near `rgb` (each channel within 40) in `area` of `image`.
int pixelsNear(const QImage &image, const QRect &area, QRgb rgb)
{
    int count = 0;
    for (int y = area.top(); y <= area.bottom(); ++y) {
        for (int x = area.left(); x <= area.right(); ++x) {
            const QRgb p = image.pixel(x, y);
            if (std::abs(qRed(p) - qRed(rgb)) < 40 && std::abs(qGreen(p) - qGreen(rgb)) < 40
                && std::abs(qBlue(p) - qBlue(rgb)) < 40)
                ++count;
        }
    }
    return count;
}

/// The column with most cursor-red pixels: where the cursor's line is.
int cursorColumn(const QImage &image)
{
    int best = -1, most = 0;
    for (int x = 0; x < image.width(); ++x) {
        const int n = pixelsNear(image, QRect(x, 0, 1, image.height()), plotstyle::cursorRgb);
        if (n > most) {
            most = n;
            best = x;
        }
    }
    return best;
}

/// The frames of a GIF.
QList<QImage> gifFrames(const QString &path)
{
    QImageReader reader(path);
    QList<QImage> frames;
    for (QImage frame = reader.read(); !frame.isNull(); frame = reader.read())
        frames.append(frame.convertToFormat(QImage::Format_RGB32));
    return frames;
}

AnimationSettings thetaSweep(const Mechanism &mechanism)
{
    AnimationSettings settings;
    settings.variable = mechanism.variableIndex("theta");
    settings.from = -60.0 * std::numbers::pi / 180.0;
    settings.to = 60.0 * std::numbers::pi / 180.0;
    settings.frames = 8;
    settings.size = QSize(640, 360);
    return settings;
}

} // namespace

class TestAnimationPlot : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        cli::registerDrawingCommands();
    }

    void curveIsTheClosedForm()
    {
        const Design design = designfile::load(QStringLiteral("pjoint-prototype")).value();
        const Mechanism &m = *design.mechanism;
        const auto plot = animationPlot(m, design.pose, thetaSweep(m), "d");
        QVERIFY2(plot.ok(), plot.ok() ? "" : plot.failure().message.c_str());
        QCOMPARE(int(plot->curve.size()), animationPlotSamples);
        QCOMPARE(plot->xMin, -60.0);
        QCOMPARE(plot->xMax, 60.0);
        // eq. (2): d = a·√(1 + k² + 2k·sin θ), a = 170 mm, k = 0.4
        for (const QPointF &point : plot->curve) {
            const double theta = point.x() * std::numbers::pi / 180.0;
            const double d = 170.0 * std::sqrt(1.0 + 0.16 + 0.8 * std::sin(theta));
            QVERIFY2(std::abs(point.y() - d) < 1e-9, qPrintable(QString::number(point.x())));
            QVERIFY(point.y() > plot->yMin && point.y() < plot->yMax);
        }
        QVERIFY(plot->title.startsWith(QStringLiteral("Diagonal length against")));
        QCOMPARE(plot->yLabel, QStringLiteral("d (mm)"));
        QCOMPARE(plot->xLabel, QStringLiteral("θ (°)"));
    }

    /// The title names the two quantities without their descriptions: the five-bar's det J
    /// against θ₁ took three lines beside the mechanism ("Determinant of J (0: direct, ∞:
    /// inverse singularity) against crank AB angle at A, from +x counter-clockwise").
    void titleNamesWithoutDescriptions()
    {
        const Design design = designfile::load(QStringLiteral("fivebar-example")).value();
        const Mechanism &m = *design.mechanism;
        AnimationSettings settings;
        settings.variable = m.variableIndex("theta1");
        settings.from = 100.0 * std::numbers::pi / 180.0;
        settings.to = 130.0 * std::numbers::pi / 180.0;
        settings.frames = 8;
        settings.size = QSize(640, 360);
        const auto plot = animationPlot(m, design.pose, settings, "det_J");
        QVERIFY2(plot.ok(), plot.ok() ? "" : plot.failure().message.c_str());
        QCOMPARE(plot->title, QStringLiteral("Determinant of J against crank AB angle at A"));
    }

    /// The title joins two labels in the nominative: Russian and Serbian say which is on the
    /// abscissa rather than put a nominative after "от"/"од" ("… в зависимости от угол …").
    void titleIsGrammaticalInEveryLanguage()
    {
        const Design design = designfile::load(QStringLiteral("pjoint-prototype")).value();
        const Mechanism &m = *design.mechanism;
        for (const QString &code : {QStringLiteral("ru"), QStringLiteral("sr"), QStringLiteral("sr_Latn")}) {
            QVERIFY(language::apply(code));
            const auto plot = animationPlot(m, design.pose, thetaSweep(m), "d");
            QVERIFY(plot.ok());
            for (const char *preposition : {" от ", " од ", " od "})
                QVERIFY2(!plot->title.contains(QString::fromUtf8(preposition)), qPrintable(plot->title));
            QVERIFY2(plot->title.contains(QLatin1Char('(')), qPrintable(plot->title));
        }
        language::apply(QStringLiteral("en"));
    }

    void unknownQuantityIsNamed()
    {
        const Design design = designfile::load(QStringLiteral("pjoint-prototype")).value();
        const auto plot = animationPlot(*design.mechanism, design.pose, thetaSweep(*design.mechanism), "foo\x1b");
        QVERIFY(!plot.ok());
        const QString message = QString::fromStdString(plot.failure().message);
        QVERIFY2(message.contains(QStringLiteral("'foo\\x1B'")) && message.contains(QStringLiteral("torque")),
                 qPrintable(message));
        // the swept variable is not offered against itself
        for (const ReportEntry *entry : animationPlotQuantities(*design.mechanism, thetaSweep(*design.mechanism).variable))
            QVERIFY(entry->name != "theta");
    }

    void cursorFollowsThePose()
    {
        const Design design = designfile::load(QStringLiteral("pjoint-prototype")).value();
        const Mechanism &m = *design.mechanism;
        const AnimationSettings settings = thetaSweep(m);
        const AnimationPlot plot = animationPlot(m, design.pose, settings, "d").value();
        const auto at = [&](double degrees) {
            return m.solveWith(design.pose, settings.variable, degrees * std::numbers::pi / 180.0).value();
        };
        const QImage left = animationPlotImage(plot, m, at(-40.0), QSize(640, 720));
        const QImage right = animationPlotImage(plot, m, at(40.0), QSize(640, 720));
        QCOMPARE(left.size(), QSize(640, 720));
        QVERIFY(pixelsNear(left, left.rect(), plotstyle::designRgb) > 500); // the curve
        const int x1 = cursorColumn(left), x2 = cursorColumn(right);
        QVERIFY2(x2 - x1 > 200, qPrintable(QStringLiteral("%1 → %2").arg(x1).arg(x2)));
        QCOMPARE(animationPlotReadout(plot, m, at(0.0)), QStringLiteral("d = 183.10 mm"));
    }

    void singularPoseReadsInfinity()
    {
        // MOMA 3c in the other assembly mode at (195, 195) mm: an inverse singularity, det J = ∞.
        const Design design = designfile::load(QStringLiteral("moma-3c")).value();
        const MechanismPtr m = design.mechanism->withParameters({{"assembly", -1.0}}).value();
        const Pose singular = m->solveInverse(Coordinates(Eigen::Vector2d(195.0, 195.0)), nullptr).value();
        AnimationSettings settings;
        settings.variable = m->variableIndex("p1");
        settings.from = singular.inputs[0] - 5.0;
        settings.to = singular.inputs[0] + 5.0;
        const AnimationPlot plot = animationPlot(*m, singular, settings, "det_J").value();
        QCOMPARE(animationPlotReadout(plot, *m, singular), QStringLiteral("det J = ∞"));
        // the axis is finite even though the curve runs off towards ∞
        QVERIFY(std::isfinite(plot.yMin) && std::isfinite(plot.yMax) && plot.yMax > plot.yMin);
        QVERIFY(!animationPlotImage(plot, *m, singular, QSize(320, 360)).isNull());
    }

    void commandLinePutsThePlotBeside()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("pjoint.gif"));
        const QStringList sweep {QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("--var"),
                                 QStringLiteral("theta"), QStringLiteral("--from"), QStringLiteral("-60"),
                                 QStringLiteral("--to"), QStringLiteral("60"), QStringLiteral("--steps"),
                                 QStringLiteral("4"), QStringLiteral("--one-way")};
        const Run written = run(sweep + QStringList {QStringLiteral("--plot"), QStringLiteral("d"),
                                                     QStringLiteral("-o"), path});
        QVERIFY2(written.status == 0, qPrintable(written.err));
        QVERIFY2(written.out.contains(QStringLiteral("4 frames of 1280 × 720 pixels")), qPrintable(written.out));
        const QList<QImage> frames = gifFrames(path);
        QCOMPARE(frames.size(), 4);
        // the curve at the right half, the mechanism at the left; the cursor moves to the right
        const QRect plotHalf(640, 0, 640, 720);
        QVERIFY(pixelsNear(frames[0], plotHalf, plotstyle::designRgb) > 500);
        const int x1 = cursorColumn(frames[1].copy(plotHalf)), x2 = cursorColumn(frames[2].copy(plotHalf));
        QVERIFY2(x2 > x1 + 100, qPrintable(QStringLiteral("%1 → %2").arg(x1).arg(x2))); // θ = −20° → +20°

        const Run unknown = run(sweep + QStringList {QStringLiteral("--plot"), QStringLiteral("foo"),
                                                     QStringLiteral("-o"), dir.filePath(QStringLiteral("x.gif"))});
        QCOMPARE(unknown.status, 2);
        QVERIFY2(unknown.err.startsWith(QStringLiteral("pkm: --plot foo: ")) && unknown.err.contains(QStringLiteral("torque")),
                 qPrintable(unknown.err));
        const Run still = run({QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("--plot"),
                               QStringLiteral("d"), QStringLiteral("-o"), dir.filePath(QStringLiteral("x.png"))});
        QCOMPARE(still.status, 2);
        QVERIFY2(still.err.contains(QStringLiteral("--plot")), qPrintable(still.err));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList {QStringLiteral("pjoint.gif")});
    }

    void dialogOffersThePlotOnScreenAndTheQuantities()
    {
        const Design design = designfile::load(QStringLiteral("pjoint-prototype")).value();
        AnimationDialog dialog(*design.mechanism, 0);
        QCOMPARE(dialog.besideChoice(), QString()); // nothing by default
        dialog.setShownPlot(QStringLiteral("Fig. 8"));
        QComboBox *box = dialog.besideBox();
        QCOMPARE(box->itemData(1).toString(), AnimationDialog::shownPlotChoice());
        QVERIFY(box->itemText(1).contains(QStringLiteral("Fig. 8")));
        QVERIFY(box->findData(QStringLiteral("torque")) > 1);
        box->setCurrentIndex(box->findData(QStringLiteral("torque")));
        QCOMPARE(dialog.besideChoice(), QStringLiteral("torque"));
        dialog.variableBox()->setCurrentIndex(1); // another variable: the choice is kept
        QCOMPARE(dialog.besideChoice(), QStringLiteral("torque"));
    }

    void dialogFitsAProjectorInEveryLanguage()
    {
        const Design design = designfile::load(QStringLiteral("moma-3a")).value();
        for (const QString &code : {QStringLiteral("en"), QStringLiteral("ru"), QStringLiteral("sr"),
                                    QStringLiteral("sr_Latn")}) {
            QVERIFY(language::apply(code));
            AnimationDialog dialog(*design.mechanism, 0);
            dialog.setShownPlot(QStringLiteral("Workspace and det J of the design, all modes (fig. 3a)"));
            dialog.besideBox()->setCurrentIndex(dialog.besideBox()->count() - 1);
            const QSize wanted = dialog.sizeHint();
            QVERIFY2(wanted.width() <= 1024 && wanted.height() <= 720,
                     qPrintable(QStringLiteral("%1: %2 × %3").arg(code).arg(wanted.width()).arg(wanted.height())));
        }
        language::apply(QStringLiteral("en"));
    }

    void windowExportsThePlotOnScreen()
    {
        QTemporaryDir dir;
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openDesign(QStringLiteral("pjoint-prototype")));
        QCustomPlot *shown = plotfocus::active(window.currentPanel());
        QVERIFY(shown);
        const Pose before = window.document()->pose();
        // a frame lays the plot out at the frame's size, and may move its ranges
        const QCPRange screenX = shown->xAxis->range(), screenY = shown->yAxis->range();
        AnimationSettings settings = thetaSweep(*window.document()->mechanism());
        settings.frames = 3;
        settings.bounce = false;
        for (const QString &beside : {AnimationDialog::shownPlotChoice(), QStringLiteral("torque")}) {
            const QString path = dir.filePath(beside.mid(1) + QStringLiteral(".gif"));
            window.exportAnimationTo(path, settings, beside);
            QTRY_VERIFY2_WITH_TIMEOUT(window.lastStatus().startsWith(QStringLiteral("Wrote %1").arg(path)),
                                      qPrintable(window.lastStatus()), 60000);
            const QList<QImage> frames = gifFrames(path);
            QCOMPARE(frames.size(), 3);
            const QRect plotHalf(320, 0, 320, 360);
            QVERIFY2(pixelsNear(frames[0], plotHalf, plotstyle::designRgb) > 100, qPrintable(beside));
            QVERIFY2(frames[0].copy(plotHalf) != frames[2].copy(plotHalf), qPrintable(beside)); // the cursor moved
        }
        QCOMPARE(window.document()->pose().inputs, before.inputs); // the window's pose never moved
        // ... and the plot on screen is laid out for the screen again, with its ranges: left at
        // the frame's layout, its cursor stood away from the pose until the window was resized
        QCoreApplication::processEvents();
        QCOMPARE(shown->viewport(), shown->rect());
        QVERIFY2(shown->rect().contains(shown->axisRect()->outerRect()),
                 qPrintable(QStringLiteral("%1 px wide, laid out to %2").arg(shown->width()).arg(shown->axisRect()->outerRect().right())));
        QCOMPARE(shown->xAxis->range(), screenX);
        QCOMPARE(shown->yAxis->range(), screenY);
    }
};

QTEST_MAIN(TestAnimationPlot)
#include "tst_animationplot.moc"
