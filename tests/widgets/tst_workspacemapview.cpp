// Tests of WorkspaceMapView: the map is MOMA's (docs/mathematics.md) computed off the GUI thread,
// a burst of design edits computes once and stale results are dropped, a pose change only moves
// the marker, clicks map to mm, and a mechanism without a planar workspace says so.

#include "pictureexport.h"
#include "planarworkspace.h"
#include "quantityformat.h"
#include "registry.h"
#include "tolerance.h"
#include "workspacemapview.h"
#include "document/designfile.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <memory>
#include <numbers>

using namespace pkm;

namespace {

constexpr double pi = std::numbers::pi;
constexpr int waitMilliseconds = 20000;

MechanismPtr moma(const ParameterSet &parameters = {})
{
    Result<MechanismPtr> result = createMechanism("moma", parameters);
    return result ? *result : nullptr;
}

/// Configuration 3d (docs/mathematics.md): the guides along the axes, both legs in their + branch.
MechanismPtr moma3d()
{
    return moma({{"R1x", 117.0}, {"R1y", 0.0}, {"R2x", 0.0}, {"R2y", 117.0}, {"alpha1", 0.0}, {"alpha2", pi / 2},
        {"branch1", 1.0}, {"branch2", 1.0}, {"assembly", 1.0}});
}

/// The area the core computes for the design at the view's resolution, mm².
double referenceArea(const MechanismPtr &mechanism, int resolution)
{
    const PlanarWorkspace *workspace = mechanism->planarWorkspace();
    const MapGrid grid = squareGrid(workspace->workspaceBounds(), resolution);
    std::vector<float> values(grid.cells());
    return computeMap(*workspace, MapQuantity::Determinant, grid, values).area;
}

Eigen::Vector2d platform(const Pose &pose)
{
    return {pose.outputs[0], pose.outputs[1]};
}

/// Sets the mechanism and waits for its map.
bool showMap(WorkspaceMapView &view, const MechanismPtr &mechanism)
{
    QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
    view.setMechanism(mechanism);
    return ready.wait(waitMilliseconds);
}

QCPCurve *curveNamed(QCustomPlot *plot, const QString &prefix)
{
    for (int i = 0; i < plot->plottableCount(); ++i)
        if (auto *curve = qobject_cast<QCPCurve *>(plot->plottable(i)); curve && curve->name().startsWith(prefix))
            return curve;
    return nullptr;
}

QPoint pixelOf(const WorkspaceMapView &view, const Eigen::Vector2d &mm)
{
    return QPoint(qRound(view.plot()->xAxis->coordToPixel(mm.x())), qRound(view.plot()->yAxis->coordToPixel(mm.y())));
}

} // namespace

class TestWorkspaceMapView : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void withoutMechanism();
    void momaMap();
    void equalAspect();
    void frameTicksFollowTheFrame();
    void poseMovesMarkerOnly();
    void burstComputesOnce();
    void staleResultDropped();
    void click();
    void conditionNumber();
    void orientationRange();
    void shortMapIsBriefAndAGridAreaIsAnEstimate();
    void capabilityMaps();
    void toleranceMap();
    void comparison();
    void directSingularities3d();
    void noPlanarWorkspace();
    void destroyWhileComputing();
};

void TestWorkspaceMapView::initTestCase()
{
    QVERIFY(moma());
    QVERIFY(moma3d());
}

void TestWorkspaceMapView::withoutMechanism()
{
    WorkspaceMapView view;
    QVERIFY(!view.message().isEmpty());
    QVERIFY(!view.busy());
    QCOMPARE(view.generation(), 0);
    QCOMPARE(view.area(), 0.0);
    QVERIFY(std::isnan(view.valueAt({0.0, -250.0})));
}

