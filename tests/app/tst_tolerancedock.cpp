// The Tolerances dock in the main window (issue 19, part 5): a tab beside "Values",
// listed in the View menu; tolerances edited through the document (undoable, saved with the
// design), the first order live at the pose, the Monte Carlo and the worst-case map off the GUI
// thread, shown as a histogram and a colour map.
//
// With PKM_GRAB_DIR set, the window with the dock raised is written there in every language
// (tolerances-LANG.png) after a Monte Carlo, and with the map (tolerances-map.png).
#include "gui/mainwindow.h"
#include "gui/tolerancepanel.h"

#include "document/designfile.h"
#include "document/document.h"
#include "document/language.h"
#include "support/app.h"
#include "support/kinematics.h"

#include <qcustomplot.h>

#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QTableWidget>
#include <QTest>

using namespace pkm;
using namespace pkm::test;

class TestToleranceDock : public QObject
{
    Q_OBJECT

    MainWindow *m_window = nullptr;
    QDockWidget *dock(const char *name) const { return m_window->findChild<QDockWidget *>(QLatin1String(name)); }
    TolerancePanel *panel() const { return m_window->findChild<TolerancePanel *>(); }
    QString summary() const { return panel()->findChild<QLabel *>(QStringLiteral("toleranceSummary"))->text(); }
    QCustomPlot *plot() const { return panel()->findChild<QCustomPlot *>(QStringLiteral("tolerancePlot")); }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1280, 720}); // a projector
        QVERIFY(m_window);
    }

    void cleanupTestCase() { delete m_window; }

    void dockBesideTheValues()
    {
        QDockWidget *tolerances = dock("toleranceDock");
        QVERIFY(tolerances);
        // behind the values with the equations; the Design shares its place with the mobility
        QVERIFY(m_window->tabifiedDockWidgets(dock("valuesDock")).contains(tolerances));
        QVERIFY(m_window->tabifiedDockWidgets(dock("valuesDock")).contains(dock("equationsDock")));
        QVERIFY(m_window->tabifiedDockWidgets(dock("designDock")).contains(dock("mobilityDock")));
        QVERIFY(panel());
    }

    /// At 1280×720 the dock is about 340 px wide: every parameter's name and the header are
    /// whole ("x_R1 (mm)" read "x_R…" under "Paramete"); a narrower dock scrolls instead.
    void namesAreWhole()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3a")));
        dock("toleranceDock")->raise();
        QVERIFY(QTest::qWaitFor([this] { return panel()->isVisible(); }));
        auto *table = panel()->findChild<QTableWidget *>(QStringLiteral("toleranceTable"));
        QVERIFY(table && table->rowCount() > 4);
        const int width = table->columnWidth(0);
        const QFontMetrics metrics(table->font());
        QCOMPARE_LE(metrics.horizontalAdvance(table->horizontalHeaderItem(0)->text()), width);
        for (int row = 0; row < table->rowCount(); ++row) {
            const QString name = table->item(row, 0)->text();
            QVERIFY2(metrics.horizontalAdvance(name) < width, qPrintable(name));
        }
    }

    /// A ratio has no unit to name: the four-bar's λ reads "λ", not "λ ()"; a length keeps it.
    void aRatioHasNoEmptyUnit()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        dock("toleranceDock")->raise();
        QVERIFY(QTest::qWaitFor([this] { return panel()->isVisible(); }));
        auto *table = panel()->findChild<QTableWidget *>(QStringLiteral("toleranceTable"));
        QVERIFY(table && table->rowCount() > 0);
        QStringList names;
        for (int row = 0; row < table->rowCount(); ++row)
            names << table->item(row, 0)->text();
        QVERIFY2(!names.join(QLatin1Char(' ')).contains(QStringLiteral("()")), qPrintable(names.join(QStringLiteral(", "))));
        QVERIFY2(names.join(QLatin1Char(' ')).contains(QStringLiteral("(mm)")), qPrintable(names.join(QStringLiteral(", "))));
    }

    /// Edits are undoable document commands; the first order follows them and the pose.
    void editsAreUndoable()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3a")));
        dock("toleranceDock")->raise();
        QVERIFY(QTest::qWaitFor([this] { return panel()->isVisible(); }));
        Document *document = m_window->document();
        QVERIFY(summary().contains(QStringLiteral("at least one")));
        const int steps = document->undoStack()->count();
        QVERIFY(document->setTolerance(QStringLiteral("l1"), 0.05).ok());
        QVERIFY(document->setTolerance(QStringLiteral("alpha1"), 0.1 * units::degree).ok());
        QCOMPARE(document->undoStack()->count(), steps + 2);
        QVERIFY2(summary().contains(QStringLiteral("≤")), qPrintable(summary()));
        const QString before = summary();
        QVERIFY(document->moveOutputsTo(Coordinates(pair(20.0, -250.0))).ok());
        QVERIFY(summary() != before);
        // refused: a non-geometric parameter names itself, nothing changes
        const auto refused = document->setTolerance(QStringLiteral("force_max1"), 1.0);
        QVERIFY(!refused.ok());
        QCOMPARE(document->undoStack()->count(), steps + 2);
        document->undoStack()->undo();
        QCOMPARE(int(document->tolerances().size()), 1);
        document->undoStack()->redo();
        QCOMPARE(int(document->tolerances().size()), 2);
        // saved with the design and read back
        const auto read = designfile::parse(designfile::serialize(document->design()), QStringLiteral("test"));
        QVERIFY(read.ok());
        QCOMPARE(read->tolerances.size(), std::size_t(2));
        QVERIFY(std::abs(read->tolerances.at("l1") - 0.05) < 1e-12);
    }

    /// The Monte Carlo runs in the background and ends as a histogram.
    void monteCarloHistogram()
    {
        panel()->runMonteCarlo();
        QVERIFY(QTest::qWaitFor([this] { return panel()->monteCarlo().has_value(); }, 60000));
        QCOMPARE(panel()->monteCarlo()->samples, tolerance::defaultSamples);
        QCOMPARE(panel()->monteCarlo()->failed, 0);
        QCOMPARE(plot()->plottableCount(), 1);
        QVERIFY(qobject_cast<QCPBars *>(plot()->plottable(0)));
        const QString dir = qEnvironmentVariable("PKM_GRAB_DIR");
        for (const char *code : {"en", "ru", "sr", "sr_Latn"}) {
            QVERIFY(language::apply(QString::fromLatin1(code)));
            QTest::qWait(50);
            QVERIFY(!summary().contains(QStringLiteral("nan")) && !summary().contains(QStringLiteral("inf")));
            if (!dir.isEmpty())
                QVERIFY(m_window->grab().save(QDir(dir).filePath(QStringLiteral("tolerances-%1.png").arg(QLatin1String(code)))));
        }
        QVERIFY(language::apply(QStringLiteral("en")));
    }

    /// The map runs in the background and ends as a colour map.
    void worstCaseMap()
    {
        panel()->runMap();
        QVERIFY(QTest::qWaitFor([this] { return plot()->plottableCount() == 1 && qobject_cast<QCPColorMap *>(plot()->plottable(0)); },
                                60000));
        const QString dir = qEnvironmentVariable("PKM_GRAB_DIR");
        if (!dir.isEmpty())
            QVERIFY(m_window->grab().save(QDir(dir).filePath(QStringLiteral("tolerances-map.png"))));
    }
};

QTEST_MAIN(TestToleranceDock)
#include "tst_tolerancedock.moc"
