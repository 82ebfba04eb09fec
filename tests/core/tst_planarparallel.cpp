// The planar parallel mechanism from a leg library (docs/mathematics.md): the five-bar and
// MOMA 3a rebuilt from legs give those kinds' poses and Jacobians; the 3-RPR of Innocenti and
// Parenti-Castelli has its six assembly modes; for random designs of every leg type every
// solution satisfies the leg equations and every solution a dense scan of φ finds is found;
// the Jacobians agree with finite differences; singular poses built by hand are classed.
#include "kinds/fivebar/fivebar.h"
#include "kinds/moma/moma.h"
#include "kinds/planarparallel/planarparallel.h"
#include "registry.h"
#include "support/kinematics.h"
#include "support/planardesigns.h"

#include <QTest>

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

using namespace pkm;
using namespace pkm::test;

namespace {
constexpr double deg = units::degree;
constexpr double pi = std::numbers::pi;

std::shared_ptr<const PlanarParallel> build(const ParameterSet &parameters)
{
    const MechanismPtr m = makeKind("planar-parallel", parameters);
    return std::dynamic_pointer_cast<const PlanarParallel>(m);
}

using pkm::test::legdesigns::fiveR;
using pkm::test::legdesigns::moma3a;

using pkm::test::legdesigns::threeRpr;

/// "A1x" from "A", "1", "x" (GCC 12 warns falsely, -Wrestrict, on chains of operator+).
std::string key(const char *head, const std::string &n, const char *tail)
{
    return joinText({head, n, tail});
}

/// The largest difference relative to the largest entry of `b` (of 1 core unit at the least, as tst_allkinds).
double relative(const Eigen::MatrixXd &a, const Eigen::MatrixXd &b)
{
    return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

/// The largest difference relative to the largest entry of `b` (a Jacobian, never all zero).
double relativeToLargest(const Eigen::MatrixXd &a, const Eigen::MatrixXd &b)
{
    return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

/// A random leg of any type from base point A to platform point B, with generous ranges.
void randomLeg(std::mt19937 &g, ParameterSet &p, int i, int type, bool free)
{
    const std::string n = std::to_string(i);
    p[key("leg", n, "_type")] = type;
    p[key("A", n, "x")] = uniform(g, -150, 150);
    p[key("A", n, "y")] = uniform(g, -150, 150);
    p[key("B", n, "x")] = free ? uniform(g, -60, 60) : 0.0;
    p[key("B", n, "y")] = free ? uniform(g, -60, 60) : 0.0;
    p[key("r", n, "")] = uniform(g, 60, 140);
    p[key("l", n, "")] = uniform(g, 80, 200);
    p[key("alpha", n, "")] = uniform(g, -pi, pi);
    p[key("a", n, "")] = uniform(g, 100, 200);
    p[key("k", n, "")] = uniform(g, 0.25, 0.6);
    p[key("working", n, "")] = uniform(g, 0, 1) < 0.5 ? -1 : 1;
    if (type == 0) {
        p[key("theta", n, "_min")] = -pi;
        p[key("theta", n, "_max")] = pi;
    } else if (type == 1) {
        p[key("q", n, "_min")] = -250;
        p[key("q", n, "_max")] = 250;
    } else if (type == 2) {
        p[key("q", n, "_min")] = 1;
        p[key("q", n, "_max")] = 500;
    } else {
        const double a = p[key("a", n, "")], k = p[key("k", n, "")];
        p[key("q", n, "_min")] = a * std::sqrt(1 + k * k - 2 * k * std::sin(80 * deg));
        p[key("q", n, "_max")] = a * std::sqrt(1 + k * k + 2 * k * std::sin(80 * deg));
    }
}

/// Every solution of the three circle equations by a dense scan of φ, independent of the
/// polynomial: at each φ legs 1 and 2 put P₁ on two circles (two branches), leg 3's residual
/// changes sign at a solution, which bisection refines.
std::vector<double> scanAngles(const std::array<PlanarLeg, 3> &legs, const std::array<planar::LegCircle, 3> &c, int samples)
{
    auto residual3 = [&](double phi, int branch, bool &ok) {
        const Eigen::Vector2d c2 = Eigen::Rotation2Dd(phi) * (legs[1].platform - legs[0].platform);
        const Eigen::Vector2d p = c[0].centre, q = c[1].centre - c2;
        const double d = (q - p).norm(), r1 = c[0].radius, r2 = c[1].radius;
        ok = d > 0 && d <= r1 + r2 && d >= std::abs(r1 - r2);
        if (!ok)
            return 0.0;
        const Eigen::Vector2d u = (q - p) / d;
        const double along = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
        const double across = std::sqrt(std::max(0.0, r1 * r1 - along * along));
        const Eigen::Vector2d P1 = p + along * u + (branch ? 1.0 : -1.0) * across * Eigen::Vector2d(-u.y(), u.x());
        const Eigen::Vector2d P3 = P1 + Eigen::Rotation2Dd(phi) * (legs[2].platform - legs[0].platform);
        return (P3 - c[2].centre).norm() - c[2].radius;
    };
    std::vector<double> found;
    for (int branch = 0; branch < 2; ++branch) {
        bool okPrev = false;
        double phiPrev = -pi, fPrev = residual3(phiPrev, branch, okPrev);
        for (int k = 1; k <= samples; ++k) {
            const double phi = -pi + 2 * pi * k / samples;
            bool ok = false;
            const double f = residual3(phi, branch, ok);
            if (ok && okPrev && (f == 0 || (f > 0) != (fPrev > 0))) {
                double lo = phiPrev, hi = phi, flo = fPrev;
                for (int it = 0; it < 60; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    bool okMid = false;
                    const double fm = residual3(mid, branch, okMid);
                    if ((fm > 0) == (flo > 0)) {
                        lo = mid;
                        flo = fm;
                    } else {
                        hi = mid;
                    }
                }
                found.push_back(0.5 * (lo + hi));
            }
            okPrev = ok;
            phiPrev = phi;
            fPrev = f;
        }
    }
    return found;
}
} // namespace

class TestPlanarParallel : public QObject
{
    Q_OBJECT

private slots:
    /// The five-bar example as two R̲RR legs: the same crank angles, platform point and J.
    void fiveBarFromLegs()
    {
        const auto pp = build(fiveR());
        const MechanismPtr fb = makeKind("fivebar");
        int compared = 0;
        for (double x = -40; x <= 140; x += 20) {
            for (double y = 60; y <= 200; y += 20) {
                const auto a = fb->solveInverse(pair(x, y));
                const auto b = pp->solveInverse(pair(x, y));
                QCOMPARE(bool(a), bool(b));
                if (!a)
                    continue;
                QVERIFY2(relative(b->inputs, a->inputs) < 1e-9, qPrintable(QString("%1 %2").arg(x).arg(y)));
                const auto direct = pp->solveDirect(a->inputs);
                QVERIFY(direct);
                QVERIFY(relative(direct->outputs, a->outputs) < 1e-9);
                Singularity s;
                evaluated(*fb, *a, &s);
                if (s.margin < 1e-3)
                    continue;
                QVERIFY(relativeToLargest(pp->jacobians(*b).full, fb->jacobians(*a).full) < 1e-9);
                ++compared;
            }
        }
        QVERIFY(compared > 20);
        QCOMPARE(pp->singularity(*pp->solveInverse(pair(50, 150))).type, SingularityType::None);
    }

    /// MOMA 3a as two P̲RR legs: the same slider positions, platform and J.
    void momaFromLegs()
    {
        const auto pp = build(moma3a());
        const MechanismPtr moma = makeKind("moma");
        int compared = 0;
        for (double p1 = 0; p1 <= 200; p1 += 25) {
            for (double p2 = 0; p2 <= 200; p2 += 25) {
                const auto a = moma->solveDirect(pair(p1, p2));
                const auto b = pp->solveDirect(pair(p1, p2));
                QCOMPARE(bool(a), bool(b));
                if (!a)
                    continue;
                QVERIFY(relative(b->outputs, a->outputs) < 1e-9);
                const auto back = pp->solveInverse(a->outputs);
                QVERIFY2(back && relative(back->inputs, a->inputs) < 1e-9, qPrintable(QString("%1 %2 %3").arg(p1).arg(p2).arg(back ? QString::number(relative(back->inputs, a->inputs)) : QString::fromStdString(back.failure().message))));
                QVERIFY(relativeToLargest(pp->jacobians(*b).full, moma->jacobians(*a).full) < 1e-9);
                ++compared;
            }
        }
        QVERIFY(compared > 40);
    }

    /// Six real assembly modes at ρ = (14.98, 15.38, 12); each satisfies the three leg
    /// equations and is found again when it is the pose to follow.
    void threeRprSixModes()
    {
        const auto m = build(threeRpr());
        const Coordinates q = triple(14.98, 15.38, 12);
        const auto start = std::chrono::steady_clock::now();
        const std::vector<Pose> modes = m->assemblies(q);
        const double micro = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
        qInfo("3-RPR direct kinematics: %zu solutions in %.1f µs", modes.size(), micro);
        QCOMPARE(int(modes.size()), 6);
        std::array<planar::LegCircle, 3> c;
        for (int i = 0; i < 3; ++i)
            c[std::size_t(i)] = planar::circle(m->design().legs[std::size_t(i)], q[i]);
        for (const Pose &pose : modes) {
            QVERIFY(planar::residual(m->design().legs, c, 3, m->platformPose(pose.outputs)) < 1e-9);
            const auto again = m->solveDirect(q, &pose);
            QVERIFY(again);
            QVERIFY((again->outputs - pose.outputs).norm() < 1e-9);
        }
        // the assembly parameter picks them in order of φ
        for (int k = 1; k <= 6; ++k) {
            ParameterSet p = threeRpr();
            p["assembly"] = k;
            const auto pose = build(p)->solveDirect(q);
            QVERIFY(pose);
            QVERIFY((pose->outputs - modes[std::size_t(k - 1)].outputs).norm() < 1e-9);
        }
    }

    /// Random 3-DOF designs of every leg type: every solution satisfies the equations, every
    /// solution of a dense φ scan is among them; continuation keeps the mode over small steps.
    void randomForwardProblems()
    {
        std::mt19937 g(20240607);
        int problems = 0, solutions = 0;
        double seconds = 0;
        for (int trial = 0; trial < 400 && problems < 150; ++trial) {
            std::array<PlanarLeg, 3> legs;
            ParameterSet p{{"platform", 2}};
            for (int i = 1; i <= 3; ++i)
                randomLeg(g, p, i, int(uniform(g, 0, 4)), true);
            for (int i = 0; i < 3; ++i) {
                const std::string n = std::to_string(i + 1);
                PlanarLeg &leg = legs[std::size_t(i)];
                leg.type = LegType(int(p[key("leg", n, "_type")]));
                leg.base = {p[key("A", n, "x")], p[key("A", n, "y")]};
                leg.platform = {p[key("B", n, "x")], p[key("B", n, "y")]};
                leg.crank = p[key("r", n, "")];
                leg.link = p[key("l", n, "")];
                leg.alpha = p[key("alpha", n, "")];
                leg.lever = p[key("a", n, "")];
                leg.ratio = p[key("k", n, "")];
                leg.range = {p[key("q", n, "_min")], p[key("q", n, "_max")]};
                leg.crankRange = {p[key("theta", n, "_min")], p[key("theta", n, "_max")]};
            }
            // inputs from a random pose, so that there is at least one solution
            const Eigen::Vector3d X0(uniform(g, -60, 60), uniform(g, -60, 60), uniform(g, -pi, pi));
            std::array<planar::LegCircle, 3> c;
            bool ok = true;
            for (int i = 0; i < 3; ++i) {
                PlanarLeg &leg = legs[std::size_t(i)];
                double q = 0;
                ok = ok && planar::inverse(leg, planar::platformPoint(leg, X0), 0.0, q) == planar::Reach::Yes;
                c[std::size_t(i)] = planar::circle(leg, q);
            }
            if (!ok)
                continue;
            ++problems;
            const auto start = std::chrono::steady_clock::now();
            const std::vector<Eigen::Vector3d> found = planar::threeCircleSolutions(legs, c);
            seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            solutions += int(found.size());
            QVERIFY(found.size() <= 6);
            for (const Eigen::Vector3d &X : found)
                QVERIFY(planar::residual(legs, c, 3, X) < 1e-9 * 500);
            auto has = [&](double phi) {
                return std::any_of(found.begin(), found.end(), [&](const Eigen::Vector3d &X) {
                    return std::abs(std::remainder(X.z() - phi, 2 * pi)) < 1e-6;
                });
            };
            QVERIFY2(has(X0.z()), qPrintable(QString("trial %1: the pose the inputs came from").arg(trial)));
            for (double phi : scanAngles(legs, c, 20000))
                QVERIFY2(has(phi), qPrintable(QString("trial %1: φ = %2° of the scan not found").arg(trial).arg(phi / deg)));
        }
        QVERIFY(problems >= 100);
        qInfo("%d random forward problems, %d solutions, %.1f µs per solve", problems, solutions, 1e6 * seconds / problems);
    }

    /// Jacobians against finite differences and round trips, for designs of every leg type
    /// on a point platform, a platform of constant orientation and a free platform.
    void jacobiansAndRoundTrips()
    {
        std::mt19937 g(7);
        int checked[3] = {0, 0, 0};
        std::array<int, 4> typesChecked{};
        for (int trial = 0; trial < 3000; ++trial) {
            const int platform = trial % 3;
            ParameterSet p{{"platform", platform}};
            const int n = platform == 2 ? 3 : 2;
            std::array<int, 3> types{};
            for (int i = 1; i <= 3; ++i) {
                int type = int(uniform(g, 0, 4));
                if (platform == 1)
                    type = uniform(g, 0, 1) < 0.5 ? 1 : 3;
                types[std::size_t(i - 1)] = type;
                randomLeg(g, p, i, type, platform != 0);
            }
            p["assembly"] = n == 2 ? (uniform(g, 0, 1) < 0.5 ? 1 : -1) : 1;
            auto made = createMechanism("planar-parallel", p);
            if (!made)
                continue;
            const Mechanism &m = **made;
            const Pose pose = m.homePose();
            Singularity s;
            evaluated(m, pose, &s);
            if (s.margin < 0.05)
                continue;
            const Jacobians j = m.jacobians(pose);
            QVERIFY((j.inputs * j.full - j.outputs).cwiseAbs().maxCoeff() <= 1e-9 * std::max(1.0, j.outputs.cwiseAbs().maxCoeff()));
            const auto differences = inverseDifferences(m, pose.outputs, 1e-6, &pose);
            if (!differences)
                continue;
            QVERIFY2(relative(*differences, j.full) < 1e-5, qPrintable(QString("trial %1").arg(trial)));
            const auto direct = m.solveDirect(pose.inputs, &pose);
            QVERIFY(direct && (direct->outputs - pose.outputs).norm() < 1e-8);
            const auto inverse = m.solveInverse(direct->outputs, &pose);
            QVERIFY(inverse && (inverse->inputs - pose.inputs).norm() < 1e-8);
            ++checked[platform];
            for (int i = 0; i < n; ++i)
                ++typesChecked[std::size_t(types[std::size_t(i)])];
        }
        qInfo("checked %d point, %d translating, %d free designs", checked[0], checked[1], checked[2]);
        QVERIFY(checked[0] >= 20 && checked[1] >= 5 && checked[2] >= 20);
        for (int count : typesChecked)
            QVERIFY(count >= 10);
    }

    /// A small input change never jumps the mode: a sweep of q₁ follows one branch.
    void continuation()
    {
        const auto m = build(threeRpr());
        Pose pose = *m->solveDirect(triple(14.98, 15.38, 12));
        for (int k = 1; k <= 200; ++k) {
            const Coordinates q = triple(14.98 + 0.01 * k, 15.38, 12);
            const auto next = m->solveDirect(q, &pose);
            if (!next)
                break;
            QVERIFY((next->outputs - pose.outputs).norm() < 0.2);
            pose = *next;
        }
    }

    /// Singular poses built by hand: a leg stretched (inverse), the distal links in line
    /// (direct), both (combined), and three struts through one point (direct, 3 DOF).
    void singularities()
    {
        // leg 1 R̲RR stretched along +x to P = (200, 0); leg 2 a strut from (300, 0) on the same line
        ParameterSet p{{"platform", 0}, {"leg1_type", 0}, {"leg2_type", 2}, {"A1x", 0}, {"A1y", 0}, {"A2x", 300},
                       {"A2y", 0}, {"r1", 80}, {"l1", 120}, {"q2_min", 10}, {"q2_max", 300}};
        const auto combined = build(p);
        Pose pose;
        pose.inputs = pair(0.0, 100.0);
        pose.outputs = pair(200.0, 0.0);
        QCOMPARE(combined->singularity(pose).type, SingularityType::Combined);
        // the strut moved off the line: inverse only
        p["A2y"] = 100;
        pose.inputs = pair(0.0, std::hypot(100.0, 100.0));
        QCOMPARE(build(p)->singularity(pose).type, SingularityType::Inverse);
        // the five-bar with its distal links in line: C on the segment between the elbows
        const auto five = build(fiveR());
        Pose line;
        line.inputs = pair(0.0, pi); // elbows at (80, 0) and (20, 0): 60 apart, links 120 each
        line.outputs = pair(50.0, std::sqrt(120.0 * 120.0 - 30.0 * 30.0));
        QCOMPARE(five->singularity(line).type, SingularityType::None);
        Pose folded;
        folded.inputs = pair(90 * deg, 90 * deg); // elbows (0, 80), (100, 80): 100 apart
        ParameterSet q = fiveR();
        q["l1"] = 50;
        q["l2"] = 50;
        q["r1"] = 80;
        const auto inLine = createMechanism("planar-parallel", q);
        QVERIFY(inLine);
        folded.outputs = pair(50.0, 80.0);
        QCOMPARE(std::dynamic_pointer_cast<const PlanarParallel>(*inLine)->singularity(folded).type, SingularityType::Direct);
        // 3-RPR: the struts' lines all through Q = (5, 5)
        const auto rpr = build(threeRpr());
        const Eigen::Vector3d X(4.0, 2.0, 0.3);
        const Eigen::Vector2d Q(5.0, 5.0);
        ParameterSet r = threeRpr();
        Pose concurrent;
        concurrent.outputs = triple(X.x(), X.y(), X.z());
        concurrent.inputs = triple(0, 0, 0);
        for (int i = 0; i < 3; ++i) {
            const PlanarLeg &leg = rpr->design().legs[std::size_t(i)];
            const Eigen::Vector2d P = planar::platformPoint(leg, X);
            const Eigen::Vector2d A = Q + 3.0 * (P - Q);
            r[key("A", std::to_string(i + 1), "x")] = A.x();
            r[key("A", std::to_string(i + 1), "y")] = A.y();
            r[key("q", std::to_string(i + 1), "_max")] = 200;
            concurrent.inputs[i] = (P - A).norm();
        }
        auto made = createMechanism("planar-parallel", r);
        QVERIFY2(made, made ? "" : made.failure().message.c_str());
        QCOMPARE(std::dynamic_pointer_cast<const PlanarParallel>(*made)->singularity(concurrent).type, SingularityType::Direct);
    }

    /// П̲RR legs: the crank angle follows the П-joint (3–5), and the П-joint at θ = ±90° is a
    /// direct singularity of the whole mechanism (J_x carries ∂d/∂θ).
    /// The other assembly modes of a 3-DOF design are made with one shared search of their
    /// home poses (modeNeighbours): each comes out as withParameters() makes it alone, to the
    /// last bit of its home pose and its bounds.
    void assemblyNeighboursAsMadeAlone()
    {
        for (const ParameterSet &parameters : {threeRpr(), pkm::test::legdesigns::threePrr()}) {
            const auto m = build(parameters);
            QVERIFY(m);
            int assemblies = 0;
            for (const ModeAlternative &neighbour : m->modeNeighbours()) {
                const auto alone = m->withParameters(neighbour.changes);
                QVERIFY(alone);
                const Pose a = neighbour.mechanism->homePose(), b = (*alone)->homePose();
                QCOMPARE(a.inputs.size(), b.inputs.size());
                for (int i = 0; i < a.inputs.size(); ++i)
                    QCOMPARE(a.inputs[i], b.inputs[i]);
                for (int i = 0; i < a.outputs.size(); ++i)
                    QCOMPARE(a.outputs[i], b.outputs[i]);
                const auto boundsOf = [](const Mechanism &mechanism) { return mechanism.planarWorkspace()->workspaceBounds(); };
                QVERIFY(boundsOf(*neighbour.mechanism).min() == boundsOf(**alone).min());
                QVERIFY(boundsOf(*neighbour.mechanism).max() == boundsOf(**alone).max());
                assemblies += neighbour.changes.size() == 1 && neighbour.changes.count("assembly");
            }
            QVERIFY(assemblies >= 2);
        }
    }

    /// The determinants' units follow the legs' types (units::power): a design scaled by 2 in
    /// every length, at the scaled pose, has each determinant scaled by 2 to the power of mm in
    /// its unit, for random designs of every leg type and platform.
    void determinantUnitsFollowTheLegs()
    {
        auto lengthPower = [](const Unit &unit) {
            for (const units::PowerUnit &p : units::powerUnits) {
                if (p.unit.symbol == unit.symbol)
                    return p.length;
            }
            return 99;
        };
        std::mt19937 g(11);
        int checked = 0;
        for (int trial = 0; trial < 400 && checked < 60; ++trial) {
            const int platform = trial % 3;
            ParameterSet p{{"platform", platform}};
            std::array<int, 3> types{};
            for (int i = 1; i <= 3; ++i) {
                types[std::size_t(i - 1)] = platform == 1 ? (uniform(g, 0, 1) < 0.5 ? 1 : 3) : int(uniform(g, 0, 4));
                randomLeg(g, p, i, types[std::size_t(i - 1)], platform != 0);
            }
            auto made = createMechanism("planar-parallel", p);
            if (!made)
                continue;
            ParameterSet scaled = p;
            for (int i = 1; i <= 3; ++i) {
                const std::string n = std::to_string(i);
                for (const char *length : {"A", "B"}) {
                    scaled[key(length, n, "x")] *= 2;
                    scaled[key(length, n, "y")] *= 2;
                }
                for (const char *length : {"r", "l", "a"})
                    scaled[key(length, n, "")] *= 2;
                if (types[std::size_t(i - 1)] != 0) {
                    scaled[key("q", n, "_min")] *= 2;
                    scaled[key("q", n, "_max")] *= 2;
                }
            }
            auto madeScaled = createMechanism("planar-parallel", scaled);
            QVERIFY(madeScaled);
            const Mechanism &m = **made, &m2 = **madeScaled;
            const Pose pose = m.homePose();
            Singularity s;
            const std::vector<double> v = evaluated(m, pose, &s);
            if (s.margin < 0.05)
                continue;
            const int n = platform == 2 ? 3 : 2;
            Pose reference = pose;
            for (int i = 0; i < n; ++i) {
                if (types[std::size_t(i)] != 0)
                    reference.inputs[i] *= 2;
            }
            reference.outputs[0] *= 2;
            reference.outputs[1] *= 2;
            const auto pose2 = m2.solveDirect(reference.inputs, &reference);
            QVERIFY(pose2 && (pose2->outputs - reference.outputs).norm() < 1e-6);
            const std::vector<double> v2 = evaluated(m2, *pose2);
            for (const char *name : {"det_J", "det_Jq", "det_Jx"}) {
                const ReportEntry *e = m.reportLayout().find(name);
                QVERIFY(e);
                const int power = lengthPower(e->unit);
                QVERIFY2(power != 99, name);
                const double ratio = v2[std::size_t(e->offset)] / v[std::size_t(e->offset)];
                QVERIFY2(std::abs(ratio / std::pow(2.0, power) - 1) < 1e-6,
                         qPrintable(QString("trial %1 %2 ratio %3 unit %4").arg(trial).arg(name).arg(ratio).arg(e->unit.symbol.data())));
            }
            ++checked;
        }
        QVERIFY(checked >= 30);
    }

    void pjointLegs()
    {
        PlanarLeg leg;
        leg.type = LegType::PiRR;
        leg.lever = 170;
        leg.ratio = 0.4;
        leg.alpha = 30 * deg;
        for (double theta = -60 * deg; theta <= 60 * deg; theta += 10 * deg) {
            const double d = planar::pjointDiagonal(leg, theta);
            QVERIFY(std::abs(planar::pjointAngle(leg, d) - theta) < 1e-12);
            const double h = 1e-6;
            const double numeric = (planar::pjointDiagonal(leg, theta + h) - planar::pjointDiagonal(leg, theta - h)) / (2 * h);
            QVERIFY(std::abs(numeric - planar::pjointJacobian(leg, theta)) < 1e-6);
        }
        QVERIFY(std::abs(planar::pjointDiagonal(leg, 60 * deg) - 231.4) < 0.05);
        QVERIFY(std::abs(planar::pjointDiagonal(leg, -60 * deg) - 116.2) < 0.05);
        QVERIFY(std::abs(planar::pjointJacobian(leg, 90 * deg)) < 1e-9);
    }
};

QTEST_MAIN(TestPlanarParallel)
#include "tst_planarparallel.moc"
