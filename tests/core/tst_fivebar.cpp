// The planar five-bar linkage (docs/mathematics.md) against constructions made again here: elbows and
// the output point by the law of cosines, round trips over the example and random designs in
// all eight mode combinations, the Jacobians against central finite differences, singular
// poses built by hand, the mode policy (no silent switch, refusals that name the mode), the
// maps against the pose solver, the kinematic chain and its mobility, failures that name
// their culprit, dragging, the drawing and the preset.
#include "kinds/fivebar/fivebar.h"
#include "registry.h"
#include "support/kinematics.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace pkm;
using namespace pkm::test;

Q_DECLARE_METATYPE(pkm::ParameterSet)
Q_DECLARE_METATYPE(pkm::FiveBarDesign)

namespace {
constexpr double pi = std::numbers::pi;
constexpr double deg = units::degree;
constexpr double notANumber = std::numeric_limits<double>::quiet_NaN();

/// The example design (AE = 100, AB = DE = 80, BC = CD = 120 mm) in mode combination `modes`:
/// bit 0 working1 = left, bit 1 working2 = left, bit 2 assembly = left.
FiveBarDesign withModes(FiveBarDesign d, int modes)
{
    d.working = {modes & 1 ? 1 : -1, modes & 2 ? 1 : -1};
    d.assembly = modes & 4 ? 1 : -1;
    return d;
}

QByteArray modesText(int modes)
{
    return QByteArray("w1 ") + (modes & 1 ? "L" : "R") + " w2 " + (modes & 2 ? "L" : "R") + " σ "
        + (modes & 4 ? "L" : "R");
}

Eigen::Vector2d pointOf(const Pose &pose)
{
    return pose.outputs.head<2>();
}

double crossOf(const Eigen::Vector2d &u, const Eigen::Vector2d &v)
{
    return u.x() * v.y() - u.y() * v.x();
}

Eigen::Vector2d rotated(const Eigen::Vector2d &v, double angle)
{
    return Eigen::Rotation2Dd(angle) * v;
}

double scaleOf(const FiveBarDesign &d)
{
    return std::max({d.ground, d.crank[0], d.crank[1], d.link[0], d.link[1]});
}

/// Random lengths (some designs have limited crank ranges); modes left to the caller.
FiveBarDesign randomDesign(std::mt19937 &generator)
{
    FiveBarDesign d;
    d.ground = uniform(generator, 20, 200);
    d.crank = {uniform(generator, 30, 150), uniform(generator, 30, 150)};
    d.link = {uniform(generator, 40, 200), uniform(generator, 40, 200)};
    if (generator() % 3 == 0) {
        for (Interval &r : d.range) {
            r.min = uniform(generator, -pi, pi);
            r.max = r.min + uniform(generator, 60 * deg, 330 * deg);
        }
    }
    return d;
}

/// The test's own elbow for C: the angle at G between G→C and G→P from the law of cosines,
/// turned towards side w. False when the leg cannot reach C.
bool constructElbow(const FiveBarDesign &d, int leg, const Eigen::Vector2d &C, Eigen::Vector2d &P)
{
    const Eigen::Vector2d G(leg == 0 ? 0.0 : d.ground, 0.0);
    const double a = d.crank[leg], b = d.link[leg], r = (C - G).norm();
    const double cosine = (a * a + r * r - b * b) / (2 * a * r);
    if (std::abs(cosine) > 1 + 1e-12)
        return false;
    P = G + a * rotated((C - G) / r, d.working[leg] * std::acos(std::clamp(cosine, -1.0, 1.0)));
    return true;
}

/// The test's own C for crank angles: the angle at B between B→D and B→C from the law of
/// cosines, turned towards side σ.
bool constructC(const FiveBarDesign &d, double theta1, double theta4, Eigen::Vector2d &C)
{
    const Eigen::Vector2d B = d.crank[0] * Eigen::Vector2d(std::cos(theta1), std::sin(theta1));
    const Eigen::Vector2d D
        = Eigen::Vector2d(d.ground, 0) + d.crank[1] * Eigen::Vector2d(std::cos(theta4), std::sin(theta4));
    const double e = (D - B).norm(), b1 = d.link[0], b2 = d.link[1];
    const double cosine = (b1 * b1 + e * e - b2 * b2) / (2 * b1 * e);
    if (std::abs(cosine) > 1 + 1e-12)
        return false;
    C = B + b1 * rotated((D - B) / e, d.assembly * std::acos(std::clamp(cosine, -1.0, 1.0)));
    return true;
}

/// The pose's modes and limits, each checked on its own: |C − P_i| = b_i, the elbows on
/// their sides, C on its side of B→D, the cranks in range. Empty when all hold.
QByteArray violation(const FiveBarDesign &d, const Pose &pose, double tolerance)
{
    const Eigen::Vector2d C = pointOf(pose);
    std::array<Eigen::Vector2d, 2> P;
    for (int leg = 0; leg < 2; ++leg) {
        const Eigen::Vector2d G(leg == 0 ? 0.0 : d.ground, 0.0);
        P[leg] = G + d.crank[leg] * Eigen::Vector2d(std::cos(pose.inputs[leg]), std::sin(pose.inputs[leg]));
        if (std::abs((C - P[leg]).norm() - d.link[leg]) > tolerance * d.link[leg])
            return "loop open at leg " + QByteArray::number(leg + 1);
        if (d.working[leg] * crossOf(C - G, P[leg] - G) < -tolerance * d.crank[leg] * d.link[leg])
            return "leg " + QByteArray::number(leg + 1) + " in the other working mode";
        if (!d.range[leg].contains(pose.inputs[leg], 1e-12))
            return "crank " + QByteArray::number(leg + 1) + " out of range";
    }
    if (d.assembly * crossOf(P[1] - P[0], C - P[0]) < -tolerance * d.link[0] * d.link[1])
        return "other assembly mode";
    return {};
}

/// Round-trip tolerance (mm): rounding ε, or √ε where a square root of a near-zero triangle
/// area amplifies it next to a singularity.
double tolerance(double scale, double margin)
{
    return (margin > 1e-3 ? 1e-9 : 1e-6) * scale;
}

/// The message of a failed result, else empty.
template <class T>
QByteArray messageOf(const Result<T> &result)
{
    return result ? QByteArray() : QByteArray::fromStdString(result.failure().message);
}

struct Trips {
    int direct = 0, inverse = 0;
};

/// θ → C → θ over an n×n grid of the crank ranges and C → θ → C over an n×n grid of the
/// bounds, every pose against the test's own construction and the design's modes.
void roundTrips(const FiveBar &m, int n, Trips &trips, const QByteArray &context)
{
    const FiveBarDesign &d = m.design();
    const double scale = scaleOf(d);
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            const double t1 = d.range[0].min + (d.range[0].max - d.range[0].min) * i / n;
            const double t4 = d.range[1].min + (d.range[1].max - d.range[1].min) * j / n;
            const QByteArray where
                = context + " θ = (" + QByteArray::number(t1 / deg) + "°, " + QByteArray::number(t4 / deg) + "°)";
            auto pose = m.solveDirect(pair(t1, t4));
            if (!pose) {
                const Failure &f = pose.failure();
                QVERIFY2(f.kind == FailureKind::Unreachable || f.kind == FailureKind::Singular, where);
                QVERIFY2(f.culprit == "theta1" || f.culprit == "theta4", where);
                continue;
            }
            QVERIFY2(violation(d, *pose, 1e-9).isEmpty(), where + ": " + violation(d, *pose, 1e-9));
            Eigen::Vector2d C = Eigen::Vector2d::Zero();
            QVERIFY2(constructC(d, t1, t4, C), where);
            const double margin = m.singularity(*pose).margin;
            QVERIFY2((C - pointOf(*pose)).norm() <= tolerance(scale, margin), where);
            auto back = m.solveInverse(pose->outputs, &*pose);
            if (!back) {
                // only on a singularity (within rounding) may the way back refuse the pose
                QVERIFY2(margin < 1e-6, where + ": " + messageOf(back));
                continue;
            }
            QVERIFY2((back->inputs - pose->inputs).cwiseAbs().maxCoeff() <= tolerance(1.0, margin), where);
            ++trips.direct;
        }
    }
    const MapGrid grid{m.workspaceBounds(), n, n};
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            const Eigen::Vector2d target(grid.x(c), grid.y(r));
            const QByteArray where
                = context + " C = (" + QByteArray::number(target.x()) + ", " + QByteArray::number(target.y()) + ")";
            auto pose = m.solveInverse(target);
            if (!pose) {
                const Failure &f = pose.failure();
                QVERIFY2(f.kind != FailureKind::InvalidParameter && f.kind != FailureKind::UnknownName, where);
                QVERIFY2(f.culprit == "x" || f.culprit == "theta1" || f.culprit == "theta4", where);
                continue;
            }
            QCOMPARE(pointOf(*pose), target);
            QVERIFY2(violation(d, *pose, 1e-9).isEmpty(), where + ": " + violation(d, *pose, 1e-9));
            const double margin = m.singularity(*pose).margin;
            for (int leg = 0; leg < 2; ++leg) {
                Eigen::Vector2d P = Eigen::Vector2d::Zero();
                QVERIFY2(constructElbow(d, leg, target, P), where);
                QVERIFY2((P - fivebar::elbow(d, leg, pose->inputs[leg])).norm() <= tolerance(scale, margin), where);
            }
            auto back = m.solveDirect(pose->inputs, &*pose);
            if (!back) {
                QVERIFY2(margin < 1e-6, where + ": " + messageOf(back));
                continue;
            }
            QVERIFY2((pointOf(*back) - target).norm() <= tolerance(scale, margin), where);
            ++trips.inverse;
        }
    }
}

