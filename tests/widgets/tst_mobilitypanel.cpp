// The Mobility panel (issue 6): for every kind of mechanism it shows Chebyshev's and
// Somov–Malyshev's formulas with the numbers put in and the mobility from the rank, marks the
// formula that fails (a sign and a word, not colour alone) and not the one that holds, says
// when a pose is singular, explains the O-X glide's under-actuation, and shows the classroom
// examples (spatial parallelogram, Bennett linkage, general 4R). The analysis runs off the GUI
// thread: the panel follows pose changes without blocking, shows the latest pose in the end,
// and computes nothing while hidden.
//
// With PKM_GRAB_DIR set, the panel's pictures are written there (mobility-panel*.png).
#include "kinds/fourbar/fourbar.h"
#include "mobilitypanel.h"
#include "registry.h"
#include "support/kinematics.h"

#include <QComboBox>
#include <QDir>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTest>
#include <QTextBrowser>

#include <map>
#include <numbers>

using namespace pkm;
using namespace pkm::test;
using Part = MobilityPanel::Part;
using Subject = MobilityPanel::Subject;

namespace {
constexpr double degree = std::numbers::pi / 180.0;

/// Waits until the panel shows an analysis of `subject` and nothing is running.
bool settled(const MobilityPanel &panel, Subject subject = Subject::ThisMechanism)
{
    return !panel.isBusy() && panel.report().valid && panel.shownSubject() == subject;
}

void grab(QWidget &widget, const QString &name)
{
    const QString dir = qEnvironmentVariable("PKM_GRAB_DIR");
    const QPixmap picture = widget.grab();
    QVERIFY(!picture.isNull());
    QCOMPARE(picture.size(), widget.size() * picture.devicePixelRatio());
    if (!dir.isEmpty())
        QVERIFY(picture.save(QDir(dir).filePath(name)));
}

/// What the panel shows for every kind at its home pose: Chebyshev's and Somov–Malyshev's
/// formulas with the numbers put in (Chebyshev empty: it does not apply), the rank line, the
/// mobility and the pairs.
struct ExpectedPanel {
    const char *chebyshev;
    const char *somovMalyshev;
    const char *rank;
    int mobility;
    const char *pairs;
};
const std::map<QString, ExpectedPanel> &expectedPanels()
{
    static const std::map<QString, ExpectedPanel> panels {
        {QStringLiteral("fourbar"),
            {"3·3 − 2·4 − 0", "6·3 − 5·4 − 4·0 − 3·0 − 2·0 − 0",
                "rank 3 of 6 loop equations → M = F − rank = 4 − 3 = 1", 1, "4 revolute (P₅ = 4)"}},
        {QStringLiteral("pjoint"),
            {"3·5 − 2·7 − 0", "6·5 − 5·7 − 4·0 − 3·0 − 2·0 − 0",
                "rank 6 of 12 loop equations → M = F − rank = 7 − 6 = 1", 1, "6 revolute, 1 prismatic (P₅ = 7)"}},
        {QStringLiteral("moma"),
            {"3·4 − 2·5 − 0", "6·4 − 5·5 − 4·0 − 3·0 − 2·0 − 0",
                "rank 3 of 6 loop equations → M = F − rank = 5 − 3 = 2", 2, "3 revolute, 2 prismatic (P₅ = 5)"}},
        {QStringLiteral("fivebar"),
            {"3·4 − 2·5 − 0", "6·4 − 5·5 − 4·0 − 3·0 − 2·0 − 0",
                "rank 3 of 6 loop equations → M = F − rank = 5 − 3 = 2", 2, "5 revolute (P₅ = 5)"}},
        // the default design is the five-bar example built from two R̲RR legs
        {QStringLiteral("planar-parallel"),
            {"3·4 − 2·5 − 0", "6·4 − 5·5 − 4·0 − 3·0 − 2·0 − 0",
                "rank 3 of 6 loop equations → M = F − rank = 5 − 3 = 2", 2, "5 revolute (P₅ = 5)"}},
        {QStringLiteral("oxglide"),
            {"", "6·8 − 5·7 − 4·0 − 3·4 − 2·0 − 0",
                "rank 15 of 18 loop equations → M = F − rank = 19 − 15 = 4", 4,
                "4 revolute, 3 prismatic (P₅ = 7); 4 spherical (P₃ = 4)"}},
    };
    return panels;
}

const QString wrong = QStringLiteral("⚠ wrong");
const QString right = QStringLiteral("✓ right");
} // namespace

