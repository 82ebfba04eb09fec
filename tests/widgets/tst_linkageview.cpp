// The 2D linkage view driven like a user would: a real П-joint, mouse presses, moves, wheel
// turns, and the scene fed back through the mechanism as the document would; MOMA's guides,
// carriages and ghosts of its other modes.

#include "linkageview.h"
#include "kinds/pjoint/pjoint.h"
#include "registry.h"
#include "scenepainter.h"

#include <QApplication>
#include <QBuffer>
#include <QImage>
#include <QMouseEvent>
#include <QPainter>
#include <QPdfWriter>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace pkm;

namespace {

Eigen::Vector2d jointPosition(const Scene &scene, int joint)
{
    return scene.joints[std::size_t(joint)].position.head<2>();
}

double distance(const QPointF &a, const QPointF &b)
{
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

bool sameMapping(const ViewMapping &a, const ViewMapping &b)
{
    return a.scale == b.scale && a.origin == b.origin;
}

/// A mouse move with the buttons still held, which QTest::mouseMove does not carry everywhere.
void moveMouse(QWidget *widget, const QPointF &position, Qt::MouseButtons buttons)
{
    QMouseEvent move(QEvent::MouseMove, position, widget->mapToGlobal(position), Qt::NoButton, buttons, Qt::NoModifier);
    QApplication::sendEvent(widget, &move);
}

void turnWheel(QWidget *widget, const QPointF &position, int angleDelta)
{
    QWheelEvent wheel(position, widget->mapToGlobal(position), QPoint(), QPoint(0, angleDelta), Qt::NoButton,
        Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &wheel);
}

/// Colour distance, summed over the channels.
int colourDistance(const QColor &a, const QColor &b)
{
    return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
}

/// The carriage's mid-tone blue-grey (its body, or its lighter band over the rail): not the
/// light rail, not the background, not a green link, not the dark outlines.
bool carriageTone(const QColor &c)
{
    const int grey = qGray(c.rgb());
    return grey >= 100 && grey <= 200 && c.blue() > c.green() && c.blue() > c.red() + 15;
}

/// A point `along` mm from `origin` in direction `u` and `across` mm to its left.
Eigen::Vector2d alongAcross(const Eigen::Vector2d &origin, const Eigen::Vector2d &u, double along, double across)
{
    return origin + along * u + across * Eigen::Vector2d(-u.y(), u.x());
}

QImage renderToImage(const Scene &scene, const QSize &size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::magenta);
    QPainter painter(&image);
    LinkageView::renderScene(painter, QRectF(image.rect()), scene, SceneStyle {});
    return image;
}

/// A 30° guide with a slider halfway along it and its reference point at its start, nothing else.
Scene slantedGuideScene()
{
    Scene scene;
    const Eigen::Vector3d start(0.0, 0.0, 0.0), end(200.0 * std::cos(std::numbers::pi / 6), 200.0 * std::sin(std::numbers::pi / 6), 0.0);
    scene.guides.push_back({start, end, 20.0, "PO₁"});
    scene.joints.push_back({0.5 * (start + end), "", JointKind::Slider});
    scene.joints.push_back({start, "", JointKind::Point});
    scene.extent = Eigen::AlignedBox3d(Eigen::Vector3d(-60.0, -60.0, 0.0), Eigen::Vector3d(240.0, 160.0, 0.0));
    return scene;
}

int darkPixels(const QImage &image, const QPoint &centre, int halfSize)
{
    int count = 0;
    for (int y = centre.y() - halfSize; y <= centre.y() + halfSize; ++y) {
        for (int x = centre.x() - halfSize; x <= centre.x() + halfSize; ++x) {
            if (image.rect().contains(x, y) && qGray(image.pixel(x, y)) < 110)
                ++count;
        }
    }
    return count;
}

} // namespace

class TestLinkageView : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();

    void fitShowsWholeExtent_data() { thetaTable(); }
    void fitShowsWholeExtent();
    void handlePositionMapsToJoint_data() { thetaTable(); }
    void handlePositionMapsToJoint();
    void dragEmitsTargetsAndFollowsScene_data() { thetaTable(); }
    void dragEmitsTargetsAndFollowsScene();
    void hoverShowsHintAndCursor();
    void wheelZoomKeepsPointUnderCursor();
    void setSceneKeepsMapping_data() { thetaTable(); }
    void setSceneKeepsMapping();
    void zoomSlotsAndDoubleClickFit();
    void resizeRefitsUntilUserMoves();
    void renderDrawsMotorBody_data() { thetaTable(); }
    void renderDrawsMotorBody();
    void degenerateScenesDoNotCrash();
    void scaleBarTextIsWhole();
    void labelsTakeHalfTheScaleAtMost();
    void rendersIntoPdf();
    void paintIsCountedAndTimed();

    void guidesAreDrawnUnderTheMechanism();
    void slidersOnASlantedGuideAreRotatedBlocks();
    void momaSceneRenders();
    void ghostsAreDrawnFadedAndNotExported();
    void ghostHoverNamesItAndClickEmits();
    void ghostPressThatDragsPans();
    void handlesTakePrecedenceOverGhosts();
    void clearingGhosts();

