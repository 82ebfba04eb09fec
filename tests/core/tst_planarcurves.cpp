// The singular curves of the planar parallel mechanism (ppcurves.cpp): every point of a
// returned curve is a singular pose of the design's modes (det J_q = 0 on the inverse curves,
// det J_x = 0 on the direct ones, relative to the regular poses' scale), and the leg
// versions of the five-bar example and of MOMA 3a have the curves of those kinds.
#include "kinds/planarparallel/planarparallel.h"
#include "registry.h"
#include "support/kinematics.h"
#include "support/planardesigns.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace pkm;
using namespace pkm::test;

Q_DECLARE_METATYPE(pkm::ParameterSet)

namespace {
constexpr double deg = units::degree;
constexpr double pi = std::numbers::pi;

std::shared_ptr<const PlanarParallel> build(const ParameterSet &parameters)
{
    return std::dynamic_pointer_cast<const PlanarParallel>(makeKind("planar-parallel", parameters));
}

using pkm::test::legdesigns::fiveR;
using pkm::test::legdesigns::moma3a;

/// resources/presets/pp-3rrr.pkm.json, its map at φ = `phi`.
ParameterSet threeRrr(double phi)
{
    ParameterSet rrr{{"platform", 2}, {"assembly", 1}, {"phi_map", phi}};
    const double ax[3] = {0, 400, 200}, ay[3] = {0, 0, 346.410162}, bx[3] = {-43.30127, 43.30127, 0}, by[3] = {-25, -25, 50};
    for (int i = 0; i < 3; ++i) {
        const std::string k = std::to_string(i + 1);
        for (const auto &[name, value] : std::initializer_list<std::pair<std::string, double>>{
                 {"leg" + k + "_type", 0}, {"A" + k + "x", ax[i]}, {"A" + k + "y", ay[i]}, {"B" + k + "x", bx[i]},
                 {"B" + k + "y", by[i]}, {"r" + k, 120}, {"l" + k, 150}, {"theta" + k + "_min", -pi},
                 {"theta" + k + "_max", pi}, {"working" + k, 1}})
            rrr[name] = value;
    }
    return rrr;
}

double segmentDistance(const Eigen::Vector2d &p, const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    const Eigen::Vector2d ab = b - a;
    const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

/// The distance from p to the nearest curve of `type`.
double distanceTo(const std::vector<SingularCurve> &curves, SingularCurve::Type type, const Eigen::Vector2d &p)
{
    double best = std::numeric_limits<double>::infinity();
    for (const SingularCurve &c : curves) {
        if (c.type != type)
            continue;
        for (std::size_t k = 1; k < c.points.size(); ++k)
            best = std::min(best, segmentDistance(p, c.points[k - 1], c.points[k]));
    }
    return best;
}

/// Every point of `a`'s curves lies on a curve of the same type of `b` (up to `tolerance`
/// mm, the chord of one sample), and the other way round.
void sameCurves(const std::vector<SingularCurve> &a, const std::vector<SingularCurve> &b, double tolerance)
{
    int total = 0;
    for (const auto type : {SingularCurve::Type::Inverse, SingularCurve::Type::Direct}) {
        std::array<int, 2> counts{};
        for (const auto *from : {&a, &b}) {
            const auto *to = from == &a ? &b : &a;
            int points = 0;
            for (const SingularCurve &c : *from) {
                if (c.type != type)
                    continue;
                for (const Eigen::Vector2d &p : c.points) {
                    QVERIFY2(distanceTo(*to, type, p) < tolerance,
                             qPrintable(QString("(%1, %2) is %3 mm off").arg(p.x()).arg(p.y()).arg(distanceTo(*to, type, p))));
                    ++points;
                }
            }
            counts[from == &a ? 0 : 1] = points;
        }
        // the same curves: both have them or neither
        QCOMPARE(counts[0] > 0, counts[1] > 0);
        total += counts[0];
    }
    QVERIFY(total > 100);
}

/// Every point of every curve is a pose of the design, singular of the curve's class: on an
/// inverse curve det J_q vanishes, on a direct one det J_x, relative to the product of the
/// rows' norms (the scale-free margins).
void curvesAreSingular(const PlanarParallel &m, int &checked)
{
    const int n = m.design().legCount();
    for (const SingularCurve &c : m.singularCurves()) {
        for (const Eigen::Vector2d &p : c.points) {
            Coordinates x(n);
            x[0] = p.x();
            x[1] = p.y();
            if (n == 3)
                x[2] = m.design().mapPhi;
            const auto pose = m.solveInverse(x);
            QVERIFY2(pose, pose ? "" : pose.failure().message.c_str());
            const Jacobians j = m.jacobians(*pose);
            if (c.type == SingularCurve::Type::Inverse) {
                // a leg's J_q entry −e·∂C/∂q against |e|·|∂C/∂q| (planar::inverseMargin)
                const Eigen::Vector3d X = m.platformPose(pose->outputs);
                double smallest = 1.0;
                for (int i = 0; i < n; ++i) {
                    const PlanarLeg &leg = m.design().legs[std::size_t(i)];
                    smallest = std::min(smallest, planar::inverseMargin(leg, pose->inputs[i], planar::platformPoint(leg, X)));
                }
                QVERIFY2(smallest < 1e-6, qPrintable(QString("(%1, %2): %3").arg(p.x()).arg(p.y()).arg(smallest)));
                QVERIFY(m.singularity(*pose).type != SingularityType::None);
            } else {
                const Eigen::MatrixXd &jx = j.outputs;
                double rows = 1.0;
                for (int i = 0; i < n; ++i)
                    rows *= jx.row(i).norm();
                QVERIFY2(std::abs(jx.determinant()) < 1e-6 * rows, qPrintable(QString("(%1, %2): %3").arg(p.x()).arg(p.y()).arg(std::abs(jx.determinant()) / rows)));
            }
            ++checked;
        }
    }
}
} // namespace

class TestPlanarCurves : public QObject
{
    Q_OBJECT

private slots:
    void fiveBarCurves()
    {
        const auto pp = build(fiveR());
        const MechanismPtr fb = makeKind("fivebar");
        sameCurves(pp->singularCurves(), fb->planarWorkspace()->singularCurves(), 1.5);
    }