/// A map over a square grid of the bounds, with margins.
struct Map {
    MapGrid grid;
    std::vector<float> values, margins;
    MapSummary summary;

    Map(const FiveBar &m, MapQuantity quantity, int resolution)
        : grid(squareGrid(m.workspaceBounds(), resolution)), values(grid.cells()), margins(grid.cells())
    {
        summary = computeMap(m, quantity, grid, values, margins);
    }
    std::size_t index(int c, int r) const { return std::size_t(r) * std::size_t(grid.columns) + std::size_t(c); }
    /// Does a cell next to (c, r) have the other reachability (so (c, r) is on the outline)?
    bool onOutline(int c, int r) const
    {
        const bool reached = !std::isnan(values[index(c, r)]);
        for (int dr = -1; dr <= 1; ++dr) {
            for (int dc = -1; dc <= 1; ++dc) {
                const int cc = c + dc, rr = r + dr;
                const bool other = cc < 0 || rr < 0 || cc >= grid.columns || rr >= grid.rows
                                || !std::isnan(values[index(cc, rr)]) != reached;
                if (other)
                    return true;
            }
        }
        return false;
    }
};

/// The designs the map tests use: the example in two modes, limited ranges, unequal links.
std::vector<std::pair<const char *, FiveBarDesign>> mapDesigns()
{
    FiveBarDesign limited;
    limited.range = {Interval{0.0, 200 * deg}, Interval{-20 * deg, 180 * deg}};
    FiveBarDesign unequal;
    unequal.ground = 60;
    unequal.crank = {50, 90};
    unequal.link = {140, 100};
    FiveBarDesign longRange; // a range of more than half a turn and less than a full one
    longRange.range = {Interval{-90 * deg, 200 * deg}, Interval{-250 * deg, 40 * deg}};
    return {{"example", FiveBarDesign{}},
            {"example, elbows in", withModes(FiveBarDesign{}, 0b110)},
            {"limited ranges", limited},
            {"ranges over half a turn", longRange},
            {"unequal links", withModes(unequal, 0b101)}};
}
} // namespace

class TestFiveBar : public QObject
{
    Q_OBJECT

private slots:
    void exampleInEveryMode_data();
    void exampleInEveryMode();
    void randomDesigns();
    void jacobiansAgainstFiniteDifferences_data();
    void jacobiansAgainstFiniteDifferences();
    void report();
    void singularPoses();
    void deadPointsStopWithTheReason();
    void noSilentModeSwitch();
    void modeAlternatives();
    void mapAgreesWithEvaluate_data();
    void mapAgreesWithEvaluate();
    void boundsAndCurves_data();
    void boundsAndCurves();
    void kinematicChain();
    void badDesigns_data();
    void badDesigns();
    void badPoses();
    void dragging();
    void drawing();
    void preset();
};

// -- kinematics ----------------------------------------------------------------------------

void TestFiveBar::exampleInEveryMode_data()
{
    QTest::addColumn<int>("modes");
    for (int modes = 0; modes < 8; ++modes)
        QTest::newRow(modesText(modes).constData()) << modes;
}