private:
    static void thetaTable();
    /// MOMA 3a at home in a shown 900 × 800 view, with its other modes as ghosts.
    struct MomaView;
    static MechanismPtr moma();
    Pose poseAt(double thetaDegrees) const;
    Scene sceneAt(double thetaDegrees) const { return m_mechanism->scene(poseAt(thetaDegrees)); }

    MechanismPtr m_mechanism;
    PJointDesign m_design;
};

void TestLinkageView::thetaTable()
{
    QTest::addColumn<double>("theta"); // degrees
    QTest::newRow("theta_min") << -60.0;
    QTest::newRow("-30") << -30.0;
    QTest::newRow("home") << 0.0;
    QTest::newRow("45") << 45.0;
    QTest::newRow("theta_max") << 60.0;
}

Pose TestLinkageView::poseAt(double thetaDegrees) const
{
    const Result<Pose> pose = m_mechanism->solveInverse(Coordinates::Constant(1, thetaDegrees * units::degree));
    return pose.ok() ? pose.value() : m_mechanism->homePose();
}

void TestLinkageView::initTestCase()
{
    const Result<MechanismPtr> mechanism = PJoint::create(m_design);
    QVERIFY(mechanism.ok());
    m_mechanism = mechanism.value();
    for (double theta : {-60.0, -30.0, 0.0, 45.0, 60.0})
        QVERIFY(m_mechanism->solveInverse(Coordinates::Constant(1, theta * units::degree)).ok());
    QCOMPARE(m_mechanism->scene(m_mechanism->homePose()).handles.front().joint, 2); // A
}

void TestLinkageView::fitShowsWholeExtent()
{
    QFETCH(double, theta);
    LinkageView view;
    view.resize(800, 600);
    view.setScene(sceneAt(theta));
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));

    const Eigen::AlignedBox3d extent = view.scene().extent;
    QVERIFY(!extent.isEmpty());
    const QRectF widget(view.rect());
    using Corner = Eigen::AlignedBox3d::CornerType;
    for (Corner corner :
        {Corner::BottomLeftFloor, Corner::BottomRightFloor, Corner::TopLeftFloor, Corner::TopRightFloor}) {
        const QPointF p = view.mapping().toDevice(extent.corner(corner));
        QVERIFY2(widget.contains(p), qPrintable(QStringLiteral("corner at %1, %2").arg(p.x()).arg(p.y())));
    }
    // Fitted, not merely inside: one axis of the extent spans the widget less the margins.
    const double width = extent.sizes().x() * view.mapping().scale, height = extent.sizes().y() * view.mapping().scale;
    QVERIFY(width > 0.85 * widget.width() || height > 0.85 * widget.height());
    // Every joint is drawn inside too.
    for (const SceneJoint &joint : view.scene().joints)
        QVERIFY(widget.contains(view.mapping().toDevice(joint.position)));
}

void TestLinkageView::handlePositionMapsToJoint()
{
    QFETCH(double, theta);
    LinkageView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const Scene scene = sceneAt(theta);
    view.setScene(scene);

    const ViewMapping mapping = view.mapping();
    const Eigen::Vector2d a = jointPosition(scene, scene.handles[0].joint);
    const Eigen::Vector2d back = mapping.toScene(view.handlePosition(0));
    QVERIFY2((back - a).norm() * mapping.scale < 0.5, qPrintable(QString::number((back - a).norm() * mapping.scale)));
    QVERIFY(distance(view.handlePosition(0), mapping.toDevice(a)) < 0.5);
    // The prototype's A: B + a(sin θ, cos θ).
    const double t = theta * units::degree;
    const Eigen::Vector2d expected(m_design.b + m_design.a * std::sin(t), m_design.a * std::cos(t));
    QVERIFY((a - expected).norm() < 1e-9);
    QCOMPARE(view.handlePosition(7), QPointF()); // no such handle
}

void TestLinkageView::dragEmitsTargetsAndFollowsScene()
{
    QFETCH(double, theta);
    LinkageView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    Pose pose = poseAt(theta);
    view.setScene(m_mechanism->scene(pose));
    const ViewMapping mapping = view.mapping();

    QSignalSpy started(&view, &LinkageView::dragStarted);
    QSignalSpy dragged(&view, &LinkageView::handleDragged);
    QSignalSpy finished(&view, &LinkageView::dragFinished);

    const QPoint press = view.handlePosition(0).toPoint();
    QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, press);
    QCOMPARE(started.count(), 1);
    QCOMPARE(started.at(0).at(0).toInt(), 0);
    QCOMPARE(view.activeHandle(), 0);
    QCOMPARE(view.cursor().shape(), Qt::ClosedHandCursor);

    // Move the pointer to where A is 10° further on, within the θ range.
    const double targetTheta = (theta <= 50.0 ? theta + 10.0 : theta - 10.0) * units::degree;
    const Eigen::Vector2d targetA(m_design.b + m_design.a * std::sin(targetTheta), m_design.a * std::cos(targetTheta));
    const QPoint mouse = mapping.toDevice(targetA).toPoint();
    moveMouse(&view, mouse, Qt::LeftButton);
    QCOMPARE(dragged.count(), 1);
    QCOMPARE(dragged.at(0).at(0).toInt(), 0);
    const Eigen::Vector2d target = dragged.at(0).at(1).value<Eigen::Vector2d>();
    QVERIFY((target - mapping.toScene(QPointF(mouse))).norm() < 1e-9);
    QVERIFY((target - targetA).norm() * mapping.scale < 1.0); // the pointer rounded to a pixel
    QVERIFY(sameMapping(view.mapping(), mapping)); // dragging does not pan

    // The owner answers with the pose that follows; the view draws A under the pointer.
    const Result<Pose> next = m_mechanism->dragHandle(pose, 0, target);
    QVERIFY(next.ok());
    QVERIFY(std::abs(next->outputs[0] - targetTheta) < 1e-2);
    const QPointF before = view.handlePosition(0);
    const int paints = view.paintCount();
    view.setScene(m_mechanism->scene(next.value()));
    QVERIFY(distance(view.handlePosition(0), QPointF(mouse)) < 1.5);
    QVERIFY(distance(view.handlePosition(0), before) > 10.0);
    QTRY_VERIFY(view.paintCount() > paints);

    const QImage shown = view.grab().toImage();
    const QPoint drawn = view.handlePosition(0).toPoint();
    QCOMPARE(QColor(shown.pixel(drawn)), QColor(Qt::white)); // the pivot's white fill
    QVERIFY(QColor(shown.pixel(before.toPoint())) != QColor(Qt::white));

    QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, mouse);
    QCOMPARE(finished.count(), 1);
    QCOMPARE(dragged.count(), 1);
    QVERIFY(view.cursor().shape() != Qt::ClosedHandCursor);

    // A move after the release is a hover, not a drag.
    moveMouse(&view, mouse + QPoint(40, 40), Qt::NoButton);
    QCOMPARE(dragged.count(), 1);
}

