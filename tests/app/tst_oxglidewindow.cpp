// The O-X glide in the main window, as the user does it: open oxglide-prototype from
// the Presets menu, drag the platform, switch O↔X with the form selector, run the crossing
// animation and watch it stop short of the singular pose with an explanation, read both areas
// — and the CLI reports the same areas and the same pose.
#include "gui/mainwindow.h"

#include "document/document.h"
#include "formworkspaceview.h"
#include "linkageview.h"
#include "linkageview3d.h"
#include "kinds/oxglide/oxglide.h"
#include "kinds/oxglide/oxglidepanel.h"
#include "variablepanel.h"
#include "support/app.h"
#include "support/process.h"

#include <qcustomplot.h>

#include <QAction>
#include <QJsonObject>
#include <QLabel>
#include <QImage>
#include <QPushButton>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace pkm;
using namespace pkm::test;

namespace {
int form(const MainWindow &w)
{
    return dynamic_cast<const OxGlide &>(*w.document()->mechanism()).design().form;
}
} // namespace

class TestOxGlideWindow : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;
    OxGlidePanel *panel() const { return m_window->kindPanel<OxGlidePanel>(); }
    const Pose &pose() const { return m_window->document()->pose(); }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1800, 1000});
        QVERIFY(m_window);
    }

    void cleanupTestCase() { delete m_window; }

    void opensFromPresetMenu()
    {
        QAction *preset = m_window->findChild<QAction *>(QStringLiteral("preset_oxglide-prototype"));
        QVERIFY(preset);
        preset->trigger();
        QCOMPARE(m_window->document()->mechanism()->kind(), std::string_view("oxglide"));
        QVERIFY(panel()->isVisible());
        QCOMPARE(form(*m_window), oxglide::formO);
        QVERIFY(panel()->formButton(oxglide::formO)->isChecked());
        QVERIFY(!panel()->formButton(oxglide::formX)->isChecked());
        // the preset's sliders: x_AB = 15, x_CD = 115 → T = (65, 40√3)
        QCOMPARE(pose().outputs[0], 65.0);
        QVERIFY(std::abs(pose().outputs[1] - 40.0 * std::sqrt(3.0)) < 1e-9);
    }

    void readsBothAreas()
    {
        // fig. 5: both forms with their areas; the O form lies inside the X form
        const QString legend = panel()->formView()->legendText();
        const OxGlideDesign d = dynamic_cast<const OxGlide &>(*m_window->document()->mechanism()).design();
        const QString areaO = QLocale().toString(oxglide::exactArea(d, oxglide::formO), 'f', 1);
        const QString areaX = QLocale().toString(oxglide::exactArea(d, oxglide::formX), 'f', 1);
        QVERIFY2(legend.contains(areaO) && legend.contains(areaX), qPrintable(legend));
        QVERIFY(legend.contains(QStringLiteral("union")));
        FormWorkspaceView *view = panel()->formView();
        QVERIFY(view->gridArea(0) > view->gridArea(1)); // X (drawn first) larger than O
        QVERIFY(std::abs(view->unionArea() - view->gridArea(0)) < 1e-9);
        QVERIFY(std::abs(view->gridArea(1) - oxglide::exactArea(d, oxglide::formO)) < 0.02 * view->gridArea(1));
        QVERIFY(std::abs(view->gridArea(0) - oxglide::exactArea(d, oxglide::formX)) < 0.01 * view->gridArea(0));
        // the marker is in both regions: the preset pose is an O pose
        QCOMPARE(view->formsAt(pose().outputs.head<2>()).size(), std::size_t(2));
        // the CLI's areas on a fine grid agree
        const QJsonObject cli = pkmJson({QStringLiteral("workspace"), QStringLiteral("oxglide-prototype"),
            QStringLiteral("--grid"), QStringLiteral("1600"), QStringLiteral("--json")});
        QVERIFY(!cli.isEmpty());
        QVERIFY(std::abs(cli.value(QStringLiteral("area_O")).toDouble() - oxglide::exactArea(d, oxglide::formO)) < 0.01 * 753.0);
        QVERIFY(std::abs(cli.value(QStringLiteral("area_X")).toDouble() - oxglide::exactArea(d, oxglide::formX)) < 0.01 * 2125.0);
        QCOMPARE(cli.value(QStringLiteral("area_union")).toDouble(), cli.value(QStringLiteral("area_X_grid")).toDouble());
        // and its picture is fig. 5: the O region (the design's own, darker) inside the X region
        QTemporaryDir directory;
        const QString path = directory.filePath(QStringLiteral("fig5.png"));
        const Run run = runPkm({QStringLiteral("workspace"), QStringLiteral("oxglide-prototype"),
            QStringLiteral("--grid"), QStringLiteral("800"), QStringLiteral("-o"), path});
        QVERIFY(run.exitCode == 0);
        const QImage picture(path);
        QVERIFY(!picture.isNull());
        qsizetype dark = 0, light = 0;
        for (int y = 0; y < picture.height(); ++y) {
            for (int x = 0; x < picture.width(); ++x) {
                const QRgb pixel = picture.pixel(x, y) & 0xffffff;
                dark += pixel == 0x2b5c8f ? 1 : 0;
                light += pixel == 0xa6cee3 ? 1 : 0;
            }
        }
        const double ratio = double(dark) / double(dark + light); // ≈ area_O / area_X
        QVERIFY2(std::abs(ratio - 753.3 / 2125.3) < 0.03, qPrintable(QString::number(ratio)));
    }

    // The plot keeps equal scales by fitting its ranges after each layout; the ticks drawn are
    // those of the fitted ranges, none left over below or beside the axes.
    void ticksStayOnTheAxes()
    {
        QCustomPlot *plot = panel()->formView()->plot();
        for (const int width : {1500, 1800}) { // another width, another aspect of the plot
            m_window->resize(width, 1000);
            QTest::qWait(100);
            for (QCPAxis *axis : {plot->xAxis, plot->yAxis}) {
                QVERIFY(!axis->tickVector().isEmpty());
                for (const double tick : axis->tickVector())
                    QVERIFY2(axis->range().contains(tick),
                             qPrintable(QStringLiteral("tick %1 outside %2…%3").arg(tick).arg(axis->range().lower).arg(axis->range().upper)));
            }
        }
    }

    void dragsThePlatform()
    {
        LinkageView *view = m_window->linkageView();
        const Eigen::Vector2d target(60.0, 72.0);
        drag(view, view->handlePosition(0), view->mapping().toDevice(target));
        const Eigen::Vector2d reached = pose().outputs.head<2>();
        QVERIFY2((reached - target).norm() < 1.0, qPrintable(QStringLiteral("at (%1, %2)").arg(reached.x()).arg(reached.y())));
        QCOMPARE(form(*m_window), oxglide::formO); // a drag never changes the form
        // a drag far below leaves the platform on the O workspace's lower edge, with the reason
        drag(view, view->handlePosition(0), view->mapping().toDevice(Eigen::Vector2d(60.0, 20.0)));
        QVERIFY(pose().outputs[1] > 55.0);
        QVERIFY(!m_window->lastStatus().isEmpty());
        QCOMPARE(form(*m_window), oxglide::formO);
    }

    void sliderStopsBeforeTheCrossing()
    {
        // moving x_CD down towards x_AB + s would cross into X: it stops short, the form stays
        const double xAB = pose().inputs[0];
        auto moved = m_window->document()->setVariable(OxGlide::variableXCD, xAB + 5.0);
        QVERIFY(!moved.ok());
        QCOMPARE(form(*m_window), oxglide::formO);
        QVERIFY(pose().inputs[1] - pose().inputs[0] > 20.0 - 1e-6);
        QVERIFY(QString::fromStdString(moved.failure().message).contains(QStringLiteral("switch the form")));
    }

    void dragStopsShortOfTheCrossing()
    {
        // dragging the x_CD pair towards x_AB stops where the crossing animation stops, not on
        // the combined singular pose x_CD − x_AB = s
        QVERIFY(m_window->openDesign(QStringLiteral("oxglide-prototype")));
        const double xAB = pose().inputs[0], l = 80.0, s = 20.0;
        auto dragged = m_window->document()->dragHandle(2, Eigen::Vector2d(xAB + 5.0, 0.0));
        QVERIFY(!dragged.ok());
        QVERIFY(QString::fromStdString(dragged.failure().message).contains(QStringLiteral("stops short")));
        QCOMPARE(form(*m_window), oxglide::formO);
        const double run = 0.5 * (pose().inputs[1] - pose().inputs[0] - s);
        QVERIFY2(std::abs(run - OxGlidePanel::stopMargin * l) < 1e-3, qPrintable(QString::number(run)));
        std::vector<double> values(std::size_t(m_window->document()->mechanism()->reportLayout().size));
        QCOMPARE(m_window->document()->mechanism()->evaluate(pose(), values).type, SingularityType::None);
        // and away from it the pair moves freely
        QVERIFY(m_window->document()->dragHandle(2, Eigen::Vector2d(xAB + 60.0, 0.0)).ok());
        QVERIFY(std::abs(pose().inputs[1] - (xAB + 60.0)) < 1e-9);
    }

    void switchesFormsWithTheSelector()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("oxglide-prototype")));
        const Coordinates outputs = pose().outputs, inputs = pose().inputs;
        QTest::mouseClick(panel()->formButton(oxglide::formX), Qt::LeftButton);
        QCOMPARE(form(*m_window), oxglide::formX);
        QVERIFY(panel()->formButton(oxglide::formX)->isChecked());
        QVERIFY((pose().outputs - outputs).norm() < 1e-9); // the platform stays
        QVERIFY(pose().inputs[0] > pose().inputs[1]);        // the pairs have passed each other
        // undo brings the O form back with its sliders
        m_window->document()->undoStack()->undo();
        QCOMPARE(form(*m_window), oxglide::formO);
        QVERIFY((pose().inputs - inputs).norm() < 1e-9);
        // an X-only position: the O form cannot reach it, and the selector says why
        QTest::mouseClick(panel()->formButton(oxglide::formX), Qt::LeftButton);
        Coordinates low(2);
        low << 65.0, 35.0;
        QVERIFY(m_window->document()->moveOutputsTo(low).ok());
        QTest::mouseClick(panel()->formButton(oxglide::formO), Qt::LeftButton);
        QCOMPARE(form(*m_window), oxglide::formX);
        QVERIFY(panel()->formButton(oxglide::formX)->isChecked());
        QVERIFY2(m_window->lastStatus().contains(QStringLiteral("extended (O) form cannot reach")), qPrintable(m_window->lastStatus()));
    }

    void crossingStopsShortOfTheSingularPose()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("oxglide-prototype")));
        const double startHeight = pose().outputs[1];
        const double x = pose().outputs[0];
        QTest::mouseClick(panel()->crossingButton(), Qt::LeftButton);
        QCOMPARE(panel()->phase(), OxGlidePanel::Phase::Rising);
        QTRY_COMPARE_WITH_TIMEOUT(panel()->phase(), OxGlidePanel::Phase::AtCrossing, 10000);
        // stopped below y = l, not singular, with the explanation on screen
        const double l = 80.0;
        QVERIFY(pose().outputs[1] < l);
        QVERIFY(std::abs(pose().outputs[1] - panel()->stopHeight()) < 1e-6);
        QVERIFY(std::abs(pose().outputs[0] - x) < 1e-9);
        std::vector<double> values(std::size_t(m_window->document()->mechanism()->reportLayout().size));
        const Singularity s = m_window->document()->mechanism()->evaluate(pose(), values);
        QCOMPARE(s.type, SingularityType::None);
        QVERIFY(std::abs(s.margin - OxGlidePanel::stopMargin) < 1e-9);
        QVERIFY(panel()->banner()->isVisible());
        QVERIFY(panel()->banner()->text().contains(QStringLiteral("short of the singular pose")));
        QVERIFY(panel()->banner()->text().contains(QStringLiteral("x_CD − x_AB = s")));
        QVERIFY(panel()->leaveOtherButton()->isVisible());
        QCOMPARE(form(*m_window), oxglide::formO);
        // leave in X: the form switches there and the platform comes back down in X
        QTest::mouseClick(panel()->leaveOtherButton(), Qt::LeftButton);
        QCOMPARE(form(*m_window), oxglide::formX);
        QTRY_COMPARE_WITH_TIMEOUT(panel()->phase(), OxGlidePanel::Phase::Idle, 10000);
        QVERIFY(std::abs(pose().outputs[1] - startHeight) < 1e-6);
        QVERIFY(pose().inputs[0] > pose().inputs[1]); // crossed
        // the CLI agrees with the window at this pose
        const QJsonObject cli = pkmJson({QStringLiteral("eval"), QStringLiteral("oxglide-prototype"),
            QStringLiteral("--set"), QStringLiteral("mode=X"), QStringLiteral("--set"),
            QStringLiteral("x=%1").arg(pose().outputs[0], 0, 'g', 17), QStringLiteral("--set"),
            QStringLiteral("y=%1").arg(pose().outputs[1], 0, 'g', 17), QStringLiteral("--json")});
        const QJsonObject cliPose = cli.value(QStringLiteral("pose")).toObject();
        QCOMPARE(cliPose.value(QStringLiteral("mode")).toString(), QStringLiteral("X"));
        QVERIFY(std::abs(cliPose.value(QStringLiteral("x_AB")).toDouble() - pose().inputs[0]) < 1e-9);
        QVERIFY(std::abs(cliPose.value(QStringLiteral("x_CD")).toDouble() - pose().inputs[1]) < 1e-9);
    }

    void noBannerAfterAnotherDesign()
    {
        // a crossing paused at the singular pose, then another kind's preset and back: the
        // banner and the paused crossing are gone, not greeting the new design as if true
        QVERIFY(m_window->openDesign(QStringLiteral("oxglide-prototype")));
        QTest::mouseClick(panel()->crossingButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(panel()->phase(), OxGlidePanel::Phase::AtCrossing, 10000);
        QVERIFY(panel()->banner()->isVisible());
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3a")));
        QVERIFY(m_window->openDesign(QStringLiteral("oxglide-prototype")));
        QVERIFY(panel()->isVisible());
        QCOMPARE(panel()->phase(), OxGlidePanel::Phase::Idle);
        QVERIFY(!panel()->banner()->isVisible());
        QVERIFY(!panel()->leaveOtherButton()->isVisible());
    }

    void theHybridIn3d()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("oxglide-prototype")));
        m_window->viewTabs()->setCurrentWidget(m_window->view3d());
        const Scene3D &model = m_window->view3d()->view()->scene();
        auto count = [&](PartRole role) {
            return std::count_if(model.solids.begin(), model.solids.end(), [&](const Solid &s) { return s.role == role; });
        };
        QCOMPARE(count(PartRole::Rod), 4);
        QCOMPARE(count(PartRole::Compensation), 3);
        QVERIFY(count(PartRole::Guide) >= 6); // four transverse, two longitudinal
        auto platformZ = [&] {
            for (const Solid &s : m_window->view3d()->view()->scene().solids) {
                if (s.role == PartRole::Platform)
                    return s.from.z();
            }
            return std::nan("");
        };
        // the z slider carries the whole planar mechanism along the longitudinal guides
        const double before = platformZ();
        QVERIFY(m_window->document()->setVariable(OxGlide::variableZ, 120.0).ok());
        QVERIFY(std::abs(platformZ() - before - (120.0 - 75.0)) < 1e-9);
        // and the sliders move it in the plane: the rods follow the 2D view
        QVERIFY(m_window->document()->setVariable(OxGlide::variableXAB, 25.0).ok());
        const Scene3D &moved = m_window->view3d()->view()->scene();
        const auto rod = std::find_if(moved.solids.begin(), moved.solids.end(),
                                      [](const Solid &s) { return s.role == PartRole::Rod && s.label == "rod A"; });
        QVERIFY(rod != moved.solids.end());
        QVERIFY(std::abs(rod->from.x() - 25.0) < 1e-9);
        m_window->viewTabs()->setCurrentIndex(0);
    }

    void badInputKeepsTheDesign()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("oxglide-prototype")));
        const ParameterSet before = m_window->document()->mechanism()->parameters();
        for (const auto &[name, value] : {std::pair{"s", 160.0}, std::pair{"L", 20.0}, std::pair{"l", 0.0}}) {
            auto changed = m_window->document()->setParameter(QString::fromLatin1(name), value);
            QVERIFY(!changed.ok());
            QCOMPARE(changed.failure().culprit, std::string(name));
            QVERIFY(m_window->document()->mechanism()->parameters() == before);
        }
    }
};

QTEST_MAIN(TestOxGlideWindow)
#include "tst_oxglidewindow.moc"