void TestWorkspaceMapView::momaMap()
{
    WorkspaceMapView view;
    const MechanismPtr m = moma(); // 3a
    view.setMechanism(m);
    QVERIFY(view.busy());
    QVERIFY(view.message().isEmpty());
    QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
    QVERIFY(ready.wait(waitMilliseconds));
    QCOMPARE(ready.count(), 1);
    QVERIFY(!view.busy());
    QCOMPARE(view.computationsStarted(), 1);

    const MapSummary &summary = view.summary();
    QVERIFY(summary.reachableCells > 0);
    QCOMPARE(std::max(summary.grid.columns, summary.grid.rows), view.resolution());
    QVERIFY2(std::abs(view.area() - 19316.0) <= 0.01 * 19316.0, qPrintable(QString::number(view.area())));
    QCOMPARE(view.area(), referenceArea(m, view.resolution()));
    QVERIFY(summary.max < 0.0); // 3a: det J < 0 all over (no direct singularity)

    // Data at a reachable cell (the home pose), transparent NaN outside the workspace.
    const Eigen::Vector2d home = platform(m->homePose());
    QCPColorMapData *data = view.colorMap()->data();
    QCOMPARE(data->keySize(), summary.grid.columns);
    QCOMPARE(data->valueSize(), summary.grid.rows);
    QVERIFY(std::isfinite(data->data(home.x(), home.y())));
    QVERIFY(data->data(home.x(), home.y()) < 0.0);
    QVERIFY(std::isfinite(view.valueAt(home)));
    const Eigen::Vector2d corner = summary.grid.bounds.min() + Eigen::Vector2d(summary.grid.dx(), summary.grid.dy());
    QVERIFY(std::isnan(data->data(corner.x(), corner.y())));
    QVERIFY(std::isnan(view.valueAt(corner)));
    QCOMPARE(view.colorMap()->gradient().nanHandling(), QCPColorGradient::nhTransparent);
    // Colours clipped symmetrically, inside the range of the values.
    const QCPRange colours = view.colorMap()->dataRange();
    QCOMPARE(colours.lower, -colours.upper);
    QVERIFY(colours.upper > -summary.max && colours.upper < -summary.min);

    // Inverse singular curves, no direct ones; the texts say what is shown.
    QVERIFY(view.curveCount(SingularCurve::Type::Inverse) > 0);
    QCOMPARE(view.curveCount(SingularCurve::Type::Direct), 0);
    QCOMPARE(view.curveCount(), view.curveCount(SingularCurve::Type::Inverse));
    QVERIFY(curveNamed(view.plot(), QStringLiteral("inverse singularity")));
    QVERIFY(curveNamed(view.plot(), QStringLiteral("direct singularity")));
    QCOMPARE(view.plot()->xAxis->label(), QStringLiteral("x (mm)"));
    QCOMPARE(view.plot()->yAxis->label(), QStringLiteral("y (mm)"));
    QVERIFY(view.plot()->plotLayout()->elementCount() > 0);
    // the range is the grid points' (a pose nearer a singularity lies outside it), and a
    // 2-DOF map is no slice
    QVERIFY2(view.titleText().endsWith(QStringLiteral("at the grid points")) && !view.titleText().contains(QStringLiteral("φ")),
             qPrintable(view.titleText()));
}

void TestWorkspaceMapView::equalAspect()
{
    WorkspaceMapView view;
    view.resize(1000, 800);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QVERIFY(showMap(view, moma()));
    for (const QSize size : {QSize(1000, 800), QSize(700, 900), QSize(1200, 500)}) {
        view.resize(size);
        QTest::qWait(50); // the resize's layouts and the fit's queued relayout
        QCustomPlot *plot = view.plot();
        const double xScale = plot->xAxis->coordToPixel(100.0) - plot->xAxis->coordToPixel(0.0);
        const double yScale = plot->yAxis->coordToPixel(0.0) - plot->yAxis->coordToPixel(100.0);
        QVERIFY2(std::abs(xScale - yScale) <= 0.01 * xScale,
            qPrintable(QStringLiteral("%1 vs %2 px per 100 mm").arg(xScale).arg(yScale)));
        // The whole workspace is in view.
        const Eigen::AlignedBox2d bounds = view.summary().grid.bounds;
        QVERIFY(plot->xAxis->range().contains(bounds.min().x()) && plot->xAxis->range().contains(bounds.max().x()));
        QVERIFY(plot->yAxis->range().contains(bounds.min().y()) && plot->yAxis->range().contains(bounds.max().y()));
    }
}

