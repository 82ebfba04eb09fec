// The planar four-bar linkage (docs/mathematics.md) against constructions made again here: the
// rocker angle from circles intersected independently, both branches, round trips, velocities
// and accelerations against finite differences of δ(α), the document's (5), (8), (9) (which
// hold up to the sign of ω₃) and its (14) (which does not), Grashof's classes, the assembly
// limits of α by the law of cosines, the instantaneous centre, singular poses, failures that
// name their culprit, the other branch, dragging and the drawing.
#include "kinds/fourbar/fourbar.h"
#include "support/kinematics.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

using namespace pkm;
using namespace pkm::test;

Q_DECLARE_METATYPE(pkm::ParameterSet)

namespace {
constexpr double pi = std::numbers::pi;
constexpr double degree = pi / 180.0;
constexpr double notANumber = std::numeric_limits<double>::quiet_NaN();

FourBarDesign lengths(double ab, double bc, double cd, double ad, int branch = +1)
{
    FourBarDesign d;
    d.crank = ab;
    d.coupler = bc;
    d.rocker = cd;
    d.ground = ad;
    d.branch = branch;
    return d;
}

/// The designs of the tests: one of each Grashof class.
struct Named {
    const char *name;
    FourBarDesign design;
};
std::vector<Named> designs()
{
    return {{"crank-rocker", lengths(40, 120, 100, 140)},   {"double-crank", lengths(100, 120, 110, 40)},
            {"rocker-crank", lengths(100, 120, 40, 140)},   {"double-rocker", lengths(100, 40, 120, 140)},
            {"triple-rocker", lengths(100, 120, 100, 140)}, {"change-point", lengths(40, 100, 60, 80)}};
}

/// C by the test's own construction: (x − AD)² + y² = CD² and |C − B|² = BC² subtracted give
/// a line; put it into the first circle and solve the quadratic; keep the root on side σ of
/// B→D. Returns false when the circles do not meet.
bool constructC(const FourBarDesign &d, double alpha, Eigen::Vector2d &C)
{
    const double bx = d.crank * std::cos(alpha), by = d.crank * std::sin(alpha);
    // 2(bx − AD)·x + 2·by·y = CD² − BC² − AD² + bx² + by²  (circle 1 minus circle 2)
    const double p = 2.0 * (bx - d.ground), q = 2.0 * by;
    const double r = d.rocker * d.rocker - d.coupler * d.coupler - d.ground * d.ground + bx * bx + by * by;
    // points of the line: X0 + t·(−q, p), X0 = r·(p, q)/(p² + q²)
    const double n2 = p * p + q * q;
    const Eigen::Vector2d x0 = r / n2 * Eigen::Vector2d(p, q), dir = Eigen::Vector2d(-q, p) / std::sqrt(n2);
    const Eigen::Vector2d w = x0 - Eigen::Vector2d(d.ground, 0.0);
    // |w + t·dir|² = CD²
    const double bq = w.dot(dir), cq = w.squaredNorm() - d.rocker * d.rocker;
    const double disc = bq * bq - cq;
    if (disc < -1e-9 * d.rocker * d.rocker)
        return false;
    for (const double sign : {1.0, -1.0}) {
        const Eigen::Vector2d c = x0 + (-bq + sign * std::sqrt(std::max(0.0, disc))) * dir;
        const Eigen::Vector2d bd = Eigen::Vector2d(d.ground - bx, -by), bc = c - Eigen::Vector2d(bx, by);
        if ((bd.x() * bc.y() - bd.y() * bc.x()) * d.branch >= 0) {
            C = c;
            return true;
        }
    }
    return false;
}

/// δ measured: the clockwise angle at D from D→A to D→C.
double measureDelta(const FourBarDesign &d, const Eigen::Vector2d &C)
{
    const Eigen::Vector2d u(-d.ground, 0.0), v = C - Eigen::Vector2d(d.ground, 0.0);
    return std::atan2(-(u.x() * v.y() - u.y() * v.x()), u.dot(v));
}

double angleDifference(double a, double b)
{
    return std::abs(std::remainder(a - b, 2.0 * pi));
}

/// α samples strictly inside the input range.
std::vector<double> interiorAlphas(const Mechanism &m, int count)
{
    const Interval r = m.variableRange(FourBar::variableAlpha);
    std::vector<double> alphas;
    for (int i = 1; i < count; ++i)
        alphas.push_back(r.min + (r.max - r.min) * i / count);
    return alphas;
}
} // namespace

