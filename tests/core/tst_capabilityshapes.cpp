// The velocity and force shapes drawn at the platform point (core/capabilityshapes.h): each
// polygon is exactly the actuators' polytope (every vertex on its boundary, its inscribed
// radius and farthest vertex the capability group's worst and best values), each ellipse lies
// inside its polygon and touches it, singular poses open or flatten the right shape, and the
// scene carries the shapes at the platform point with a legend in 1/2/5 steps.
#include "capabilityshapes.h"
#include "support/kinematics.h"
#include "support/planardesigns.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace pkm;
using namespace pkm::test;

namespace {

using capability::Actuators;
using capability::Matrix;

struct Case {
    MechanismPtr mechanism;
    Pose pose;
    Actuators actuators;
    Matrix jq, jx;
    SingularityType type = SingularityType::None;
    std::vector<double> values; ///< the capability group
};

Case prepare(MechanismPtr mechanism, const Coordinates *outputs = nullptr)
{
    Case c;
    c.mechanism = std::move(mechanism);
    c.pose = c.mechanism->homePose();
    if (outputs)
        c.pose = *c.mechanism->solveInverse(*outputs, &c.pose);
    c.actuators = capability::actuatorsOf(*c.mechanism);
    Singularity s;
    evaluated(*c.mechanism, c.pose, &s);
    c.type = s.type;
    const Jacobians j = c.mechanism->jacobians(c.pose);
    const int n = c.actuators.count;
    c.jq.resize(n, n);
    c.jx.resize(n, n);
    for (int r = 0; r < n; ++r) {
        for (int k = 0; k < n; ++k) {
            c.jq(r, k) = j.inputs(c.actuators.inputs[std::size_t(r)], c.actuators.inputs[std::size_t(k)]);
            c.jx(r, k) = j.outputs(c.actuators.inputs[std::size_t(r)], k);
        }
    }
    c.values.assign(std::size_t(capability::layoutFor(c.actuators)->size), 0.0);
    capability::evaluate(c.actuators, c.jq, c.jx, c.type, c.values);
    return c;
}

double value(const Case &c, const char *name)
{
    return c.values[std::size_t(capability::layoutFor(c.actuators)->find(name)->offset)];
}

/// The slabs of one quantity: normals (rows, over x and y) and limits, in the units the
/// shapes use (N·mm for a rotary actuator's torque).
struct Slabs {
    Eigen::MatrixXd normals;
    Eigen::VectorXd limits;
    /// max_i |a_i·v| / b_i: 1 on the polygon's boundary, below 1 inside.
    double load(const Eigen::Vector2d &v) const
    {
        double worst = 0.0;
        for (int i = 0; i < normals.rows(); ++i)
            worst = std::max(worst, std::abs(normals.row(i).dot(v)) / limits[i]);
        return worst;
    }
};

Slabs velocitySlabs(const Case &c)
{
    const Eigen::MatrixXd J = Eigen::MatrixXd(c.jq).partialPivLu().solve(Eigen::MatrixXd(c.jx));
    Slabs s{J.leftCols(2), Eigen::VectorXd(c.actuators.count)};
    for (int i = 0; i < c.actuators.count; ++i)
        s.limits[i] = c.actuators.items[std::size_t(i)].speed;
    return s;
}

Slabs forceSlabs(const Case &c)
{
    const Eigen::MatrixXd G = Eigen::MatrixXd(c.jx).partialPivLu().solve(Eigen::MatrixXd(c.jq));
    Slabs s{G.topRows(2).transpose(), Eigen::VectorXd(c.actuators.count)};
    for (int i = 0; i < c.actuators.count; ++i) {
        const capability::Actuator &a = c.actuators.items[std::size_t(i)];
        s.limits[i] = a.force * (a.rotary ? 1e3 : 1.0);
    }
    return s;
}

/// The distance from the origin to the nearest edge of a convex polygon around it.
double inscribed(const std::vector<Eigen::Vector2d> &polygon)
{
    double r = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Eigen::Vector2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        const Eigen::Vector2d edge = b - a;
        r = std::min(r, std::abs(a.x() * edge.y() - a.y() * edge.x()) / edge.norm());
    }
    return r;
}