    void momaCurves()
    {
        const auto pp = build(moma3a());
        const MechanismPtr moma = makeKind("moma");
        sameCurves(pp->singularCurves(), moma->planarWorkspace()->singularCurves(), 1.5);
    }

    /// Every leg type in 2-DOF designs, and a 3-RRR at its map's φ.
    void pointsAreSingular_data()
    {
        QTest::addColumn<ParameterSet>("design");
        QTest::newRow("5R") << fiveR();
        QTest::newRow("2-PRR") << moma3a();
        QTest::newRow("5R П-joints") << pkm::test::legdesigns::fiveRPjoint();
        // a crank and a slider, a strut and a crank
        QTest::newRow("RRR + PRR") << pkm::test::legdesigns::crankAndSlider();
        QTest::newRow("RPR + RRR") << pkm::test::legdesigns::strutAndCrank();
        QTest::newRow("3-RRR") << threeRrr(10 * deg);
        // resources/presets/pp-3rpr.pkm.json: the 3-RPR of Innocenti and Parenti-Castelli, whose
        // slice at φ = 0 has direct curves inside it and no inverse ones
        const double d1 = 17.04, d2 = 16.54, d3 = 20.84;
        const double bx = (d3 * d3 - d2 * d2 + d1 * d1) / (2 * d1), by = std::sqrt(d3 * d3 - bx * bx);
        QTest::newRow("3-RPR") << ParameterSet{{"platform", 2}, {"leg1_type", 2}, {"leg2_type", 2}, {"leg3_type", 2}, {"A1x", 0},
                                               {"A1y", 0}, {"A2x", 15.91}, {"A2y", 0}, {"A3x", 0}, {"A3y", 10}, {"B1x", 0},
                                               {"B1y", 0}, {"B2x", d1}, {"B2y", 0}, {"B3x", bx}, {"B3y", by}, {"q1_min", 5},
                                               {"q1_max", 30}, {"q2_min", 5}, {"q2_max", 30}, {"q3_min", 5}, {"q3_max", 30},
                                               {"assembly", 1}};
    }
    void pointsAreSingular()
    {
        QFETCH(ParameterSet, design);
        const auto pp = build(design);
        QVERIFY(pp);
        int checked = 0;
        curvesAreSingular(*pp, checked);
        QVERIFY2(checked > 20, qPrintable(QString::number(checked)));
        if (pp->design().legCount() == 3 && pp->design().legs[0].type == LegType::RPR) {
            const auto curves = pp->singularCurves();
            QVERIFY(std::any_of(curves.begin(), curves.end(), [](const SingularCurve &c) { return c.type == SingularCurve::Type::Direct; }));
        }
    }