class TestFourBar : public QObject
{
    Q_OBJECT

private slots:
    void deltaAgainstConstruction_data();
    void deltaAgainstConstruction();
    void roundTrips_data();
    void roundTrips();
    void velocitiesAgainstFiniteDifferences_data();
    void velocitiesAgainstFiniteDifferences();
    void documentOmega3HoldsUpToSign();
    void documentEpsilon3IsWrong();
    void grashofClasses_data();
    void grashofClasses();
    void assemblyLimits();
    void instantCentre();
    void singularPoses();
    void badInput_data();
    void badInput();
    void otherBranch();
    void dragging();
    void drawing();
    void report();
};

// -- positions -----------------------------------------------------------------------------

void TestFourBar::deltaAgainstConstruction_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("branch");
    const auto all = designs();
    for (int i = 0; i < int(all.size()); ++i) {
        QTest::addRow("%s open", all[std::size_t(i)].name) << i << +1;
        QTest::addRow("%s crossed", all[std::size_t(i)].name) << i << -1;
    }
}

void TestFourBar::deltaAgainstConstruction()
{
    QFETCH(int, index);
    QFETCH(int, branch);
    FourBarDesign d = designs()[std::size_t(index)].design;
    d.branch = branch;
    const auto m = make(d);
    double worst = 0.0;
    for (const double alpha : interiorAlphas(*m, 97)) {
        auto pose = m->solveDirect(one(alpha));
        QVERIFY2(pose.ok(), pose.ok() ? "" : pose.failure().message.c_str());
        Eigen::Vector2d C = Eigen::Vector2d::Zero();
        QVERIFY(constructC(d, alpha, C));
        const double delta = pose->outputs[0];
        worst = std::max(worst, angleDifference(delta, measureDelta(d, C)));
        QVERIFY(m->variableRange(FourBar::variableDelta).contains(delta, 1e-12));
        QCOMPARE(pose->mode, branch);
        // the document's relations between the angles, with γ signed by the branch
        const fourbar::Angles a = fourbar::angles(d, alpha, delta);
        QVERIFY(std::abs(std::cos(a.gamma) - fourbar::documentCosGamma(d.crank, d.coupler, d.rocker, d.ground, alpha)) < 1e-9); // (5)
        QVERIFY(a.gamma * branch >= -1e-12);
        QVERIFY(angleDifference(a.beta, 2 * pi - (alpha + a.gamma + delta)) < 1e-9);
        QVERIFY(angleDifference(a.delta1, std::atan2(d.crank * std::sin(alpha), d.ground - d.crank * std::cos(alpha))) < 1e-12); // (4)
        const double delta6 = std::atan2(d.coupler * std::sin(a.gamma), d.rocker - d.coupler * std::cos(a.gamma)) + a.delta1;
        QVERIFY(angleDifference(delta, delta6) < 1e-9); // (6) with atan2
    }
    QVERIFY2(worst < 1e-10, qPrintable(QString::number(worst)));
}

void TestFourBar::roundTrips_data()
{
    deltaAgainstConstruction_data();
}

void TestFourBar::roundTrips()
{
    QFETCH(int, index);
    QFETCH(int, branch);
    FourBarDesign d = designs()[std::size_t(index)].design;
    d.branch = branch;
    const auto m = make(d);
    for (const double alpha : interiorAlphas(*m, 61)) {
        auto pose = m->solveDirect(one(alpha));
        QVERIFY(pose.ok());
        // near the pose: the crank angle itself (both roots may be in the branch)
        auto back = m->solveInverse(pose->outputs, &*pose);
        QVERIFY2(back.ok(), back.ok() ? "" : back.failure().message.c_str());
        QVERIFY2(std::abs(back->inputs[0] - alpha) < 1e-7, qPrintable(QString("%1 vs %2").arg(back->inputs[0]).arg(alpha)));
        // without `near`: some crank angle of the branch giving the same δ
        auto any = m->solveInverse(pose->outputs);
        QVERIFY(any.ok());
        auto again = m->solveDirect(any->inputs);
        QVERIFY(again.ok());
        QVERIFY(std::abs(again->outputs[0] - pose->outputs[0]) < 1e-9);
    }
}

// -- velocities and accelerations -----------------------------------------------------------

void TestFourBar::velocitiesAgainstFiniteDifferences_data()
{
    deltaAgainstConstruction_data();
}