/// A video frame with the map beside the mechanism lays the map out at the frame's size, and
/// the map fits its ranges after that layout: a frame drew its ticks for the screen's ranges,
/// so that the 3-RP̲R's "25" stood past the x axis, under the colour scale.
void TestWorkspaceMapView::frameTicksFollowTheFrame()
{
    auto design = designfile::load(QStringLiteral("pp-3rpr"));
    QVERIFY(design);
    WorkspaceMapView view;
    view.resize(1000, 500);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QVERIFY(showMap(view, design->mechanism));
    QTest::qWait(50); // the fit's queued relayouts
    QCustomPlot *plot = view.plot();
    QCPRange last;
    const QMetaObject::Connection watch = connect(plot, &QCustomPlot::afterLayout, plot, [&] { last = plot->xAxis->range(); });
    const QCPRange screen = plot->xAxis->range();
    const QImage frame = plotImage(plot, QSize(640, 720), 1.0);
    disconnect(watch);
    QCOMPARE(frame.size(), QSize(640, 720));
    QVERIFY(last.size() < 0.9 * screen.size()); // the frame's layout fitted other ranges
    const QVector<double> ticks = plot->xAxis->tickVector();
    QVERIFY(!ticks.isEmpty());
    for (double tick : ticks)
        QVERIFY2(last.contains(tick), qPrintable(QStringLiteral("tick %1 outside %2 … %3").arg(tick).arg(last.lower).arg(last.upper)));
}

void TestWorkspaceMapView::poseMovesMarkerOnly()
{
    WorkspaceMapView view;
    view.resize(1000, 800);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const MechanismPtr m = moma();
    QVERIFY(showMap(view, m));
    QTest::qWait(50); // the fit's queued relayouts

    QCPLayer *layer = view.plot()->layer(QStringLiteral("pose"));
    QVERIFY(layer);
    QCOMPARE(layer->mode(), QCPLayer::lmBuffered);
    QCOMPARE(layer->children().size(), 2); // the circle and the cross: nothing else to redraw

    const int generation = view.generation();
    const int started = view.computationsStarted();
    QSignalSpy fullReplots(view.plot(), &QCustomPlot::beforeReplot);
    Pose pose = m->homePose();
    view.setPose(pose);
    QCOMPARE(view.markerPosition(), platform(pose));
    Result<Pose> moved = m->solveInverse(Coordinates(Eigen::Vector2d(30.0, -260.0)), &pose);
    QVERIFY(moved);
    view.setPose(*moved);
    QVERIFY((view.markerPosition() - Eigen::Vector2d(30.0, -260.0)).norm() < 1e-9);
    QCoreApplication::processEvents();
    QCOMPARE(fullReplots.count(), 0);
    QCOMPARE(view.generation(), generation);
    QCOMPARE(view.computationsStarted(), started);
    QVERIFY(!view.busy());

    // The marker is drawn there: white disc with a dark rim, on the map.
    const QImage image = view.plot()->grab().toImage();
    const QPoint at = pixelOf(view, {30.0, -260.0});
    QCOMPARE(image.pixelColor(at + QPoint(3, 3)), QColor(Qt::white));
    QVERIFY(image.pixelColor(at + QPoint(15, 0)) != QColor(Qt::white)); // outside it: the map

    // A pose without two outputs hides the marker.
    view.setPose(Pose());
    QVERIFY(std::isnan(view.markerPosition().x()));
}

