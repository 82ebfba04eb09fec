// The Mobility dock in the main window (issue 6): a tab behind "Values at this pose", listed
// in the View menu, idle while hidden; raised, it shows the current preset's formulas and rank
// and follows pose and design changes.
//
// With PKM_GRAB_DIR set, the window with the dock raised is written there
// (mobility-window.png).
#include "gui/mainwindow.h"

#include "document/document.h"
#include "mobilitypanel.h"

#include <QDir>
#include <QDockWidget>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include <numbers>

using namespace pkm;
using Part = MobilityPanel::Part;

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
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        m_window = new MainWindow;
        m_window->resize(1600, 1000);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
    }

    void cleanupTestCase() { delete m_window; }

    /// The dock is a tab behind the values, in the View menu, and computes nothing hidden.
    void dockBehindValues()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        QDockWidget *mobility = dock("mobilityDock");
        QDockWidget *values = dock("valuesDock");
        QVERIFY(mobility && values);
        QCOMPARE(mobility->widget(), panel());
        QCOMPARE(mobility->windowTitle(), QStringLiteral("Mobility"));
        QVERIFY(m_window->tabifiedDockWidgets(values).contains(mobility));
        QVERIFY(values->isVisible());
        QVERIFY(panel()->visibleRegion().isEmpty()); // a tab behind: visible to Qt, not seen
        QVERIFY(!panel()->isBusy());

        // behind the values it computes nothing: a pose change leaves it as it was
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
    void presets_data()
    {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QString>("chebyshev");
        QTest::addColumn<QString>("somovMalyshev");
        QTest::addColumn<int>("mobility");
        QTest::newRow("pjoint") << "pjoint-prototype"
                                << "= 1"
                                << "= −5" << 1;
        QTest::newRow("moma") << "moma-3a"
                              << "= 2"
                              << "= −1" << 2;
        QTest::newRow("fivebar") << "fivebar-example"
                                 << "= 2"
                                 << "= −1" << 2;
        QTest::newRow("oxglide") << "oxglide-prototype"
                                 << ""
                                 << "= 1" << 4;
        QTest::newRow("fourbar") << "fourbar-example"
                                 << "= 1"
                                 << "= −2" << 1;
    }

    void presets()
    {
        QFETCH(QString, preset);
        QFETCH(QString, chebyshev);
        QFETCH(QString, somovMalyshev);
        QFETCH(int, mobility);
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