void TestFourBar::velocitiesAgainstFiniteDifferences()
{
    QFETCH(int, index);
    QFETCH(int, branch);
    FourBarDesign d = designs()[std::size_t(index)].design;
    d.branch = branch;
    d.omega1 = 7.0;
    const auto m = make(d);
    auto deltaAt = [&](double alpha, double reference) {
        auto pose = m->solveDirect(one(alpha));
        return std::remainder(pose->outputs[0] - reference, 2 * pi) + reference;
    };
    double worstI31 = 0.0, worstEpsilon = 0.0;
    int checked = 0;
    const Interval range = m->variableRange(FourBar::variableAlpha);
    for (const double alpha : interiorAlphas(*m, 41)) {
        auto pose = m->solveDirect(one(alpha));
        QVERIFY(pose.ok());
        const double margin = reportValue(*m, *pose, "margin");
        if (margin < 0.05 || alpha - range.min < 1e-3 || range.max - alpha < 1e-3)
            continue; // finite differences are poor next to a dead point
        const double h1 = 1e-6, h2 = 1e-4;
        const double d0 = pose->outputs[0];
        const double i31 = (deltaAt(alpha + h1, d0) - deltaAt(alpha - h1, d0)) / (2 * h1);
        const double second = (deltaAt(alpha + h2, d0) - 2 * d0 + deltaAt(alpha - h2, d0)) / (h2 * h2);
        const fourbar::Motion motion = fourbar::motion(d, alpha, d0, d.omega1);
        const double scale = std::max(1.0, std::abs(i31));
        worstI31 = std::max(worstI31, std::abs(motion.omega3 / d.omega1 - i31) / scale);
        QCOMPARE(reportValue(*m, *pose, "omega3"), motion.omega3);
        QVERIFY(std::abs(reportValue(*m, *pose, "i31") - motion.omega3 / d.omega1) < 1e-9 * scale);
        // J = dα/dδ is the inverse of i₃₁
        QVERIFY(std::abs(reportValue(*m, *pose, "J") * reportValue(*m, *pose, "i31") - 1.0) < 1e-9);
        const double epsilon = second * d.omega1 * d.omega1;
        worstEpsilon = std::max(worstEpsilon, std::abs(motion.epsilon3 - epsilon) / std::max(1.0, std::abs(epsilon)));
        ++checked;
    }
    QVERIFY(checked > 10);
    qInfo("%s: max relative error i31 %.2e, epsilon3 %.2e over %d poses", QTest::currentDataTag(), worstI31,
          worstEpsilon, checked);
    QVERIFY(worstI31 < 1e-7);
    QVERIFY(worstEpsilon < 1e-4);
}

void TestFourBar::documentOmega3HoldsUpToSign()
{
    // (8) and (9) give the rocker's counter-clockwise angular velocity dθ₃/dt = −dδ/dt.
    for (const Named &named : designs()) {
        for (const int branch : {+1, -1}) {
            FourBarDesign d = named.design;
            d.branch = branch;
            const auto m = make(d);
            for (const double alpha : interiorAlphas(*m, 23)) {
                auto pose = m->solveDirect(one(alpha));
                const fourbar::Angles a = fourbar::angles(d, alpha, pose->outputs[0]);
                const double omega3 = reportValue(*m, *pose, "omega3");
                const double document = fourbar::documentOmega3(d.crank, d.rocker, d.omega1, a.beta, a.gamma);
                QVERIFY2(std::abs(omega3 + document) <= 1e-9 * std::max(1.0, std::abs(omega3)),
                         qPrintable(QString("%1: %2 vs %3").arg(named.name).arg(omega3).arg(document)));
                QVERIFY(std::abs(reportValue(*m, *pose, "i31") + fourbar::documentI31(d.crank, d.rocker, a.beta, a.gamma))
                        <= 1e-9 * std::max(1.0, std::abs(omega3)));
            }
        }
    }
}