void TestWorkspaceMapView::burstComputesOnce()
{
    WorkspaceMapView view;
    const MechanismPtr base = moma();
    QVERIFY(showMap(view, base));
    const int started = view.computationsStarted();

    // γ₁ held down on a spin box: five designs within the debounce interval.
    QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
    MechanismPtr last;
    for (int step = 1; step <= 5; ++step) {
        Result<MechanismPtr> next = base->withParameter("gamma1", (-5.0 - 2.0 * step) * pi / 180.0);
        QVERIFY(next);
        last = *next;
        view.setMechanism(last);
    }
    QVERIFY(ready.wait(waitMilliseconds));
    QTest::qWait(4 * WorkspaceMapView::debounceMilliseconds);
    QCOMPARE(ready.count(), 1);
    QCOMPARE(view.computationsStarted(), started + 1);
    QVERIFY(!view.busy());
    QCOMPARE(view.area(), referenceArea(last, view.resolution()));
    QVERIFY(std::abs(view.area() - referenceArea(base, view.resolution())) > 1.0);
}

void TestWorkspaceMapView::staleResultDropped()
{
    WorkspaceMapView view;
    view.setResolution(1200); // long enough to be overtaken
    const MechanismPtr first = moma();
    const MechanismPtr second = moma3d();
    QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
    view.setMechanism(first);
    while (view.computationsStarted() == 0) // until the debounce has started the first job
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    QVERIFY(view.busy());
    view.setMechanism(second);
    QVERIFY(ready.wait(waitMilliseconds));
    QTest::qWait(4 * WorkspaceMapView::debounceMilliseconds);
    QCOMPARE(ready.count(), 1);
    QCOMPARE(view.computationsStarted(), 2);
    QCOMPARE(view.area(), referenceArea(second, view.resolution()));
}

void TestWorkspaceMapView::click()
{
    WorkspaceMapView view;
    view.resize(1000, 800);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QVERIFY(showMap(view, moma()));
    QTest::qWait(50);

    QSignalSpy clicked(&view, &WorkspaceMapView::pointClicked);
    QCustomPlot *plot = view.plot();
    const Eigen::Vector2d target(-20.0, -280.0);
    QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, pixelOf(view, target));
    QCOMPARE(clicked.count(), 1);
    const auto point = clicked.takeFirst().at(0).value<Eigen::Vector2d>();
    const double cell = view.summary().grid.dx();
    QVERIFY2((point - target).norm() <= 2.0 * cell,
        qPrintable(QStringLiteral("(%1, %2) for (%3, %4)").arg(point.x()).arg(point.y()).arg(target.x()).arg(target.y())));

    // A drag pans the map and is no click; nor is a click outside the axis rect.
    const QPoint from = pixelOf(view, target);
    QTest::mousePress(plot, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(plot, from + QPoint(20, 10));
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::NoModifier, from + QPoint(40, 20));
    QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, QPoint(plot->width() / 2, 5)); // the title
    QTest::mouseClick(plot, Qt::RightButton, Qt::NoModifier, pixelOf(view, target));
    QCOMPARE(clicked.count(), 0);
}

void TestWorkspaceMapView::conditionNumber()
{
    WorkspaceMapView view;
    const MechanismPtr m = moma();
    QVERIFY(showMap(view, m));
    QCOMPARE(view.quantityBox()->currentIndex(), 0);

    QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
    view.setQuantity(MapQuantity::Condition);
    QCOMPARE(view.quantityBox()->currentIndex(), 1);
    QVERIFY(ready.wait(waitMilliseconds));
    QCOMPARE(view.summary().grid.columns > 0, true);
    QVERIFY(view.summary().min >= 1.0 - 1e-5);
    QVERIFY(view.valueAt(platform(m->homePose())) >= 1.0 - 1e-5);
    QCOMPARE(view.colorMap()->dataScaleType(), QCPAxis::stLogarithmic);
    QCOMPARE(view.colorMap()->dataRange().lower, 1.0);
    QVERIFY(view.colorMap()->dataRange().upper > 1.0);
    QCOMPARE(view.area(), referenceArea(m, view.resolution())); // the same workspace

    // Back through the combo box, as a user would.
    emit view.quantityBox()->activated(0);
    QCOMPARE(view.quantity(), MapQuantity::Determinant);
    QVERIFY(ready.wait(waitMilliseconds));
    QCOMPARE(view.colorMap()->dataScaleType(), QCPAxis::stLinear);
    QVERIFY(view.summary().max < 0.0);
}