void TestLinkageView::hoverShowsHintAndCursor()
{
    LinkageView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(sceneAt(20.0));

    const QPointF c = view.handlePosition(1);
    moveMouse(&view, c + QPointF(5.0, -5.0), Qt::NoButton);
    QCOMPARE(view.activeHandle(), 1);
    QCOMPARE(view.cursor().shape(), Qt::OpenHandCursor);
    QCOMPARE(view.toolTip(), QString::fromStdString(view.scene().handles[1].hint));
    QVERIFY(!view.toolTip().isEmpty());

    moveMouse(&view, c + QPointF(LinkageView::hitRadius + 20.0, 0.0), Qt::NoButton);
    QCOMPARE(view.activeHandle(), -1);
    QVERIFY(view.toolTip().isEmpty());
    QVERIFY(view.cursor().shape() != Qt::OpenHandCursor);
}

void TestLinkageView::wheelZoomKeepsPointUnderCursor()
{
    LinkageView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(sceneAt(0.0));

    for (const QPointF anchor : {QPointF(300.0, 250.0), QPointF(620.5, 80.25)}) {
        const ViewMapping before = view.mapping();
        const Eigen::Vector2d fixed = before.toScene(anchor);
        turnWheel(&view, anchor, 120);
        QVERIFY(std::abs(view.mapping().scale / before.scale - LinkageView::zoomStep) < 1e-12);
        QVERIFY(distance(view.mapping().toDevice(fixed), anchor) < 1e-6);
        turnWheel(&view, anchor, -240);
        QVERIFY(view.mapping().scale < before.scale);
        QVERIFY(distance(view.mapping().toDevice(fixed), anchor) < 1e-6);
    }
}

void TestLinkageView::setSceneKeepsMapping()
{
    QFETCH(double, theta);
    LinkageView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(sceneAt(0.0));
    const ViewMapping fitted = view.mapping();

    view.setScene(sceneAt(theta));
    QVERIFY(sameMapping(view.mapping(), fitted));

    // After a zoom the new pose does not refit either.
    view.zoomIn();
    const ViewMapping zoomed = view.mapping();
    view.setScene(sceneAt(-theta));
    QVERIFY(sameMapping(view.mapping(), zoomed));
}

void TestLinkageView::zoomSlotsAndDoubleClickFit()
{
    LinkageView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(sceneAt(30.0));
    const ViewMapping fitted = view.mapping();
    const QPointF centre = QRectF(view.rect()).center();
    const Eigen::Vector2d middle = fitted.toScene(centre);

    view.zoomIn();
    QVERIFY(std::abs(view.mapping().scale - fitted.scale * LinkageView::zoomStep) < 1e-9);
    QVERIFY(distance(view.mapping().toDevice(middle), centre) < 1e-6);
    view.zoomOut();
    view.zoomOut();
    QVERIFY(view.mapping().scale < fitted.scale);

    // Pan with the middle button, then double-click on empty space: back to the fit.
    QTest::mousePress(&view, Qt::MiddleButton, Qt::NoModifier, QPoint(100, 100));
    moveMouse(&view, QPointF(160.0, 130.0), Qt::MiddleButton);
    QTest::mouseRelease(&view, Qt::MiddleButton, Qt::NoModifier, QPoint(160, 130));
    QVERIFY(!sameMapping(view.mapping(), fitted));
    QPoint empty(10, 10);
    QVERIFY(view.handleAt(empty) < 0);
    QTest::mouseDClick(&view, Qt::LeftButton, Qt::NoModifier, empty);
    QVERIFY(sameMapping(view.mapping(), fitted));

    // The fitToView() slot does the same.
    view.zoomIn();
    view.fitToView();
    QVERIFY(sameMapping(view.mapping(), fitted));
}