void TestFourBar::documentEpsilon3IsWrong()
{
    // docs/mathematics.md. For the example (40/120/100/140 mm, ω₁ = 10 rad/s) the printed (14) follows
    // d²δ/dt² only roughly: it is exact where sin α = 0 (its second term vanishes) and off
    // elsewhere, by 7 % at α = 60° and by a factor of 3.7 at α = 330°. It matches neither sign
    // (the document's (8) is −dδ/dt, so its own derivative would be −d²δ/dt²).
    const auto m = make(lengths(40, 120, 100, 140));
    const FourBarDesign &d = m->design();
    auto compare = [&](double alpha, double *exact, double *printed, double *fd) {
        auto pose = m->solveDirect(one(alpha));
        QVERIFY(pose.ok());
        const double delta = pose->outputs[0];
        const fourbar::Angles a = fourbar::angles(d, alpha, delta);
        *exact = reportValue(*m, *pose, "epsilon3");
        const double h = 1e-4;
        auto deltaAt = [&](double x) { return m->solveDirect(one(x))->outputs[0]; };
        *fd = (deltaAt(alpha + h) - 2 * delta + deltaAt(alpha - h)) / (h * h) * d.omega1 * d.omega1;
        *printed = fourbar::documentEpsilon3(d.crank, d.coupler, d.rocker, d.ground, d.omega1, alpha, a.beta, a.gamma, delta);
    };
    double exact = 0, printed = 0, fd = 0;
    compare(330 * degree, &exact, &printed, &fd);
    qInfo("alpha = 330 deg: exact epsilon3 = %.6f rad/s^2, finite differences %.6f, document (14) %.6f", exact, fd, printed);
    QVERIFY(std::abs(exact - fd) < 1e-4 * std::abs(exact));
    QVERIFY(std::abs(exact - 10.9263) < 1e-3);
    QVERIFY(std::abs(printed - 2.9480) < 1e-3);
    QVERIFY(std::abs(printed - exact) > 0.5 * std::abs(exact));
    QVERIFY(std::abs(printed + exact) > 0.5 * std::abs(exact));
    compare(60 * degree, &exact, &printed, &fd);
    qInfo("alpha = 60 deg: exact epsilon3 = %.6f rad/s^2, finite differences %.6f, document (14) %.6f", exact, fd, printed);
    QVERIFY(std::abs(exact - fd) < 1e-4 * std::abs(exact));
    QVERIFY(std::abs(printed - exact) > 0.05 * std::abs(exact));
    QVERIFY(std::abs(printed + exact) > 0.5 * std::abs(exact));
    // where sin α = 0 the printed formula happens to be right
    compare(180 * degree, &exact, &printed, &fd);
    QVERIFY(std::abs(printed - exact) < 1e-9 * std::abs(exact));
    // over the turn, (14) is off by more than 0.1 % almost everywhere else
    int wrong = 0, poses = 0;
    for (int i = 1; i < 72; ++i) {
        if (i == 36)
            continue; // α = 180°
        compare(i * 5 * degree, &exact, &printed, &fd);
        ++poses;
        wrong += std::abs(printed - exact) > 1e-3 * std::max(1.0, std::abs(exact)) ? 1 : 0;
    }
    QVERIFY2(wrong > poses * 9 / 10, qPrintable(QString("%1 of %2").arg(wrong).arg(poses)));
}

// -- Grashof and the assembly limits ----------------------------------------------------------

void TestFourBar::grashofClasses_data()
{
    QTest::addColumn<double>("ab");
    QTest::addColumn<double>("bc");
    QTest::addColumn<double>("cd");
    QTest::addColumn<double>("ad");
    QTest::addColumn<int>("expected");
    QTest::addColumn<QString>("word");
    QTest::addColumn<bool>("fullTurn");
    using G = fourbar::Grashof;
    QTest::newRow("crank-rocker") << 40.0 << 120.0 << 100.0 << 140.0 << int(G::CrankRocker) << "crank-rocker" << true;
    QTest::newRow("double-crank") << 100.0 << 120.0 << 110.0 << 40.0 << int(G::DoubleCrank) << "double-crank" << true;
    QTest::newRow("rocker-crank") << 100.0 << 120.0 << 40.0 << 140.0 << int(G::RockerCrank) << "rocker-crank" << false;
    QTest::newRow("double-rocker") << 100.0 << 40.0 << 120.0 << 140.0 << int(G::DoubleRocker) << "double-rocker" << false;
    QTest::newRow("triple-rocker") << 100.0 << 120.0 << 100.0 << 140.0 << int(G::TripleRocker) << "triple-rocker" << false;
    QTest::newRow("change-point") << 40.0 << 100.0 << 60.0 << 80.0 << int(G::ChangePoint) << "change-point" << true;
    QTest::newRow("parallelogram") << 50.0 << 100.0 << 50.0 << 100.0 << int(G::ChangePoint) << "change-point" << true;
}

void TestFourBar::grashofClasses()
{
    QFETCH(double, ab);
    QFETCH(double, bc);
    QFETCH(double, cd);
    QFETCH(double, ad);
    QFETCH(int, expected);
    QFETCH(QString, word);
    QFETCH(bool, fullTurn);
    const auto m = make(lengths(ab, bc, cd, ad));
    QCOMPARE(int(FourBar::grashof(m->design())), expected);
    QCOMPARE(QString::fromLatin1(fourbar::grashofName(fourbar::Grashof(expected))), word);
    QCOMPARE(m->crankTurnsFully(), fullTurn);
    const auto texts = m->reportText(m->homePose());
    const auto grashof = std::find_if(texts.begin(), texts.end(), [](const ReportText &t) { return t.name == "grashof"; });
    QVERIFY(grashof != texts.end());
    QCOMPARE(grashof->group, ReportGroup::Derived);
    QCOMPARE(QString::fromStdString(grashof->text), word);
    // the crank turns fully exactly when it sweeps [0°, 360°] with every pose solvable
    const Interval r = m->variableRange(FourBar::variableAlpha);
    if (fullTurn) {
        QCOMPARE(r.min, 0.0);
        QCOMPARE(r.max, 2 * pi);
    } else {
        QVERIFY(r.max - r.min < 2 * pi - 1e-3);
    }
    for (int i = 0; i <= 200; ++i) {
        const double alpha = r.min + (r.max - r.min) * i / 200;
        auto pose = m->solveDirect(one(alpha));
        // (a change point's folded pose with B on D is undetermined, nothing else fails)
        QVERIFY2(pose.ok() || pose.failure().kind == FailureKind::Singular, pose.ok() ? "" : pose.failure().message.c_str());
    }
}