class TestMobilityPanel : public QObject
{
    Q_OBJECT

private slots:
    void presets_data() { addKindRows(); }

    /// Every kind at its home pose: the formulas with their numbers, the marker on the one that
    /// fails and only there, the rank, the verdict.
    void presets()
    {
        QFETCH(QString, kind);
        const auto found = expectedPanels().find(kind);
        QVERIFY2(found != expectedPanels().end(),
            qPrintable(QStringLiteral("no expected panel for kind %1: add it to expectedPanels()").arg(kind)));
        const QString chebyshev = QString::fromUtf8(found->second.chebyshev);
        const QString somovMalyshev = QString::fromUtf8(found->second.somovMalyshev);
        const QString rank = QString::fromUtf8(found->second.rank);
        const int mobility = found->second.mobility;
        const QString pairs = QString::fromUtf8(found->second.pairs);

        MobilityPanel panel;
        panel.resize(380, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        const MechanismPtr m = makeKind(qPrintable(kind));
        panel.setMechanism(m, m->homePose());
        QTRY_VERIFY(settled(panel));
        const MobilityReport expected = analyseMobility(m->kinematicChain(m->homePose()));
        QCOMPARE(panel.report().mobility, mobility);
        QCOMPARE(expected.mobility, mobility);

        const QString chain = panel.partText(Part::Chain);
        QVERIFY2(chain.contains(pairs), qPrintable(chain));
        QVERIFY2(chain.contains(QStringLiteral("n = %1").arg(expected.movingLinks)), qPrintable(chain));
        QVERIFY(
            chain.startsWith(QString::fromStdString(m->kinematicChain(m->homePose()).description).left(1).toUpper()));

        const QString cheb = panel.partText(Part::Chebyshev);
        if (chebyshev.isEmpty()) {
            QVERIFY2(cheb.contains(QStringLiteral("Does not apply: a spatial chain")), qPrintable(cheb));
            QVERIFY(!cheb.contains(wrong) && !cheb.contains(right));
        } else {
            // Chebyshev holds for every planar preset: no warning
            QVERIFY2(cheb.contains(QStringLiteral("3n − 2P₅ − P₄")), qPrintable(cheb));
            QVERIFY2(cheb.contains(QStringLiteral("= ") + chebyshev), qPrintable(cheb));
            QVERIFY2(cheb.contains(QStringLiteral("= %1").arg(mobility)), qPrintable(cheb));
            QVERIFY(cheb.contains(right));
            QVERIFY(!cheb.contains(QStringLiteral("⚠")));
        }

        // Somov–Malyshev fails for all of them (planar chains; the O-X glide's parallel hinges)
        const QString sm = panel.partText(Part::SomovMalyshev);
        QVERIFY2(sm.contains(QStringLiteral("6n − 5P₅ − 4P₄ − 3P₃ − 2P₂ − P₁")), qPrintable(sm));
        QVERIFY2(sm.contains(QStringLiteral("= ") + somovMalyshev), qPrintable(sm));
        const QString w = expected.somovMalyshev < 0 ? QStringLiteral("−%1").arg(-expected.somovMalyshev)
                                                     : QString::number(expected.somovMalyshev);
        QVERIFY2(sm.contains(QStringLiteral("= ") + w), qPrintable(sm));
        QVERIFY(sm.contains(wrong));
        QVERIFY(!sm.contains(right));
        QVERIFY2(
            sm.contains(QStringLiteral("%1 of them are redundant").arg(expected.redundantConstraints)), qPrintable(sm));

        const QString r = panel.partText(Part::Rank);
        QVERIFY2(r.contains(rank), qPrintable(r));
        QVERIFY2(r.contains(QStringLiteral("Mobility M = %1").arg(mobility)), qPrintable(r));
        if (kind != QLatin1String("oxglide"))
            QVERIFY2(r.contains(QStringLiteral("the joint axes are parallel")), qPrintable(r));

        QVERIFY(panel.partText(Part::Singularity).isEmpty());
        QVERIFY(panel.partText(Part::Example).isEmpty());
        QVERIFY(panel.partText(Part::Verdict).contains(QString::fromStdString(expected.verdict)));
        QVERIFY(panel.partText(Part::Note).contains(QStringLiteral("“+ P₁”: a typo")));
        QVERIFY(!panel.partText(Part::Note).contains(QStringLiteral("⚠"))); // no pair of class 1: no effect

        const QString actuation = panel.partText(Part::Actuation);
        if (kind == QLatin1String("oxglide")) {
            // the report: 3 actuators for mobility 4, one freedom left with them locked
            QCOMPARE(expected.actuators, 3);
            QCOMPARE(expected.lockedMobilityNearby, 1);
            QVERIFY2(actuation.contains(QStringLiteral("⚠ Under-actuated by 1:")), qPrintable(actuation));
            QVERIFY(actuation.contains(QStringLiteral("3 actuated freedoms (z, x_AB, x_CD) for mobility 4")));
            QVERIFY(actuation.contains(QStringLiteral("the platform's tilt")));
            QVERIFY(actuation.contains(QStringLiteral("the document's kinematics assume it stays level")));
        } else {
            QVERIFY2(actuation.contains(QStringLiteral("✓ Fully actuated:")), qPrintable(actuation));
            QVERIFY(!actuation.contains(QStringLiteral("⚠")));
            QVERIFY(!actuation.contains(QStringLiteral("tilt")));
        }

        // readable in a narrow dock: everything wraps, nothing scrolls sideways
        panel.resize(330, 700);
        QApplication::processEvents();
        QVERIFY(!panel.browser()->horizontalScrollBar()->isVisible());
        grab(panel, QStringLiteral("mobility-panel-%1-narrow.png").arg(kind));
        panel.resize(400, 1100);
        grab(panel, QStringLiteral("mobility-panel-%1.png").arg(kind));
    }

    /// The classroom examples: the same display for the parallelogram, the Bennett linkage
    /// and a general 4R; back to the mechanism with "This mechanism".
    void examples()
    {
        MobilityPanel panel;
        panel.resize(400, 1000);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QCOMPARE(panel.subjectBox()->count(), 4);
        const MechanismPtr m = makeKind("fourbar");
        panel.setMechanism(m, m->homePose());
        QTRY_VERIFY(settled(panel));

        panel.setSubject(Subject::BennettLinkage);
        QTRY_VERIFY(settled(panel, Subject::BennettLinkage));
        QVERIFY(panel.partText(Part::Example).contains(QStringLiteral("Bennett linkage")));
        QVERIFY(panel.partText(Part::Chebyshev).contains(QStringLiteral("Does not apply: a spatial chain")));
        QString sm = panel.partText(Part::SomovMalyshev);
        QVERIFY2(sm.contains(QStringLiteral("= 6·3 − 5·4 − 4·0 − 3·0 − 2·0 − 0")), qPrintable(sm));
        QVERIFY(sm.contains(QStringLiteral("= −2")));
        QVERIFY(sm.contains(wrong));
        QVERIFY(sm.contains(QStringLiteral("W = −2, but the rank gives M = 1")));
        QString rank = panel.partText(Part::Rank);
        QVERIFY2(
            rank.contains(QStringLiteral("rank 3 of 6 loop equations → M = F − rank = 4 − 3 = 1")), qPrintable(rank));
        QVERIFY(rank.contains(QStringLiteral("Mobility M = 1")));
        QVERIFY(rank.contains(QStringLiteral("Bennett's proportions")));
        QVERIFY(panel.partText(Part::Actuation).isEmpty()); // not the point of an example
        QVERIFY(panel.partText(Part::Singularity).isEmpty());
        grab(panel, QStringLiteral("mobility-panel-bennett.png"));

        panel.setSubject(Subject::SpatialFourR);
        QTRY_VERIFY(settled(panel, Subject::SpatialFourR));
        QCOMPARE(panel.report().mobility, 0);
        sm = panel.partText(Part::SomovMalyshev);
        QVERIFY(sm.contains(QStringLiteral("= −2")));
        QVERIFY(sm.contains(QStringLiteral("A negative W rightly says “rigid”")));
        rank = panel.partText(Part::Rank);
        QVERIFY2(
            rank.contains(QStringLiteral("rank 4 of 6 loop equations → M = F − rank = 4 − 4 = 0")), qPrintable(rank));
        QVERIFY(rank.contains(QStringLiteral("Mobility M = 0")));
        QVERIFY(rank.contains(QStringLiteral("a rigid chain")));

        panel.setSubject(Subject::SpatialParallelogram);
        QTRY_VERIFY(settled(panel, Subject::SpatialParallelogram));
        QVERIFY(panel.partText(Part::SomovMalyshev).contains(QStringLiteral("W = −2, but the rank gives M = 1")));
        rank = panel.partText(Part::Rank);
        QVERIFY(rank.contains(QStringLiteral("Mobility M = 1")));
        QVERIFY(rank.contains(QStringLiteral("3 redundant loop equations: the joint axes are parallel")));

        // a pose change while an example is shown changes nothing shown; "This mechanism"
        // shows the mechanism again, at its latest pose
        const auto moved = m->solveWith(m->homePose(), FourBar::variableAlpha, 120.0 * degree);
        QVERIFY(moved.ok());
        panel.setPose(*moved);
        QVERIFY(!panel.isBusy());
        QCOMPARE(panel.shownSubject(), Subject::SpatialParallelogram);
        panel.setSubject(Subject::ThisMechanism);
        QTRY_VERIFY(settled(panel));
        QVERIFY(panel.partText(Part::Example).isEmpty());
        QVERIFY(panel.partText(Part::Chain).startsWith(QStringLiteral("Planar four-bar")));
        QVERIFY(panel.partText(Part::Chebyshev).contains(QStringLiteral("3·3 − 2·4 − 0")));
        QVERIFY(panel.shownChain().pairs[1].point.isApprox(m->kinematicChain(*moved).pairs[1].point));
    }

    /// Singular poses are said prominently and go away with the pose: a triple-rocker four-bar
    /// at its dead point (direct singularity), a change-point four-bar folded flat (the rank
    /// drops).
    void singularPoses()
    {
        MobilityPanel panel;
        panel.resize(400, 1000);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));