double farthest(const std::vector<Eigen::Vector2d> &polygon)
{
    double r = 0.0;
    for (const Eigen::Vector2d &p : polygon)
        r = std::max(r, p.norm());
    return r;
}

double area(const std::vector<Eigen::Vector2d> &polygon)
{
    double twice = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Eigen::Vector2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        twice += a.x() * b.y() - a.y() * b.x();
    }
    return 0.5 * twice;
}

constexpr double huge = 1e9;

} // namespace

class TestCapabilityShapes : public QObject
{
    Q_OBJECT

private:
    static void addCases()
    {
        QTest::addColumn<int>("which");
        QTest::addRow("fivebar") << 0;
        QTest::addRow("moma") << 1;
        QTest::addRow("oxglide") << 2;
        QTest::addRow("planar-parallel 5R") << 3;
        QTest::addRow("planar-parallel 3-PRR") << 4;
        QTest::addRow("planar-parallel 3-PRR turned") << 5;
    }

    static Case currentCase()
    {
        QFETCH(int, which);
        const char *kinds[] = {"fivebar", "moma", "oxglide"};
        if (which < 3)
            return prepare(makeKind(kinds[which]));
        if (which == 3)
            return prepare(makeKind("planar-parallel", legdesigns::fiveR()));
        const Coordinates turned = triple(12.0, -8.0, 10.0 * units::degree);
        return prepare(makeKind("planar-parallel", legdesigns::threePrr()), which == 5 ? &turned : nullptr);
    }

private slots:
    void polygonsAreThePolytopes_data() { addCases(); }
    void polygonsAreThePolytopes()
    {
        const Case c = currentCase();
        QVERIFY(c.actuators.count >= 2);
        QCOMPARE(c.type, SingularityType::None);
        const capability::Shapes shapes = capability::shapesOf(c.actuators, c.jq, c.jx, c.type, huge, huge);
        const auto check = [&](const capability::Shape &shape, const Slabs &slabs, const char *worst, const char *best) {
            QVERIFY(!shape.unbounded);
            QVERIFY(shape.polygon.size() >= 4);
            QVERIFY(area(shape.polygon) > 0.0); // counter-clockwise
            for (const Eigen::Vector2d &v : shape.polygon) // every vertex on the boundary
                QVERIFY2(std::abs(slabs.load(v) - 1.0) < 1e-9, qPrintable(QString::number(slabs.load(v) - 1.0, 'g', 17)));
            QVERIFY(std::abs(inscribed(shape.polygon) / value(c, worst) - 1.0) < 1e-9);
            QVERIFY(std::abs(farthest(shape.polygon) / value(c, best) - 1.0) < 1e-9);
        };
        check(shapes.velocity, velocitySlabs(c), "speed_worst", "speed_best");
        check(shapes.force, forceSlabs(c), "force_worst", "force_best");
    }

    void ellipsesAreInscribed_data() { addCases(); }
    void ellipsesAreInscribed()
    {
        const Case c = currentCase();
        const capability::Shapes shapes = capability::shapesOf(c.actuators, c.jq, c.jx, c.type, huge, huge);
        for (const auto &[shape, slabs] : {std::pair{&shapes.velocity, velocitySlabs(c)}, std::pair{&shapes.force, forceSlabs(c)}}) {
            QVERIFY(shape->ellipse.size() >= 32);
            double most = 0.0;
            for (const Eigen::Vector2d &v : shape->ellipse) {
                QVERIFY(slabs.load(v) <= 1.0 + 1e-9); // inside every slab
                most = std::max(most, slabs.load(v));
            }
            // two actuators: the ellipse touches every edge (at its middle); three: the polygon
            // lies within √3 × the ellipse, since Σ of three terms ≤ 1 is implied by each ≤ 1/3
            if (c.actuators.count == 2) {
                QVERIFY2(most > 0.99, qPrintable(QString::number(most)));
            } else {
                for (const Eigen::Vector2d &v : shape->polygon) {
                    double sum = 0.0;
                    for (int i = 0; i < slabs.normals.rows(); ++i)
                        sum += std::pow(slabs.normals.row(i).dot(v) / slabs.limits[i], 2);
                    QVERIFY(sum <= 3.0 + 1e-9);
                }
                QVERIFY(most > 0.5);
            }
        }
    }