void TestFourBar::assemblyLimits()
{
    // Triple-rocker 100/120/100/140: |BD| = BC + CD at cos α = (AB² + AD² − (BC + CD)²)/(2·AB·AD).
    {
        const auto m = make(lengths(100, 120, 100, 140));
        const double limit = std::acos((100.0 * 100 + 140.0 * 140 - 220.0 * 220) / (2 * 100.0 * 140));
        const Interval r = m->variableRange(FourBar::variableAlpha);
        QVERIFY(std::abs(r.max - limit) < 1e-12);
        QVERIFY(std::abs(r.min + limit) < 1e-12);
        auto at = m->solveDirect(one(limit));
        QVERIFY(at.ok());
        // there the coupler and the rocker are in line: the dead point (direct singularity)
        QCOMPARE(m->singularity(*at).type, SingularityType::Direct);
        QVERIFY(std::abs(std::abs(reportValue(*m, *at, "gamma")) - pi) < 1e-6);
        for (const double beyond : {limit + 1e-6, limit + 0.3, -limit - 1e-6}) {
            auto refused = m->solveDirect(one(beyond));
            QVERIFY(!refused.ok());
            QCOMPARE(refused.failure().kind, FailureKind::OutOfRange);
            QCOMPARE(refused.failure().culprit, std::string("alpha"));
            const QString message = QString::fromStdString(refused.failure().message);
            QVERIFY2(message.startsWith(QStringLiteral("alpha = ")), qPrintable(message));
            QVERIFY2(message.contains(QStringLiteral("BC + CD = 220 mm")), qPrintable(message));
            QVERIFY2(message.contains(QString::fromStdString(formatNumber(limit / degree, 3))), qPrintable(message));
            QVERIFY2(message.contains(QStringLiteral("triple-rocker")), qPrintable(message));
        }
    }
    // Grashof double-rocker 100/40/120/140: both limits bind, the upper interval is kept:
    // |BD| = |BC − CD| at its start, BC + CD at its end.
    {
        const auto m = make(lengths(100, 40, 120, 140));
        const double k1 = (100.0 * 100 + 140.0 * 140 - 160.0 * 160) / (2 * 100.0 * 140);
        const double k2 = (100.0 * 100 + 140.0 * 140 - 80.0 * 80) / (2 * 100.0 * 140);
        const Interval r = m->variableRange(FourBar::variableAlpha);
        QVERIFY(std::abs(r.min - std::acos(k2)) < 1e-12);
        QVERIFY(std::abs(r.max - std::acos(k1)) < 1e-12);
        auto below = m->solveDirect(one(r.min - 1e-3));
        QVERIFY(!below.ok());
        QVERIFY2(below.failure().message.find("|BC − CD| = 80 mm") != std::string::npos, below.failure().message.c_str());
        QVERIFY(m->homePose().inputs[0] > r.min && m->homePose().inputs[0] < r.max);
    }
    // A full turn is [0°, 360°]; beyond it the message says so.
    {
        const auto m = make(lengths(40, 120, 100, 140));
        auto refused = m->solveDirect(one(2 * pi + 0.1));
        QVERIFY(!refused.ok());
        QCOMPARE(refused.failure().culprit, std::string("alpha"));
        QVERIFY(refused.failure().message.find("360°") != std::string::npos);
        QVERIFY(m->solveDirect(one(0.0)).ok() && m->solveDirect(one(2 * pi)).ok());
        // the rocker's range: δ at the two collinear positions of crank and coupler
        const Interval delta = m->variableRange(FourBar::variableDelta);
        const double extended = std::acos((100.0 * 100 + 140.0 * 140 - 160.0 * 160) / (2 * 100.0 * 140));
        const double folded = std::acos((100.0 * 100 + 140.0 * 140 - 80.0 * 80) / (2 * 100.0 * 140));
        QVERIFY2(std::abs(delta.max - extended) < 1e-9, qPrintable(QString::number(delta.max / degree, 'g', 15)));
        QVERIFY2(std::abs(delta.min - folded) < 1e-9, qPrintable(QString::number(delta.min / degree, 'g', 15)));
        auto outside = m->solveInverse(one(extended + 0.01));
        QVERIFY(!outside.ok());
        QCOMPARE(outside.failure().culprit, std::string("delta"));
        QCOMPARE(outside.failure().kind, FailureKind::OutOfRange);
    }
}

