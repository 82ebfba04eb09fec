// Play and pose bookmarks in the main window, as a teacher uses them: a joint variable moved by
// itself forth and back, in a loop or once; stopped at a limit or before a singular pose with
// the reason in the status bar; bookmarks kept with one key, stepped through with Page Up and
// Page Down (a presenter's clicker) whatever has the focus, saved with the design and undone.
#include "gui/mainwindow.h"
#include "gui/player.h"

#include "document/designfile.h"
#include "document/document.h"
#include "linkageview.h"
#include "playbar.h"
#include "variablepanel.h"
#include "support/app.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QStatusBar>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include <cmath>
#include <numbers>
#include <vector>

using namespace pkm;
using namespace pkm::test;

namespace {
constexpr double deg = units::degree;

/// The index of the П-joint's θ (its input d comes first).
int theta(MainWindow &window)
{
    return window.document()->mechanism()->variableIndex("theta");
}

double variable(MainWindow &window, int index)
{
    return window.document()->mechanism()->variableValue(window.document()->pose(), index);
}

Singularity singularityOf(const Mechanism &mechanism, const Pose &pose)
{
    std::vector<double> values(mechanism.reportLayout().size);
    return mechanism.evaluate(pose, values);
}
} // namespace

class TestPlay : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;

    void open(const QString &preset)
    {
        QVERIFY(m_window->openDesign(preset));
        m_window->setPlaying(false);
    }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow(QSize(1280, 720));
        QVERIFY(m_window);
    }
    void cleanupTestCase() { delete m_window; }

    void forthAndBackTurnsAtTheEnds()
    {
        open(QStringLiteral("pjoint-prototype"));
        MainWindow &w = *m_window;
        PlayBar *bar = w.playBar();
        const int t = theta(w);
        bar->setVariable(t);
        bar->setRange(-30 * deg, 30 * deg);
        bar->setSpeed(60 * deg); // °/s
        bar->setMode(PlayMode::ForthAndBack);
        QTest::mouseClick(bar->playButton(), Qt::LeftButton);
        QVERIFY(w.player()->isPlaying());
        QVERIFY(bar->playButton()->isChecked());
        const double start = variable(w, t);
        w.player()->advance(0.1);
        QCOMPARE_LT(std::abs(variable(w, t) - (start + 6 * deg)), 1e-9);
        // At the upper end it stops exactly there and comes back.
        for (int i = 0; i < 20 && variable(w, t) < 30 * deg - 1e-9; ++i)
            w.player()->advance(0.1);
        QCOMPARE_LT(std::abs(variable(w, t) - 30 * deg), 1e-9);
        w.player()->advance(0.1);
        QCOMPARE_LT(std::abs(variable(w, t) - 24 * deg), 1e-9);
        QVERIFY(w.player()->isPlaying());
        // The sliders, the values and the plots follow the document as with a slider's drag.
        const QSlider *slider = w.variablePanel()->slider(t);
        const Interval range = w.document()->mechanism()->variableRange(t);
        QCOMPARE(slider->value(), int(std::lround((variable(w, t) - range.min) / (range.max - range.min)
                                                  * VariablePanel::sliderSteps)));
        QTest::mouseClick(bar->playButton(), Qt::LeftButton); // Pause
        QVERIFY(!w.player()->isPlaying());
    }

    /// While Play turns at a limit, the note is in the status bar only: over the drawing it
    /// covered part of what the class watches. A hand that moves there gets it over the drawing.
    void aLimitDuringPlayLeavesTheDrawingFree()
    {
        open(QStringLiteral("pjoint-prototype"));
        MainWindow &w = *m_window;
        PlayBar *bar = w.playBar();
        const int t = theta(w);
        bar->setVariable(t);
        const Interval range = w.document()->mechanism()->variableRange(t);
        bar->setRange(range.max - 12 * deg, range.max);
        bar->setSpeed(60 * deg);
        bar->setMode(PlayMode::ForthAndBack);
        w.setPlaying(true);
        for (int i = 0; i < 20 && variable(w, t) < range.max - 1e-9; ++i)
            w.player()->advance(0.1);
        QCOMPARE_LT(std::abs(variable(w, t) - range.max), 1e-9);
        QVERIFY(w.player()->isPlaying());
        QVERIFY(!w.document()->limitNote().isEmpty());
        QVERIFY2(w.linkageView()->message().isEmpty(), qPrintable(w.linkageView()->message()));
        w.setPlaying(false);
        QVERIFY(w.document()->setVariable(t, range.max + 1 * deg).ok()); // a hand past the limit
        QCOMPARE(w.linkageView()->message(), w.document()->limitNote());
    }

    void onceStopsAtTheEndAndSaysSo()
    {
        open(QStringLiteral("pjoint-prototype"));
        MainWindow &w = *m_window;
        w.playBar()->setVariable(theta(w));
        w.playBar()->setRange(0, 10 * deg);
        w.playBar()->setSpeed(50 * deg);
        w.playBar()->setMode(PlayMode::Once);
        QSignalSpy stopped(w.player(), &Player::stopped);
        w.setPlaying(true);
        for (int i = 0; i < 5 && w.player()->isPlaying(); ++i)
            w.player()->advance(0.1);
        QCOMPARE(stopped.count(), 1);
        QVERIFY(!w.player()->isPlaying());
        QVERIFY(!w.playBar()->playButton()->isChecked());
        QCOMPARE_LT(std::abs(variable(w, theta(w)) - 10 * deg), 1e-9);
        QVERIFY2(w.lastStatus().contains(QStringLiteral("end of its range")), qPrintable(w.lastStatus()));
    }

    void loopStartsAgain()
    {
        open(QStringLiteral("fourbar-example"));
        MainWindow &w = *m_window;
        w.playBar()->setVariable(0); // the crank α
        w.playBar()->setRange(0, 360 * deg);
        w.playBar()->setSpeed(180 * deg);
        w.playBar()->setMode(PlayMode::Loop);
        w.setPlaying(true);
        QVERIFY(w.player()->isPlaying());
        double previous = variable(w, 0);
        bool wrapped = false;
        for (int i = 0; i < 40 && w.player()->isPlaying(); ++i) {
            w.player()->advance(0.1);
            wrapped = wrapped || variable(w, 0) < previous;
            previous = variable(w, 0);
        }
        QVERIFY2(w.player()->isPlaying(), qPrintable(w.lastStatus()));
        QVERIFY(wrapped);
        w.setPlaying(false);
    }

    /// A crank-rocker's crank at the speed a class watches: where crank and coupler line up the
    /// rocker stands still at either end (an inverse singular pose), and the crank goes on
    /// round — Play stopped there, at α = 221.86°, as if the mechanism locked.
    void aCrankPassesTheRockersEnds()
    {
        open(QStringLiteral("fourbar-example"));
        MainWindow &w = *m_window;
        w.playBar()->setVariable(0); // the crank α over its whole turn, a degree a frame
        w.playBar()->setMode(PlayMode::Loop);
        const Interval range = w.document()->mechanism()->variableRange(0);
        w.playBar()->setRange(range.min, range.max);
        w.playBar()->setSpeed(Player::framesPerSecond * deg);
        QSignalSpy stopped(w.player(), &Player::stopped);
        w.setPlaying(true);
        const int output = w.document()->mechanism()->inputCount(); // the rocker δ
        double closest = 1.0, turned = 0.0, previous = variable(w, 0);
        std::vector<double> rocker;
        for (int i = 0; i < 4000 && w.player()->isPlaying() && turned < 2 * 360 * deg; ++i) {
            w.player()->advance(1.0 / Player::framesPerSecond);
            const double now = variable(w, 0);
            turned += now - previous < -std::numbers::pi ? now - previous + 2 * std::numbers::pi : now - previous; // 360° is 0°
            previous = now;
            rocker.push_back(variable(w, output));
            closest = std::min(closest, singularityOf(*w.document()->mechanism(), w.document()->pose()).margin);
        }
        QVERIFY2(stopped.isEmpty(), qPrintable(stopped.isEmpty() ? QString() : stopped.first().first().toString()));
        QVERIFY2(turned >= 2 * 360 * deg, qPrintable(QString::number(turned / deg)));
        QVERIFY2(closest < Player::stopMargin(), qPrintable(QString::number(closest))); // it went through the rocker's ends
        int reversals = 0;
        for (std::size_t i = 2; i < rocker.size(); ++i)
            reversals += (rocker[i] - rocker[i - 1]) * (rocker[i - 1] - rocker[i - 2]) < 0 ? 1 : 0;
        QVERIFY2(reversals >= 3, qPrintable(QString::number(reversals)));
        w.setPlaying(false);
    }

    /// The five-bar's first crank moved alone: the other leg holds the platform on a circle
    /// until the legs fold into a singular pose, which Play never reaches.
    void stopsBeforeASingularPose()
    {
        open(QStringLiteral("fivebar-example"));
        MainWindow &w = *m_window;
        w.playBar()->setVariable(0);
        const Interval range = w.document()->mechanism()->variableRange(0);
        w.playBar()->setRange(range.min, range.max);
        w.playBar()->setSpeed((range.max - range.min) / 5);
        w.playBar()->setMode(PlayMode::Once);
        QSignalSpy stopped(w.player(), &Player::stopped);
        w.setPlaying(true);
        for (int i = 0; i < 2000 && w.player()->isPlaying(); ++i)
            w.player()->advance(1.0 / Player::framesPerSecond);
        QCOMPARE(stopped.count(), 1);
        const QString reason = stopped.first().first().toString();
        QVERIFY(!reason.isEmpty());
        QCOMPARE(w.lastStatus(), reason);
        const Singularity there = singularityOf(*w.document()->mechanism(), w.document()->pose());
        QCOMPARE(there.type, SingularityType::None);
        QVERIFY2(there.margin > 0, qPrintable(reason));
    }

    /// Fast, forth and back over the five-bar crank's whole turn: each step that would pass
    /// where the legs stretch stops short of it and turns, in Play's own words (it landed on
    /// the singular pose itself, saying "theta1 = 62.208°, theta4 = …" in the solver's terms).
    void forthAndBackTurnsBeforeASingularPose()
    {
        open(QStringLiteral("fivebar-example"));
        MainWindow &w = *m_window;
        w.playBar()->setVariable(0); // its range and speed as the bar offers them
        w.playBar()->setMode(PlayMode::ForthAndBack);
        QSignalSpy turned(w.player(), &Player::turned);
        w.setPlaying(true);
        int stepsSinceTurn = -1;
        for (int i = 0; i < 400 && w.player()->isPlaying(); ++i) {
            const qsizetype turnsBefore = turned.count();
            w.player()->advance(1.0 / Player::framesPerSecond);
            // the reason stays in the status bar while it plays on (the next pose cleared it
            // before anyone could read it)
            stepsSinceTurn = turned.count() > turnsBefore ? 0 : stepsSinceTurn < 0 ? -1 : stepsSinceTurn + 1;
            if (stepsSinceTurn == 5)
                QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("turned back")),
                    qPrintable(w.statusBar()->currentMessage()));
            const Singularity here = singularityOf(*w.document()->mechanism(), w.document()->pose());
            QCOMPARE(here.type, SingularityType::None);
            QVERIFY2(here.margin >= Player::stopMargin(), qPrintable(w.lastStatus()));
        }
        QVERIFY(turned.count() >= 2);
        for (const QList<QVariant> &turn : turned) {
            const QString reason = turn.first().toString();
            // one sentence: "Play turned back: Play stopped before …" said both
            QVERIFY2(reason.startsWith(QStringLiteral("Play turned back")) && reason.contains(QStringLiteral("singular pose"))
                         && !reason.contains(QStringLiteral("stopped")),
                     qPrintable(reason));
            QVERIFY2(!reason.contains(QStringLiteral("theta")), qPrintable(reason));
        }
        w.setPlaying(false);
    }

    /// The 3-R̲RR's platform stays in its assembly mode while Play moves q₁ forth and back in
    /// large steps (a slow repaint): it turned back near a direct singularity and came down in
    /// another mode (φ −55° where it had gone up through −8°), and where that one ended it
    /// snapped back (φ turned 116° in a frame). An assembly mode keeps the sign of det J_x.
    void theRRRPlatformStaysInItsAssemblyMode()
    {
        open(QStringLiteral("pp-3rrr"));
        MainWindow &w = *m_window;
        w.playBar()->setVariable(0);
        w.playBar()->setMode(PlayMode::ForthAndBack);
        QSignalSpy turned(w.player(), &Player::turned);
        const Mechanism &mechanism = *w.document()->mechanism();
        const ReportEntry *detJx = mechanism.reportLayout().find("det_Jx");
        QVERIFY(detJx);
        std::vector<double> values(mechanism.reportLayout().size);
        const auto sign = [&] {
            mechanism.evaluate(w.document()->pose(), values);
            return values[std::size_t(detJx->offset)] > 0.0;
        };
        const bool first = sign();
        w.setPlaying(true);
        for (int i = 0; i < 300 && w.player()->isPlaying(); ++i) {
            w.player()->advance(0.1); // 7.2° of q₁ a step
            QVERIFY2(sign() == first, qPrintable(QStringLiteral("q₁ = %1°, φ = %2°")
                .arg(variable(w, 0) / deg).arg(variable(w, mechanism.variableIndex("phi")) / deg)));
        }
        QVERIFY(turned.count() >= 2);
        w.setPlaying(false);
    }

    void aNewDesignStopsPlay()
    {
        open(QStringLiteral("pjoint-prototype"));
        MainWindow &w = *m_window;
        w.playBar()->setMode(PlayMode::ForthAndBack);
        w.setPlaying(true);
        QVERIFY(w.player()->isPlaying());
        QVERIFY(w.openDesign(QStringLiteral("moma-3a")));
        QVERIFY(!w.player()->isPlaying());
        QVERIFY(!w.playBar()->playButton()->isChecked());
        QCOMPARE(w.playBar()->variableBox()->count(), int(w.document()->mechanism()->variableInfo().size()));
    }

    /// The Play button keeps its width as it turns into Pause, in every language, so that the
    /// bar does not shift under the pointer (it widened by the longer word).
    void playButtonKeepsItsWidth()
    {
        open(QStringLiteral("pjoint-prototype"));
        MainWindow &w = *m_window;
        QToolButton *button = w.playBar()->playButton();
        w.setPlaying(false);
        QCoreApplication::processEvents();
        const int playing = button->width();
        w.setPlaying(true);
        QCoreApplication::processEvents();
        QCOMPARE(button->width(), playing);
        QVERIFY(button->text().contains(QStringLiteral("❚❚")));
        w.setPlaying(false);
        QCoreApplication::processEvents();
        QCOMPARE(button->width(), playing);
        QCOMPARE_GE(button->width(), button->sizeHint().width());
    }

    /// Another design of the same kind: the chosen range where it still fits, cut to the new
    /// design where it overlaps, the whole range (and its speed) where nothing of it is left;
    /// never a range of one point (the 1 m study after the 170 mm prototype once offered
    /// "from 622.30 mm to 622.30 mm").
    void aNewDesignKeepsOnlyARangeThatStillFits()
    {
        open(QStringLiteral("pjoint-prototype"));
        MainWindow &w = *m_window;
        PlayBar *bar = w.playBar();
        bar->setVariable(0); // d, mm
        bar->setRange(130.0, 200.0);
        QVERIFY(w.document()->setParameter(QStringLiteral("a"), 175.0).ok());
        QCOMPARE(bar->settings().from, 130.0); // an edit keeps the teacher's range
        QCOMPARE(bar->settings().to, 200.0);
        QVERIFY(w.document()->setParameter(QStringLiteral("a"), 150.0).ok());
        const Interval edited = w.document()->mechanism()->variableRange(0);
        QCOMPARE(bar->settings().from, 130.0);
        QVERIFY(qAbs(bar->settings().to - std::min(200.0, edited.max)) < 0.01);

        QVERIFY(w.openDesign(QStringLiteral("pjoint-study-k04")));
        const Interval range = w.document()->mechanism()->variableRange(0);
        const PlaySettings fresh = bar->settings();
        QVERIFY2(qAbs(fresh.from - range.min) < 0.01 && qAbs(fresh.to - range.max) < 0.01,
                 qPrintable(QStringLiteral("%1 … %2 mm").arg(fresh.from).arg(fresh.to)));
        QVERIFY(qAbs(fresh.speed - (range.max - range.min) / 5.0) < 0.01);
    }

    /// A crank that turns fully loops, as its motor turns it; a crank that only rocks, a slider
    /// and a 2-DOF mechanism's crank go forth and back (a loop would jump back to the start);
    /// Once stays as chosen.
    void theModeSuitsTheVariable()
    {
        open(QStringLiteral("fourbar-example"));
        MainWindow &w = *m_window;
        PlayBar *bar = w.playBar();
        bar->setVariable(0); // α of a crank-rocker: 0 … 360°
        QCOMPARE(bar->settings().mode, PlayMode::Loop);
        bar->setVariable(1); // δ, the rocker: an output
        QCOMPARE(bar->settings().mode, PlayMode::ForthAndBack);
        bar->setVariable(0);
        QCOMPARE(bar->settings().mode, PlayMode::Loop);
        QVERIFY(w.document()->setParameter(QStringLiteral("AB"), 130.0).ok()); // a double rocker
        QVERIFY(w.document()->mechanism()->variableRange(0).max < 2.0 * std::numbers::pi);
        QCOMPARE(bar->settings().mode, PlayMode::ForthAndBack);
        for (const char *preset : {"fivebar-example", "pp-3rpr", "pjoint-prototype"}) {
            QVERIFY(w.openDesign(QLatin1String(preset)));
            QVERIFY2(bar->settings().mode == PlayMode::ForthAndBack, preset);
        }
        bar->setMode(PlayMode::Once);
        QVERIFY(w.openDesign(QStringLiteral("fourbar-example")));
        QCOMPARE(bar->settings().mode, PlayMode::Once);
        bar->setMode(PlayMode::ForthAndBack);
    }

    void bookmarksStepWithPageKeys()
    {
        open(QStringLiteral("pjoint-prototype"));
        MainWindow &w = *m_window;
        QAction *add = w.findChild<QAction *>(QStringLiteral("addBookmarkAction"));
        QVERIFY(add);
        const double thetas[] = {-40 * deg, 0, 35 * deg};
        for (double angle : thetas) {
            QVERIFY(w.document()->setVariable(theta(w), angle));
            add->trigger();
        }
        QCOMPARE(w.document()->bookmarks().size(), 3);
        QVERIFY(w.document()->setVariable(theta(w), 10 * deg));
        // The clicker's key reaches the window with a slider focused, which would take it as
        // a page step of its own.
        QSlider *slider = w.variablePanel()->slider(theta(w));
        slider->setFocus();
        QTest::keyClick(slider, Qt::Key_PageDown);
        QCOMPARE_LT(std::abs(variable(w, theta(w)) - thetas[0]), 1e-9); // after the last kept: round to the first
        QTest::keyClick(slider, Qt::Key_PageDown);
        QCOMPARE_LT(std::abs(variable(w, theta(w)) - thetas[1]), 1e-9);
        QTest::keyClick(slider, Qt::Key_PageUp);
        QTest::keyClick(slider, Qt::Key_PageUp);
        QCOMPARE_LT(std::abs(variable(w, theta(w)) - thetas[2]), 1e-9);
        QCOMPARE(w.currentBookmark(), 2);
        QVERIFY(w.lastStatus().contains(QStringLiteral("3")));

        // Undo forgets the last bookmark and leaves the pose where it is.
        const double before = variable(w, theta(w));
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->bookmarks().size(), 2);
        QCOMPARE(variable(w, theta(w)), before);
        w.document()->undoStack()->redo();
        QCOMPARE(w.document()->bookmarks().size(), 3);
    }

    void bookmarksAreSavedWithTheDesign()
    {
        MainWindow &w = *m_window;
        QCOMPARE(w.document()->bookmarks().size(), 3);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("lesson.pkm.json"));
        QVERIFY(designfile::save(w.document()->design(), path));
        auto reopened = designfile::load(path);
        QVERIFY2(reopened, reopened ? "" : reopened.failure().message.c_str());
        QCOMPARE(reopened->bookmarks, w.document()->bookmarks());
        QVERIFY(w.openDesign(path));
        QTest::keyClick(&w, Qt::Key_PageDown);
        QCOMPARE_LT(std::abs(variable(w, theta(w)) - (-40 * deg)), 1e-9);
    }

    void badBookmarksAreRefused_data()
    {
        QTest::addColumn<QByteArray>("bookmarks");
        QTest::addColumn<QString>("message");
        QTest::newRow("not a list") << QByteArray("{}") << QStringLiteral("is not a list");
        QTest::newRow("unknown variable") << QByteArray(R"([{"name": "x", "pose": {"nope": 1}}])")
                                          << QStringLiteral("invalid pose value 'nope'");
        QByteArray many = "[";
        for (int i = 0; i <= designfile::maxBookmarks; ++i)
            many += QByteArray(i ? "," : "") + R"({"name": "b", "pose": {"theta": 1}})";
        QTest::newRow("too many") << many + "]" << QStringLiteral("more than 100 bookmarks");
    }

    void badBookmarksAreRefused()
    {
        QFETCH(QByteArray, bookmarks);
        QFETCH(QString, message);
        const QByteArray file = R"({"format": "pkm-studio-design", "version": 2, "mechanism": "pjoint", "bookmarks": )"
            + bookmarks + "}";
        auto parsed = designfile::parse(file, QStringLiteral("lesson.pkm.json"));
        QVERIFY(!parsed);
        QVERIFY2(QString::fromStdString(parsed.failure().message).contains(message), parsed.failure().message.c_str());
    }

    /// A mechanism whose range of motion dwarfs it — the 3-RP̲R's platform reaches about three
    /// times the mechanism's own size, the five-bar's cranks sweep whole circles — is drawn fitted to its pose, about twice as large as a
    /// fit to the whole range; as Play moves it, the view widens in a few steps so that it never
    /// leaves sight, never beyond the whole range. Fit brings a large drawing back.
    void aSmallMechanismIsDrawnLargeAndKeptInSight_data()
    {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<double>("gain"); // the pose's scale over the whole range's, at least
        QTest::newRow("3-RP̲R") << QStringLiteral("pp-3rpr") << 1.8;
        QTest::newRow("five-bar") << QStringLiteral("fivebar-example") << 1.3;
    }

    void aSmallMechanismIsDrawnLargeAndKeptInSight()
    {
        QFETCH(QString, preset);
        QFETCH(double, gain);
        open(preset);
        MainWindow &w = *m_window;
        LinkageView *view = w.linkageView();
        QTest::keyClick(view, Qt::Key_Home);
        const QRectF area(view->rect());
        const auto drawn = [&] { return ScenePainter::jointBounds(view->scene(), view->mapping(), view->sceneStyle()); };
        const auto wholeScale = [&] {
            return LinkageView::screenMapping(view->scene(), view->scene().extent, area, view->sceneStyle()).scale;
        };
        const double fitted = view->mapping().scale;
        QCOMPARE_GT(fitted, gain * wholeScale());
        QCOMPARE_GT(std::max(drawn().width() / area.width(), drawn().height() / area.height()), 0.5);

        PlayBar *bar = w.playBar();
        int widenings = 0;
        double scale = fitted;
        for (int index = 0; index < w.document()->mechanism()->inputCount(); ++index) {
            bar->setVariable(index);
            const Interval range = w.document()->mechanism()->variableRange(index);
            bar->setRange(range.min, range.max);
            bar->setMode(PlayMode::ForthAndBack);
            w.setPlaying(true);
            for (int step = 0; step < 120 && w.player()->isPlaying(); ++step) {
                w.player()->advance(0.1);
                QVERIFY2(area.contains(drawn()), qPrintable(QStringLiteral("input %1, step %2").arg(index + 1).arg(step)));
                if (view->mapping().scale != scale) {
                    QCOMPARE_LT(view->mapping().scale, scale); // it only widens
                    scale = view->mapping().scale;
                    ++widenings;
                }
            }
            w.setPlaying(false);
        }
        QCOMPARE_GT(widenings, 0);
        QCOMPARE_LE(widenings, 4);
        QCOMPARE_GE(scale, 0.99 * wholeScale());
        // Fit: the pose again (with its ghosts, spread wider at some poses than at others)
        QTest::keyClick(view, Qt::Key_Home);
        QVERIFY(view->fittedBox().contains(view->scene().poseExtent));
        QVERIFY(!view->fittedBox().contains(view->scene().extent));
        QCOMPARE_GT(view->mapping().scale, wholeScale());
    }

    void aBookmarkThatNoLongerFitsSaysSo()
    {
        open(QStringLiteral("pjoint-prototype"));
        MainWindow &w = *m_window;
        QVERIFY(w.document()->setVariable(theta(w), 50 * deg));
        QVERIFY(w.document()->addBookmark(QStringLiteral("far out")));
        QVERIFY(w.document()->setParameter(QStringLiteral("theta_max"), 40.0));
        const double now = variable(w, theta(w));
        QTest::keyClick(&w, Qt::Key_PageDown);
        QVERIFY2(w.lastStatus().contains(QStringLiteral("far out")), qPrintable(w.lastStatus()));
        QCOMPARE(variable(w, theta(w)), now);
    }
};

QTEST_MAIN(TestPlay)
#include "tst_play.moc"