    /// The constant-orientation workspace of a 3-DOF platform at φ = phi_map is the set where
    /// the inverse kinematics at that φ succeeds, cell by cell.
    void constantOrientationSlice()
    {
        for (const double phi : {0.0, 10 * deg, -25 * deg}) {
            const auto pp = build(threeRrr(phi));
            QVERIFY(pp);
            const MapGrid grid = squareGrid(pp->workspaceBounds(), 60);
            std::vector<float> values(grid.cells());
            computeMap(*pp, MapQuantity::Determinant, grid, values);
            int reached = 0;
            for (int r = 0; r < grid.rows; ++r) {
                for (int c = 0; c < grid.columns; ++c) {
                    Coordinates x(3);
                    x << grid.x(c), grid.y(r), phi;
                    const bool solves = bool(pp->solveInverse(x));
                    QCOMPARE(!std::isnan(values[std::size_t(r) * std::size_t(grid.columns) + std::size_t(c)]), solves);
                    reached += solves;
                }
            }
            QVERIFY(reached > 100);
        }
    }

    /// The orientation range map: at each reachable cell the platform can be held at the
    /// middle of every interval found and at φ sampled inside them, and not at φ sampled
    /// outside them; the map's value is the intervals' total width. Platforms that do not turn
    /// do not offer it.
    void orientationRange()
    {
        const auto pp = build(threeRrr(0.0));
        QVERIFY(pp->offers(MapQuantity::OrientationRange));
        QVERIFY(!build(fiveR())->offers(MapQuantity::OrientationRange));
        QVERIFY(!makeKind("moma")->planarWorkspace()->offers(MapQuantity::OrientationRange));
        const MapGrid grid = squareGrid(pp->workspaceBounds(), 24);
        std::vector<float> values(grid.cells());
        computeMap(*pp, MapQuantity::OrientationRange, grid, values);
        int inside = 0, outside = 0, partial = 0;
        for (int r = 0; r < grid.rows; ++r) {
            for (int c = 0; c < grid.columns; ++c) {
                std::array<Interval, 8> found;
                const Eigen::Vector2d xy(grid.x(c), grid.y(r));
                const int count = pp->orientationIntervals(xy, found);
                const float value = values[std::size_t(r) * std::size_t(grid.columns) + std::size_t(c)];
                QCOMPARE(std::isnan(value), count == 0);
                double width = 0.0;
                for (int k = 0; k < count; ++k)
                    width += found[std::size_t(k)].max - found[std::size_t(k)].min;
                if (count > 0)
                    QVERIFY(std::abs(double(value) - width) < 1e-5);
                if (count > 0 && width < 2 * pi - 1e-9)
                    ++partial;
                for (int s = 0; s < 90; ++s) {
                    const double phi = -pi + (s + 0.5) * 2 * pi / 90;
                    bool in = false, near = false;
                    for (int k = 0; k < count; ++k) {
                        const Interval &f = found[std::size_t(k)];
                        for (const double turn : {0.0, 2 * pi}) {
                            in = in || f.contains(phi + turn);
                            near = near || std::abs(phi + turn - f.min) < 1e-4 || std::abs(phi + turn - f.max) < 1e-4;
                        }
                    }
                    if (near)
                        continue;
                    Coordinates x(3);
                    x << xy.x(), xy.y(), phi;
                    QCOMPARE(bool(pp->solveInverse(x)), in);
                    ++(in ? inside : outside);
                }
            }
        }
        QVERIFY(inside > 1000);
        QVERIFY(outside > 1000);
        QVERIFY(partial > 20);
    }
};

QTEST_MAIN(TestPlanarCurves)
#include "tst_planarcurves.moc"