// -- instantaneous centre and singular poses ---------------------------------------------------

void TestFourBar::instantCentre()
{
    const auto m = make(lengths(40, 120, 100, 140));
    const FourBarDesign &d = m->design();
    int checked = 0;
    for (const double alpha : interiorAlphas(*m, 37)) {
        auto pose = m->solveDirect(one(alpha));
        const double delta = pose->outputs[0];
        const Eigen::Vector2d P = fourbar::instantCentre(d, alpha, delta);
        if (!std::isfinite(P.x()))
            continue;
        const Eigen::Vector2d B(d.crank * std::cos(alpha), d.crank * std::sin(alpha));
        const Eigen::Vector2d D(d.ground, 0.0), C = D + d.rocker * Eigen::Vector2d(-std::cos(delta), std::sin(delta));
        auto cross = [](const Eigen::Vector2d &u, const Eigen::Vector2d &v) { return u.x() * v.y() - u.y() * v.x(); };
        const double scale = std::max(1.0, P.norm());
        QVERIFY(std::abs(cross(B, P)) < 1e-9 * scale * d.crank);         // on AB
        QVERIFY(std::abs(cross(C - D, P - D)) < 1e-9 * scale * d.rocker); // on DC
        // v_B = ω₁ × AB, v_C = θ̇₃ × DC (θ̇₃ = −ω₃), and both are ω₂ × (· − P)
        const fourbar::Motion motion = fourbar::motion(d, alpha, delta, d.omega1);
        const Eigen::Vector2d vB = d.omega1 * Eigen::Vector2d(-B.y(), B.x());
        const Eigen::Vector2d r = C - D;
        const Eigen::Vector2d vC = -motion.omega3 * Eigen::Vector2d(-r.y(), r.x());
        const double v = std::max(vB.norm(), vC.norm());
        QVERIFY(std::abs(vB.dot(B - P)) < 1e-9 * v * scale);
        QVERIFY(std::abs(vC.dot(C - P)) < 1e-9 * v * scale);
        const Eigen::Vector2d pb = B - P, pc = C - P;
        QVERIFY((vB - motion.omega2 * Eigen::Vector2d(-pb.y(), pb.x())).norm() < 1e-9 * v);
        QVERIFY((vC - motion.omega2 * Eigen::Vector2d(-pc.y(), pc.x())).norm() < 1e-9 * v);
        QCOMPARE(reportValue(*m, *pose, "P_x"), P.x());
        ++checked;
    }
    QVERIFY(checked > 30);
    // a parallelogram (AB = CD, BC = AD): AB ∥ DC always, the coupler translates, no P
    const auto parallel = make(lengths(50, 100, 50, 100));
    auto pose = parallel->solveDirect(one(1.0));
    QVERIFY(pose.ok());
    QVERIFY(std::isnan(reportValue(*parallel, *pose, "P_x")));
    QVERIFY(std::abs(reportValue(*parallel, *pose, "omega2")) < 1e-12);
    const Scene scene = parallel->scene(*pose);
    QVERIFY(std::none_of(scene.joints.begin(), scene.joints.end(), [](const SceneJoint &j) { return j.label == "P"; }));
    QVERIFY(scene.bars[2].label.find("infinity") != std::string::npos);
}

void TestFourBar::singularPoses()
{
    // Crank and coupler in line (|AC| = AB + BC): δ at its limit, J_q = 0: inverse singularity.
    const auto m = make(lengths(40, 120, 100, 140));
    const double extended = std::acos((100.0 * 100 + 140.0 * 140 - 160.0 * 160) / (2 * 100.0 * 140));
    auto pose = m->solveInverse(one(extended));
    QVERIFY(pose.ok());
    QCOMPARE(m->singularity(*pose).type, SingularityType::Inverse);
    QVERIFY(std::abs(reportValue(*m, *pose, "i31")) < 1e-6);
    QVERIFY(std::abs(reportValue(*m, *pose, "Jq")) < 1e-3);
    // the crank angle there: A, B, C in line
    const double alpha = pose->inputs[0];
    const Eigen::Vector2d C(140 - 100 * std::cos(extended), 100 * std::sin(extended));
    QVERIFY(angleDifference(alpha, std::atan2(C.y(), C.x())) < 1e-6);
    // the home pose is far from both
    QCOMPARE(m->singularity(m->homePose()).type, SingularityType::None);
    QVERIFY(m->singularity(m->homePose()).margin > 0.5);
}

// -- validation ----------------------------------------------------------------------------

