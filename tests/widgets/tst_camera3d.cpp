// The 3D view's maths without GL: the camera (rigid view, turntable orbit, standard views,
// fit in both projections, pan and zoom that keep the point under the cursor, pixel ↔ ray),
// the tessellation (counts, outward unit normals, winding, bounds, colours, grid) and the
// extrusion of a 2D scene into solids.

#include "camera3d.h"
#include "mesh3d.h"
#include "registry.h"
#include "renderer3d.h"
#include "scene3d.h"
#include "support/kinematics.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <string>

Q_DECLARE_METATYPE(pkm::Solid)
Q_DECLARE_METATYPE(pkm::Camera3D::Projection)
Q_DECLARE_METATYPE(pkm::Camera3D::StandardView)

using namespace pkm;
using namespace pkm::test;
using Projection = Camera3D::Projection;
using View = Camera3D::StandardView;

namespace {

constexpr double pi = std::numbers::pi;

const Eigen::AlignedBox3d testBox(Eigen::Vector3d(-120.0, -40.0, -25.0), Eigen::Vector3d(260.0, 310.0, 35.0));

Camera3D camera(Projection projection, View view, int width, int height)
{
    Camera3D c;
    c.setViewport(width, height);
    c.setProjection(projection);
    c.setStandardView(view);
    c.fit(testBox);
    return c;
}

/// A small mechanism drawn by hand: ground pivot O, pins A and B, a slider S on a guide, a
/// ball C on a rod, a marker M; an actuator from O to B.
Scene handScene()
{
    Scene scene;
    scene.joints = {{{0, 0, 0}, "O", JointKind::Ground}, {{0, 100, 0}, "A", JointKind::Revolute},
        {{100, 100, 0}, "B", JointKind::Revolute}, {{150, 0, 0}, "S", JointKind::Slider},
        {{60, 160, 0}, "C", JointKind::Spherical}, {{30, 50, 0}, "M", JointKind::Point}};
    scene.bars = {{0, 1, BarKind::Crank, "a"}, {1, 2, BarKind::Coupler, "b"}, {2, 3, BarKind::Link, "c"},
        {1, 4, BarKind::Rod, "r"}};
    scene.actuators = {{0, 2, 60.0, 24.0, 6.0, "d"}};
    scene.guides = {{Eigen::Vector3d(100, 0, 0), Eigen::Vector3d(220, 0, 0), 16.0, "G"}};
    scene.extent = Eigen::AlignedBox3d(Eigen::Vector3d(-30, -30, 0), Eigen::Vector3d(250, 190, 0));
    return scene;
}

std::vector<const Solid *> withRole(const Scene3D &model, PartRole role)
{
    std::vector<const Solid *> found;
    for (const Solid &s : model.solids)
        if (s.role == role)
            found.push_back(&s);
    return found;
}

bool contains(const Eigen::AlignedBox3d &outer, const Eigen::AlignedBox3d &inner, double tolerance = 1e-9)
{
    return (inner.min().array() >= outer.min().array() - tolerance).all()
        && (inner.max().array() <= outer.max().array() + tolerance).all();
}

} // namespace

class TestCamera3D : public QObject
{
    Q_OBJECT

private slots:
    void viewMatrixIsRigid();
    void orbitKeepsDistanceAndClampsPitch();
    void standardViewsLookAlongTheirAxes();
    void fitShowsAllCorners_data();
    void fitShowsAllCorners();
    void fitPointsFillsTheView_data() { projections(); }
    void fitPointsFillsTheView();
    void panKeepsPointUnderCursor_data() { projections(); }
    void panKeepsPointUnderCursor();
    void zoomKeepsPointUnderCursor_data() { projections(); }
    void zoomKeepsPointUnderCursor();
    void rayRoundTrip_data() { projections(); }
    void rayRoundTrip();
    void meshCounts();
    void normalsAreUnitOutwardAndWound_data();
    void normalsAreUnitOutwardAndWound();
    void meshBoundsMatchSolids_data() { normalsAreUnitOutwardAndWound_data(); }
    void meshBoundsMatchSolids();
    void degenerateSolidsAddNothing();
    void roleColoursAreDistinct();
    void groundGridLiesUnderTheExtent();
    void extrudeHandScene();
    void extrudedMechanismsStayInTheirExtent_data() { addKindRows(); }
    void extrudedMechanismsStayInTheirExtent();

private:
    static void projections()
    {
        QTest::addColumn<Projection>("projection");
        QTest::newRow("perspective") << Projection::Perspective;
        QTest::newRow("orthographic") << Projection::Orthographic;
    }
};