void TestLinkageView::resizeRefitsUntilUserMoves()
{
    LinkageView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(sceneAt(0.0));
    const double small = view.mapping().scale;

    view.resize(1200, 900);
    QTRY_COMPARE(view.size(), QSize(1200, 900));
    QVERIFY(view.mapping().scale > small);
    QVERIFY(sameMapping(view.mapping(),
        LinkageView::screenMapping(view.scene(), view.scene().extent, QRectF(view.rect()), view.sceneStyle())));

    view.zoomOut();
    const double zoomed = view.mapping().scale;
    view.resize(900, 700);
    QTRY_COMPARE(view.size(), QSize(900, 700));
    QCOMPARE(view.mapping().scale, zoomed);
}

void TestLinkageView::renderDrawsMotorBody()
{
    QFETCH(double, theta);
    const Scene scene = sceneAt(theta);
    const SceneStyle style;
    QImage image(1200, 900, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::magenta); // anything left unpainted would show
    {
        QPainter painter(&image);
        LinkageView::renderScene(painter, QRectF(image.rect()), scene, style);
    }
    const ViewMapping mapping = LinkageView::fittedMapping(scene, QRectF(image.rect()), style);

    // The motor body: a dark block from O along O→A. Sample it on a 5 × 5 grid over its inner
    // part (labels with knock-out boxes may cover a strip of it).
    const SceneActuator &actuator = scene.actuators.front();
    const Eigen::Vector2d o = jointPosition(scene, actuator.from), a = jointPosition(scene, actuator.to);
    const Eigen::Vector2d along = (a - o).normalized(), across(-along.y(), along.x());
    int dark = 0;
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 5; ++j) {
            const Eigen::Vector2d sample
                = o + (0.2 + 0.15 * i) * actuator.bodyLength * along + (-0.3 + 0.15 * j) * actuator.bodyWidth * across;
            if (qGray(image.pixel(mapping.toDevice(sample).toPoint())) < 110)
                ++dark;
        }
    }
    QVERIFY2(dark >= 15, qPrintable(QStringLiteral("%1 dark samples of 25").arg(dark)));
    // Its middle in particular, unless a label sits there.
    QVERIFY(darkPixels(image, mapping.toDevice(o + 0.5 * actuator.bodyLength * along).toPoint(), 3) >= 5);

    // Far from the mechanism: background, not magenta, not dark.
    const QColor corner = image.pixelColor(4, 4);
    QVERIFY(corner != QColor(Qt::magenta));
    QVERIFY(qGray(corner.rgb()) > 200);
    // The screw, between the body and A, is drawn and lighter than the body.
    const Eigen::Vector2d screwPoint = o + (actuator.bodyLength + 4.0) * (a - o).normalized();
    const QColor screw = image.pixelColor(mapping.toDevice(screwPoint).toPoint());
    QVERIFY(qGray(screw.rgb()) > 110 && qGray(screw.rgb()) < 235);
}

/// The scale bar's text wider than the bar (presentation mode's large text over a bar of about
/// 90 px) ends with the bar, whole: it was cut at the bar's ends, "100 mm" to "100 m".
/// A short view with large text (presentation mode, a status message of two lines): the fit
/// that keeps labels whole shrank the five-bar to 60 px under a 500 mm bar. The labels may
/// take half of the plain fit's scale at most.
void TestLinkageView::labelsTakeHalfTheScaleAtMost()
{
    const Result<MechanismPtr> made = createMechanism("fivebar", {});
    QVERIFY(made);
    const MechanismPtr fivebar = *made;
    const Scene scene = fivebar->scene(fivebar->homePose());
    SceneStyle style;
    style.fontPixels *= 2.0; // large text, as presentation mode at 200 %
    style.jointFontPixels *= 2.0;
    for (const QRectF room : {QRectF(0, 0, 700, 265), QRectF(0, 0, 700, 180), QRectF(0, 0, 300, 400)}) {
        const double plain = ViewMapping::fit(scene.extent, room, 20.0).scale;
        const double withLabels = ScenePainter::fitWithLabels(scene, scene.extent, room, room, 20.0, style).scale;
        QVERIFY2(withLabels >= 0.5 * plain - 1e-9,
                 qPrintable(QStringLiteral("%1 × %2: %3 of %4 px/mm").arg(room.width()).arg(room.height()).arg(withLabels).arg(plain)));
    }
}

void TestLinkageView::scaleBarTextIsWhole()
{
    SceneStyle style;
    style.fontPixels = 40.0;
    QImage image(400, 200, QImage::Format_RGB32);
    image.fill(Qt::white);
    ViewMapping mapping;
    mapping.scale = 0.9; // px per mm: a bar of 100 mm is 90 px
    QPainter painter(&image);
    ScenePainter::paintScaleBar(painter, QRectF(image.rect()), mapping, style);
    painter.end();
    const int barLeft = 400 - 16 - 90;
    int inkLeftOfBar = 0;
    for (int y = 0; y < 200 - 16 - 8; ++y) {
        for (int x = 0; x < barLeft - 2; ++x)
            inkLeftOfBar += qGray(image.pixel(x, y)) < 128;
    }
    QCOMPARE_GT(inkLeftOfBar, 20); // the first digits stand left of the bar
}

