// The leg library's editor in the main window, as the issue's user does it: start a 3-RPR from
// File ▸ New from Template, drag a platform point in the linkage view (the parameter follows,
// the map is computed again, one undo step restores it), save and reopen the design, retype a
// leg and add and remove one, and see an edit that cannot be assembled refused with one message
// naming the leg while the design stays; the design panel shows only what the legs use.
#include "gui/mainwindow.h"

#include "designpanel.h"
#include "document/designsession.h"
#include "document/document.h"
#include "kinds/planarparallel/planarparallel.h"
#include "kinds/planarparallel/planarparallelpanel.h"
#include "kinds/workspacepanel.h"
#include "linkageview.h"
#include "modebar.h"
#include "workspacemapview.h"
#include "support/app.h"

#include <QAbstractButton>
#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace pkm;
using namespace pkm::test;

namespace {
const PlanarParallel &legsOf(const MainWindow &w)
{
    return dynamic_cast<const PlanarParallel &>(*w.document()->mechanism());
}

/// Waits until the map shows the current design (a new design is computed off the GUI thread).
bool mapFollows(WorkspaceMapView *map, const MechanismPtr &mechanism)
{
    QSignalSpy ready(map, &WorkspaceMapView::mapReady);
    for (int i = 0; i < 40 && (map->mechanism() != mechanism || map->busy()); ++i)
        ready.wait(500);
    return map->mechanism() == mechanism && !map->busy();
}
} // namespace

