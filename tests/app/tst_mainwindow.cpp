// The main window driven as a person would: spin boxes, sliders, the design panel, dragging in
// the view, undo. Checks that d, the view, the values and the plot cursors follow.
#include "gui/mainwindow.h"
#include "kinds/workspacepanel.h"

#include "designpanel.h"
#include "document/document.h"
#include "linkageview.h"
#include "kinds/pjoint/pjoint.h"
#include "kinds/pjoint/pjointplots.h"
#include "valuestable.h"
#include "variablepanel.h"
#include "support/app.h"

#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QMessageBox>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>

using namespace pkm;
using namespace pkm::test;

namespace {
constexpr double deg = units::degree;

const PJoint &joint(MainWindow &window)
{
    return static_cast<const PJoint &>(*window.document()->mechanism());
}

void typeInto(QWidget *field, const QString &text)
{
    auto *edit = qobject_cast<QLineEdit *>(field);
    if (!edit)
        edit = field->findChild<QLineEdit *>();
    QVERIFY(edit);
    edit->setFocus();
    edit->selectAll();
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}
} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;

    /// θ shown everywhere equals `theta` (rad): document, d spin box, view, plots, values.
    void checkFollows(double theta)
    {
        MainWindow &w = *m_window;
        const PJointDesign &p = joint(w).design();
        const double d = pjoint::diagonal(p, theta);
        QVERIFY(std::abs(w.document()->pose().outputs[0] - theta) < 1e-9);
        QVERIFY(std::abs(w.document()->pose().inputs[0] - d) < 1e-9);
        QCOMPARE(w.variablePanel()->spinBox(PJoint::variableD)->value(), std::round(d * 100) / 100);
        QCOMPARE(w.variablePanel()->spinBox(PJoint::variableTheta)->value(), std::round(theta / deg * 100) / 100);
        // the view draws A where the pose puts it
        const Eigen::Vector3d A = w.linkageView()->scene().joints[2].position;
        QVERIFY((A.head<2>() - (Eigen::Vector2d(p.b, 0) + p.a * Eigen::Vector2d(std::sin(theta), std::cos(theta))))
                    .norm()
                < 1e-9);
        // the plot cursors sit at θ
        QVERIFY(std::abs(w.kindPanel<PJointPlots>()->cursorTheta() - theta / deg) < 1e-9);
        // the values table shows d
        QCOMPARE(w.valuesTable()->valueText(QStringLiteral("d")), QLocale().toString(d, 'f', 2) + QStringLiteral(" mm"));
    }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1600, 1000});
        QVERIFY(m_window);
    }

    void cleanupTestCase() { delete m_window; }

    void opensPrototype()
    {
        const PJointDesign &p = joint(*m_window).design();
        QCOMPARE(p.a, 170.0);
        QCOMPARE(p.b, 68.0);
        checkFollows(0.0);
        QVERIFY(m_window->windowTitle().contains(QStringLiteral("prototype")));
    }

    void thetaSpinBox_data()
    {
        QTest::addColumn<double>("thetaDeg");
        QTest::newRow("30") << 30.0;
        QTest::newRow("-60") << -60.0;
        QTest::newRow("45.5") << 45.5;
        QTest::newRow("0") << 0.0;
    }
    void thetaSpinBox()
    {
        QFETCH(double, thetaDeg);
        QDoubleSpinBox *spin = m_window->variablePanel()->spinBox(PJoint::variableTheta);
        spin->setFocus();
        spin->selectAll();
        QTest::keyClicks(spin, QLocale().toString(thetaDeg, 'f', 2));
        QTest::keyClick(spin, Qt::Key_Return);
        checkFollows(thetaDeg * deg);
    }

    void thetaSlider()
    {
        QSlider *slider = m_window->variablePanel()->slider(PJoint::variableTheta);
        const int paintsBefore = m_window->linkageView()->paintCount();
        slider->setFocus();
        QTest::keyClick(slider, Qt::Key_Home);
        checkFollows(-60 * deg);
        // the slider stops at the limit and the status bar says why
        QVERIFY2(m_window->lastStatus().contains(QStringLiteral("lower limit")), qPrintable(m_window->lastStatus()));
        QTest::keyClick(slider, Qt::Key_End);
        checkFollows(60 * deg);
        QVERIFY(m_window->lastStatus().contains(QStringLiteral("upper limit")));
        // half way along the slider is θ = 0
        slider->setValue(VariablePanel::sliderSteps / 2);
        checkFollows(0.0);
        QTRY_VERIFY(m_window->linkageView()->paintCount() > paintsBefore);
    }

    void sliderDragKeepsTheHand()
    {
        // While the hand holds the slider, the pose follows it and the slider is not moved
        // back under the hand by the answer.
        QSlider *slider = m_window->variablePanel()->slider(PJoint::variableTheta);
        slider->setSliderDown(true);
        for (int position : {6000, 7000, 8000}) {
            slider->setValue(position);
            QCOMPARE(slider->value(), position);
            checkFollows((-60 + 120.0 * position / VariablePanel::sliderSteps) * deg);
        }
        slider->setSliderDown(false);
        QCOMPARE(slider->value(), 8000);
    }

    void dSpinBoxSolvesTheta()
    {
        const PJointDesign &p = joint(*m_window).design();
        const double theta = 20 * deg;
        const double d = std::round(pjoint::diagonal(p, theta) * 100) / 100;
        QDoubleSpinBox *spin = m_window->variablePanel()->spinBox(PJoint::variableD);
        spin->setValue(d);
        QVERIFY(std::abs(m_window->document()->pose().outputs[0] - pjoint::angle(p, d)) < 1e-12);
        QVERIFY(std::abs(m_window->document()->pose().outputs[0] - theta) < 1e-3);
    }

    void dragCrankInView()
    {
        LinkageView *view = m_window->linkageView();
        const QPointF start = view->handlePosition(0);
        const QPointF target = QPointF((start + QPointF(-40, 10)).toPoint());
        QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, start.toPoint());
        QMouseEvent move(QEvent::MouseMove, target, view->mapToGlobal(target), Qt::NoButton, Qt::LeftButton,
                         Qt::NoModifier);
        QApplication::sendEvent(view, &move);
        QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, target.toPoint());
        // θ is the direction of the pointer seen from B, from the vertical
        const Eigen::Vector2d mm = view->mapping().toScene(QPointF(target.toPoint()));
        const PJointDesign &p = joint(*m_window).design();
        const double expected = std::atan2(mm.x() - p.b, mm.y());
        QVERIFY2(std::abs(m_window->document()->pose().outputs[0] - expected) < 1e-9,
                 qPrintable(QStringLiteral("θ = %1°, expected %2°")
                                .arg(m_window->document()->pose().outputs[0] / deg)
                                .arg(expected / deg)));
        checkFollows(expected);
    }

    void designEditAndUndo()
    {
        MainWindow &w = *m_window;
        w.variablePanel()->spinBox(PJoint::variableTheta)->setValue(30);
        typeInto(w.designPanel()->field(QStringLiteral("a")), QStringLiteral("200"));
        QCOMPARE(joint(w).design().a, 200.0);
        checkFollows(30 * deg); // θ kept, d follows the new a
        QVERIFY(std::abs(w.kindPanel<PJointPlots>()->cursorValue(0) - pjoint::diagonal(joint(w).design(), 30 * deg)) < 1e-9);
        typeInto(w.designPanel()->field(QStringLiteral("k")), QStringLiteral("0.5"));
        QCOMPARE(joint(w).design().b, 100.0);
        QCOMPARE(w.designPanel()->field(QStringLiteral("b"))->text(), QLocale().toString(100));

        w.document()->undoStack()->undo();
        QCOMPARE(joint(w).design().b, 68.0); // editing a kept b; k = b/a followed
        QCOMPARE(joint(w).design().a, 200.0);
        w.document()->undoStack()->undo();
        QCOMPARE(joint(w).design().a, 170.0);
        QCOMPARE(w.designPanel()->field(QStringLiteral("a"))->text(), QLocale().toString(170));
        checkFollows(30 * deg);
        w.document()->undoStack()->redo();
        QCOMPARE(joint(w).design().a, 200.0);
        w.document()->undoStack()->undo();
    }

    void viewKeepsLargerDesignInSight()
    {
        MainWindow &w = *m_window;
        typeInto(w.designPanel()->field(QStringLiteral("a")), QStringLiteral("600"));
        QCOMPARE(joint(w).design().a, 600.0);
        LinkageView *view = w.linkageView();
        for (const SceneJoint &j : view->scene().joints)
            QVERIFY(QRectF(view->rect()).contains(view->mapping().toDevice(Eigen::Vector2d(j.position.head<2>()))));
        w.document()->undoStack()->undo();
        QCOMPARE(joint(w).design().a, 170.0);
    }

    void badInput_data()
    {
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expected");
        QTest::newRow("a negative") << "a" << "-5" << "a (crank";
        QTest::newRow("a zero") << "a" << "0" << "a (crank";
        QTest::newRow("b zero") << "b" << "0" << "b (base";
        QTest::newRow("not a number") << "a" << "abc" << "not a number";
        QTest::newRow("theta_min over max") << "theta_min" << "70" << "theta_min";
        QTest::newRow("theta_max out") << "theta_max" << "95" << "theta_max";
        QTest::newRow("lead zero") << "lead" << "0" << "lead";
        QTest::newRow("force negative") << "force_max" << "-130" << "force_max";
        QTest::newRow("efficiency") << "efficiency" << "2" << "efficiency";
    }
    void badInput()
    {
        QFETCH(QString, field);
        QFETCH(QString, text);
        QFETCH(QString, expected);
        MainWindow &w = *m_window;
        const ParameterSet before = w.document()->mechanism()->parameters();
        const int undoCount = w.document()->undoStack()->count();
        QLineEdit *edit = w.designPanel()->field(field);
        typeInto(edit, text);
        QCOMPARE(w.document()->mechanism()->parameters(), before); // last valid design kept
        QCOMPARE(w.document()->undoStack()->count(), undoCount);
        QVERIFY2(w.designPanel()->message().contains(expected), qPrintable(w.designPanel()->message()));
        QVERIFY(!edit->styleSheet().isEmpty()); // the field is marked
        QVERIFY(!w.valuesTable()->valueText(QStringLiteral("J")).contains(QStringLiteral("nan")));
        // Escape restores the valid value and clears the mark
        edit->setFocus();
        QTest::keyClick(edit, Qt::Key_Escape);
        QVERIFY(edit->styleSheet().isEmpty());
    }

    void helpListsTheSourceDocuments()
    {
        // Help ▸ Source Documents names all four documents by their authors and titles
        MainWindow &w = *m_window;
        auto *action = w.findChild<QAction *>(QStringLiteral("sourceDocumentsAction"));
        QVERIFY(action);
        action->trigger();
        auto *box = w.findChild<QMessageBox *>(QStringLiteral("sourceDocuments"));
        QVERIFY(box);
        QTRY_VERIFY(box->isVisible());
        const QString text = box->text();
        for (const char *author : {"Milutinović", "Vasilić", "Mladenović", "Khabibullina"})
            QVERIFY2(text.contains(QString::fromUtf8(author)), author);
        for (const char *title : {"П-зглоба", "MOMA", "O-X glide", "мехатронных систем"})
            QVERIFY2(text.contains(QString::fromUtf8(title)), title);
        QVERIFY(!text.contains(QStringLiteral("seed"), Qt::CaseInsensitive));
        box->close();
        QTRY_VERIFY(!w.findChild<QMessageBox *>(QStringLiteral("sourceDocuments")));
        // the window has the focus again for the tests after this one
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
    }

    void undoRightAfterEditingAField()
    {
        // Ctrl+Z with the focus still in the field just edited undoes the edit in the document
        MainWindow &w = *m_window;
        const double before = w.document()->mechanism()->parameters().at("a");
        QLineEdit *edit = w.designPanel()->field(QStringLiteral("a"));
        typeInto(edit, QStringLiteral("180"));
        QVERIFY(std::abs(w.document()->mechanism()->parameters().at("a") - 180.0) < 1e-9);
        QVERIFY(edit->hasFocus());
        QTest::keySequence(edit, QKeySequence::Undo);
        QVERIFY(std::abs(w.document()->mechanism()->parameters().at("a") - before) < 1e-9);
        QTest::keySequence(edit, QKeySequence::Redo);
        QVERIFY(std::abs(w.document()->mechanism()->parameters().at("a") - 180.0) < 1e-9);
        // while typing, Ctrl+Z is the field's own: the document is not touched
        edit->setFocus();
        edit->selectAll();
        QTest::keyClicks(edit, QStringLiteral("19"));
        QTest::keySequence(edit, QKeySequence::Undo);
        QVERIFY(std::abs(w.document()->mechanism()->parameters().at("a") - 180.0) < 1e-9);
        QTest::keyClick(edit, Qt::Key_Escape);
        w.document()->undoStack()->undo();
        QVERIFY(std::abs(w.document()->mechanism()->parameters().at("a") - before) < 1e-9);
    }

    void closingWithRejectedFieldIsSafe()
    {
        // Closing moves the focus out of the field, which commits it once more while the
        // window is being destroyed.
        auto *window = new MainWindow;
        window->show();
        QApplication::setActiveWindow(window);
        QVERIFY(QTest::qWaitForWindowActive(window));
        typeInto(window->designPanel()->field(QStringLiteral("a")), QStringLiteral("-5"));
        QVERIFY(window->designPanel()->field(QStringLiteral("a"))->hasFocus());
        delete window;
        // Reaching this line is the test; the Asan build also reports any use after free.
    }

    void layoutIsRemembered()
    {
        QDockWidget *values = m_window->findChild<QDockWidget *>(QStringLiteral("valuesDock"));
        QVERIFY(values);
        values->hide();
        m_window->resize(1500, 950);
        m_window->close(); // saves the layout
        MainWindow second;
        QVERIFY(second.restoredGeometry());
        QCOMPARE(second.height(), 950); // the width may grow to the docks' minimum
        second.show();
        QVERIFY(QTest::qWaitForWindowExposed(&second));
        QVERIFY(!second.findChild<QDockWidget *>(QStringLiteral("valuesDock"))->isVisible());
        values->show();
        m_window->show();
    }

    void presetMenuOpensStudy()
    {
        QAction *preset = m_window->findChild<QAction *>(QStringLiteral("preset_pjoint-study-k03"));
        QVERIFY(preset);
        preset->trigger();
        QCOMPARE(joint(*m_window).design().a, 1000.0);
        QVERIFY(std::abs(joint(*m_window).design().k() - 0.3) < 1e-12);
        QCOMPARE(m_window->variablePanel()->spinBox(PJoint::variableTheta)->maximum(), 75.0);
        m_window->document()->undoStack()->undo();
        QCOMPARE(joint(*m_window).design().a, 170.0);
        QVERIFY(!m_window->openDesign(QStringLiteral("no-such-preset")));
        QVERIFY(m_window->lastStatus().contains(QStringLiteral("no-such-preset")));
    }

    void plotsBelongToTheMechanism()
    {
        // a mechanism without plots of its own shows none, never the previous mechanism's
        QVERIFY(m_window->openDesign(QStringLiteral("pjoint-prototype")));
        QVERIFY(m_window->kindPanel<PJointPlots>()->isVisible());
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        QVERIFY(!m_window->kindPanel<PJointPlots>()->isVisible());
        QVERIFY(!m_window->workspacePanel()->isVisible());
        QVERIFY(m_window->linkageView()->isVisible());
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3a")));
        QVERIFY(m_window->workspacePanel()->isVisible());
        QVERIFY(m_window->openDesign(QStringLiteral("pjoint-prototype")));
        QVERIFY(m_window->kindPanel<PJointPlots>()->isVisible());
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