void TestLinkageView::degenerateScenesDoNotCrash()
{
    Scene scene = sceneAt(0.0);
    QImage image(600, 400, QImage::Format_ARGB32_Premultiplied);
    auto render = [&image](const Scene &s) {
        image.fill(Qt::white);
        QPainter painter(&image);
        LinkageView::renderScene(painter, QRectF(image.rect()), s, SceneStyle {});
    };

    // The pose is shorter than the motor body: the body is clipped at A, no screw.
    Scene shortActuator = scene;
    shortActuator.actuators[0].bodyLength = 1000.0;
    render(shortActuator);
    const ViewMapping mapping = LinkageView::fittedMapping(shortActuator, QRectF(image.rect()), SceneStyle {});
    const Eigen::Vector2d o = jointPosition(scene, 0), a = jointPosition(scene, 2);
    QVERIFY(darkPixels(image, mapping.toDevice(0.5 * (o + a)).toPoint(), 2) >= 20); // body up to A

    // Zero length, zero and negative sizes, bad joint indices, an empty extent, empty scene.
    Scene odd = scene;
    odd.joints[2].position = odd.joints[0].position;
    odd.actuators[0].rodDiameter = 0.0;
    odd.actuators.push_back({0, 3, -5.0, -1.0, -1.0, "x"});
    odd.bars.push_back({1, 99, BarKind::Rod, "bad"});
    odd.angles.push_back({42, 0.0, 1.0, 10.0, "bad"});
    odd.angles.push_back({1, 0.0, 0.0, 0.0, "zero"});
    odd.dimensions.push_back({3, 3, 5.0, "same joint"});
    odd.dimensions.push_back({0, 1, 0.0, ""});
    odd.handles.push_back({-1, "bad"});
    render(odd);
    odd.extent = Eigen::AlignedBox3d();
    render(odd);
    render(Scene {});

    LinkageView view;
    view.resize(400, 300);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(odd);
    view.repaint();
    QVERIFY(view.handleAt(QPointF(-1e6, -1e6)) < 0);
    QCOMPARE(view.handlePosition(2), QPointF());
}

void TestLinkageView::rendersIntoPdf()
{
    // The export path: a vector device at 300 dpi, symbols and text scaled with pixelSize.
    QBuffer buffer;
    QVERIFY(buffer.open(QIODevice::WriteOnly));
    {
        QPdfWriter pdf(&buffer);
        pdf.setResolution(300);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setPageOrientation(QPageLayout::Landscape);
        SceneStyle style;
        style.pixelSize = pdf.resolution() / 96.0;
        QPainter painter(&pdf);
        QVERIFY(painter.isActive());
        LinkageView view;
        view.setScene(sceneAt(30.0));
        view.setSceneStyle(style);
        view.renderTo(painter, QRectF(0, 0, pdf.width(), pdf.height()));
    }
    QVERIFY(buffer.data().startsWith("%PDF"));
    QVERIFY(buffer.size() > 2000);
}

void TestLinkageView::paintIsCountedAndTimed()
{
    LinkageView view;
    view.resize(1600, 1000);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(sceneAt(30.0));
    view.setMessage(QStringLiteral("θ stops at its upper limit 60°"));

    const int before = view.paintCount();
    double fastest = 1e9, total = 0.0;
    constexpr int repeats = 50;
    for (int i = 0; i < repeats; ++i) {
        view.repaint();
        fastest = std::min(fastest, view.lastPaintMilliseconds());
        total += view.lastPaintMilliseconds();
    }
    QCOMPARE(view.paintCount(), before + repeats);
    QVERIFY(view.lastPaintMilliseconds() > 0.0);
    // Reported, not asserted: timings belong to bench/, this only shows them in the log.
    qInfo("paint 1600x1000: fastest %.3f ms, mean %.3f ms", fastest, total / repeats);
}

MechanismPtr TestLinkageView::moma()
{
    const Result<MechanismPtr> mechanism = createMechanism("moma", {});
    return mechanism.ok() ? mechanism.value() : MechanismPtr();
}

void TestLinkageView::guidesAreDrawnUnderTheMechanism()
{
    const Scene scene = slantedGuideScene();
    Scene bare = scene;
    bare.guides.clear();
    const QImage withGuide = renderToImage(scene, QSize(1000, 800));
    const QImage without = renderToImage(bare, QSize(1000, 800));
    const ViewMapping mapping = LinkageView::fittedMapping(scene, QRectF(withGuide.rect()), SceneStyle {});
    const SceneStyle style;

    // On the rail, a quarter along and off its dash-dot axis: the steel fill, not background.
    const Eigen::Vector2d start = scene.guides[0].start.head<2>(), end = scene.guides[0].end.head<2>();
    const Eigen::Vector2d u = (end - start).normalized();
    for (double across : {-5.0, 5.0}) {
        const QPoint rail = mapping.toDevice(alongAcross(start, u, 50.0, across)).toPoint();
        QVERIFY2(colourDistance(withGuide.pixelColor(rail), style.guideFill) < 30,
            qPrintable(withGuide.pixelColor(rail).name()));
        QVERIFY(colourDistance(without.pixelColor(rail), style.background) < 30);
    }
    // End stops, dark, just past both ends of the stroke and the carriage's overrun (0.9 × width).
    for (const Eigen::Vector2d &stop : {alongAcross(start, u, -19.5, 0.0), alongAcross(end, u, 19.5, 0.0)})
        QVERIFY(darkPixels(withGuide, mapping.toDevice(stop).toPoint(), 1) >= 3);
    // The label names the guide somewhere beside it: some dark text pixels near the rail that
    // the unlabelled drawing lacks.
    Scene unlabelled = scene;
    unlabelled.guides[0].label.clear();
    const QImage noLabel = renderToImage(unlabelled, QSize(1000, 800));
    QVERIFY(withGuide != noLabel);
}