    void singularPosesOpenOrFlattenTheShapes()
    {
        // as in tst_capability: leg 2 stretched (inverse) — the platform cannot move along it,
        // and holds any force there; a direct singularity — the reverse
        Actuators a;
        a.count = a.outputs = 2;
        a.inputs = {0, 1, 2};
        for (int i = 0; i < 2; ++i)
            a.items[std::size_t(i)] = {100.0, 50.0, 0.01, 1e4, false};
        Matrix jq(2, 2), jx(2, 2);
        jx << 1.0, 0.3, -0.2, 1.0;
        jq << 1.0, 0.0, 0.0, 0.0;
        capability::Shapes s = capability::shapesOf(a, jq, jx, SingularityType::Inverse, 1e4, 1e4);
        QVERIFY(s.force.unbounded);
        QVERIFY(!s.velocity.unbounded);
        QVERIFY(std::abs(area(s.velocity.polygon)) < 1e-9 * farthest(s.velocity.polygon) * farthest(s.velocity.polygon));
        QVERIFY(farthest(s.velocity.polygon) > 0.0);

        jq << 1.0, 0.0, 0.0, 1.0;
        jx << 1.0, 2.0, 0.5, 1.0;
        s = capability::shapesOf(a, jq, jx, SingularityType::Direct, 1e4, 1e4);
        QVERIFY(s.velocity.unbounded);
        QVERIFY(!s.force.unbounded);
        QVERIFY(std::abs(area(s.force.polygon)) < 1e-9 * farthest(s.force.polygon) * farthest(s.force.polygon));
        for (const auto *shape : {&s.velocity, &s.force}) {
            for (const Eigen::Vector2d &p : shape->polygon)
                QVERIFY(p.allFinite() && p.cwiseAbs().maxCoeff() <= 1e4 * (1.0 + 1e-9)); // cut by the clip box
            for (const Eigen::Vector2d &p : shape->ellipse)
                QVERIFY(p.allFinite() && p.cwiseAbs().maxCoeff() <= 1e4 * (1.0 + 1e-9));
        }
    }

    void sceneCarriesTheShapesAtThePlatformPoint()
    {
        const MechanismPtr moma = makeKind("moma");
        const Actuators actuators = capability::actuatorsOf(*moma);
        const capability::ShapeScales scales = capability::scalesFor(*moma, actuators);
        QVERIFY(scales.valid());
        // the legend's numbers are 1, 2 or 5 × 10ⁿ
        for (double units : {scales.velocityUnits, scales.forceUnits}) {
            const double mantissa = units / std::pow(10.0, std::floor(std::log10(units)));
            QVERIFY2(std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 || std::abs(mantissa - 5.0) < 1e-9,
                     qPrintable(QString::number(units)));
        }
        Pose pose = moma->homePose();
        for (const Coordinates &at : {Coordinates(pose.outputs), pair(pose.outputs[0] + 15.0, pose.outputs[1] - 10.0)}) {
            pose = *moma->solveInverse(at, &pose);
            Scene scene = moma->scene(pose);
            const std::size_t before = scene.polylines.size();
            capability::addShapes(scene, *moma, actuators, scales, pose, SingularityType::None);
            QCOMPARE(scene.polylines.size(), before + 4);
            QCOMPARE(scene.legend.size(), std::size_t(2));
            for (std::size_t i = before; i < scene.polylines.size(); ++i) {
                Eigen::AlignedBox2d box;
                for (const Eigen::Vector3d &p : scene.polylines[i].points)
                    box.extend(Eigen::Vector2d(p.head<2>()));
                // the shapes are symmetric about the platform point
                QVERIFY((box.center() - at.head<2>()).norm() < 1e-6 * box.sizes().norm());
            }
            QVERIFY(QString::fromStdString(scene.legend[0].text).contains(QStringLiteral("mm/s")));
        }
        // an output that is an angle has no platform point: nothing is drawn
        const MechanismPtr pjoint = makeKind("pjoint");
        QVERIFY(!capability::scalesFor(*pjoint, capability::actuatorsOf(*pjoint)).valid());
    }
};

QTEST_APPLESS_MAIN(TestCapabilityShapes)
#include "tst_capabilityshapes.moc"