void TestFourBar::badInput_data()
{
    QTest::addColumn<ParameterSet>("changes");
    QTest::addColumn<QString>("culprit");
    QTest::newRow("zero crank") << ParameterSet{{"AB", 0.0}} << "AB";
    QTest::newRow("negative coupler") << ParameterSet{{"BC", -5.0}} << "BC";
    QTest::newRow("NaN rocker") << ParameterSet{{"CD", notANumber}} << "CD";
    QTest::newRow("infinite ground") << ParameterSet{{"AD", std::numeric_limits<double>::infinity()}} << "AD";
    QTest::newRow("ground too long") << ParameterSet{{"AD", 400.0}} << "AD";
    QTest::newRow("flat") << ParameterSet{{"AD", 260.0}} << "AD";
    QTest::newRow("coupler too long") << ParameterSet{{"BC", 300.0}, {"AD", 100.0}} << "BC";
    QTest::newRow("branch 0.5") << ParameterSet{{"branch", 0.5}} << "branch";
    QTest::newRow("branch 0") << ParameterSet{{"branch", 0.0}} << "branch";
    QTest::newRow("coupler point 2") << ParameterSet{{"coupler_point", 2.0}} << "coupler_point";
    QTest::newRow("NaN omega") << ParameterSet{{"omega1", notANumber}} << "omega1";
    QTest::newRow("unknown") << ParameterSet{{"EF", 1.0}} << "EF";
}

void TestFourBar::badInput()
{
    QFETCH(ParameterSet, changes);
    QFETCH(QString, culprit);
    auto made = FourBar::createFrom(changes);
    QVERIFY(!made.ok());
    QCOMPARE(QString::fromStdString(made.failure().culprit), culprit);
    QVERIFY2(QString::fromStdString(made.failure().message).contains(culprit), made.failure().message.c_str());
    // the same through withParameters of a valid design
    const auto example = make(FourBarDesign{});
    auto changed = example->withParameters(changes);
    QVERIFY(!changed.ok());
    QCOMPARE(QString::fromStdString(changed.failure().culprit), culprit);
    if (culprit == QLatin1String("AD") && changes.begin()->second == 400.0) {
        QCOMPARE(QString::fromStdString(made.failure().message),
                 QStringLiteral("AD = 400 mm is not shorter than AB + BC + CD = 260 mm: the links cannot close the loop "
                                "ABCD for any crank angle α (each link must be shorter than the other three together)."));
    }
    // NaN joint variables are refused too
    auto nanAlpha = example->solveDirect(one(notANumber));
    QVERIFY(!nanAlpha.ok());
    QCOMPARE(nanAlpha.failure().culprit, std::string("alpha"));
    auto nanDelta = example->solveInverse(one(notANumber));
    QVERIFY(!nanDelta.ok());
    QCOMPARE(nanDelta.failure().culprit, std::string("delta"));
}

// -- modes, dragging, drawing, report ---------------------------------------------------------

void TestFourBar::otherBranch()
{
    const auto m = make(lengths(40, 120, 100, 140));
    const auto neighbours = m->modeNeighbours();
    QCOMPARE(neighbours.size(), std::size_t(1));
    QVERIFY(neighbours[0].sameInputs);
    QCOMPARE(neighbours[0].changes.at("branch"), -1.0);
    auto pose = m->solveDirect(one(60 * degree));
    const auto alternatives = m->modeAlternatives(*pose);
    QCOMPARE(alternatives.size(), std::size_t(1));
    const Pose &other = alternatives[0].pose;
    QCOMPARE(other.inputs[0], pose->inputs[0]);
    QCOMPARE(other.mode, -1);
    // C mirrored across BD: δ − δ₁ changes sign
    const double delta1 = std::atan2(40 * std::sin(60 * degree), 140 - 40 * std::cos(60 * degree));
    QVERIFY(angleDifference(other.outputs[0] - delta1, -(pose->outputs[0] - delta1)) < 1e-9);
    QVERIFY(reportValue(*alternatives[0].mechanism, other, "gamma") < 0);
    QVERIFY(std::abs(reportValue(*alternatives[0].mechanism, other, "gamma") + reportValue(*m, *pose, "gamma")) < 1e-9);
    // a design keeps its branch along a whole turn: γ never changes sign
    for (int i = 0; i <= 360; ++i) {
        auto p = m->solveDirect(one(i * degree));
        QVERIFY(reportValue(*m, *p, "gamma") > 0);
    }
}