/// A map too short for its full words gives them briefly, as presentation mode asks; a grid's
/// count of the area is marked as an estimate and the O-X glide's closed-form area is not, and a
/// number keeps its unit on its line.
void TestWorkspaceMapView::shortMapIsBriefAndAGridAreaIsAnEstimate()
{
    auto moma = designfile::load(QStringLiteral("moma-3a"));
    QVERIFY(moma);
    WorkspaceMapView view;
    view.resize(600, 900);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QVERIFY(showMap(view, moma->mechanism));
    QVERIFY(!view.brief());
    QVERIFY2(view.titleText().startsWith(QStringLiteral("Workspace ≈ ")) && view.titleText().contains(QStringLiteral("det J from")),
             qPrintable(view.titleText()));
    view.resize(600, 320);
    QTRY_VERIFY(view.brief());
    QVERIFY2(!view.titleText().contains(QStringLiteral("det J from")), qPrintable(view.titleText()));
    QVERIFY(view.plot()->toolTip().contains(QStringLiteral("det J from")));
    view.resize(600, 900);
    QTRY_VERIFY(!view.brief());
    view.setBrief(true); // asked for: brief whatever its height
    QVERIFY(view.brief());
    view.setBrief(false);
    QVERIFY(!view.brief());
    auto ox = designfile::load(QStringLiteral("oxglide-prototype"));
    QVERIFY(ox);
    QVERIFY(showMap(view, ox->mechanism));
    QVERIFY2(view.titleText().startsWith(QStringLiteral("Workspace 753 mm²")), qPrintable(view.titleText()));
    // "mm²" after a no-break space: never alone at the start of a line when the title wraps
    // the area's number and unit joined by a no-break space, which the title's line breaking
    // never breaks at (the Russian title had put "мм²" at the start of its second line)
    auto moma3c = designfile::load(QStringLiteral("moma-3c"));
    QVERIFY(moma3c);
    QVERIFY(showMap(view, moma3c->mechanism));
    const QString area = QString::number(std::lround(view.area()));
    QVERIFY2(view.titleLines().join(u' ').contains(QStringLiteral("≈\u00A0") + area + QStringLiteral("\u00A0mm²")),
             qPrintable(view.titleLines().join(u'|')));
}