void TestLinkageView::slidersOnASlantedGuideAreRotatedBlocks()
{
    const Scene scene = slantedGuideScene();
    const QImage image = renderToImage(scene, QSize(1000, 800));
    const ViewMapping mapping = LinkageView::fittedMapping(scene, QRectF(image.rect()), SceneStyle {});
    QVERIFY(mapping.scale > 2.0); // so the block has its mm size, not a minimum in pixels
    const SceneStyle style;
    const Eigen::Vector2d centre = scene.joints[0].position.head<2>();
    const Eigen::Vector2d u = (scene.guides[0].end - scene.guides[0].start).head<2>().normalized();
    auto colourAt = [&](double along, double across) {
        return image.pixelColor(mapping.toDevice(alongAcross(centre, u, along, across)).toPoint());
    };

    // The block is 1.8 × 20 mm long along the guide and 1.3 × 20 mm wide: its sides, off the
    // rail's band, are carriage-coloured near its corners, which an upright block would miss
    // (along 14, across 11 is 16.5 mm above the centre here).
    for (double along : {-14.0, 14.0}) {
        for (double across : {-11.0, 11.0}) {
            QVERIFY2(colourDistance(colourAt(along, across), style.carriage) < 40,
                qPrintable(QStringLiteral("%1, %2: %3").arg(along).arg(across).arg(colourAt(along, across).name())));
        }
    }
    // Along the guide past the block: the rail; across it past the block: not the carriage.
    QVERIFY(colourDistance(colourAt(24.0, 5.0), style.guideFill) < 30);
    QVERIFY(colourDistance(colourAt(-24.0, -5.0), style.guideFill) < 30);
    for (double across : {-17.0, 17.0})
        QVERIFY(!carriageTone(colourAt(0.0, across)));
    // An upright block of that size would cover these; the turned one does not.
    const Eigen::Vector2d x(1.0, 0.0), y(0.0, 1.0);
    for (const Eigen::Vector2d &corner : {Eigen::Vector2d(centre + 15.0 * x - 12.0 * y), Eigen::Vector2d(centre - 15.0 * x + 12.0 * y)})
        QVERIFY(!carriageTone(image.pixelColor(mapping.toDevice(corner).toPoint())));
    // The revolute pin at the centre: a white disc.
    QCOMPARE(image.pixelColor(mapping.toDevice(centre).toPoint()), QColor(Qt::white));

    // Off the guide, a slider keeps its small upright block: nothing carriage-coloured around it.
    Scene offGuide = scene;
    offGuide.joints[0].position += Eigen::Vector3d(-30.0, 60.0, 0.0);
    const QImage moved = renderToImage(offGuide, QSize(1000, 800));
    const Eigen::Vector2d away = offGuide.joints[0].position.head<2>();
    for (double along : {-14.0, 14.0}) {
        QVERIFY(!carriageTone(moved.pixelColor(mapping.toDevice(alongAcross(away, u, along, 11.0)).toPoint())));
    }
}

void TestLinkageView::momaSceneRenders()
{
    const MechanismPtr mechanism = moma();
    QVERIFY(mechanism);
    const Scene scene = mechanism->scene(mechanism->homePose());
    QCOMPARE(scene.guides.size(), std::size_t(2));
    QVERIFY(!scene.dimensions.empty());
    QVERIFY(!scene.angles.empty());
    const QImage image = renderToImage(scene, QSize(1200, 900));
    const ViewMapping mapping = LinkageView::fittedMapping(scene, QRectF(image.rect()), SceneStyle {});
    const SceneStyle style;
    for (const SceneGuide &guide : scene.guides) {
        // A rail, steel-coloured, somewhere across it three quarters of the way along (the
        // carriage, the axis or a dashed reference line may cover single points).
        const Eigen::Vector2d start = guide.start.head<2>(), end = guide.end.head<2>();
        const Eigen::Vector2d u = (end - start).normalized();
        int steel = 0;
        for (double across = -0.45 * guide.width; across <= 0.45 * guide.width; across += 0.05 * guide.width) {
            if (colourDistance(image.pixelColor(mapping.toDevice(alongAcross(start, u, 0.75 * (end - start).norm(), across)).toPoint()),
                    style.guideFill) < 30)
                ++steel;
        }
        QVERIFY2(steel >= 8, qPrintable(QString::number(steel)));
    }
    // The sliders (joints 1 and 2) ride carriages: carriage-coloured pixels near them.
    for (int joint : {1, 2}) {
        const QPoint centre = mapping.toDevice(jointPosition(scene, joint)).toPoint();
        int carriage = 0;
        for (int dy = -20; dy <= 20; ++dy) {
            for (int dx = -20; dx <= 20; ++dx) {
                if (image.rect().contains(centre + QPoint(dx, dy)) && carriageTone(image.pixelColor(centre + QPoint(dx, dy))))
                    ++carriage;
            }
        }
        QVERIFY2(carriage > 600, qPrintable(QString::number(carriage)));
    }
}