void TestFourBar::dragging()
{
    const auto m = make(lengths(40, 120, 100, 140));
    const Pose home = m->homePose();
    // B towards 100°: the crank follows
    auto turned = m->dragHandle(home, 0, 40 * Eigen::Vector2d(std::cos(100 * degree), std::sin(100 * degree)));
    QVERIFY(turned.ok());
    QVERIFY(std::abs(turned->inputs[0] - 100 * degree) < 1e-12);
    // C towards the direction of δ = 70° from D: the rocker follows, the crank solves for it
    const Eigen::Vector2d target = Eigen::Vector2d(140, 0) + 80 * Eigen::Vector2d(-std::cos(70 * degree), std::sin(70 * degree));
    auto swung = m->dragHandle(*turned, 1, target);
    QVERIFY2(swung.ok(), swung.ok() ? "" : swung.failure().message.c_str());
    QVERIFY(std::abs(swung->outputs[0] - 70 * degree) < 1e-12);
    QVERIFY(std::abs(m->solveDirect(swung->inputs)->outputs[0] - 70 * degree) < 1e-9);
    // a rocker angle it cannot reach is refused with the reason
    auto far = m->dragHandle(*turned, 1, Eigen::Vector2d(140, 0) + 80 * Eigen::Vector2d(-std::cos(150 * degree), std::sin(150 * degree)));
    QVERIFY(!far.ok());
    QCOMPARE(far.failure().culprit, std::string("delta"));
    QVERIFY(!m->dragHandle(home, 7, {0, 0}).ok());
}

void TestFourBar::drawing()
{
    const auto m = make(lengths(40, 120, 100, 140));
    const FourBarDesign &d = m->design();
    const Scene first = m->scene(m->homePose());
    QCOMPARE(first.joints.size(), std::size_t(6)); // A, D, B, C, M, P
    QCOMPARE(first.bars.size(), std::size_t(4));
    QCOMPARE(first.angles.size(), std::size_t(3));
    QCOMPARE(first.handles.size(), std::size_t(2));
    QCOMPARE(first.polylines.size(), std::size_t(1));
    QVERIFY(first.polylines[0].closed);
    QVERIFY(first.polylines[0].points.size() > 300);
    for (int i = 0; i < 360; i += 7) {
        auto pose = m->solveDirect(one(i * degree));
        const Scene s = m->scene(*pose);
        QVERIFY(s.extent.isApprox(first.extent)); // constant over the motion
        for (int j = 0; j < 5; ++j)
            QVERIFY(s.extent.contains(s.joints[std::size_t(j)].position));
        // M on the curve (within the sampling), and at λ of BC
        const Eigen::Vector3d M = s.joints[4].position;
        const Eigen::Vector3d expected = s.joints[2].position + d.couplerPoint * (s.joints[3].position - s.joints[2].position);
        QVERIFY((M - expected).norm() < 1e-12);
        double nearest = 1e300;
        for (const Eigen::Vector3d &p : first.polylines[0].points)
            nearest = std::min(nearest, (p - M).norm());
        QVERIFY(nearest < 1.0);
        QCOMPARE(s.joints[std::size_t(s.handles[0].joint)].label, std::string("B"));
        QCOMPARE(s.joints[std::size_t(s.handles[1].joint)].label, std::string("C"));
    }
}

void TestFourBar::report()
{
    const auto m = make(FourBarDesign{});
    const ReportLayout &layout = m->reportLayout();
    for (const char *name : {"alpha", "delta", "gamma", "delta1", "beta"})
        QCOMPARE(layout.find(name)->group, ReportGroup::Pose);
    for (const char *name : {"J", "det_J", "Jq", "Jx"})
        QCOMPARE(layout.find(name)->group, ReportGroup::Jacobian);
    for (const char *name : {"omega3", "epsilon3", "i31", "omega1", "transmission", "M_x", "P_y"})
        QCOMPARE(layout.find(name)->group, ReportGroup::Derived);
    auto pose = m->solveDirect(one(60 * degree));
    // J_q·J = J_x, the interface's convention
    const Jacobians j = m->jacobians(*pose);
    QVERIFY(std::abs(j.inputs(0, 0) * j.full(0, 0) - j.outputs(0, 0)) < 1e-9 * std::abs(j.outputs(0, 0)));
    QCOMPARE(reportValue(*m, *pose, "J"), j.full(0, 0));
    const double gamma = std::abs(reportValue(*m, *pose, "gamma"));
    QCOMPARE(reportValue(*m, *pose, "transmission"), std::min(gamma, pi - gamma));
    // the example's transmission angle stays within [53.13°, 109.47°]: no warning
    QVERIFY(m->designWarnings().empty());
    const auto poor = make(lengths(70, 120, 100, 140)); // cos γ = −0.0042 + 0.8167·cos α: γ up to 145.2°, μ 34.8°
    QVERIFY(!poor->designWarnings().empty());
    QVERIFY(poor->designWarnings().front().find("transmission angle") != std::string::npos);
    const auto words = m->reportText(*pose);
    QCOMPARE(words.size(), std::size_t(2));
    QCOMPARE(words[0].name, std::string("branch"));
    QCOMPARE(words[0].text, std::string("open"));
}

QTEST_APPLESS_MAIN(TestFourBar)
#include "tst_fourbar.moc"