        const MechanismPtr m = make(tripleRockerFourBar());
        const auto dead
            = m->solveWith(m->homePose(), FourBar::variableAlpha, m->variableRange(FourBar::variableAlpha).max);
        QVERIFY(dead.ok());
        const auto inside = m->solveWith(*dead, FourBar::variableAlpha, dead->inputs[0] - 5.0 * degree);
        QVERIFY(inside.ok());

        panel.setMechanism(m, *inside);
        QTRY_VERIFY(settled(panel));
        QVERIFY(panel.partText(Part::Singularity).isEmpty());
        panel.setPose(*dead);
        QTRY_VERIFY(!panel.isBusy() && !panel.partText(Part::Singularity).isEmpty());
        QString singular = panel.partText(Part::Singularity);
        QVERIFY2(singular.contains(QStringLiteral("⚠ Singular pose")), qPrintable(singular));
        QVERIFY(singular.contains(QStringLiteral("a direct singularity")));
        grab(panel, QStringLiteral("mobility-panel-deadpoint.png"));
        panel.setPose(*inside);
        QTRY_VERIFY(!panel.isBusy() && panel.partText(Part::Singularity).isEmpty());

        FourBarDesign c;
        c.crank = 40;
        c.coupler = 120;
        c.rocker = 100;
        c.ground = 60;
        const MechanismPtr changePoint = *FourBar::create(c);
        Pose flat;
        flat.inputs.resize(1);
        flat.outputs.resize(1);
        flat.inputs << 0.0;
        flat.outputs << std::numbers::pi;
        panel.setMechanism(changePoint, flat);
        QTRY_VERIFY(!panel.isBusy() && panel.report().singular);
        singular = panel.partText(Part::Singularity);
        QVERIFY2(singular.contains(
                     QStringLiteral("At this pose the mechanism gains an instantaneous freedom (singularity)")),
            qPrintable(singular));
        QVERIFY(singular.contains(QStringLiteral("drops from 3 to 2")));
        const QString rank = panel.partText(Part::Rank);
        QVERIFY2(rank.contains(QStringLiteral("At this pose: rank 2 of 6 → F − rank = 4 − 2 = 2 (instantaneous)")),
            qPrintable(rank));
        QVERIFY(rank.contains(QStringLiteral("Next to it: rank 3 of 6 → M = F − rank = 4 − 3 = 1")));
        QVERIFY(rank.contains(QStringLiteral("Mobility M = 1 (2 at this pose)")));
        // Chebyshev holds (W = 1 = M): no warning although the pose is singular
        QVERIFY(!panel.partText(Part::Chebyshev).contains(QStringLiteral("⚠")));
    }

    /// A bare chain (setChain), and a chain that cannot be analysed.
    void chains()
    {
        MobilityPanel panel;
        panel.resize(400, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.setChain(mobility::planarFiveBar({Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 50), Eigen::Vector2d(40, 110),
            Eigen::Vector2d(80, 50), Eigen::Vector2d(80, 0)}));
        QTRY_VERIFY(settled(panel));
        QVERIFY(panel.partText(Part::Chebyshev).contains(QStringLiteral("3·4 − 2·5 − 0")));
        QCOMPARE(panel.report().mobility, 2);

        KinematicChain broken;
        broken.links = {"ground", "link"};
        broken.pairs = {mobility::planarRevolute("A", 0, 5, Eigen::Vector2d(0, 0))};
        broken.description = "a broken chain";
        panel.setChain(broken);
        QTRY_VERIFY(!panel.isBusy() && !panel.report().valid
            && panel.partText(Part::Chain).startsWith(QStringLiteral("A broken chain")));
        QVERIFY(panel.partText(Part::Verdict).contains(QStringLiteral("Cannot analyse the mobility")));
        QVERIFY(panel.partText(Part::Chebyshev).isEmpty());
    }

    /// Pose changes never wait for the analysis: a burst of O-X glide poses returns at once,
    /// is coalesced, and the display ends at the last pose. Hidden, the panel computes
    /// nothing and catches up when shown.
    void doesNotBlock()
    {
        MobilityPanel panel;
        panel.resize(400, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        const MechanismPtr m = makeKind("oxglide");
        std::vector<Pose> poses;
        const Interval range = m->variableRange(0);
        for (int i = 0; i <= 40; ++i) {
            const auto p = m->solveWith(m->homePose(), 0, range.min + (range.max - range.min) * (0.3 + 0.4 * i / 40.0));
            if (p)
                poses.push_back(*p);
        }
        QVERIFY(poses.size() > 20);

        QCOMPARE(analyseMobility(m->kinematicChain(poses.front())).mobility, 4);

        QSignalSpy shown(&panel, &MobilityPanel::analysisShown);
        panel.setMechanism(m);
        for (const Pose &p : poses)
            panel.setPose(p);
        // Nothing was analysed on this thread: every result comes back through the event loop,
        // which has not run yet. (How fast is a benchmark's business, not a test's.)
        QVERIFY(panel.isBusy());
        QCOMPARE(shown.count(), 0);
        QTRY_VERIFY(!panel.isBusy());
        QVERIFY(shown.count() >= 1);
        QVERIFY(shown.count() < int(poses.size())); // coalesced
        const KinematicChain last = m->kinematicChain(poses.back());
        QCOMPARE(panel.shownChain().pairs.size(), last.pairs.size());
        for (std::size_t k = 0; k < last.pairs.size(); ++k)
            QVERIFY(panel.shownChain().pairs[k].point.isApprox(last.pairs[k].point));
        QCOMPARE(panel.report().mobility, 4);

        // hidden: nothing runs; shown: the latest pose
        panel.hide();
        shown.clear();
        panel.setPose(poses.front());
        QVERIFY(!panel.isBusy());
        QTest::qWait(20);
        QCOMPARE(shown.count(), 0);
        panel.show();
        QTRY_VERIFY(shown.count() == 1 && !panel.isBusy());
        QVERIFY(panel.shownChain().pairs[1].point.isApprox(m->kinematicChain(poses.front()).pairs[1].point));
    }

    /// Deleting the panel while an analysis runs is safe.
    void deleteWhileRunning()
    {
        auto *panel = new MobilityPanel;
        panel->show();
        QVERIFY(QTest::qWaitForWindowExposed(panel));
        const MechanismPtr m = makeKind("oxglide");
        panel->setMechanism(m, m->homePose());
        QVERIFY(panel->isBusy());
        delete panel;
    }
};

QTEST_MAIN(TestMobilityPanel)
#include "tst_mobilitypanel.moc"