struct TestLinkageView::MomaView {
    MechanismPtr mechanism;
    Pose pose;
    QList<Scene> ghosts;
    QStringList labels;
    LinkageView view;

    bool setUp()
    {
        mechanism = moma();
        if (!mechanism)
            return false;
        pose = mechanism->homePose();
        for (const ModeAlternative &alternative : mechanism->modeAlternatives(pose)) {
            if (!alternative.mechanism || alternative.pose.inputs.size() == 0)
                continue;
            ghosts.push_back(alternative.mechanism->scene(alternative.pose));
            labels.push_back(QString::fromStdString(alternative.label));
        }
        view.resize(900, 800);
        view.setScene(mechanism->scene(pose));
        view.setGhostScenes(ghosts, labels);
        view.show();
        return !ghosts.isEmpty() && QTest::qWaitForWindowExposed(&view);
    }

    /// A point on ghost `index`'s first moving member, `fraction` along it, clear of the
    /// real scene's handles; a null point when there is none.
    QPointF onGhost(int index) const
    {
        const Scene &ghost = ghosts[index];
        for (const SceneBar &bar : ghost.bars) {
            if (bar.kind == BarKind::Ground)
                continue;
            for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7}) {
                const QPointF a = view.mapping().toDevice(ghost.joints[std::size_t(bar.from)].position);
                const QPointF b = view.mapping().toDevice(ghost.joints[std::size_t(bar.to)].position);
                const QPointF p = a + fraction * (b - a);
                if (view.handleAt(p) < 0 && QRectF(view.rect()).adjusted(5, 5, -5, -5).contains(p)
                    && view.ghostAt(p) == index)
                    return p;
            }
        }
        return {};
    }
};

void TestLinkageView::ghostsAreDrawnFadedAndNotExported()
{
    MomaView m;
    QVERIFY(m.setUp());
    QCOMPARE(m.view.ghostScenes().size(), m.ghosts.size());
    // The first ghosts are fitted: their joints are inside the view.
    for (const Scene &ghost : m.ghosts) {
        for (const SceneJoint &joint : ghost.joints)
            QVERIFY(QRectF(m.view.rect()).contains(m.view.mapping().toDevice(joint.position)));
    }
    const QPointF on = m.onGhost(0);
    QVERIFY(!on.isNull());
    const QImage shown = m.view.grab().toImage();
    const ViewMapping mapping = m.view.mapping();

    LinkageView plain;
    plain.resize(900, 800);
    plain.setScene(m.view.scene());
    plain.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plain));
    plain.fitToView();
    QVERIFY(plain.mapping().scale >= mapping.scale);
    // Same mapping as the view with ghosts, to compare pixels.
    plain.setGhostScenes(m.ghosts, m.labels);
    plain.fitToView();
    plain.setGhostScenes({}, {});
    QVERIFY(sameMapping(plain.mapping(), mapping));
    const QImage bare = plain.grab().toImage();
    // On the ghost's member: drawn (differs from the bare view), faded (not dark).
    int differing = 0;
    for (int dy = -3; dy <= 3; ++dy) {
        for (int dx = -3; dx <= 3; ++dx) {
            const QPoint p = on.toPoint() + QPoint(dx, dy);
            if (shown.pixelColor(p) != bare.pixelColor(p)) {
                ++differing;
                QVERIFY(qGray(shown.pixel(p)) > 120);
            }
        }
    }
    QVERIFY(differing > 0);

    // Export draws the real scene only.
    QImage withGhosts(800, 600, QImage::Format_ARGB32_Premultiplied), withoutGhosts = withGhosts;
    {
        QPainter painter(&withGhosts);
        m.view.renderTo(painter, QRectF(withGhosts.rect()));
    }
    {
        QPainter painter(&withoutGhosts);
        plain.renderTo(painter, QRectF(withoutGhosts.rect()));
    }
    QCOMPARE(withGhosts, withoutGhosts);
}

void TestLinkageView::ghostHoverNamesItAndClickEmits()
{
    MomaView m;
    QVERIFY(m.setUp());
    m.view.setMessage(QStringLiteral("owner's message"));
    QSignalSpy clicked(&m.view, &LinkageView::ghostClicked);
    QSignalSpy dragged(&m.view, &LinkageView::handleDragged);
    const int last = int(m.ghosts.size()) - 1;

    for (int index : {0, last}) {
        const QPointF on = m.onGhost(index);
        QVERIFY2(!on.isNull(), qPrintable(QString::number(index)));
        const ViewMapping before = m.view.mapping();
        const QImage unhovered = m.view.grab().toImage();
        moveMouse(&m.view, on, Qt::NoButton);
        QCOMPARE(m.view.hoveredGhost(), index);
        QCOMPARE(m.view.activeHandle(), -1);
        const QString expected = QStringLiteral("Click to switch to: ") + m.labels[index];
        QCOMPARE(m.view.toolTip(), expected);
        QCOMPARE(m.view.shownMessage(), expected);
        QCOMPARE(m.view.message(), QStringLiteral("owner's message")); // not overwritten
        QCOMPARE(m.view.cursor().shape(), Qt::PointingHandCursor);
        QVERIFY(m.view.grab().toImage() != unhovered); // highlighted, and the message shown

        QTest::mouseClick(&m.view, Qt::LeftButton, Qt::NoModifier, on.toPoint());
        QCOMPARE(clicked.count(), 1);
        QCOMPARE(clicked.takeFirst().at(0).toInt(), index);
        QVERIFY(sameMapping(m.view.mapping(), before)); // a click does not pan
        // Nothing else happens: the view keeps its scene and its ghosts.
        QCOMPARE(m.view.ghostScenes().size(), m.ghosts.size());
        QCOMPARE(m.view.scene().joints.size(), m.mechanism->scene(m.pose).joints.size());

        // Away from everything: no ghost, the owner's message again.
        moveMouse(&m.view, QPointF(3.0, 3.0), Qt::NoButton);
        QCOMPARE(m.view.hoveredGhost(), -1);
        QVERIFY(m.view.toolTip().isEmpty());
        QCOMPARE(m.view.shownMessage(), QStringLiteral("owner's message"));
    }
    QCOMPARE(dragged.count(), 0);
}