/// A tall slanted bar seen isometrically: every point is inside the viewport, the outline is
/// centred and fills it along one axis, where fitting the bar's box leaves much of it empty.
void TestCamera3D::fitPointsFillsTheView()
{
    QFETCH(Projection, projection);
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i <= 20; ++i) {
        const double t = i / 20.0;
        points.emplace_back(40.0 * t, 300.0 * t, -25.0 * t);
        points.emplace_back(40.0 * t + 10.0, 300.0 * t, -25.0 * t + 10.0);
    }
    Camera3D c;
    c.setViewport(640, 480);
    c.setProjection(projection);
    c.setStandardView(Camera3D::StandardView::Isometric);
    c.fitPoints(points);
    Eigen::AlignedBox2d outline;
    for (const Eigen::Vector3d &p : points) {
        const Eigen::Vector2d pixel = c.project(p);
        QVERIFY2(pixel.x() >= 0 && pixel.x() <= 640 && pixel.y() >= 0 && pixel.y() <= 480,
                 qPrintable(QStringLiteral("(%1, %2) off the view").arg(pixel.x()).arg(pixel.y())));
        outline.extend(pixel);
    }
    const double fill = std::max(outline.sizes().x() / 640.0, outline.sizes().y() / 480.0);
    QVERIFY2(fill > 0.8, qPrintable(QStringLiteral("the points fill %1 of the view").arg(fill)));
    if (projection == Projection::Orthographic)
        QVERIFY((outline.center() - Eigen::Vector2d(320, 240)).norm() < 1.0);

    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d &p : points)
        box.extend(p);
    Camera3D boxed = c;
    boxed.fit(box);
    QVERIFY(c.distance() < boxed.distance()); // closer than the box would allow
}