/// A platform that turns (the 3-RP̲R) offers the orientation range of φ, in degrees on a 0–360°
/// scale; a point platform does not, and a range chosen before falls back to det J.
void TestWorkspaceMapView::orientationRange()
{
    auto design = designfile::load(QStringLiteral("pp-3rpr"));
    QVERIFY2(design, design ? "" : design.failure().message.c_str());
    WorkspaceMapView view;
    QVERIFY(showMap(view, design->mechanism));
    const int item = view.quantityBox()->findData(int(MapQuantity::OrientationRange));
    QVERIFY(item >= 0);
    QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
    emit view.quantityBox()->activated(item);
    QCOMPARE(view.quantity(), MapQuantity::OrientationRange);
    QVERIFY(ready.wait(waitMilliseconds));
    QVERIFY(view.summary().reachableCells > 0);
    QVERIFY(view.summary().min >= 0.0);
    QVERIFY2(view.summary().max > 0.0 && view.summary().max <= 2 * std::numbers::pi + 1e-6,
             qPrintable(QStringLiteral("range from %1 to %2 rad").arg(view.summary().min).arg(view.summary().max)));
    // at the home pose the platform is held at its own φ: a range of more than nothing
    QVERIFY(view.valueAt(platform(design->mechanism->homePose())) > 0.0);
    QCOMPARE(view.colorMap()->dataRange().lower, 0.0);
    QCOMPARE(view.colorMap()->dataRange().upper, 360.0);
    // the map of a platform that turns is its slice at φ_map, whatever φ the pose has; the
    // titles say so
    QVERIFY2(view.titleText().contains(QStringLiteral("at φ = 0.0°")), qPrintable(view.titleText()));
    ready.clear();
    emit view.quantityBox()->activated(view.quantityBox()->findData(int(MapQuantity::Determinant)));
    QVERIFY(ready.wait(waitMilliseconds));
    QVERIFY2(view.titleText().contains(QStringLiteral("at φ = 0.0° · det J from")), qPrintable(view.titleText()));
    // with det J's unit, as the values panel gives it
    QVERIFY2(view.titleText().endsWith(QStringLiteral(" mm/rad at the grid points")), qPrintable(view.titleText()));
    // a pose at another φ is off the slice: a dashed ring, and the title says so
    Pose pose = design->pose;
    QVERIFY(std::abs(pose.outputs[2]) > 0.1); // the preset stands at φ = 57°
    // and it is drawn: a pose change replots the marker's layer alone, which left the title
    // of a playing 3-R̲RR as it was
    view.resize(900, 800);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QTest::qWait(100); // the replots of showing it done
    QSignalSpy replots(view.plot(), &QCustomPlot::afterReplot);
    view.setPose(pose);
    QVERIFY(view.markerOffSlice());
    QTRY_VERIFY(replots.count() > 0);
    QVERIFY2(view.titleText().contains(QStringLiteral("at φ = 0.0°, not the pose's φ · det J")), qPrintable(view.titleText()));
    pose.outputs[2] = 2.0 * std::numbers::pi; // a whole turn from the slice is on it
    view.setPose(pose);
    QVERIFY(!view.markerOffSlice());
    QVERIFY2(!view.titleText().contains(QStringLiteral("not the pose")), qPrintable(view.titleText()));
    // the slice moved to the pose's φ (an edit of φ_map) puts the pose on it
    pose.outputs[2] = design->pose.outputs[2];
    view.setPose(pose);
    QVERIFY(view.markerOffSlice());
    auto turned = design->mechanism->withParameter("phi_map", pose.outputs[2]);
    QVERIFY(turned);
    ready.clear();
    view.setMechanism(*turned);
    QVERIFY(!view.markerOffSlice());
    QVERIFY(ready.wait(waitMilliseconds));

    ready.clear();
    view.setMechanism(moma());
    QVERIFY(ready.wait(waitMilliseconds));
    QCOMPARE(view.quantityBox()->findData(int(MapQuantity::OrientationRange)), -1);
    QCOMPARE(view.quantity(), MapQuantity::Determinant);
    QVERIFY(view.summary().max < 0.0); // MOMA 3a's det J
}

