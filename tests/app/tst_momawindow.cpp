// MOMA in the main window, driven as a person would: open 3a from the Presets menu, drag the
// platform across the workspace, switch to 3b, turn a guide and watch the map follow, click
// the map, switch modes only by clicking — and the CLI gives the same numbers.
#include "gui/mainwindow.h"

#include "designpanel.h"
#include "document/document.h"
#include "linkageview.h"
#include "modebar.h"
#include "kinds/moma/moma.h"
#include "valuestable.h"
#include "variablepanel.h"
#include "workspacemapview.h"
#include "kinds/workspacepanel.h"
#include "support/app.h"
#include "support/process.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonObject>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>

#include <qcustomplot.h>

using namespace pkm;
using namespace pkm::test;

namespace {
constexpr double deg = units::degree;

double parameter(MainWindow &w, const char *name)
{
    return w.document()->mechanism()->parameters().at(name);
}

} // namespace

class TestMomaWindow : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;

    WorkspaceMapView *map() const { return m_window->workspacePanel()->mapView(); }

    /// Waits until the map shows the current design.
    bool waitForMap()
    {
        QSignalSpy ready(map(), &WorkspaceMapView::mapReady);
        if (!map()->busy() && map()->summary().reachableCells > 0)
            return true;
        return ready.wait(10000);
    }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1800, 1000});
        QVERIFY(m_window);
    }

    void cleanupTestCase() { delete m_window; }

    void opensFromPresetMenu()
    {
        QAction *preset = m_window->findChild<QAction *>(QStringLiteral("preset_moma-3a"));
        QVERIFY(preset);
        preset->trigger();
        QCOMPARE(m_window->document()->mechanism()->kind(), std::string_view("moma"));
        QCOMPARE(parameter(*m_window, "gamma1"), -5 * deg);
        QVERIFY(m_window->workspacePanel()->isVisible());
        QVERIFY(waitForMap());
        QVERIFY(std::abs(map()->area() - 19316.0) < 0.01 * 19316.0);
        // 3c and 3d are interpreted, and say so where the user picks them
        for (const char *id : {"preset_moma-3c", "preset_moma-3d"}) {
            QAction *interpreted = m_window->findChild<QAction *>(QString::fromLatin1(id));
            QVERIFY(interpreted);
            QVERIFY(interpreted->text().contains(QStringLiteral("interpreted")));
        }
    }

    void dragPlatformAcrossTheWorkspace()
    {
        LinkageView *view = m_window->linkageView();
        const Document *document = m_window->document();
        const double y0 = document->pose().outputs[1];
        // handle 0 is the platform: drag it sideways and down, inside the workspace
        const QPointF start = view->handlePosition(0);
        const Eigen::Vector2d targetMm(30.0, y0 - 40.0);
        drag(view, start, view->mapping().toDevice(targetMm));
        const Eigen::Vector2d reached = document->pose().outputs.head<2>();
        QVERIFY2((reached - targetMm).norm() < 2.0, qPrintable(QStringLiteral("at (%1, %2)").arg(reached.x()).arg(reached.y())));
        // the sliders follow (inverse kinematics), the view and the map marker too
        QCOMPARE(m_window->variablePanel()->spinBox(Moma::variableX)->value(), std::round(reached.x() * 100) / 100);
        QVERIFY((map()->markerPosition() - reached).norm() < 1e-9);
        QVERIFY((view->scene().joints[0].position.head<2>() - reached).norm() < 1e-9);
        // far outside: the platform stops on the edge and the status bar says why
        drag(view, view->handlePosition(0), view->mapping().toDevice(Eigen::Vector2d(0.0, y0 - 1000.0)));
        QVERIFY(!m_window->lastStatus().isEmpty());
        const Eigen::Vector2d edge = document->pose().outputs.head<2>();
        QVERIFY(std::isfinite(edge.x()) && std::isfinite(edge.y()));
        QVERIFY(document->mechanism()->solveInverse(document->pose().outputs).ok());
        QVERIFY2(edge.y() < reached.y() - 20.0, qPrintable(QStringLiteral("edge at (%1, %2)").arg(edge.x()).arg(edge.y())));
    }

    void capabilityShapesFollowADrag()
    {
        LinkageView *view = m_window->linkageView();
        const Document *document = m_window->document();
        QAction *shapes = m_window->findChild<QAction *>(QStringLiteral("capabilityShapesAction"));
        QAction *button = m_window->findChild<QAction *>(QStringLiteral("capabilityShapesButton"));
        QVERIFY(shapes && button);
        const auto shapeCentre = [&] {
            Eigen::AlignedBox2d box;
            for (const ScenePolyline &line : view->scene().polylines) {
                if (line.kind == PathKind::VelocityPolygon) {
                    for (const Eigen::Vector3d &p : line.points)
                        box.extend(Eigen::Vector2d(p.head<2>()));
                }
            }
            return box;
        };
        shapes->setChecked(false);
        QVERIFY(shapeCentre().isEmpty());
        QVERIFY(view->scene().legend.empty());
        button->trigger(); // the toolbar's button and the menu's action are one switch
        QVERIFY(shapes->isChecked());
        QVERIFY(!shapeCentre().isEmpty());
        QCOMPARE(view->scene().legend.size(), std::size_t(2));
        QVERIFY((shapeCentre().center() - document->pose().outputs.head<2>()).norm() < 1e-6);
        // a drag carries them along, redrawn at every pose
        const Eigen::Vector2d target = document->pose().outputs.head<2>() + Eigen::Vector2d(-20.0, 15.0);
        drag(view, view->handlePosition(0), view->mapping().toDevice(target));
        QVERIFY((document->pose().outputs.head<2>() - target).norm() < 2.0);
        QVERIFY((shapeCentre().center() - document->pose().outputs.head<2>()).norm() < 1e-6);
        shapes->setChecked(false);
        QVERIFY(shapeCentre().isEmpty());
        QVERIFY(!button->isChecked());
    }

    void switchToThreeBChangesTheMap()
    {
        const double area3a = map()->area();
        const double min3a = map()->summary().min;
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3b")));
        QVERIFY(waitForMap());
        QVERIFY(std::abs(map()->area() - 31259.0) < 0.01 * 31259.0);
        QVERIFY(map()->area() > area3a * 1.3);
        QVERIFY(map()->summary().min != min3a);
    }

    void turningAGuideMovesTheMap()
    {
        const double before = map()->area();
        const int generation = map()->generation();
        QVERIFY(m_window->document()->setParameter(QStringLiteral("gamma1"), 8.0).ok());
        QVERIFY(waitForMap());
        QVERIFY(map()->generation() > generation);
        QVERIFY(std::abs(map()->area() - before) > 50.0);
        // the map is the one of the new design: compare with the core at the same grid
        const auto *workspace = m_window->document()->mechanism()->planarWorkspace();
        const MapGrid grid = squareGrid(workspace->workspaceBounds(), map()->resolution());
        std::vector<float> values(grid.cells());
        const MapSummary expected = computeMap(*workspace, MapQuantity::Determinant, grid, values);
        QCOMPARE(map()->summary().reachableCells, expected.reachableCells);
        m_window->document()->undoStack()->undo();
        QCOMPARE(parameter(*m_window, "gamma1"), 5 * deg);
        // a negative turn shows with the typographic minus, as in the values panel; a typed
        // "-" is read
        QLineEdit *field = m_window->designPanel()->field(QStringLiteral("gamma1"));
        QVERIFY(m_window->document()->setParameter(QStringLiteral("gamma1"), -6.0).ok());
        QCOMPARE(field->text(), QStringLiteral("\u22126"));
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, QStringLiteral("-7"));
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(parameter(*m_window, "gamma1"), -7 * deg);
        QCOMPARE(field->text(), QStringLiteral("\u22127"));
        m_window->document()->undoStack()->undo();
        m_window->document()->undoStack()->undo();
        QCOMPARE(parameter(*m_window, "gamma1"), 5 * deg);
    }

    void clickOnTheMapMovesTheMechanism()
    {
        QVERIFY(waitForMap());
        QCustomPlot *plot = map()->plot();
        const Eigen::Vector2d target(-20.0, -260.0);
        QVERIFY(!std::isnan(map()->valueAt(target)));
        const QPoint pixel(qRound(plot->xAxis->coordToPixel(target.x())), qRound(plot->yAxis->coordToPixel(target.y())));
        QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, pixel);
        const Eigen::Vector2d at = m_window->document()->pose().outputs.head<2>();
        // within a pixel of the target
        const double mmPerPixel = std::abs(plot->xAxis->pixelToCoord(1) - plot->xAxis->pixelToCoord(0));
        QVERIFY2((at - target).norm() < 2 * mmPerPixel, qPrintable(QStringLiteral("at (%1, %2)").arg(at.x()).arg(at.y())));
    }

    void anErrorGoesWhenAPoseArrives()
    {
        // a click outside the workspace says why in red; a click that moves the platform to a
        // good pose takes that message away
        QVERIFY(waitForMap());
        QCustomPlot *plot = map()->plot();
        auto click = [plot](const Eigen::Vector2d &target) {
            const QPoint pixel(
                qRound(plot->xAxis->coordToPixel(target.x())), qRound(plot->yAxis->coordToPixel(target.y())));
            QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, pixel);
        };
        const Eigen::Vector2d outside(plot->xAxis->range().lower + 1.0, plot->yAxis->range().upper - 1.0);
        QVERIFY(std::isnan(map()->valueAt(outside)));
        click(outside);
        QVERIFY(!m_window->statusBar()->currentMessage().isEmpty());
        const Eigen::Vector2d inside(-20.0, -260.0);
        QVERIFY(!std::isnan(map()->valueAt(inside)));
        click(inside);
        QVERIFY2(m_window->statusBar()->currentMessage().isEmpty(), qPrintable(m_window->statusBar()->currentMessage()));
    }

    void modesSwitchOnlyOnAClick()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3d")));
        const double assembly = parameter(*m_window, "assembly");
        // sliding through the whole stroke never changes the mode
        for (double p = 0; p <= 200; p += 5) {
            m_window->variablePanel()->spinBox(Moma::variableP1)->setValue(p);
            QCOMPARE(parameter(*m_window, "assembly"), assembly);
        }
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3d")));
        ModeBar *bar = m_window->modeBar();
        QVERIFY(!bar->labels().isEmpty());
        QCOMPARE(m_window->linkageView()->ghostScenes().size(), bar->labels().size());
        const QString label = bar->labels().front();
        const int steps = m_window->document()->undoStack()->count();
        QTest::mouseClick(bar->button(0), Qt::LeftButton);
        QCOMPARE(m_window->document()->undoStack()->count(), steps + 1);
        QVERIFY(m_window->lastStatus().contains(label));
        m_window->document()->undoStack()->undo();
        QCOMPARE(parameter(*m_window, "assembly"), assembly);
        // and the same through a ghost in the view
        QSignalSpy changed(m_window->document(), &Document::designChanged);
        emit m_window->linkageView()->ghostClicked(0);
        QCOMPARE(changed.count(), 1);
        m_window->document()->undoStack()->undo();
    }

    void compareTwoConfigurations()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3a")));
        QVERIFY(waitForMap());
        QComboBox *box = m_window->workspacePanel()->comparisonBox();
        const int index = box->findData(QStringLiteral("moma-3b"));
        QVERIFY(index > 0);
        QSignalSpy compared(map(), &WorkspaceMapView::comparisonReady);
        box->setCurrentIndex(index);
        emit box->activated(index);
        QVERIFY(compared.wait(10000));
        QVERIFY(std::abs(map()->comparisonArea() - 31259.0) < 0.01 * 31259.0);
        // pin 3a, then turn a guide: the pinned outline stays, the map follows the design
        QTest::mouseClick(m_window->workspacePanel()->pinButton(), Qt::LeftButton);
        QVERIFY(compared.wait(10000));
        QVERIFY(std::abs(map()->comparisonArea() - map()->area()) < 1.0);
    }

    void cliAgreesWithTheWindow()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3a")));
        QVERIFY(waitForMap());
        const QJsonObject workspace = pkmJson({QStringLiteral("workspace"), QStringLiteral("moma-3a"),
            QStringLiteral("--grid"), QString::number(map()->resolution()), QStringLiteral("--json")});
        QVERIFY(!workspace.isEmpty());
        QVERIFY(std::abs(workspace.value(QStringLiteral("area")).toDouble() - map()->area()) < 1e-6 * map()->area());
        const Pose pose = m_window->document()->pose();
        const QJsonObject eval = pkmJson({QStringLiteral("eval"), QStringLiteral("moma-3a"), QStringLiteral("--json")});
        const QJsonObject cliPose = eval.value(QStringLiteral("pose")).toObject();
        QVERIFY(std::abs(cliPose.value(QStringLiteral("x")).toDouble() - pose.outputs[0]) < 1e-9);
        QVERIFY(std::abs(cliPose.value(QStringLiteral("y")).toDouble() - pose.outputs[1]) < 1e-9);
        const double det = eval.value(QStringLiteral("jacobian")).toObject().value(QStringLiteral("det_J")).toDouble();
        QVERIFY(det < 0); // shown with the minus sign, not the hyphen the locale gives
        QCOMPARE(m_window->valuesTable()->valueText(QStringLiteral("det_J")),
                 QLocale().toString(det, 'f', 4).replace(QLatin1Char('-'), QChar(0x2212)));
    }
};

QTEST_MAIN(TestMomaWindow)
#include "tst_momawindow.moc"