void TestCamera3D::viewMatrixIsRigid()
{
    for (double yaw : {-2.5, 0.0, 0.7, 3.0}) {
        for (double pitch : {-1.2, 0.0, 0.4, 0.5 * pi}) {
            Camera3D c;
            c.setTarget(Eigen::Vector3d(10, -20, 5));
            c.setDistance(321.0);
            c.setOrientation(yaw, pitch);
            const Eigen::Matrix4d v = c.viewMatrix();
            const Eigen::Matrix3d r = v.topLeftCorner<3, 3>();
            QVERIFY((r * r.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-12);
            QVERIFY(std::abs(r.determinant() - 1.0) < 1e-12);
            QVERIFY((v.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() == 0.0);
            // The eye goes to the origin and the target straight ahead along −z.
            QVERIFY((v * c.eye().homogeneous()).head<3>().norm() < 1e-9);
            QVERIFY(((v * c.target().homogeneous()).head<3>() - Eigen::Vector3d(0, 0, -321.0)).norm() < 1e-9);
        }
    }
}

void TestCamera3D::orbitKeepsDistanceAndClampsPitch()
{
    Camera3D c;
    c.setTarget(Eigen::Vector3d(5, 6, 7));
    c.setDistance(400.0);
    const double yaw = c.yaw();
    for (const auto &[dx, dy] : {std::pair {35.0, -12.0}, {-300.0, 80.0}, {4.0, 1.0}}) {
        c.orbit(dx, dy);
        QVERIFY(std::abs((c.eye() - c.target()).norm() - 400.0) < 1e-9);
        QCOMPARE(c.target(), Eigen::Vector3d(5, 6, 7));
    }
    QVERIFY(c.yaw() != yaw);
    c.orbit(0.0, 1e6);
    QCOMPARE(c.pitch(), Camera3D::maximumPitch);
    QVERIFY(c.pitch() < 0.5 * pi);
    c.orbit(0.0, -1e6);
    QCOMPARE(c.pitch(), -Camera3D::maximumPitch);
    // Dragging right turns the model's front (+z) to the right.
    Camera3D front;
    const double before = front.project(Eigen::Vector3d(0, 0, 50)).x();
    front.orbit(20.0, 0.0);
    QVERIFY(front.project(Eigen::Vector3d(0, 0, 50)).x() > before + 1.0);
}

void TestCamera3D::standardViewsLookAlongTheirAxes()
{
    const struct {
        View view;
        Eigen::Vector3d direction;
    } cases[] = {{View::Front, {0, 0, -1}}, {View::Top, {0, -1, 0}}, {View::Side, {-1, 0, 0}},
        {View::Isometric, Eigen::Vector3d(-1, -1, -1).normalized()}};
    for (const auto &entry : cases) {
        Camera3D c;
        c.setStandardView(entry.view);
        QVERIFY((c.viewDirection() - entry.direction).norm() < 1e-12);
        QVERIFY((c.right().cross(c.up()) - c.back()).norm() < 1e-12);
    }
    Camera3D c;
    c.setDistance(300.0);
    c.setStandardView(View::Front);
    // Front: +z nearer, +x to the right, +y up — the 2D view's picture.
    QVERIFY(c.depth(Eigen::Vector3d(0, 0, 10)) < c.depth(Eigen::Vector3d(0, 0, -10)));
    QVERIFY(c.project(Eigen::Vector3d(50, 0, 0)).x() > c.project(Eigen::Vector3d::Zero()).x());
    QVERIFY(c.project(Eigen::Vector3d(0, 50, 0)).y() < c.project(Eigen::Vector3d::Zero()).y());
    // Top: +y nearer, the front (+z) at the bottom of the screen, +x still to the right.
    c.setStandardView(View::Top);
    QVERIFY(c.depth(Eigen::Vector3d(0, 10, 0)) < c.depth(Eigen::Vector3d(0, -10, 0)));
    QVERIFY(c.project(Eigen::Vector3d(0, 0, 50)).y() > c.project(Eigen::Vector3d::Zero()).y());
    QVERIFY(c.project(Eigen::Vector3d(50, 0, 0)).x() > c.project(Eigen::Vector3d::Zero()).x());
    // Side: from +x, so +x nearer and the front (+z) to the left.
    c.setStandardView(View::Side);
    QVERIFY(c.depth(Eigen::Vector3d(10, 0, 0)) < c.depth(Eigen::Vector3d(-10, 0, 0)));
    QVERIFY(c.project(Eigen::Vector3d(0, 0, 50)).x() < c.project(Eigen::Vector3d::Zero()).x());
    c.setStandardView(View::Isometric);
    QVERIFY(c.depth(Eigen::Vector3d(10, 10, 10)) < c.depth(Eigen::Vector3d(-10, -10, -10)));
}

void TestCamera3D::fitShowsAllCorners_data()
{
    QTest::addColumn<Projection>("projection");
    QTest::addColumn<View>("view");
    QTest::addColumn<QSize>("viewport");
    const std::pair<const char *, View> views[]
        = {{"front", View::Front}, {"top", View::Top}, {"side", View::Side}, {"isometric", View::Isometric}};
    for (const auto &[projectionName, projection] :
        {std::pair {"perspective", Projection::Perspective}, {"orthographic", Projection::Orthographic}})
        for (const auto &[viewName, view] : views)
            for (const QSize size : {QSize(400, 300), QSize(300, 700), QSize(1600, 400)})
                QTest::addRow("%s %s %dx%d", projectionName, viewName, size.width(), size.height())
                    << projection << view << size;
}

void TestCamera3D::fitShowsAllCorners()
{
    QFETCH(Projection, projection);
    QFETCH(View, view);
    QFETCH(QSize, viewport);
    Camera3D c = camera(projection, view, viewport.width(), viewport.height());
    c.orbit(0.0, 0.0); // a no-op keeps a Top view looking straight down
    const double w = viewport.width(), h = viewport.height();
    // The margin is fitMargin of the half size on each side; the fit is tight on one axis.
    const double mx = 0.5 * w * Camera3D::fitMargin * 0.99, my = 0.5 * h * Camera3D::fitMargin * 0.99;
    double reach = 0.0;
    const Eigen::AlignedBox3d box = testBox;
    for (int i = 0; i < 8; ++i) {
        double depth = 0.0;
        const Eigen::Vector2d p = c.project(box.corner(Eigen::AlignedBox3d::CornerType(i)), &depth);
        QVERIFY2(p.x() >= mx && p.x() <= w - mx && p.y() >= my && p.y() <= h - my,
            qPrintable(QStringLiteral("corner %1 at %2, %3").arg(i).arg(p.x()).arg(p.y())));
        QVERIFY(depth > -1.0 && depth < 1.0); // between the near and far planes
        reach = std::max({reach, std::abs(p.x() - 0.5 * w) / (0.5 * w), std::abs(p.y() - 0.5 * h) / (0.5 * h)});
    }
    QVERIFY2(reach > 0.97 * (1.0 - Camera3D::fitMargin), qPrintable(QString::number(reach)));
    QVERIFY((c.target() - box.center()).norm() < 1e-9);
}

void TestCamera3D::panKeepsPointUnderCursor()
{
    QFETCH(Projection, projection);
    Camera3D c = camera(projection, View::Isometric, 640, 480);
    const Eigen::Vector2d cursor(500.0, 120.0);
    const Eigen::Vector3d point = c.pointAtTargetDepth(cursor);
    QVERIFY(std::abs(c.depth(point) - c.distance()) < 1e-9);
    c.pan(-37.0, 55.0, 480.0);
    QVERIFY((c.project(point) - cursor - Eigen::Vector2d(-37.0, 55.0)).norm() < 1e-6);
}

void TestCamera3D::zoomKeepsPointUnderCursor()
{
    QFETCH(Projection, projection);
    Camera3D c = camera(projection, View::Isometric, 640, 480);
    for (const double steps : {2.0, -3.0, 0.5}) {
        const Eigen::Vector2d cursor(90.0, 400.0);
        const Eigen::Vector3d point = c.pointAtTargetDepth(cursor);
        const double before = c.distance();
        c.zoom(steps, cursor);
        QVERIFY(std::abs(c.distance() - before * std::pow(Camera3D::zoomStep, -steps)) < 1e-9 * before);
        QVERIFY((c.project(point) - cursor).norm() < 1e-6);
    }
    // Without a cursor the target stays.
    const Eigen::Vector3d target = c.target();
    c.zoom(1.0);
    QCOMPARE(c.target(), target);
}

void TestCamera3D::rayRoundTrip()
{
    QFETCH(Projection, projection);
    Camera3D c = camera(projection, View::Isometric, 800, 500);
    for (const Eigen::Vector2d &pixel : {Eigen::Vector2d(0, 0), Eigen::Vector2d(400, 250), Eigen::Vector2d(799, 17)}) {
        const Camera3D::Ray r = c.ray(pixel);
        QVERIFY(std::abs(r.direction.norm() - 1.0) < 1e-12);
        for (const double s : {0.5 * c.distance(), c.distance(), 1.5 * c.distance()})
            QVERIFY((c.project(r.at(s)) - pixel).norm() < 1e-6);
    }
}

void TestCamera3D::meshCounts()
{
    Mesh3D mesh;
    mesh.appendSolid(Solid::box({0, 0, 0}, {100, 0, 0}, 10, 5, Eigen::Vector3d::UnitZ(), PartRole::Link));
    QCOMPARE(mesh.vertices().size(), std::size_t(24));
    QCOMPARE(mesh.triangleCount(), std::size_t(12));
    const int n = Mesh3D::cylinderSegments;
    mesh.clear();
    mesh.appendSolid(Solid::cylinder({0, 0, 0}, {0, 0, 30}, 8, PartRole::Joint));
    QCOMPARE(mesh.vertices().size(), std::size_t(4 * n + 2));
    QCOMPARE(mesh.triangleCount(), std::size_t(4 * n));
    mesh.clear();
    mesh.appendSolid(Solid::sphere({1, 2, 3}, 8, PartRole::Marker));
    const int slices = Mesh3D::sphereSlices, stacks = Mesh3D::sphereStacks;
    QCOMPARE(mesh.vertices().size(), std::size_t(slices * (stacks - 1) + 2));
    QCOMPARE(mesh.triangleCount(), std::size_t(2 * slices * (stacks - 1)));
    for (std::uint32_t index : mesh.indices())
        QVERIFY(index < mesh.vertices().size());
    // One mesh per scene: the sum of its solids.
    Scene3D scene;
    scene.solids = {Solid::box({0, 0, 0}, {1, 1, 1}, 1, 1, Eigen::Vector3d::UnitZ(), PartRole::Ground),
        Solid::sphere({0, 0, 0}, 1, PartRole::Joint)};
    QCOMPARE(Mesh3D::fromScene(scene).triangleCount(), std::size_t(12 + 2 * slices * (stacks - 1)));
}

void TestCamera3D::normalsAreUnitOutwardAndWound_data()
{
    QTest::addColumn<Solid>("solid");
    QTest::newRow("box along x") << Solid::box({0, 0, 0}, {100, 0, 0}, 12, 6, Eigen::Vector3d::UnitZ(), PartRole::Link);
    const Eigen::Vector3d slanted(0.2, 1, 0.3);
    QTest::newRow("oblique box") << Solid::box({-5, 3, 2}, {40, 70, -20}, 9, 14, slanted, PartRole::Actuator);
    QTest::newRow("box up its axis") << Solid::box({0, 0, 0}, {0, 0, 50}, 8, 8, {0, 0, 1}, PartRole::Slider);
    QTest::newRow("pin along z") << Solid::cylinder({10, 20, -15}, {10, 20, 15}, 7, PartRole::Joint);
    QTest::newRow("oblique screw") << Solid::cylinder({0, 0, 0}, {60, -30, 25}, 2.5, PartRole::Screw);
    QTest::newRow("sphere") << Solid::sphere({3, -4, 5}, 11, PartRole::Marker);
}

void TestCamera3D::normalsAreUnitOutwardAndWound()
{
    QFETCH(Solid, solid);
    Mesh3D mesh;
    mesh.appendSolid(solid);
    QVERIFY(!mesh.isEmpty());
    const Eigen::Vector3f centre = (0.5 * (solid.from + solid.to)).cast<float>();
    auto position = [&](std::uint32_t i) { return Eigen::Vector3f(mesh.vertices()[i].position.data()); };
    auto normal = [&](std::uint32_t i) { return Eigen::Vector3f(mesh.vertices()[i].normal.data()); };
    for (std::uint32_t i = 0; i < mesh.vertices().size(); ++i) {
        QVERIFY(std::abs(normal(i).norm() - 1.0f) < 1e-5f);
        QVERIFY(normal(i).dot(position(i) - centre) > 0.0f);
    }
    // Counter-clockwise from outside: each face's winding normal agrees with its normals.
    const auto &indices = mesh.indices();
    for (std::size_t t = 0; t < indices.size(); t += 3) {
        const Eigen::Vector3f a = position(indices[t]), b = position(indices[t + 1]), c = position(indices[t + 2]);
        const Eigen::Vector3f n = normal(indices[t]) + normal(indices[t + 1]) + normal(indices[t + 2]);
        QVERIFY((b - a).cross(c - a).dot(n) > 0.0f);
    }
}

void TestCamera3D::meshBoundsMatchSolids()
{
    QFETCH(Solid, solid);
    Mesh3D mesh;
    mesh.appendSolid(solid);
    const Eigen::AlignedBox3d expected = solidBounds(solid), actual = mesh.bounds();
    // Boxes exactly (in float); round shapes within the facets' sag r·(1 − cos(π/n)).
    const double sag = solid.shape == Solid::Shape::Box ? 0.0 : solid.radius * (1.0 - std::cos(pi / 16.0));
    const double tolerance = sag + 1e-4 * (1.0 + expected.diagonal().norm());
    QVERIFY(contains(expected, actual, 1e-4 * (1.0 + expected.diagonal().norm())));
    QVERIFY2((actual.min() - expected.min()).cwiseAbs().maxCoeff() <= tolerance
            && (actual.max() - expected.max()).cwiseAbs().maxCoeff() <= tolerance,
        qPrintable(QStringLiteral("sag %1").arg(sag)));
}

void TestCamera3D::degenerateSolidsAddNothing()
{
    Mesh3D mesh;
    mesh.appendSolid(Solid::box({1, 1, 1}, {1, 1, 1}, 5, 5, Eigen::Vector3d::UnitZ(), PartRole::Link));
    mesh.appendSolid(Solid::cylinder({0, 0, 0}, {0, 0, 10}, 0.0, PartRole::Joint));
    mesh.appendSolid(Solid::sphere({0, 0, 0}, -1.0, PartRole::Joint));
    mesh.appendSolid(Solid::sphere({std::nan(""), 0, 0}, 1.0, PartRole::Joint));
    QVERIFY(mesh.isEmpty());
    QVERIFY(mesh.bounds().isEmpty());
}

void TestCamera3D::roleColoursAreDistinct()
{
    const PartRole roles[]
        = {PartRole::Ground, PartRole::Guide, PartRole::Slider, PartRole::Link, PartRole::Rod, PartRole::Platform,
            PartRole::Joint, PartRole::Actuator, PartRole::Screw, PartRole::Compensation, PartRole::Marker};
    const QColor background = Renderer3D::backgroundColour();
    auto difference = [](const QColor &a, const QColor &b) {
        return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
    };
    for (std::size_t i = 0; i < std::size(roles); ++i) {
        const PartFinish finish = partFinish(roles[i]);
        QVERIFY(finish.specular >= 0.0f && finish.specular <= 1.0f);
        QVERIFY2(difference(finish.colour, background) >= 40, qPrintable(finish.colour.name()));
        for (std::size_t j = 0; j < i; ++j)
            QVERIFY2(difference(finish.colour, partFinish(roles[j]).colour) >= 40,
                qPrintable(finish.colour.name() + QStringLiteral(" ~ ") + partFinish(roles[j]).colour.name()));
    }
    // The vertices carry their role's colour.
    Mesh3D mesh;
    mesh.appendSolid(Solid::sphere({0, 0, 0}, 1, PartRole::Rod));
    const QColor rod = partFinish(PartRole::Rod).colour;
    QVERIFY(std::abs(mesh.vertices().front().colour[0] - float(rod.redF())) < 1e-6f);
    QVERIFY(std::abs(mesh.vertices().front().colour[3] - partFinish(PartRole::Rod).specular) < 1e-6f);
}

void TestCamera3D::groundGridLiesUnderTheExtent()
{
    const Eigen::AlignedBox3d extent(Eigen::Vector3d(-150, -80, -40), Eigen::Vector3d(260, 200, 40));
    const GroundGrid grid = groundGrid(extent);
    QVERIFY(grid.y < extent.min().y() && grid.y > extent.min().y() - 2.0);
    QVERIFY(grid.vertices.size() % 2 == 0 && grid.vertices.size() >= 20 && grid.vertices.size() <= 200);
    const double mantissa = grid.spacing / std::pow(10.0, std::floor(std::log10(grid.spacing)));
    QVERIFY2(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9,
        qPrintable(QString::number(grid.spacing)));
    QVERIFY(
        grid.bounds.min().x() <= extent.min().x() - 0.2 * 410 && grid.bounds.max().x() >= extent.max().x() + 0.2 * 410);
    QVERIFY(
        grid.bounds.min().z() <= extent.min().z() - 0.2 * 410 && grid.bounds.max().z() >= extent.max().z() + 0.2 * 410);
    for (const LineVertex &v : grid.vertices) {
        QCOMPARE(v.position[1], float(grid.y));
        QVERIFY(std::abs(std::remainder(double(v.position[0]), grid.spacing)) < 1e-3
            || std::abs(std::remainder(double(v.position[2]), grid.spacing)) < 1e-3);
    }
    QVERIFY(!groundGrid(Eigen::AlignedBox3d()).vertices.empty()); // a default grid about the origin
}

void TestCamera3D::extrudeHandScene()
{
    const double t = 10.0;
    const Scene scene = handScene();
    const Scene3D model = extrudeScene(scene, t);
    // Links: 4 bars, each a box and two eyes (the rod in the rod's role).
    QCOMPARE(withRole(model, PartRole::Link).size(), std::size_t(9));
    QCOMPARE(withRole(model, PartRole::Rod).size(), std::size_t(3));
    // Pins at O, A, B, S (not the ball C, not the marker); the ball is a sphere.
    std::size_t pins = 0, balls = 0;
    for (const Solid *s : withRole(model, PartRole::Joint))
        (s->shape == Solid::Shape::Cylinder ? pins : balls) += 1;
    QCOMPARE(balls, std::size_t(1));
    QVERIFY(pins >= 4);
    QCOMPARE(withRole(model, PartRole::Marker).size(), std::size_t(1));
    QCOMPARE(withRole(model, PartRole::Guide).size(), std::size_t(1));
    // The ground pivot's support (upright and foot) and the guide's two end stops.
    QCOMPARE(withRole(model, PartRole::Ground).size(), std::size_t(4));

    // Links that share a pin lie in different layers, and the pin carries both.
    const Solid *crank = withRole(model, PartRole::Link)[0];
    const Solid *coupler = withRole(model, PartRole::Link)[3];
    QVERIFY(std::abs(crank->from.z() - coupler->from.z()) >= 0.5 * t);
    QCOMPARE(crank->section, Eigen::Vector2d(t, 0.5 * t));
    QCOMPARE(crank->up, Eigen::Vector3d::UnitZ());
    bool pinAtA = false;
    for (const Solid *s : withRole(model, PartRole::Joint)) {
        if (s->shape != Solid::Shape::Cylinder || (s->from.head<2>() - Eigen::Vector2d(0, 100)).norm() > 1e-9)
            continue;
        pinAtA = true;
        QVERIFY(std::abs(s->radius - 0.45 * t) < 1e-12);
        const double low = std::min(s->from.z(), s->to.z()), high = std::max(s->from.z(), s->to.z());
        for (const Solid *link : {crank, coupler})
            QVERIFY(low < link->from.z() - 0.25 * t && high > link->from.z() + 0.25 * t);
    }
    QVERIFY(pinAtA);
    // The slider's carriage sits on S behind the plane, along the guide.
    const auto sliders = withRole(model, PartRole::Slider);
    QCOMPARE(sliders.size(), std::size_t(1));
    const Solid &carriage = *sliders[0];
    QVERIFY((0.5 * (carriage.from + carriage.to)).head<2>().isApprox(Eigen::Vector2d(150, 0)));
    QVERIFY(std::abs((carriage.to - carriage.from).normalized().dot(Eigen::Vector3d::UnitX())) > 1.0 - 1e-12);
    QVERIFY(carriage.from.z() < 0.0);
    const Solid &rail = *withRole(model, PartRole::Guide)[0];
    QVERIFY(rail.from.z() < carriage.from.z());
    QCOMPARE(rail.section.x(), 16.0);

    // The motor body at O along O→B; the screw from it to B.
    const auto motors = withRole(model, PartRole::Actuator);
    QCOMPARE(motors.size(), std::size_t(1));
    const Eigen::Vector2d ob = Eigen::Vector2d(100, 100).normalized();
    QVERIFY(motors[0]->from.head<2>().isZero(1e-12));
    QVERIFY(motors[0]->to.head<2>().isApprox(60.0 * ob));
    QCOMPARE(motors[0]->section, Eigen::Vector2d(24, 24));
    bool screwReachesB = false;
    for (const Solid *s : withRole(model, PartRole::Screw))
        screwReachesB = screwReachesB || (s->to.head<2>() - Eigen::Vector2d(100, 100)).norm() < 1e-9;
    QVERIFY(screwReachesB);
    QVERIFY(motors[0]->from.z() > crank->from.z() + 0.5 * t); // in front of the links

    // The extent: the 2D one thickened by at least 2t in z, holding every solid's depth and
    // every fixed part.
    QVERIFY(contains(model.extent, scene.extent));
    QVERIFY(model.extent.min().z() <= -2.0 * t && model.extent.max().z() >= 2.0 * t);
    for (const Solid &s : model.solids) {
        const Eigen::AlignedBox3d b = solidBounds(s);
        QVERIFY(b.min().z() >= model.extent.min().z() - 1e-9 && b.max().z() <= model.extent.max().z() + 1e-9);
        if (s.role == PartRole::Ground || s.role == PartRole::Guide)
            QVERIFY(contains(model.extent, b));
    }
    QVERIFY(extrudeScene(Scene {}, t).solids.empty());
}

void TestCamera3D::extrudedMechanismsStayInTheirExtent()
{
    QFETCH(QString, kind);
    const Result<MechanismPtr> created = createMechanism(kind.toStdString(), {});
    QVERIFY(created.ok());
    const MechanismPtr mechanism = *created;
    const Pose home = mechanism->homePose();
    const Scene3D first = mechanism->scene3d(home);
    QVERIFY(first.solids.size() >= 10);
    const Interval range = mechanism->variableRange(0);
    std::string outside; // the first solid out of its model's extent
    for (int i = 0; i <= 8; ++i) {
        const Result<Pose> pose = mechanism->solveWith(home, 0, range.min + (range.max - range.min) * i / 8.0);
        if (!pose.ok())
            continue;
        const Scene3D model = mechanism->scene3d(*pose);
        QVERIFY(model.extent.isApprox(first.extent)); // fitting does not jump with the pose
        for (const Solid &s : model.solids)
            if (outside.empty() && !contains(model.extent, solidBounds(s), 1e-6))
                outside = s.label;
    }
    QVERIFY2(outside.empty(), outside.c_str());
}

QTEST_MAIN(TestCamera3D)
#include "tst_camera3d.moc"