class TestPlanarParallelEditor : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;
    QTemporaryDir m_dir;
    PlanarParallelPanel *panel() const { return m_window->kindPanel<PlanarParallelPanel>(); }
    WorkspaceMapView *map() const { return panel()->mapPanel()->mapView(); }
    bool fieldShown(const char *name) const
    {
        QLineEdit *field = m_window->designPanel()->field(QString::fromLatin1(name));
        return field && field->isVisibleTo(m_window->designPanel());
    }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1800, 1000});
        QVERIFY(m_window);
        m_window->setQuestion([](const QString &, const QString &, QMessageBox::StandardButtons) {
            return QMessageBox::Discard;
        });
    }

    void cleanupTestCase() { delete m_window; }

    void startsFromTheTemplate()
    {
        QAction *start = m_window->findChild<QAction *>(QStringLiteral("template_pp-3rpr"));
        QVERIFY(start);
        for (const char *id : {"pp-5r", "pp-5r-pjoint", "pp-pa-pjoint", "pp-3rrr", "pp-3prr", "pp-2prr-moma3a"})
            QVERIFY2(m_window->findChild<QAction *>(QStringLiteral("template_") + QLatin1String(id)), id);
        start->trigger();
        QCOMPARE(m_window->document()->mechanism()->kind(), std::string_view("planar-parallel"));
        QCOMPARE(legsOf(*m_window).design().legCount(), 3);
        // a new design of the user's own: no file, not the preset, modified until saved
        QVERIFY(m_window->session()->filePath().isEmpty());
        QVERIFY(m_window->document()->design().id.isEmpty());
        QVERIFY(m_window->session()->isModified());
        QVERIFY(panel()->isVisible());
        QVERIFY(mapFollows(map(), m_window->document()->mechanism()));
        // the legs editor shows three struts on a free body
        QCOMPARE(panel()->platformBox()->currentData().toInt(), int(PlatformType::Free));
        for (int i = 0; i < 3; ++i)
            QCOMPARE(panel()->typeBox(i)->currentData().toInt(), int(LegType::RPR));
    }

    void showsOnlyWhatTheLegsUse()
    {
        for (const char *name : {"A3x", "B2y", "q1_min", "q3_max", "assembly", "phi_map"})
            QVERIFY2(fieldShown(name), name);
        // struts: no cranks, links, guides, П-joints or working modes
        for (const char *name : {"r1", "l2", "alpha3", "a1", "k2", "working3", "theta1_min"})
            QVERIFY2(!fieldShown(name), name);
    }

    void dragsAnAttachmentPoint()
    {
        LinkageView *view = m_window->linkageView();
        const Scene scene = view->scene();
        int handle = -1;
        for (int i = 0; i < int(scene.handles.size()); ++i) {
            if (scene.handles[std::size_t(i)].xParameter == "B2x")
                handle = i;
        }
        QVERIFY(handle > 0);
        const double before = legsOf(*m_window).design().legs[1].platform.x();
        const MechanismPtr original = m_window->document()->mechanism();
        const int steps = m_window->document()->undoStack()->count();
        const QPointF from = view->handlePosition(handle);
        QCOMPARE(view->handleAt(from), handle);
        // a short drag to the right: B₂ moves out along the platform's x (φ of the home pose)
        drag(view, from, from + QPointF(24.0, 0.0), 6);
        const double after = legsOf(*m_window).design().legs[1].platform.x();
        const double phi = m_window->document()->pose().outputs[2];
        const double expected = 24.0 / view->mapping().scale * std::cos(phi);
        QVERIFY2(std::abs(after - before - expected) < 0.05 * std::abs(expected) + 1e-3,
                 qPrintable(QStringLiteral("%1 → %2").arg(before).arg(after)));
        // the whole drag is one undo step, and the map follows the new design
        QCOMPARE(m_window->document()->undoStack()->count(), steps + 1);
        QVERIFY(mapFollows(map(), m_window->document()->mechanism()));
        m_window->document()->undoStack()->undo();
        QCOMPARE(legsOf(*m_window).design().legs[1].platform.x(), before);
        QCOMPARE(m_window->document()->mechanism(), original);
        QVERIFY(mapFollows(map(), original));
        m_window->document()->undoStack()->redo();
        QCOMPARE(legsOf(*m_window).design().legs[1].platform.x(), after);
    }

    void savesAndReopens()
    {
        const QString path = m_dir.filePath(QStringLiteral("my-3rpr.pkm.json"));
        QVERIFY(m_window->session()->saveAs(path).ok());
        const ParameterSet saved = m_window->document()->mechanism()->parameters();
        const Pose pose = m_window->document()->pose();
        QVERIFY(m_window->openDesign(QStringLiteral("pp-5r")));
        QVERIFY2(m_window->openDesign(path), qPrintable(m_window->lastStatus()));
        QCOMPARE(m_window->document()->mechanism()->parameters().size(), saved.size());
        for (const auto &[name, value] : saved)
            QVERIFY2(std::abs(m_window->document()->mechanism()->parameters().at(name) - value) < 1e-6, name.c_str());
        for (int i = 0; i < pose.outputs.size(); ++i)
            QVERIFY(std::abs(m_window->document()->pose().outputs[i] - pose.outputs[i]) < 1e-6);
    }

    void retypesALeg()
    {
        const Pose pose = m_window->document()->pose();
        QComboBox *type = panel()->typeBox(0);
        type->setCurrentIndex(type->findData(int(LegType::RRR)));
        emit type->activated(type->currentIndex());
        QCOMPARE(legsOf(*m_window).design().legs[0].type, LegType::RRR);
        // the platform stays; a crank's parameters appear, the strut's stroke goes
        for (int i = 0; i < 3; ++i)
            QVERIFY(std::abs(m_window->document()->pose().outputs[i] - pose.outputs[i]) < 1e-9);
        QVERIFY(fieldShown("r1") && fieldShown("theta1_min") && fieldShown("working1"));
        QVERIFY(!fieldShown("q1_min"));
        QVERIFY(panel()->workingBox(0)->isVisibleTo(panel()));
        // in the words of the Design panel and the modes line ("w₁ = left"), not "mode +1"
        QCOMPARE(panel()->workingBox(0)->itemText(0), QStringLiteral("left"));
        QCOMPARE(panel()->workingBox(0)->itemText(1), QStringLiteral("right"));
        m_window->document()->undoStack()->undo();
        QCOMPARE(legsOf(*m_window).design().legs[0].type, LegType::RPR);
        QCOMPARE(panel()->typeBox(0)->currentData().toInt(), int(LegType::RPR));
    }

    /// The Design panel lists a leg's types by name, as the legs editor does, where it had a
    /// number field to be read against its label ("2" for RP̲R); a name typed is taken too.
    void retypesALegInTheDesignPanel()
    {
        QLineEdit *field = m_window->designPanel()->field(QStringLiteral("leg1_type"));
        QVERIFY(field);
        auto *box = qobject_cast<QComboBox *>(field->parentWidget());
        QVERIFY(box);
        QCOMPARE(field->text(), QStringLiteral("RP̲R"));
        QCOMPARE(box->count(), 4);
        // the opened list marks the value, and leaving the field unchanged keeps its words: it
        // showed the code "2" once the list had been opened and closed without a choice
        QCOMPARE(box->currentIndex(), 2);
        const int before = m_window->document()->undoStack()->index();
        emit field->editingFinished();
        QCOMPARE(field->text(), QStringLiteral("RP̲R"));
        field->setText(QStringLiteral("2")); // typed as a number, unchanged
        emit field->editingFinished();
        QCOMPARE(field->text(), QStringLiteral("RP̲R"));
        QCOMPARE(m_window->document()->undoStack()->index(), before);
        QCOMPARE(box->itemText(0), QStringLiteral("R̲RR"));
        // the list names the types, so its label does not spell out their codes as the
        // command line's does
        const QList<QLabel *> labels = m_window->designPanel()->findChildren<QLabel *>();
        const auto label = std::find_if(labels.begin(), labels.end(), [&](QLabel *l) { return l->buddy() == field; });
        QVERIFY(label != labels.end());
        QVERIFY2((*label)->text().contains(QStringLiteral("actuated joint underlined"))
                     && !(*label)->text().contains(QStringLiteral("0 R̲RR")),
                 qPrintable((*label)->text()));
        box->setCurrentIndex(0);
        emit box->activated(0);
        QCOMPARE(legsOf(*m_window).design().legs[0].type, LegType::RRR);
        QCOMPARE(field->text(), QStringLiteral("R̲RR"));
        QCOMPARE(panel()->typeBox(0)->currentData().toInt(), int(LegType::RRR));
        m_window->document()->undoStack()->undo();
        QCOMPARE(legsOf(*m_window).design().legs[0].type, LegType::RPR);
        QCOMPARE(field->text(), QStringLiteral("RP̲R"));
        // the name of files and the command line, typed in any case
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, QStringLiteral("rrr"));
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(legsOf(*m_window).design().legs[0].type, LegType::RRR);
        m_window->document()->undoStack()->undo();
        QCOMPARE(legsOf(*m_window).design().legs[0].type, LegType::RPR);
    }

    /// Play passes poses with no other assembly mode (the 3-R̲RR): the row keeps its height
    /// when its button goes, so the view and sliders above do not jump.
    void modeRowKeepsItsHeight()
    {
        ModeBar bar;
        QFont large = bar.font(); // presentation mode's text size
        large.setPointSizeF(2.0 * large.pointSizeF());
        bar.setFont(large);
        bar.resize(900, 100);
        bar.show();
        bar.setModes(QStringLiteral("w₁ = left, w₂ = left, w₃ = left"), {QStringLiteral("assembly mode 1 (same inputs)")});
        QCoreApplication::processEvents(); // a button added to a shown bar shows then
        const int withButton = bar.layout()->heightForWidth(900);
        QVERIFY(withButton > bar.fontMetrics().height());
        bar.setModes(QStringLiteral("w₁ = left, w₂ = left, w₃ = left"), {});
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete); // the retired button
        QCOMPARE(bar.layout()->heightForWidth(900), withButton);
    }

    void removesAndAddsALeg()
    {
        QTest::mouseClick(panel()->removeLegButton(), Qt::LeftButton);
        QCOMPARE(legsOf(*m_window).design().legCount(), 2);
        QCOMPARE(legsOf(*m_window).design().platform, PlatformType::Point);
        QVERIFY(!panel()->typeBox(2)->isVisibleTo(panel()));
        // the third leg's parameters and the platform points no longer show
        for (const char *name : {"A3x", "q3_max", "leg3_type", "B1x", "phi_map"})
            QVERIFY2(!fieldShown(name), name);
        // only the button that applies: no greyed "Remove leg 3" under two legs
        QVERIFY(panel()->addLegButton()->isVisibleTo(panel()) && !panel()->removeLegButton()->isVisibleTo(panel()));
        QTest::mouseClick(panel()->addLegButton(), Qt::LeftButton);
        QCOMPARE(legsOf(*m_window).design().legCount(), 3);
        QVERIFY(fieldShown("A3x"));
        QVERIFY(!panel()->addLegButton()->isVisibleTo(panel()) && panel()->removeLegButton()->isVisibleTo(panel()));
    }

    void refusesADesignThatCannotAssemble()
    {
        const MechanismPtr kept = m_window->document()->mechanism();
        const int steps = m_window->document()->undoStack()->count();
        // leg 2 moved far away: its strut cannot reach the platform
        QLineEdit *field = m_window->designPanel()->field(QStringLiteral("A2x"));
        QVERIFY(field);
        field->setText(QLocale().toString(5000));
        emit field->editingFinished();
        QCOMPARE(m_window->document()->mechanism(), kept);
        QCOMPARE(m_window->document()->undoStack()->count(), steps);
        const QString message = m_window->designPanel()->message();
        QVERIFY2(message.contains(QStringLiteral("leg 2")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("The last valid design is kept.")), qPrintable(message));
        QVERIFY2(m_window->lastStatus().contains(QStringLiteral("leg 2")), qPrintable(m_window->lastStatus()));
    }

    void refusesADragThatCannotAssemble()
    {
        // the base point of a 5R dragged far away: its leg cannot reach the platform
        QVERIFY(m_window->openDesign(QStringLiteral("pp-5r")));
        const MechanismPtr kept = m_window->document()->mechanism();
        m_window->document()->beginDrag();
        auto moved = m_window->document()->dragHandle(1, Eigen::Vector2d(-2000.0, 0.0));
        QVERIFY(!moved);
        QVERIFY2(QString::fromStdString(moved.failure().message).contains(QStringLiteral("leg 1")),
                 moved.failure().message.c_str());
        QCOMPARE(m_window->document()->mechanism(), kept);
    }

    /// The 3-RPR's other assembly modes: every real direct solution at the current inputs is a
    /// ghost (the preset's home pose has six, so five ghosts), each a pose of the legs at the
    /// same inputs; switching to one is one undoable step, and a drag from there stays in it.
    void showsTheOtherAssemblyModesAsGhosts()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("pp-3rpr")));
        Document *document = m_window->document();
        const Pose home = document->pose();
        const auto alternatives = document->modeAlternatives();
        QCOMPARE(int(alternatives.size()), 5);
        std::vector<Pose> poses{home};
        for (const ModeAlternative &alternative : alternatives) {
            QVERIFY(alternative.sameInputs);
            QVERIFY(alternative.pose.inputs.isApprox(home.inputs, 1e-12));
            for (const Pose &seen : poses)
                QVERIFY((alternative.pose.outputs - seen.outputs).norm() > 1e-6);
            // the legs hold that pose at the same inputs
            auto back = document->mechanism()->solveInverse(alternative.pose.outputs, &home);
            QVERIFY(back.ok());
            QVERIFY((back->inputs - home.inputs).norm() < 1e-9);
            poses.push_back(alternative.pose);
        }
        ModeBar *bar = m_window->modeBar();
        QCOMPARE(bar->labels().size(), 5);
        QCOMPARE(m_window->linkageView()->ghostScenes().size(), 5);
        // five ghosts are drawn fainter than a five-bar's two; the pointer on a mode's button
        // brings its ghost to the front, and leaving the button lets it go
        LinkageView *view = m_window->linkageView();
        QVERIFY(view->ghostShare() < 0.6);
        QEvent enter(QEvent::Enter), leave(QEvent::Leave);
        QCoreApplication::sendEvent(bar->button(2), &enter);
        QCOMPARE(view->hoveredGhost(), 2);
        QVERIFY(view->shownMessage().contains(bar->labels()[2]));
        QCoreApplication::sendEvent(bar->button(2), &leave);
        QCOMPARE(view->hoveredGhost(), -1);
        // the group's numbers 1 … 6 in all: the mode the pose is in pressed among the five others
        // ("1 2 3 4 6" looked as if 5 were missing)
        QSet<QString> numbers;
        for (int i = 0; i < 5; ++i)
            numbers << bar->button(i)->text();
        const auto *current = bar->findChild<QAbstractButton *>(QStringLiteral("currentModeButton"));
        QVERIFY(current && current->isChecked() && !numbers.contains(current->text()));
        numbers << current->text();
        QCOMPARE(numbers, QSet<QString>({QStringLiteral("1"), QStringLiteral("2"), QStringLiteral("3"), QStringLiteral("4"), QStringLiteral("5"), QStringLiteral("6")}));
        const double assembly = document->mechanism()->parameters().at("assembly");
        const int steps = document->undoStack()->index();
        const ModeAlternative target = alternatives.back();
        QTest::mouseClick(bar->button(int(alternatives.size()) - 1), Qt::LeftButton);
        QCOMPARE(document->undoStack()->index(), steps + 1);
        QVERIFY((document->pose().outputs - target.pose.outputs).norm() < 1e-9);
        QCOMPARE(document->mechanism()->parameters().at("assembly"), target.changes.at("assembly"));
        // the ghosts now show the other five, the pose left among them
        const auto after = document->modeAlternatives();
        QCOMPARE(int(after.size()), 5);
        QVERIFY(std::any_of(after.begin(), after.end(),
                            [&](const ModeAlternative &a) { return (a.pose.outputs - home.outputs).norm() < 1e-9; }));
        // a small move of an input follows the new mode by continuation
        QVERIFY(document->setVariable(0, document->pose().inputs[0] + 0.05).ok());
        QVERIFY((document->pose().outputs.head<2>() - target.pose.outputs.head<2>()).norm() < 1.0);
        document->undoStack()->setIndex(steps);
        QCOMPARE(document->mechanism()->parameters().at("assembly"), assembly);
        QVERIFY((document->pose().outputs - home.outputs).norm() < 1e-9);
    }
};

QTEST_MAIN(TestPlanarParallelEditor)
#include "tst_planarparalleleditor.moc"
