// The Equations dock in the main window (issue 18): a tab beside "Values" and
// Mobility, listed in the View menu; raised, it shows the open preset's equations, each result
// reading as the values table reads it, and follows the pose and the design.
//
// With PKM_GRAB_DIR set, the window with the dock raised is written there for the O-X glide
// (equations-window.png), for the П-joint at θ = 30° (equations-pjoint.png) and in Russian
// (equations-ru.png).
#include "gui/mainwindow.h"

#include "document/document.h"
#include "document/language.h"
#include "equationspanel.h"
#include "support/app.h"
#include "valuestable.h"

#include <QDir>
#include <QDockWidget>
#include <QTest>

using namespace pkm;
using namespace pkm::test;

class TestEquationsDock : public QObject
{
    Q_OBJECT

    MainWindow *m_window = nullptr;
    EquationsPanel *panel() const { return m_window->equationsPanel(); }
    QDockWidget *dock(const char *name) const { return m_window->findChild<QDockWidget *>(QLatin1String(name)); }

    /// Every result that is a scalar of the report, as the panel and the values table show it.
    void compareWithValues()
    {
        const Mechanism &m = *m_window->document()->mechanism();
        int compared = 0;
        for (int i = 0; i < int(panel()->shownEquations().size()); ++i) {
            const std::string &name = panel()->shownEquations()[std::size_t(i)].resultName;
            const ReportEntry *entry = name.empty() ? nullptr : m.reportLayout().find(name);
            if (!entry || entry->rows * entry->cols != 1)
                continue;
            QCOMPARE(panel()->resultText(i), m_window->valuesTable()->valueText(QString::fromStdString(name)));
            ++compared;
        }
        QVERIFY(compared > 0);
    }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1280, 720}); // a projector
        QVERIFY(m_window);
    }

    void cleanupTestCase() { delete m_window; }

    void dockBesideTheValues()
    {
        QDockWidget *equations = dock("equationsDock");
        QVERIFY(equations);
        QVERIFY(m_window->tabifiedDockWidgets(dock("valuesDock")).contains(equations));
        QVERIFY(equations->toggleViewAction());
        QCOMPARE(equations->widget(), static_cast<QWidget *>(panel()));
    }

    void followsThePose_data() { addPresetPerKindRows(); }
    void followsThePose()
    {
        PKM_FETCH_PRESET(preset);
        QVERIFY(m_window->openDesign(preset));
        dock("equationsDock")->raise();
        QVERIFY(QTest::qWaitFor([this] { return panel()->isVisible(); }));
        QVERIFY(!panel()->shownEquations().empty());
        compareWithValues();
        const QString before = panel()->toPlainText();
        // a variable moved through the document: the first that reaches a share of its range
        Document *document = m_window->document();
        bool moved = false;
        for (int v = 0; v < int(document->mechanism()->variableInfo().size()) && !moved; ++v) {
            const Interval range = document->mechanism()->variableRange(v);
            for (double share : {0.75, 0.25, 0.6}) {
                if (!moved && document->setVariable(v, range.min + share * (range.max - range.min)))
                    moved = true;
            }
        }
        QVERIFY(moved);
        QVERIFY(panel()->toPlainText() != before);
        compareWithValues();
        const QString dir = qEnvironmentVariable("PKM_GRAB_DIR");
        if (!dir.isEmpty() && preset == QLatin1String("oxglide-prototype"))
            QVERIFY(m_window->grab().save(QDir(dir).filePath(QStringLiteral("equations-window.png"))));
        if (!dir.isEmpty() && preset == QLatin1String("pjoint-prototype")) {
            QVERIFY(document->setVariable(document->mechanism()->variableIndex("theta"), 30.0 * units::degree));
            QVERIFY(m_window->grab().save(QDir(dir).filePath(QStringLiteral("equations-pjoint.png"))));
        }
        dock("valuesDock")->raise(); // as a new user finds the window
    }

    /// Another language: the titles, sources and notes in it, the numbers in its locale, as the
    /// values table writes them.
    void followsTheLanguage()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("pjoint-prototype")));
        dock("equationsDock")->raise();
        QVERIFY(QTest::qWaitFor([this] { return panel()->isVisible(); }));
        QVERIFY(language::apply(QStringLiteral("ru")));
        // the widgets hear of the change from the event loop
        QVERIFY(QTest::qWaitFor([this] { return panel()->toPlainText().contains(QStringLiteral("Обратная кинематика")); }));
        const QString text = panel()->toPlainText();
        QVERIFY2(text.contains(QStringLiteral("Обратная кинематика")), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("документа о П-шарнире")));
        QVERIFY(panel()->resultText(0).contains(QLatin1Char(','))); // "…,.. мм"
        compareWithValues();
        const QString dir = qEnvironmentVariable("PKM_GRAB_DIR");
        if (!dir.isEmpty())
            QVERIFY(m_window->grab().save(QDir(dir).filePath(QStringLiteral("equations-ru.png"))));
        QVERIFY(language::apply(QStringLiteral("en")));
        QVERIFY(QTest::qWaitFor([this] { return panel()->toPlainText().contains(QStringLiteral("Inverse kinematics")); }));
        dock("valuesDock")->raise();
    }
};

QTEST_MAIN(TestEquationsDock)
#include "tst_equationsdock.moc"