void TestFiveBar::exampleInEveryMode()
{
    QFETCH(int, modes);
    const auto m = make(withModes(FiveBarDesign{}, modes));
    Trips trips;
    roundTrips(*m, 60, trips, modesText(modes));
    if (QTest::currentTestFailed())
        return;
    // every mode combination of the example has a workspace, reached both ways
    QVERIFY2(trips.direct > 100 && trips.inverse > 100,
             qPrintable(QStringLiteral("%1 direct, %2 inverse").arg(trips.direct).arg(trips.inverse)));
    QVERIFY(violation(m->design(), m->homePose(), 1e-9).isEmpty());
}

void TestFiveBar::randomDesigns()
{
    std::mt19937 generator(20241123);
    int designs = 0, refused = 0;
    Trips trips;
    while (designs < 60) {
        const FiveBarDesign d = withModes(randomDesign(generator), int(generator() % 8));
        auto made = FiveBar::create(d);
        if (!made) {
            // only a loop that cannot close in these modes and ranges is refused
            QVERIFY2(
                made.failure().kind == FailureKind::Unreachable || made.failure().kind == FailureKind::InvalidParameter,
                made.failure().message.c_str());
            ++refused;
            continue;
        }
        const auto m = std::static_pointer_cast<const FiveBar>(*made);
        roundTrips(*m, 24, trips, "design " + QByteArray::number(designs));
        if (QTest::currentTestFailed())
            return;
        ++designs;
    }
    QVERIFY(trips.direct > 60 * 50 && trips.inverse > 60 * 50);
    QVERIFY(refused < designs);
    qInfo("%d random designs (%d refused): %d direct and %d inverse round trips", designs, refused, trips.direct,
        trips.inverse);
}

void TestFiveBar::jacobiansAgainstFiniteDifferences_data()
{
    exampleInEveryMode_data();
}

void TestFiveBar::jacobiansAgainstFiniteDifferences()
{
    QFETCH(int, modes);
    const auto m = make(withModes(FiveBarDesign{}, modes));
    const FiveBarDesign &d = m->design();
    const double h = 1e-5;
    int checked = 0;
    const MapGrid grid{m->workspaceBounds(), 17, 17};
    for (int r = 0; r < grid.rows; ++r) {
        for (int c = 0; c < grid.columns; ++c) {
            auto pose = m->solveInverse(pair(grid.x(c), grid.y(r)));
            if (!pose || m->singularity(*pose).margin < 0.05)
                continue;
            const Jacobians j = m->jacobians(*pose);
            const Eigen::Vector2d C = pointOf(*pose);
            // J_x = ½·∂f/∂C and J_q = −½·∂f/∂θ of f_i = |C − P_i|² − b_i², by central differences
            Eigen::Matrix2d jx, jq = Eigen::Matrix2d::Zero();
            for (int leg = 0; leg < 2; ++leg) {
                const double theta = pose->inputs[leg];
                for (int k = 0; k < 2; ++k) {
                    const Eigen::Vector2d step = h * Eigen::Vector2d::Unit(k);
                    jx(leg, k) = 0.5
                        * (fivebar::constraint(d, leg, theta, C + step) - fivebar::constraint(d, leg, theta, C - step))
                        / (2 * h);
                }
                jq(leg, leg) = -0.5
                    * (fivebar::constraint(d, leg, theta + h, C) - fivebar::constraint(d, leg, theta - h, C)) / (2 * h);
            }
            QVERIFY((jx - j.outputs).norm() <= 1e-6 * j.outputs.norm());
            QVERIFY((jq - j.inputs).norm() <= 1e-6 * j.inputs.norm());
            QVERIFY((j.inputs * j.full - j.outputs).norm() <= 1e-12 * j.outputs.norm());
            // J = dθ/dC: the inverse kinematics of C ± h
            const std::optional<Eigen::MatrixXd> differences = inverseDifferences(*m, pose->outputs, h, &*pose);
            QVERIFY(differences);
            const Eigen::Matrix2d numeric = *differences;
            QVERIFY2((numeric - j.full).norm() <= 1e-6 * j.full.norm(),
                qPrintable(QString::number((numeric - j.full).norm())));
            // the sign conventions: det J_x has the sign of σ, k_i the sign of −w_i
            QCOMPARE(j.outputs.determinant() > 0, d.assembly > 0);
            QCOMPARE(j.inputs(0, 0) > 0, d.working[0] < 0);
            QCOMPARE(j.inputs(1, 1) > 0, d.working[1] < 0);
            ++checked;
        }
    }
    QVERIFY(checked > 20);
}

void TestFiveBar::report()
{
    const auto m = make(FiveBarDesign{});
    const FiveBarDesign &d = m->design();
    int checked = 0;
    for (double x = -40; x <= 140; x += 20) {
        for (double y = 60; y <= 190; y += 13) {
            auto pose = m->solveInverse(pair(x, y));
            if (!pose)
                continue;
            Singularity s;
            const std::vector<double> v = evaluated(*m, *pose, &s);
            for (double value : v)
                QVERIFY(!std::isnan(value));
            const Jacobians j = m->jacobians(*pose);
            QCOMPARE(matrixEntry(*m, v, "Jq"), Eigen::Matrix2d(j.inputs));
            QCOMPARE(matrixEntry(*m, v, "Jx"), Eigen::Matrix2d(j.outputs));
            QVERIFY((matrixEntry(*m, v, "J") - j.full).norm() <= 1e-15 * j.full.norm());
            QVERIFY(std::abs(entry(*m, v, "det_J") - j.full.determinant()) <= 1e-9 * std::abs(j.full.determinant()));
            QVERIFY(
                std::abs(entry(*m, v, "det_Jq") - j.inputs.determinant()) <= 1e-9 * std::abs(j.inputs.determinant()));
            QVERIFY(
                std::abs(entry(*m, v, "det_Jx") - j.outputs.determinant()) <= 1e-9 * std::abs(j.outputs.determinant()));
            // det J has the sign σ·w₁·w₂ everywhere in the workspace
            QCOMPARE(entry(*m, v, "det_J") > 0, d.assembly * d.working[0] * d.working[1] > 0);
            const Eigen::JacobiSVD<Eigen::Matrix2d> svd(Eigen::Matrix2d(j.full));
            QVERIFY(std::abs(entry(*m, v, "cond") - svd.singularValues()(0) / svd.singularValues()(1))
                <= 1e-9 * entry(*m, v, "cond"));
            // the angles, measured again
            const Eigen::Vector2d A(0, 0), E(d.ground, 0), C = pointOf(*pose);
            const Eigen::Vector2d B = fivebar::elbow(d, 0, pose->inputs[0]), D = fivebar::elbow(d, 1, pose->inputs[1]);
            auto angle = [](const Eigen::Vector2d &u, const Eigen::Vector2d &w) {
                return std::acos(std::clamp(u.dot(w) / (u.norm() * w.norm()), -1.0, 1.0));
            };
            const double psi = angle(B - C, D - C);
            QVERIFY(std::abs(entry(*m, v, "elbow_angle1") - angle(A - B, C - B)) < 1e-9);
            QVERIFY(std::abs(entry(*m, v, "elbow_angle2") - angle(E - D, C - D)) < 1e-9);
            QVERIFY(std::abs(entry(*m, v, "links_angle") - psi) < 1e-9);
            QVERIFY(std::abs(entry(*m, v, "transmission") - std::min(psi, pi - psi)) < 1e-9);
            const double inverse = std::min(std::sin(angle(A - B, C - B)), std::sin(angle(E - D, C - D)));
            QVERIFY(std::abs(entry(*m, v, "margin_inverse") - inverse) < 1e-9);
            QVERIFY(std::abs(entry(*m, v, "margin_direct") - std::sin(psi)) < 1e-9);
            QCOMPARE(entry(*m, v, "margin"), s.margin);
            QCOMPARE(s.margin, std::min(entry(*m, v, "margin_inverse"), entry(*m, v, "margin_direct")));
            ++checked;
        }
    }
    QVERIFY(checked > 30);
}