void TestWorkspaceMapView::capabilityMaps()
{
    auto design = designfile::load(QStringLiteral("moma-3a"));
    QVERIFY(design);
    WorkspaceMapView view;
    view.setPose(design->pose);
    QVERIFY(showMap(view, design->mechanism));
    const double workspace = view.area();
    for (MapQuantity quantity : {MapQuantity::ForceWorst, MapQuantity::SpeedWorst, MapQuantity::ResolutionWorst,
                                 MapQuantity::StiffnessWorst}) {
        const int item = view.quantityBox()->findData(int(quantity));
        QVERIFY(item >= 0);
        QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
        emit view.quantityBox()->activated(item);
        QVERIFY(ready.wait(waitMilliseconds));
        QCOMPARE(view.quantity(), quantity);
        // the coarser grid of solved cells covers the same workspace
        QVERIFY(view.summary().grid.columns <= 500 && view.summary().grid.rows <= 500);
        QVERIFY(std::abs(view.area() - workspace) < 0.03 * workspace);
        QVERIFY(view.summary().min > 0.0);
        QCOMPARE(view.colorMap()->dataRange().lower, 0.0);
        // the cell under the pose is the pose's value (display units: N, mm/s, mm, N/mm)
        const Pose &pose = design->pose;
        QVERIFY(std::isfinite(view.valueAt(platform(pose))));
        QVERIFY(view.plot()->toolTip().contains(QStringLiteral("actuators")));
    }
    // the specification: a force half-way between the least and the most holds in part of the
    // workspace; adding an impossible speed leaves none
    QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
    view.setQuantity(MapQuantity::ForceWorst);
    QVERIFY(ready.wait(waitMilliseconds));
    const double force = 0.5 * (view.summary().min + view.summary().max);
    view.setRequirements({{"force_worst", true, force}});
    ready.clear();
    view.setQuantity(MapQuantity::Specification);
    QVERIFY(ready.wait(waitMilliseconds));
    const double met = view.specificationArea();
    QVERIFY(met > 0.0 && met < view.area());
    ready.clear();
    view.setRequirements({{"force_worst", true, force}, {"speed_worst", true, 1e9}});
    QVERIFY(ready.wait(waitMilliseconds));
    QCOMPARE(view.specificationArea(), 0.0);
    QVERIFY(view.plot()->toolTip().contains(QStringLiteral("speed_worst")));
}

/// The design's tolerances put their worst-case error in the Map list: the cell under the pose
/// is the pose's first-order worst case, the scale starts at 0, and without tolerances the
/// entry goes and det J comes back.
void TestWorkspaceMapView::toleranceMap()
{
    auto design = designfile::load(QStringLiteral("moma-3a"));
    QVERIFY(design);
    WorkspaceMapView view;
    view.setPose(design->pose);
    QVERIFY(showMap(view, design->mechanism));
    QCOMPARE(view.quantityBox()->findData(int(MapQuantity::ToleranceWorst)), -1);
    const ParameterSet tolerances{{"l1", 0.1}, {"R1x", 0.05}};
    view.setTolerances(tolerances);
    const int item = view.quantityBox()->findData(int(MapQuantity::ToleranceWorst));
    QVERIFY(item >= 0);
    QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
    emit view.quantityBox()->activated(item);
    QVERIFY(ready.wait(waitMilliseconds));
    QCOMPARE(view.quantity(), MapQuantity::ToleranceWorst);
    QVERIFY(view.summary().reachableCells > 1000);
    QCOMPARE(view.colorMap()->dataRange().lower, 0.0);
    QVERIFY(view.plot()->toolTip().contains(QStringLiteral("tolerances")));
    // the cell under the pose against the analysis at the cell's centre
    const MapGrid &grid = view.summary().grid;
    const Eigen::Vector2d at = platform(design->pose);
    const int c = int((at.x() - grid.bounds.min().x()) / grid.dx()), r = int((at.y() - grid.bounds.min().y()) / grid.dy());
    Coordinates centre = design->pose.outputs;
    centre[0] = grid.x(c);
    centre[1] = grid.y(r);
    const auto pose = design->mechanism->solveInverse(centre, &design->pose);
    QVERIFY(pose);
    const auto analysis = tolerance::Analysis::make(design->mechanism, tolerances);
    QVERIFY(analysis);
    const double expected = analysis->firstOrder(*pose).worstNorm;
    const double cell = view.valueAt({grid.x(c), grid.y(r)});
    QVERIFY2(std::abs(cell - expected) <= 1e-5 * expected, qPrintable(QStringLiteral("%1 against %2").arg(cell).arg(expected)));
    // a changed tolerance recomputes the map; none takes the entry away
    ready.clear();
    view.setTolerances({{"l1", 0.2}});
    QVERIFY(ready.wait(waitMilliseconds));
    ready.clear();
    view.setTolerances({});
    QCOMPARE(view.quantityBox()->findData(int(MapQuantity::ToleranceWorst)), -1);
    QCOMPARE(view.quantity(), MapQuantity::Determinant);
    QVERIFY(ready.wait(waitMilliseconds));
}

