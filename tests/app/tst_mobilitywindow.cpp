// The Mobility dock in the main window (issue 6): a tab behind "Design", listed
// in the View menu, idle while hidden; raised, it shows the current preset's formulas and rank
// and follows pose and design changes.
//
// With PKM_GRAB_DIR set, the window with the dock raised is written there
// (mobility-window.png).
#include "gui/mainwindow.h"

#include "document/document.h"
#include "mobilitypanel.h"
#include "support/app.h"

#include <QDir>
#include <QDockWidget>
#include <QMenuBar>
#include <QTest>

#include <map>
#include <numbers>

using namespace pkm;
using namespace pkm::test;
using Part = MobilityPanel::Part;

namespace {
/// What the Mobility dock says for the preset of every kind (presetPerKind()): Chebyshev's W
/// (empty: it does not apply, the chain is spatial), Somov–Malyshev's W and the mobility.
struct ExpectedReport {
    const char *chebyshev;
    const char *somovMalyshev;
    int mobility;
};
const std::map<QString, ExpectedReport> &expectedReports()
{
    static const std::map<QString, ExpectedReport> reports {
        {QStringLiteral("pjoint-prototype"), {"= 1", "= −5", 1}},
        {QStringLiteral("moma-3a"), {"= 2", "= −1", 2}},
        {QStringLiteral("fivebar-example"), {"= 2", "= −1", 2}},
        {QStringLiteral("oxglide-prototype"), {"", "= 1", 4}},
        {QStringLiteral("fourbar-example"), {"= 1", "= −2", 1}},
        {QStringLiteral("pp-2prr-moma3a"), {"= 2", "= −1", 2}}, // MOMA 3a from two P̲RR legs
    };
    return reports;
}
} // namespace

class TestMobilityWindow : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;
    MobilityPanel *panel() const { return m_window->mobilityPanel(); }
    QDockWidget *dock(const char *name) const { return m_window->findChild<QDockWidget *>(QLatin1String(name)); }

    /// Opens a preset and waits for the panel to show its analysis.
    bool open(const char *preset)
    {
        if (!m_window->openDesign(QLatin1String(preset)))
            return false;
        return QTest::qWaitFor([this] {
            return !panel()->isBusy() && panel()->report().valid
                && panel()->shownChain().description
                == m_window->document()->mechanism()->kinematicChain(m_window->document()->pose()).description;
        });
    }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1600, 1000});
        QVERIFY(m_window);
    }

    void cleanupTestCase() { delete m_window; }

    /// The dock is a tab behind the Design (two tabs a group fit a projector's 340 px docks),
    /// in the View menu, and computes nothing hidden.
    void dockBehindTheDesign()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        QDockWidget *mobility = dock("mobilityDock");
        QDockWidget *values = dock("valuesDock");
        QVERIFY(mobility && values);
        QCOMPARE(mobility->widget(), panel());
        QCOMPARE(mobility->windowTitle(), QStringLiteral("Mobility"));
        QVERIFY(m_window->tabifiedDockWidgets(dock("designDock")).contains(mobility));
        QVERIFY(values->isVisible());
        QVERIFY(panel()->visibleRegion().isEmpty()); // a tab behind: visible to Qt, not seen
        QVERIFY(!panel()->isBusy());

        // behind the Design it computes nothing: a pose change leaves it as it was
        Document *document = m_window->document();
        const Eigen::Vector3d before
            = panel()->shownChain().pairs.empty() ? Eigen::Vector3d::Zero() : panel()->shownChain().pairs[1].point;
        QVERIFY(document->setVariable(0, document->pose().inputs[0] + 0.3).ok());
        QVERIFY(!panel()->isBusy());
        QTest::qWait(50);
        QVERIFY(panel()->shownChain().pairs.empty() || panel()->shownChain().pairs[1].point == before);
        bool listed = false;
        for (QAction *action : m_window->menuBar()->actions()) {
            if (action->menu() && action->text() == QStringLiteral("&View"))
                listed = action->menu()->actions().contains(mobility->toggleViewAction());
        }
        QVERIFY(listed);

        mobility->raise();
        QTRY_VERIFY(!panel()->visibleRegion().isEmpty() && !panel()->isBusy() && panel()->report().valid);
        // caught up with the pose
        QVERIFY(panel()->shownChain().pairs[1].point.isApprox(
            document->mechanism()->kinematicChain(document->pose()).pairs[1].point));
        QVERIFY(panel()->partText(Part::Chain).startsWith(QStringLiteral("Planar four-bar")));
        QVERIFY(panel()->partText(Part::Chebyshev).contains(QStringLiteral("= 3·3 − 2·4 − 0")));
        QVERIFY(panel()->partText(Part::Chebyshev).contains(QStringLiteral("✓ right")));
        QVERIFY(panel()->partText(Part::SomovMalyshev).contains(QStringLiteral("⚠ wrong")));
        QVERIFY(panel()->partText(Part::Rank).contains(QStringLiteral("Mobility M = 1")));
    }

    /// A pose change reaches the panel.
    void followsThePose()
    {
        Document *document = m_window->document();
        const double alpha = document->pose().inputs[0];
        QVERIFY(document->setVariable(0, alpha + 40.0 * std::numbers::pi / 180.0).ok());
        const Eigen::Vector3d b = document->mechanism()->kinematicChain(document->pose()).pairs[1].point;
        QTRY_VERIFY(!panel()->isBusy() && panel()->shownChain().pairs[1].point.isApprox(b));
    }

    /// Every preset kind through the window: the numbers of the report.
    void presets_data() { addPresetPerKindRows(); }

    void presets()
    {
        PKM_FETCH_PRESET(preset);
        const auto expected = expectedReports().find(preset);
        QVERIFY2(expected != expectedReports().end(),
            qPrintable(QStringLiteral("no expected report for preset %1: add it to expectedReports()").arg(preset)));
        const QString chebyshev = QString::fromUtf8(expected->second.chebyshev);
        const QString somovMalyshev = QString::fromUtf8(expected->second.somovMalyshev);
        const int mobility = expected->second.mobility;
        QVERIFY(open(qPrintable(preset)));
        if (chebyshev.isEmpty())
            QVERIFY(panel()->partText(Part::Chebyshev).contains(QStringLiteral("Does not apply")));
        else
            QVERIFY2(
                panel()->partText(Part::Chebyshev).contains(chebyshev), qPrintable(panel()->partText(Part::Chebyshev)));
        QVERIFY(panel()->partText(Part::SomovMalyshev).contains(somovMalyshev));
        QVERIFY(panel()->partText(Part::Rank).contains(QStringLiteral("Mobility M = %1").arg(mobility)));
        QCOMPARE(panel()->report().mobility, mobility);
        QCOMPARE(panel()->partText(Part::Actuation).contains(QStringLiteral("⚠ Under-actuated by 1")),
            preset == QLatin1String("oxglide-prototype"));
        const QString dir = qEnvironmentVariable("PKM_GRAB_DIR");
        if (!dir.isEmpty() && preset == QLatin1String("fourbar-example"))
            QVERIFY(m_window->grab().save(QDir(dir).filePath(QStringLiteral("mobility-window.png"))));
    }
};

QTEST_MAIN(TestMobilityWindow)
#include "tst_mobilitywindow.moc"