void TestFiveBar::singularPoses()
{
    // AB = 40, BC = 60, CD = 50, DE = 120, AE = 100: leg 1 and the distal links can be in line
    // together (AB + BC + CD = 150 mm lies between |AE − DE| and AE + DE).
    FiveBarDesign d;
    d.crank = {40, 120};
    d.link = {60, 50};
    const auto m = make(d);
    int disagreements = 0; // between singularity() and evaluate()
    using Point = Eigen::Vector2d;
    auto classOf = [&](const Point &B, const Point &D, const Point &C, double *margin = nullptr) {
        Pose pose;
        pose.inputs = pair(std::atan2(B.y(), B.x()), std::atan2(D.y(), D.x() - d.ground));
        pose.outputs = pair(C.x(), C.y());
        Singularity evaluatedClass;
        evaluated(*m, pose, &evaluatedClass);
        const Singularity s = m->singularity(pose);
        disagreements += s.type != evaluatedClass.type || s.margin != evaluatedClass.margin ? 1 : 0;
        if (margin)
            *margin = s.margin;
        return s.type;
    };
    auto onCircle = [&](const Eigen::Vector2d &centre, double radius, double angle) {
        return Eigen::Vector2d(centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    };
    const Eigen::Vector2d A(0, 0), E(d.ground, 0);
    // inverse: leg 1 stretched, C = A + (AB + BC)·u; D from C on crank DE's circle
    {
        const Eigen::Vector2d C = onCircle(A, 100, 80 * deg), B = onCircle(A, 40, 80 * deg);
        Eigen::Vector2d D;
        QCOMPARE(fivebar::circleIntersection(E, 120, C, 50, -1, D, 0), fivebar::Meet::Yes);
        double margin = 1;
        QCOMPARE(classOf(B, D, C, &margin), SingularityType::Inverse);
        QVERIFY(margin < 1e-12);
        // folded: C = A + (BC − AB)·u with B behind A
        const Eigen::Vector2d folded = onCircle(A, 20, 100 * deg), behind = onCircle(A, 40, -80 * deg);
        QCOMPARE(fivebar::circleIntersection(E, 120, folded, 50, -1, D, 0), fivebar::Meet::Yes);
        QCOMPARE(classOf(behind, D, folded), SingularityType::Inverse);
    }
    // direct: the distal links in line, stretched (C between B and D) and folded
    {
        const Eigen::Vector2d B = onCircle(A, 40, 100 * deg);
        Eigen::Vector2d D;
        QCOMPARE(fivebar::circleIntersection(B, 110, E, 120, 1, D, 0), fivebar::Meet::Yes);
        QCOMPARE(classOf(B, D, B + 60 * (D - B) / 110), SingularityType::Direct);
        QCOMPARE(fivebar::circleIntersection(B, 10, E, 120, 1, D, 0), fivebar::Meet::Yes);
        QCOMPARE(classOf(B, D, B + 60 * (D - B) / 10), SingularityType::Direct); // D between B and C
        // a step off the direct singularity is regular
        QCOMPARE(classOf(B, D, B + 60 * rotated((D - B) / 10, 1e-3)), SingularityType::None);
    }
    // combined: A, B, C, D on one line with leg 1 stretched and BC, CD stretched
    {
        Eigen::Vector2d end;
        QCOMPARE(fivebar::circleIntersection(A, 150, E, 120, 1, end, 0), fivebar::Meet::Yes);
        const Eigen::Vector2d u = end.normalized();
        QCOMPARE(classOf(40 * u, end, 100 * u), SingularityType::Combined);
    }
    QCOMPARE(disagreements, 0);
    // a generic pose is regular
    QCOMPARE(m->singularity(m->homePose()).type, SingularityType::None);
    QVERIFY(m->singularity(m->homePose()).margin > 0.3);
}

void TestFiveBar::deadPointsStopWithTheReason()
{
    // Turning one crank from home in small steps, the solver stops at the first dead point with
    // a reason, the last pose it gave close to that singularity, and never in another mode.
    for (int modes = 0; modes < 8; ++modes) {
        const auto m = make(withModes(FiveBarDesign{}, modes));
        for (int leg = 0; leg < 2; ++leg) {
            for (const double direction : {1.0, -1.0}) {
                Pose pose = m->homePose();
                Result<Pose> next = pose;
                int steps = 0;
                while (next && steps < 7200) {
                    pose = *next;
                    Coordinates inputs = pose.inputs;
                    inputs[leg] += direction * 0.05 * deg;
                    if (!m->design().range[leg].contains(inputs[leg]))
                        break; // a full turn without a dead point
                    next = m->solveDirect(inputs, &pose);
                    ++steps;
                    QVERIFY(!next || violation(m->design(), *next, 1e-9).isEmpty());
                }
                if (next)
                    continue;
                const QByteArray where
                    = modesText(modes) + ", crank " + QByteArray::number(leg + 1) + ": " + messageOf(next);
                const std::string &message = next.failure().message;
                // the moved crank is the culprit; the message says which dead point it is
                QCOMPARE(next.failure().culprit, std::string(leg == 0 ? "theta1" : "theta4"));
                const bool links
                    = message.find("BC + CD") != std::string::npos || message.find("|BC − CD|") != std::string::npos;
                const bool working = message.find("working") != std::string::npos
                    && message.find("inverse singularity") != std::string::npos;
                QVERIFY2(links || working, where);
                const Singularity s = m->singularity(pose);
                QVERIFY2(s.margin < 0.1, where + " margin " + QByteArray::number(s.margin));
            }
        }
    }
}

void TestFiveBar::noSilentModeSwitch()
{
    // Where the design with one mode flipped has a regular pose, this design never returns that
    // pose: at the same inputs with a working mode flipped (the same C) and at the same C with
    // the assembly flipped (the same elbows) it refuses and names the mode to switch; otherwise
    // it finds its own, different pose in its own modes, or refuses.
    const auto m = make(FiveBarDesign{});
    struct Flip {
        const char *parameter;
        bool sameInputs;
    };
    const Flip flips[] = {{"working1", true}, {"working2", true},  {"assembly", false},
                          {"assembly", true}, {"working1", false}, {"working2", false}};
    for (const Flip flip : flips) {
        const bool named = flip.sameInputs == (std::string(flip.parameter) != "assembly");
        auto flipped = m->withParameter(flip.parameter, -m->parameters().at(flip.parameter));
        QVERIFY(flipped);
        const auto &other = dynamic_cast<const FiveBar &>(**flipped);
        int refused = 0, own = 0;
        for (int i = 0; i < 40; ++i) {
            for (int j = 0; j < 40; ++j) {
                const Coordinates q = pair(-pi + 2 * pi * (i + 0.5) / 40, -pi + 2 * pi * (j + 0.5) / 40);
                auto there = other.solveDirect(q);
                if (!there || other.singularity(*there).margin < 1e-3)
                    continue;
                auto here = flip.sameInputs ? m->solveDirect(q) : m->solveInverse(there->outputs);
                const QByteArray where
                    = QByteArray(flip.parameter) + (flip.sameInputs ? " (direct) " : " (inverse) ") + messageOf(here);
                if (here) {
                    QVERIFY2(!named, where);
                    QVERIFY2(violation(m->design(), *here, 1e-9).isEmpty(), where);
                    const bool different = flip.sameInputs ? (pointOf(*here) - pointOf(*there)).norm() > 1e-6
                                                           : (here->inputs - there->inputs).norm() > 1e-9;
                    QVERIFY2(different, where);
                    ++own;
                } else if (named) {
                    QVERIFY2(here.failure().message.find(flip.parameter) != std::string::npos, where);
                    QVERIFY2(here.failure().message.find("switch") != std::string::npos, where);
                    ++refused;
                }
            }
        }
        QVERIFY2(named ? refused > 50 : own > 50,
            qPrintable(QStringLiteral("%1: %2 refused, %3 own poses").arg(flip.parameter).arg(refused).arg(own)));
    }
}

void TestFiveBar::modeAlternatives()
{
    const auto m = make(FiveBarDesign{});
    auto pose = m->solveInverse(pair(50, 150));
    QVERIFY(pose);
    const std::vector<ModeAlternative> alternatives = m->modeAlternatives(*pose);
    QCOMPARE(alternatives.size(), std::size_t(3)); // one per label
    const Eigen::Vector2d B = fivebar::elbow(m->design(), 0, pose->inputs[0]);
    const Eigen::Vector2d D = fivebar::elbow(m->design(), 1, pose->inputs[1]);
    for (const ModeAlternative &alternative : alternatives) {
        const auto *other = dynamic_cast<const FiveBar *>(alternative.mechanism.get());
        QVERIFY(other);
        QVERIFY(violation(other->design(), alternative.pose, 1e-9).isEmpty());
        if (alternative.sameInputs) {
            // the other assembly mode: C mirrored across BD
            QCOMPARE(alternative.pose.inputs, pose->inputs);
            QCOMPARE(other->design().assembly, -m->design().assembly);
            const Eigen::Vector2d u = (D - B).normalized(), C = pointOf(*pose);
            const Eigen::Vector2d mirrored = B + 2 * (C - B).dot(u) * u - (C - B);
            QVERIFY((pointOf(alternative.pose) - mirrored).norm() < 1e-9);
        } else {
            // a leg's other working mode: the same C, that elbow mirrored across G→C
            QCOMPARE(alternative.pose.outputs, pose->outputs);
            const int leg = other->design().working[0] != m->design().working[0] ? 0 : 1;
            QCOMPARE(other->design().working[leg], -m->design().working[leg]);
            QCOMPARE(alternative.pose.inputs[1 - leg], pose->inputs[1 - leg]);
            const Eigen::Vector2d G(leg == 0 ? 0.0 : 100.0, 0.0), C = pointOf(*pose);
            const Eigen::Vector2d P = fivebar::elbow(m->design(), leg, pose->inputs[leg]);
            const Eigen::Vector2d u = (C - G).normalized();
            const Eigen::Vector2d mirrored = G + 2 * (P - G).dot(u) * u - (P - G);
            QVERIFY((fivebar::elbow(other->design(), leg, alternative.pose.inputs[leg]) - mirrored).norm() < 1e-9);
        }
    }
}

// -- maps ----------------------------------------------------------------------------------

void TestFiveBar::mapAgreesWithEvaluate_data()
{
    QTest::addColumn<FiveBarDesign>("design");
    QTest::addColumn<int>("quantity");
    for (const auto &[name, design] : mapDesigns()) {
        QTest::addRow("%s det", name) << design << int(MapQuantity::Determinant);
        QTest::addRow("%s cond", name) << design << int(MapQuantity::Condition);
    }
}

void TestFiveBar::mapAgreesWithEvaluate()
{
    QFETCH(FiveBarDesign, design);
    QFETCH(int, quantity);
    const auto m = make(design);
    const Map map(*m, MapQuantity(quantity), 200);
    const char *name = quantity == int(MapQuantity::Condition) ? "cond" : "det_J";
    int compared = 0, outline = 0;
    for (int r = 0; r < map.grid.rows; ++r) {
        for (int c = r % 2; c < map.grid.columns; c += 2) {
            const float cell = map.values[map.index(c, r)];
            const float margin = map.margins[map.index(c, r)];
            auto pose = m->solveInverse(pair(map.grid.x(c), map.grid.y(r)));
            const QByteArray where
                = "cell " + QByteArray::number(c) + ", " + QByteArray::number(r) + " " + messageOf(pose);
            QCOMPARE(std::isnan(cell), std::isnan(margin));
            if (std::isnan(cell) == !pose) {
                if (!pose)
                    continue;
                Singularity s;
                const std::vector<double> v = evaluated(*m, *pose, &s);
                const double expected = entry(*m, v, name);
                QVERIFY2(std::abs(cell - expected) <= (s.margin > 1e-3 ? 1e-5 : 1e-3) * std::abs(expected),
                         where + " map " + QByteArray::number(cell) + ", evaluate " + QByteArray::number(expected));
                QVERIFY2(std::abs(margin - s.margin) <= 1e-6, where);
                ++compared;
                continue;
            }
            // the map and the solver may differ by rounding on the outline only
            QVERIFY2(map.onOutline(c, r), where);
            ++outline;
        }
    }
    QVERIFY(compared > 1000);
    QVERIFY2(outline <= compared / 50, qPrintable(QString::number(outline)));
    if (quantity == int(MapQuantity::Condition))
        QVERIFY(map.summary.min >= 1.0);
}

void TestFiveBar::boundsAndCurves_data()
{
    QTest::addColumn<FiveBarDesign>("design");
    for (const auto &[name, design] : mapDesigns())
        QTest::newRow(name) << design;
}

void TestFiveBar::boundsAndCurves()
{
    QFETCH(FiveBarDesign, design);
    const auto m = make(design);
    const Eigen::AlignedBox2d bounds = m->workspaceBounds();
    QVERIFY(!bounds.isEmpty());
    QVERIFY(bounds.contains(pointOf(m->homePose())));
    // no reachable cell of a fine map over a box twice the size lies outside the bounds
    const Eigen::Vector2d centre = bounds.center(), half = bounds.sizes();
    const MapGrid grid = squareGrid(Eigen::AlignedBox2d(centre - half, centre + half), 500);
    std::vector<float> values(grid.cells());
    const MapSummary summary = computeMap(*m, MapQuantity::Determinant, grid, values);
    QVERIFY(summary.reachableCells > 1000);
    for (int r = 0; r < grid.rows; ++r) {
        for (int c = 0; c < grid.columns; ++c) {
            if (!std::isnan(values[std::size_t(r) * std::size_t(grid.columns) + std::size_t(c)]))
                QVERIFY(bounds.contains(Eigen::Vector2d(grid.x(c), grid.y(r))));
        }
    }
    // every point of a singular curve is a singular pose of the design, of the curve's type
    const std::vector<SingularCurve> curves = m->singularCurves();
    QVERIFY(!curves.empty());
    for (const SingularCurve &curve : curves) {
        QVERIFY(curve.points.size() > 1);
        for (std::size_t i = 0; i < curve.points.size(); i += 7) {
            const FiveBar::Check check
                = m->checkInverse(curve.points[i], 1e-6, {m->homePose().inputs[0], m->homePose().inputs[1]});
            QVERIFY2(check.ok(), curve.label.c_str());
            Pose pose;
            pose.inputs = pair(check.thetas[0], check.thetas[1]);
            pose.outputs = pair(curve.points[i].x(), curve.points[i].y());
            const std::vector<double> v = evaluated(*m, pose);
            const bool inverse = curve.type == SingularCurve::Type::Inverse;
            QVERIFY2(entry(*m, v, inverse ? "margin_inverse" : "margin_direct") < 1e-5, curve.label.c_str());
            QVERIFY(bounds.contains(curve.points[i]));
        }
    }
    // the example reaches its stretched legs, and its direct singularities are the reason for
    // its warning
    const bool direct = std::any_of(
        curves.begin(), curves.end(), [](const SingularCurve &c) { return c.type == SingularCurve::Type::Direct; });
    QCOMPARE(!m->designWarnings().empty(), direct);
}

// -- structure, validation, interaction -------------------------------------------------------

void TestFiveBar::kinematicChain()
{
    const auto m = make(FiveBarDesign{});
    auto pose = m->solveInverse(pair(50, 150));
    QVERIFY(pose);
    const KinematicChain chain = m->kinematicChain(*pose);
    QCOMPARE(chain.links.size(), std::size_t(5));
    QCOMPARE(chain.links.front(), std::string("ground"));
    QCOMPARE(chain.pairs.size(), std::size_t(5));
    QVERIFY(chain.planar);
    QVERIFY(!chain.description.empty());
    const Scene scene = m->scene(*pose);
    int actuated = 0, p5 = 0, p4 = 0;
    std::vector<int> degree(chain.links.size(), 0);
    for (const KinematicPair &kp : chain.pairs) {
        QCOMPARE(kp.type, PairType::Revolute);
        QVERIFY(kp.axis == Eigen::Vector3d::UnitZ());
        QVERIFY(kp.link1 != kp.link2);
        ++degree[std::size_t(kp.link1)];
        ++degree[std::size_t(kp.link2)];
        actuated += kp.actuated ? 1 : 0;
        const bool oneFreedom
            = kp.type == PairType::Revolute || kp.type == PairType::Prismatic || kp.type == PairType::Screw;
        p5 += oneFreedom ? 1 : 0;
        p4 += kp.type == PairType::Cylindrical || kp.type == PairType::CamPlanar ? 1 : 0;
        // the axis passes through the joint of the same name in the drawing
        const auto joint = std::find_if(
            scene.joints.begin(), scene.joints.end(), [&](const SceneJoint &j) { return j.label == kp.name; });
        QVERIFY(joint != scene.joints.end());
        QVERIFY((joint->position - kp.point).norm() < 1e-12);
        QVERIFY(kp.actuated == (kp.name == "A" || kp.name == "E"));
    }
    QCOMPARE(actuated, 2);
    // a single loop: every link in two pairs
    QVERIFY(std::all_of(degree.begin(), degree.end(), [](int n) { return n == 2; }));
    // Chebyshev: W = 3n − 2P₅ − P₄ = 3·4 − 2·5 − 0 = 2, the number of actuators
    QCOMPARE(chain.movingLinks(), 4);
    QCOMPARE(p5, 5);
    const int mobility = 3 * chain.movingLinks() - 2 * p5 - p4;
    QCOMPARE(mobility, 2);
    QCOMPARE(mobility, m->inputCount());
    // the loop's velocity closure: the planar twists (1, y, −x) of the five joints add up to
    // zero; its rank 3 at a regular pose leaves 5 − 3 = 2 freedoms, as counted
    Eigen::Matrix<double, 3, 5> loop;
    for (int i = 0; i < 5; ++i) {
        const Eigen::Vector3d &p = chain.pairs[std::size_t(i)].point;
        loop.col(i) << 1.0, p.y(), -p.x();
    }
    QCOMPARE(5 - int(Eigen::FullPivLU<Eigen::MatrixXd>(loop).rank()), 2);
}

void TestFiveBar::badDesigns_data()
{
    QTest::addColumn<ParameterSet>("changes");
    QTest::addColumn<QString>("culprit");
    QTest::addColumn<int>("kind");
    const int invalid = int(FailureKind::InvalidParameter);
    QTest::newRow("AB zero") << ParameterSet{{"AB", 0.0}} << "AB" << invalid;
    QTest::newRow("BC negative") << ParameterSet{{"BC", -5.0}} << "BC" << invalid;
    QTest::newRow("CD NaN") << ParameterSet{{"CD", notANumber}} << "CD" << invalid;
    QTest::newRow("DE infinite") << ParameterSet{{"DE", std::numeric_limits<double>::infinity()}} << "DE" << invalid;
    QTest::newRow("AE too long") << ParameterSet{{"AE", 500.0}} << "AE" << invalid;
    QTest::newRow("BC too long") << ParameterSet{{"BC", 381.0}} << "BC" << invalid;
    QTest::newRow("working1 half") << ParameterSet{{"working1", 0.5}} << "working1" << invalid;
    QTest::newRow("assembly zero") << ParameterSet{{"assembly", 0.0}} << "assembly" << invalid;
    QTest::newRow("working2 two") << ParameterSet{{"working2", 2.0}} << "working2" << invalid;
    QTest::newRow("range inverted") << ParameterSet{{"theta1_min", 90 * deg}, {"theta1_max", 10 * deg}}
                                    << "theta1_min" << invalid;
    QTest::newRow("range over a turn") << ParameterSet{{"theta4_min", -200 * deg}, {"theta4_max", 200 * deg}}
                                       << "theta4_max" << invalid;
    QTest::newRow("min past max") << ParameterSet{{"theta1_min", 180 * deg}} << "theta1_min" << invalid;
    QTest::newRow("unknown") << ParameterSet{{"EF", 3.0}} << "EF" << int(FailureKind::UnknownName);
    // the cranks held below the ground with C above BD and elbows out: the loop never closes
    QTest::newRow("no workspace") << ParameterSet{{"theta1_min", -170 * deg}, {"theta1_max", -100 * deg},
                                                  {"theta4_min", -80 * deg}, {"theta4_max", -10 * deg}, {"AE", 300.0}}
                                  << "theta1_min" << int(FailureKind::Unreachable);
}

void TestFiveBar::badDesigns()
{
    QFETCH(ParameterSet, changes);
    QFETCH(QString, culprit);
    QFETCH(int, kind);
    const auto m = make(FiveBarDesign{});
    const ParameterSet before = m->parameters();
    auto changed = m->withParameters(changes);
    QVERIFY(!changed);
    QCOMPARE(QString::fromStdString(changed.failure().culprit), culprit);
    QCOMPARE(int(changed.failure().kind), kind);
    QVERIFY2(QString::fromStdString(changed.failure().message).contains(culprit), changed.failure().message.c_str());
    QCOMPARE(m->parameters(), before); // the design is unchanged
    // from scratch and through the registry alike
    auto made = createMechanism("fivebar", changes);
    QVERIFY(!made);
    QCOMPARE(QString::fromStdString(made.failure().culprit), culprit);
    // a single change is blamed on itself
    if (changes.size() == 1) {
        auto single = m->withParameter(changes.begin()->first, changes.begin()->second);
        QVERIFY(!single);
        QCOMPARE(QString::fromStdString(single.failure().culprit), culprit);
    }
}

void TestFiveBar::badPoses()
{
    FiveBarDesign limited;
    limited.range[1] = {0.0, 170 * deg};
    const auto m = make(limited);
    const Pose home = m->homePose();
    struct Case {
        Result<Pose> result;
        const char *culprit;
        FailureKind kind;
        const char *says;
    };
    FiveBarDesign equal; // AB = BC: C on A leaves θ₁ undetermined
    equal.crank[0] = equal.link[0] = 100;
    const auto e = make(equal);
    Pose stretchedNear; // only θ₄ differs from it: θ₄ is the culprit
    stretchedNear.inputs = pair(pi, 0.5);
    const Case cases[] = {
        {m->solveDirect(pair(notANumber, 1.0)), "theta1", FailureKind::OutOfRange, "finite"},
        {m->solveDirect(pair(1.0, 200 * deg)), "theta4", FailureKind::OutOfRange, "[0°, 170°]"},
        {m->solveDirect(pair(4.0, 1.0)), "theta1", FailureKind::OutOfRange, "turns fully"},
        {m->solveDirect(pair(pi, 0.0)), "theta1", FailureKind::Unreachable, "BC + CD"},
        {m->solveDirect(pair(pi, 0.0), &stretchedNear), "theta4", FailureKind::Unreachable, "BC + CD"},
        {m->solveInverse(pair(notANumber, 0.0)), "x", FailureKind::OutOfRange, "finite"},
        {m->solveInverse(pair(0.0, 250.0)), "x", FailureKind::Unreachable, "AB + BC"},
        {m->solveInverse(pair(home.outputs[0], 300.0), &home), "y", FailureKind::Unreachable, "AB + BC"},
        {m->solveInverse(pair(10.0, 5.0)), "x", FailureKind::Unreachable, "|AB − BC|"},
        {e->solveInverse(pair(0.0, 0.0)), "x", FailureKind::Singular, "undetermined"},
        {m->solveInverse(pair(150.0, -60.0)), "theta4", FailureKind::OutOfRange, "[0°, 170°]"},
    };
    for (const Case &c : cases) {
        QVERIFY(!c.result);
        const Failure &f = c.result.failure();
        QVERIFY2(f.culprit == c.culprit && f.kind == c.kind && f.message.find(c.says) != std::string::npos,
            f.message.c_str());
    }
    // a hair beyond the reach: the lengths compared are printed so that they differ (it read
    // "it lies 200 mm from A, more than AB + BC = 200 mm")
    const auto hair = m->solveInverse(pair(0.0, 200.0 + 1e-4));
    QVERIFY(!hair);
    QVERIFY2(hair.failure().message.find("200.0001 mm from A, more than AB + BC = 200 mm") != std::string::npos,
             hair.failure().message.c_str());
}

void TestFiveBar::dragging()
{
    FiveBarDesign limited;
    limited.range[0] = {30 * deg, 150 * deg};
    const auto m = make(limited);
    const Pose home = m->homePose();
    // handle 0: C to the target
    auto moved = m->dragHandle(home, 0, pointOf(home) + Eigen::Vector2d(3, -4));
    QVERIFY(moved);
    QVERIFY((pointOf(*moved) - pointOf(home) - Eigen::Vector2d(3, -4)).norm() < 1e-9);
    // handle 2: crank DE turned towards the target, crank AB held
    const Eigen::Vector2d E(m->design().ground, 0);
    const double theta4 = home.inputs[1] + 5 * deg;
    auto turned = m->dragHandle(home, 2, E + 37 * Eigen::Vector2d(std::cos(theta4), std::sin(theta4)));
    QVERIFY2(turned, messageOf(turned).constData());
    QVERIFY(std::abs(turned->inputs[1] - theta4) < 1e-12);
    QCOMPARE(turned->inputs[0], home.inputs[0]);
    // handle 1 beyond the range stops at its nearer end
    auto stopped = m->dragHandle(home, 1, Eigen::Vector2d(std::cos(10 * deg), std::sin(10 * deg)));
    if (stopped)
        QVERIFY(std::abs(stopped->inputs[0] - 30 * deg) < 1e-12);
    else
        QCOMPARE(stopped.failure().culprit, std::string("theta1"));
    QVERIFY(!m->dragHandle(home, 3, Eigen::Vector2d(0, 0)));
}

void TestFiveBar::drawing()
{
    const auto m = make(FiveBarDesign{});
    auto pose = m->solveInverse(pair(30, 140));
    QVERIFY(pose);
    const Scene s = m->scene(*pose);
    const FiveBarDesign &d = m->design();
    const Eigen::Vector2d B = fivebar::elbow(d, 0, pose->inputs[0]), D = fivebar::elbow(d, 1, pose->inputs[1]);
    const std::vector<Eigen::Vector2d> expected = {{0, 0}, {d.ground, 0}, B, D, pointOf(*pose)};
    QCOMPARE(s.joints.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        QVERIFY((s.joints[i].position.head<2>() - expected[i]).norm() < 1e-12);
    QCOMPARE(s.joints[0].kind, JointKind::Ground);
    QCOMPARE(s.joints[1].kind, JointKind::Ground);
    // the bars keep their lengths
    const std::vector<double> lengths = {d.ground, d.crank[0], d.crank[1], d.link[0], d.link[1]};
    QCOMPARE(s.bars.size(), lengths.size());
    for (std::size_t i = 0; i < lengths.size(); ++i) {
        const SceneBar &bar = s.bars[i];
        const Eigen::Vector3d &from = s.joints[std::size_t(bar.from)].position;
        const Eigen::Vector3d &to = s.joints[std::size_t(bar.to)].position;
        QVERIFY(std::abs((to - from).norm() - lengths[i]) < 1e-9);
    }
    // the angle arcs sweep θ₁ at A and θ₄ at E from +x
    QCOMPARE(s.angles.size(), std::size_t(2));
    QCOMPARE(s.angles[0].sweep, pose->inputs[0]);
    QCOMPARE(s.angles[1].vertex, 1);
    QCOMPARE(s.angles[1].sweep, pose->inputs[1]);
    // handles: C, B, D, in the order of dragHandle
    QCOMPARE(s.handles.size(), std::size_t(3));
    QCOMPARE(s.handles[0].joint, 4);
    QCOMPARE(s.handles[1].joint, 2);
    QCOMPARE(s.handles[2].joint, 3);
    // the extent holds the workspace and the cranks' circles
    QVERIFY(s.extent.contains(Eigen::Vector3d(m->workspaceBounds().min().x(), m->workspaceBounds().min().y(), 0)));
    QVERIFY(s.extent.contains(Eigen::Vector3d(-d.crank[0], d.crank[0], 0)));
    QVERIFY(s.extent.contains(Eigen::Vector3d(d.ground + d.crank[1], -d.crank[1], 0)));
}

void TestFiveBar::preset()
{
    QFile file(QFINDTESTDATA("../../resources/presets/fivebar-example.pkm.json"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("fivebar"));
    QCOMPARE(root.value(QStringLiteral("id")).toString(), QStringLiteral("fivebar-example"));
    QVERIFY(!root.value(QStringLiteral("description")).toString().isEmpty());
    // parameters in display units, modes by name or number
    auto defaults = createMechanism("fivebar", {});
    QVERIFY(defaults);
    ParameterSet values;
    const QJsonObject parameters = root.value(QStringLiteral("parameters")).toObject();
    for (auto it = parameters.begin(); it != parameters.end(); ++it) {
        const auto &infos = (*defaults)->parameterInfo();
        const auto info = std::find_if(
            infos.begin(), infos.end(), [&](const ParameterInfo &i) { return i.name == it.key().toStdString(); });
        QVERIFY2(info != infos.end(), qPrintable(it.key()));
        if (it.value().isString()) {
            const std::string word = it.value().toString().toStdString();
            const auto choice = std::find_if(info->choices.begin(), info->choices.end(),
                                             [&](const auto &c) { return c.first == word; });
            QVERIFY(choice != info->choices.end());
            values[info->name] = choice->second;
        } else {
            values[info->name] = info->unit.fromDisplay(it.value().toDouble());
        }
    }
    auto made = createMechanism("fivebar", values);
    QVERIFY2(made, made ? "" : made.failure().message.c_str());
    const auto *m = dynamic_cast<const FiveBar *>(made->get());
    QVERIFY(m);
    // the example: elbows out, C above BD
    QCOMPARE(m->design().working, (std::array<int, 2>{fivebar::left, fivebar::right}));
    QCOMPARE(m->design().assembly, fivebar::left);
    const QJsonObject poseObject = root.value(QStringLiteral("pose")).toObject();
    const Coordinates C
        = pair(poseObject.value(QStringLiteral("x")).toDouble(), poseObject.value(QStringLiteral("y")).toDouble());
    auto pose = m->solveInverse(C);
    QVERIFY2(pose, messageOf(pose).constData());
    // C above the ground, near the middle, far from every singularity, the elbows out
    QVERIFY(C[1] > 0 && std::abs(C[0] - 0.5 * m->design().ground) < 0.1 * m->design().ground);
    QVERIFY(m->singularity(*pose).margin > 0.9);
    QVERIFY(fivebar::elbow(m->design(), 0, pose->inputs[0]).x() < 0);
    QVERIFY(fivebar::elbow(m->design(), 1, pose->inputs[1]).x() > m->design().ground);
}

QTEST_APPLESS_MAIN(TestFiveBar)
#include "tst_fivebar.moc"