void TestWorkspaceMapView::comparison()
{
    WorkspaceMapView view;
    QVERIFY(showMap(view, moma()));
    const MechanismPtr other = moma3d();
    QSignalSpy compared(&view, &WorkspaceMapView::comparisonReady);
    const int generation = view.generation();
    view.setComparison(other, QStringLiteral("3d"));
    QVERIFY(compared.wait(waitMilliseconds));
    QCOMPARE(view.generation(), generation); // the map itself is not recomputed
    QCOMPARE(view.comparisonArea(), referenceArea(other, view.resolution()));
    QCPCurve *outline = curveNamed(view.plot(), QStringLiteral("3d"));
    QVERIFY(outline);
    QVERIFY(outline->visible());
    QVERIFY(outline->dataCount() > 10);
    QVERIFY(view.plot()->legend->hasItemWithPlottable(outline));
    QVERIFY(outline->pen().style() != Qt::SolidLine);
    QVERIFY2(outline->name().contains(formatQuantity(view.comparisonArea(), units::squareMillimetre, 0)),
        qPrintable(outline->name()));

    view.clearComparison();
    QCOMPARE(view.comparisonArea(), 0.0);
    QCOMPARE(outline->dataCount(), 0);
    QVERIFY(!outline->visible());
    QVERIFY(!view.plot()->legend->hasItemWithPlottable(outline));
    QVERIFY(!view.busy());
}

void TestWorkspaceMapView::directSingularities3d()
{
    WorkspaceMapView view;
    QVERIFY(showMap(view, moma3d()));
    QVERIFY(view.summary().reachableCells > 0);
    QVERIFY(view.curveCount(SingularCurve::Type::Direct) > 0);
    QVERIFY(view.curveCount() > 0);
    QVERIFY(view.summary().min >= 0.0); // det J ≥ 0 over 3d's workspace, 0 at the direct singularity
}

void TestWorkspaceMapView::noPlanarWorkspace()
{
    WorkspaceMapView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(showMap(view, moma()));
    Result<MechanismPtr> pjoint = createMechanism("pjoint", {});
    QVERIFY(pjoint);
    QSignalSpy ready(&view, &WorkspaceMapView::mapReady);
    view.setMechanism(*pjoint);
    QVERIFY(view.message().contains(QStringLiteral("planar workspace")));
    QVERIFY(!view.busy());
    QCOMPARE(view.area(), 0.0);
    QCOMPARE(view.curveCount(), 0);
    view.setPose((*pjoint)->homePose());
    QVERIFY(std::isnan(view.markerPosition().x()));
    QTest::qWait(4 * WorkspaceMapView::debounceMilliseconds);
    QCOMPARE(ready.count(), 0);
    QVERIFY(!view.plot()->isVisible());

    // And back to a planar mechanism.
    QVERIFY(showMap(view, moma()));
    QVERIFY(view.message().isEmpty());
    QVERIFY(view.plot()->isVisible());
    QVERIFY(view.area() > 0.0);
}

void TestWorkspaceMapView::destroyWhileComputing()
{
    // Deleted while the debounce waits, and while the worker runs.
    {
        WorkspaceMapView view;
        view.setMechanism(moma());
        QVERIFY(view.busy());
    }
    for (const int resolution : {500, 2000}) {
        auto view = std::make_unique<WorkspaceMapView>();
        view->setResolution(resolution);
        view->setMechanism(moma());
        view->setComparison(moma3d(), QStringLiteral("3d"));
        while (view->computationsStarted() == 0)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
        QVERIFY(view->busy());
        view.reset();
    }
    QTest::qWait(50); // nothing arrives for the dead widget
}

QTEST_MAIN(TestWorkspaceMapView)
#include "tst_workspacemapview.moc"