void TestLinkageView::ghostPressThatDragsPans()
{
    MomaView m;
    QVERIFY(m.setUp());
    QSignalSpy clicked(&m.view, &LinkageView::ghostClicked);
    const QPointF on = m.onGhost(0).toPoint(); // where QTest presses
    QVERIFY(!on.isNull() && m.view.ghostAt(on) == 0);
    const ViewMapping before = m.view.mapping();

    QTest::mousePress(&m.view, Qt::LeftButton, Qt::NoModifier, on.toPoint());
    // A jitter within the drag distance neither pans nor cancels the click…
    moveMouse(&m.view, on + QPointF(1.0, 0.0), Qt::LeftButton);
    QVERIFY(sameMapping(m.view.mapping(), before));
    // …a real move pans the whole way from the press, and the release is no click.
    moveMouse(&m.view, on + QPointF(60.0, 25.0), Qt::LeftButton);
    QTest::mouseRelease(&m.view, Qt::LeftButton, Qt::NoModifier, (on + QPointF(60.0, 25.0)).toPoint());
    QCOMPARE(clicked.count(), 0);
    QVERIFY(distance(m.view.mapping().origin, before.origin + QPointF(60.0, 25.0)) < 1e-9);
}

void TestLinkageView::handlesTakePrecedenceOverGhosts()
{
    MomaView m;
    QVERIFY(m.setUp());
    QSignalSpy clicked(&m.view, &LinkageView::ghostClicked);
    QSignalSpy dragged(&m.view, &LinkageView::handleDragged);
    QSignalSpy finished(&m.view, &LinkageView::dragFinished);

    // The other assembly mode keeps the slider positions: its Z₁ is under the real Z₁ handle.
    const int handle = 1;
    const QPointF z1 = m.view.handlePosition(handle);
    const Scene &ghost = m.ghosts[0];
    QVERIFY(distance(m.view.mapping().toDevice(ghost.joints[std::size_t(m.view.scene().handles[handle].joint)].position), z1) < 1.0);
    QCOMPARE(m.view.ghostAt(z1), -1);

    moveMouse(&m.view, z1, Qt::NoButton);
    QCOMPARE(m.view.activeHandle(), handle);
    QCOMPARE(m.view.hoveredGhost(), -1);
    QCOMPARE(m.view.toolTip(), QString::fromStdString(m.view.scene().handles[handle].hint));

    QTest::mousePress(&m.view, Qt::LeftButton, Qt::NoModifier, z1.toPoint());
    moveMouse(&m.view, z1 + QPointF(0.0, 30.0), Qt::LeftButton);
    QTest::mouseRelease(&m.view, Qt::LeftButton, Qt::NoModifier, (z1 + QPointF(0.0, 30.0)).toPoint());
    QCOMPARE(dragged.count(), 1);
    QCOMPARE(dragged.at(0).at(0).toInt(), handle);
    QCOMPARE(finished.count(), 1);
    QCOMPARE(clicked.count(), 0);

    // A click on the handle without a drag is no ghost click either.
    QTest::mouseClick(&m.view, Qt::LeftButton, Qt::NoModifier, z1.toPoint());
    QCOMPARE(clicked.count(), 0);
}

void TestLinkageView::clearingGhosts()
{
    MomaView m;
    QVERIFY(m.setUp());
    QSignalSpy clicked(&m.view, &LinkageView::ghostClicked);
    const QPointF on = m.onGhost(0);
    QVERIFY(!on.isNull());
    moveMouse(&m.view, on, Qt::NoButton);
    QCOMPARE(m.view.hoveredGhost(), 0);

    m.view.setGhostScenes({}, {});
    QVERIFY(m.view.ghostScenes().isEmpty());
    QCOMPARE(m.view.hoveredGhost(), -1);
    QVERIFY(m.view.toolTip().isEmpty());
    QCOMPARE(m.view.ghostAt(on), -1);
    moveMouse(&m.view, on + QPointF(1.0, 0.0), Qt::NoButton);
    QCOMPARE(m.view.hoveredGhost(), -1);
    QTest::mouseClick(&m.view, Qt::LeftButton, Qt::NoModifier, on.toPoint());
    QCOMPARE(clicked.count(), 0);
    m.view.repaint();
}

QTEST_MAIN(TestLinkageView)
#include "tst_linkageview.moc"
