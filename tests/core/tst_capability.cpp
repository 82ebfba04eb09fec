// What the actuators deliver at the platform (core/capability.h), for every kind: force and
// speed against virtual work and against the actuator box sampled by brute force, the
// stiffness against finite differences of an elastic model built on the kind's own inverse
// kinematics, the exact 0/∞ of singular poses, and the П-joint's published characteristics.
#include "capability.h"
#include "kinds/pjoint/pjoint.h"
#include "support/kinematics.h"
#include "support/planardesigns.h"

#include <QTest>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>
#include <random>

using namespace pkm;
using namespace pkm::test;

namespace {

using capability::Actuators;

struct Case {
    MechanismPtr mechanism;
    Pose pose;
    Actuators actuators;
    std::vector<double> values;
    Eigen::MatrixXd J; ///< rows and columns of the actuators
};

Case prepare(const char *kind, const ParameterSet &parameters, const Coordinates *outputs = nullptr)
{
    Case c;
    c.mechanism = makeKind(kind, parameters);
    c.pose = c.mechanism->homePose();
    if (outputs)
        c.pose = *c.mechanism->solveInverse(*outputs, &c.pose);
    c.actuators = capability::actuatorsOf(*c.mechanism);
    const ReportLayout *layout = capability::layoutFor(c.actuators);
    if (!layout)
        return c;
    c.values.assign(std::size_t(layout->size), std::nan(""));
    Singularity s;
    evaluated(*c.mechanism, c.pose, &s);
    capability::evaluate(*c.mechanism, c.actuators, c.pose, s.type, c.values);
    const Eigen::MatrixXd full = c.mechanism->jacobians(c.pose).full;
    const int n = c.actuators.count;
    c.J.resize(n, n);
    for (int r = 0; r < n; ++r)
        c.J.row(r) = full.row(c.actuators.inputs[std::size_t(r)]).head(n);
    return c;
}

double value(const Case &c, const char *name)
{
    const ReportEntry *entry = capability::layoutFor(c.actuators)->find(name);
    return c.values[std::size_t(entry->offset)];
}

/// An actuator's limit in the units the Jacobian products take (N·mm, N·mm/rad for a rotary).
double scaled(const Case &c, int i, double capability::Actuator::*field)
{
    const capability::Actuator &a = c.actuators.items[std::size_t(i)];
    const bool perMetre = a.rotary && (field == &capability::Actuator::force || field == &capability::Actuator::stiffness);
    return a.*field * (perMetre ? 1e3 : 1.0);
}

/// A rotary output's force and stiffness are reported in N·m, the products give N·mm.
double outputScale(const Case &c) { return c.actuators.rotaryOutput ? 1e3 : 1.0; }

/// Points of the image of the box |u_i| ≤ limit_i under M (n×n): every vertex, then random
/// points of the box; for a 3-DOF platform only those with zero last component (zero moment
/// or rotation, capability.h), found by solving for the last actuator.
std::vector<Eigen::Vector2d> sampledImage(const Eigen::MatrixXd &M, const Eigen::VectorXd &limit, bool cut, int count)
{
    std::mt19937 generator(19);
    std::vector<Eigen::Vector2d> points;
    const int n = int(M.cols());
    const auto keep = [&](const Eigen::VectorXd &u) {
        const Eigen::VectorXd image = M * u;
        points.push_back(n == 1 ? Eigen::Vector2d(image[0], 0.0) : Eigen::Vector2d(image[0], image[1]));
    };
    for (int s = 0; s < count; ++s) {
        Eigen::VectorXd u(n);
        for (int j = 0; j < n; ++j) {
            const double pick = uniform(generator, 0.0, 1.0);
            u[j] = s < (1 << n) ? ((s >> j & 1) ? limit[j] : -limit[j])
                                : (pick < 0.3 ? limit[j] : pick < 0.6 ? -limit[j] : uniform(generator, -limit[j], limit[j]));
        }
        if (cut) {
            for (int k = 0; k < n; ++k) { // make the last row vanish by moving one actuator
                Eigen::VectorXd v = u;
                const double rest = M.row(n - 1).dot(v) - M(n - 1, k) * v[k];
                if (M(n - 1, k) == 0.0)
                    continue;
                v[k] = -rest / M(n - 1, k);
                if (std::abs(v[k]) <= limit[k])
                    keep(v);
            }
        } else {
            keep(u);
        }
    }
    return points;
}

/// The largest norm of the points, and the smallest over directions of the largest reach.
std::pair<double, double> bestAndWorst(const std::vector<Eigen::Vector2d> &points, bool line)
{
    double best = 0.0, worst = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d &p : points)
        best = std::max(best, p.norm());
    const int directions = line ? 2 : 7200;
    for (int d = 0; d < directions; ++d) {
        const double angle = 2.0 * std::numbers::pi * d / directions;
        const Eigen::Vector2d u(std::cos(angle), std::sin(angle));
        double reach = 0.0;
        for (const Eigen::Vector2d &p : points)
            reach = std::max(reach, p.dot(u));
        worst = std::min(worst, reach);
    }
    return {best, worst};
}

} // namespace

class TestCapability : public QObject
{
    Q_OBJECT

private:
    static void addCases()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<int>("variant");
        for (const char *kind : {"pjoint", "fourbar", "fivebar", "moma", "oxglide", "planar-parallel"})
            QTest::addRow("%s", kind) << QString(kind) << 0;
        QTest::addRow("planarparallel 3-PRR") << QStringLiteral("planar-parallel") << 1;
        QTest::addRow("planarparallel 3-PRR turned") << QStringLiteral("planar-parallel") << 2;
    }

    static Case currentCase()
    {
        QFETCH(QString, kind);
        QFETCH(int, variant);
        if (variant == 0)
            return prepare(kind.toUtf8().constData(), {});
        const ParameterSet p = legdesigns::threePrr();
        const Coordinates turned = triple(12.0, -8.0, 10.0 * units::degree);
        return variant == 2 ? prepare("planar-parallel", p, &turned) : prepare("planar-parallel", p);
    }

private slots:
    void everyKindHasActuators_data() { addCases(); }
    void everyKindHasActuators()
    {
        const Case c = currentCase();
        QVERIFY(c.actuators.count >= 1);
        QCOMPARE(c.actuators.count, c.actuators.outputs);
        for (const double v : c.values)
            QVERIFY2(std::isfinite(v), "a regular pose has finite capability values");
        QVERIFY(value(c, "force_worst") > 0.0);
        QVERIFY(value(c, "force_best") >= value(c, "force_worst") * (1 - 1e-12));
        QVERIFY(value(c, "speed_best") >= value(c, "speed_worst") * (1 - 1e-12));
    }

    void forceAgainstSampledActuatorBox_data() { addCases(); }
    void forceAgainstSampledActuatorBox()
    {
        const Case c = currentCase();
        const int n = c.actuators.count;
        Eigen::VectorXd limit(n);
        for (int i = 0; i < n; ++i)
            limit[i] = scaled(c, i, &capability::Actuator::force);
        // F = Jᵀ·τ: the statics of the ideal mechanism
        const auto [best, worst] = bestAndWorst(sampledImage(c.J.transpose(), limit, n == 3, 20000), n == 1);
        const double scale = outputScale(c);
        QVERIFY2(best <= value(c, "force_best") * scale * (1 + 1e-9), "no sampled force exceeds force_best");
        QVERIFY2(best >= value(c, "force_best") * scale * (1 - 1e-9), "a vertex reaches force_best");
        QVERIFY2(worst >= value(c, "force_worst") * scale * (1 - 1e-9), "every direction reaches force_worst");
        QVERIFY2(worst <= value(c, "force_worst") * scale * (1 + 1e-3), "the weakest direction reaches no more");
    }

    void speedAgainstSampledActuatorBox_data() { addCases(); }
    void speedAgainstSampledActuatorBox()
    {
        const Case c = currentCase();
        const int n = c.actuators.count;
        Eigen::VectorXd limit(n);
        for (int i = 0; i < n; ++i)
            limit[i] = c.actuators.items[std::size_t(i)].speed;
        const Eigen::MatrixXd G = c.J.inverse(); // ẋ = J⁻¹·q̇
        const auto [best, worst] = bestAndWorst(sampledImage(G, limit, n == 3, 20000), n == 1);
        QVERIFY(best <= value(c, "speed_best") * (1 + 1e-9));
        QVERIFY(best >= value(c, "speed_best") * (1 - 1e-9));
        QVERIFY(worst >= value(c, "speed_worst") * (1 - 1e-9));
        QVERIFY(worst <= value(c, "speed_worst") * (1 + 1e-3));
    }

    void forceAndSpeedByVirtualWork_data() { addCases(); }
    void forceAndSpeedByVirtualWork()
    {
        // τ·q̇ = F·ẋ for any admissible τ and motion, with q̇ from a finite difference of the
        // kind's own inverse kinematics (not from J)
        const Case c = currentCase();
        const int n = c.actuators.count;
        std::mt19937 generator(7);
        for (int trial = 0; trial < 5; ++trial) {
            Eigen::VectorXd tau(n), xdot(n);
            for (int i = 0; i < n; ++i) {
                tau[i] = uniform(generator, -1.0, 1.0) * scaled(c, i, &capability::Actuator::force);
                xdot[i] = uniform(generator, -1.0, 1.0);
            }
            const double h = 1e-6;
            const auto inputsAt = [&](double s) {
                const Coordinates x = c.pose.outputs + s * xdot;
                const Result<Pose> pose = c.mechanism->solveInverse(x, &c.pose);
                Eigen::VectorXd q(n);
                for (int i = 0; i < n; ++i)
                    q[i] = pose->inputs[c.actuators.inputs[std::size_t(i)]];
                return q;
            };
            const Eigen::VectorXd qdot = (inputsAt(h) - inputsAt(-h)) / (2 * h);
            const Eigen::VectorXd force = c.J.transpose() * tau;
            QVERIFY(std::abs(tau.dot(qdot) - force.dot(xdot)) <= 1e-5 * (tau.norm() * qdot.norm() + 1.0));
        }
    }

    void stiffnessAgainstElasticModel_data() { addCases(); }
    void stiffnessAgainstElasticModel()
    {
        // actuators as springs about the pose's inputs: U(x) = ½·Σ k_i·(q_i(x) − q_i)², with
        // q(x) the kind's inverse kinematics; K is the Hessian of U at the pose
        const Case c = currentCase();
        const int n = c.actuators.count;
        const auto energy = [&](const Eigen::VectorXd &dx) {
            const Coordinates x = c.pose.outputs + dx;
            const Result<Pose> pose = c.mechanism->solveInverse(x, &c.pose);
            double u = 0.0;
            for (int i = 0; i < n; ++i) {
                const int input = c.actuators.inputs[std::size_t(i)];
                const double dq = pose->inputs[input] - c.pose.inputs[input];
                u += 0.5 * scaled(c, i, &capability::Actuator::stiffness) * dq * dq;
            }
            return u;
        };
        const ReportEntry *entry = capability::layoutFor(c.actuators)->find("stiffness");
        const double h = 1e-3;
        for (int j = 0; j < n; ++j) {
            for (int k = 0; k < n; ++k) {
                const double step = (c.actuators.rotaryOutput || j == 2 || k == 2) ? 1e-5 : h;
                Eigen::VectorXd ej = Eigen::VectorXd::Zero(n), ek = Eigen::VectorXd::Zero(n);
                ej[j] = step;
                ek[k] = step;
                const double hessian = (energy(ej + ek) - energy(ej - ek) - energy(ek - ej) + energy(-ej - ek)) / (4 * step * step);
                const double reported = c.values[std::size_t(entry->offset + j * n + k)] * outputScale(c);
                const double diagonal = c.values[std::size_t(entry->offset + j * n + j)] * outputScale(c);
                QVERIFY2(std::abs(hessian - reported) <= 1e-3 * std::abs(diagonal) + 1e-6,
                         qPrintable(QStringLiteral("K[%1][%2] = %3, elastic model %4").arg(j).arg(k).arg(reported).arg(hessian)));
            }
        }
        // the weakest direction: no unit force deflects more than 1/stiffness_worst
        const double worst = value(c, "stiffness_worst");
        QVERIFY(worst > 0.0);
        Eigen::MatrixXd K(n, n);
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                K(j, k) = c.values[std::size_t(entry->offset + j * n + k)];
        if (n <= 2)
            QVERIFY(std::abs(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues()[0] - worst) <= 1e-9 * K.norm());
    }

    void deflectionBalancesTheLoad_data() { addCases(); }
    void deflectionBalancesTheLoad()
    {
        // the deflection under the design's load is the elastic equilibrium K·δ = F of the
        // actuators' springs; with no load (the default) it is 0
        const Case c = currentCase();
        const int n = c.actuators.count;
        QCOMPARE(value(c, "deflection"), 0.0);
        ParameterSet load;
        if (c.actuators.rotaryOutput) {
            load = {{"load_torque", 3.0}};
        } else {
            load = {{"load_x", 20.0}, {"load_y", -35.0}};
            if (n == 3)
                load["load_moment"] = 1.5;
        }
        const MechanismPtr loaded = *c.mechanism->withParameters(load);
        const Actuators actuators = capability::actuatorsOf(*loaded);
        std::vector<double> v(c.values.size());
        Singularity s;
        evaluated(*loaded, c.pose, &s);
        capability::evaluate(*loaded, actuators, c.pose, s.type, v);
        const ReportLayout *layout = capability::layoutFor(actuators);
        const auto at = [&](const char *name, int i = 0) { return v[std::size_t(layout->find(name)->offset + i)]; };
        Eigen::MatrixXd K(n, n);
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                K(j, k) = at("stiffness", j * n + k) * outputScale(c); // N/mm, N·mm/rad
        Eigen::VectorXd delta(n), force(n);
        if (c.actuators.rotaryOutput) {
            delta[0] = at("deflection");
            force[0] = 3.0e3; // N·mm
        } else {
            delta[0] = at("deflection", 0);
            delta[1] = at("deflection", 1);
            force[0] = 20.0;
            force[1] = -35.0;
            QVERIFY(std::abs(at("deflection_norm") - delta.head(2).norm()) <= 1e-12 * delta.head(2).norm());
            if (n == 3) {
                delta[2] = at("deflection_angle");
                force[2] = 1.5e3;
            }
        }
        QVERIFY(delta.norm() > 0.0);
        const Eigen::VectorXd balance = K * delta;
        QVERIFY2((balance - force).norm() <= 1e-6 * force.norm(),
                 qPrintable(QStringLiteral("K·δ − F = %1 N").arg((balance - force).norm())));
    }

    void resolutionIsTheFarthestHalfStepError_data() { addCases(); }
    void resolutionIsTheFarthestHalfStepError()
    {
        const Case c = currentCase();
        const int n = c.actuators.count;
        Eigen::VectorXd half(n);
        for (int i = 0; i < n; ++i)
            half[i] = 0.5 * c.actuators.items[std::size_t(i)].step;
        const Eigen::MatrixXd G = c.J.inverse().topRows(std::min(n, 2));
        std::mt19937 generator(3);
        double largest = 0.0;
        for (int s = 0; s < 4000; ++s) {
            Eigen::VectorXd dq(n);
            for (int i = 0; i < n; ++i)
                dq[i] = s < (1 << n) ? ((s >> i & 1) ? half[i] : -half[i]) : uniform(generator, -half[i], half[i]);
            largest = std::max(largest, (G * dq).norm());
        }
        QCOMPARE_LE(std::abs(largest - value(c, "resolution_worst")), 1e-12 * largest);
    }

    void pjointKeepsItsCharacteristics()
    {
        // the capability of the П-joint is its figs. 15–17 torque, speed and resolution
        const auto joint = make(PJointDesign{});
        for (const double thetaDeg : {-60.0, -20.0, 0.0, 35.0, 60.0}) {
            const Pose pose = *joint->solveInverse(one(thetaDeg * units::degree));
            Case c;
            c.mechanism = joint;
            c.pose = pose;
            c.actuators = capability::actuatorsOf(*joint);
            QCOMPARE(c.actuators.count, 1);
            QVERIFY(c.actuators.rotaryOutput);
            c.values.assign(std::size_t(capability::layoutFor(c.actuators)->size), 0.0);
            capability::evaluate(*joint, c.actuators, pose, SingularityType::None, c.values);
            const PJointDesign &d = joint->design();
            const double theta = pose.outputs[0];
            QCOMPARE(value(c, "force_worst"), pjoint::outputTorque(d, theta, d.forceMax));
            QCOMPARE(value(c, "force_best"), value(c, "force_worst"));
            QCOMPARE(value(c, "speed_worst"), pjoint::outputSpeed(d, theta, d.speedMax));
            QCOMPARE(value(c, "resolution_worst"), 0.5 * pjoint::outputResolution(d, theta, d.step));
            const double J = pjoint::jacobian(d, theta);
            QCOMPARE(value(c, "stiffness"), J * J * d.stiffness * 1e-3); // N·mm/rad → N·m/rad
            QCOMPARE(value(c, "stiffness_measured"), 3.5e4);
            // the existing report keeps its values
            QCOMPARE(reportValue(*joint, pose, "torque"), pjoint::outputTorque(d, theta, d.forceMax));
        }
    }

    void singularPosesAreExact()
    {
        // a constructed 2-DOF platform: at an inverse singularity J_q loses rank, at a direct
        // one J_x does; the values are then 0 or ∞, never a huge number
        Actuators a;
        a.count = a.outputs = 2;
        a.inputs = {0, 1, 2};
        for (int i = 0; i < 2; ++i)
            a.items[std::size_t(i)] = {100.0, 50.0, 0.01, 1e4, false};
        const ReportLayout *layout = capability::layoutFor(a);
        QVERIFY(layout);
        const auto at = [&](const std::vector<double> &v, const char *name) { return v[std::size_t(layout->find(name)->offset)]; };
        capability::Matrix jq(2, 2), jx(2, 2);
        jx << 1.0, 0.3, -0.2, 1.0;
        jq << 1.0, 0.0, 0.0, 0.0; // leg 2 stretched
        std::vector<double> v(std::size_t(layout->size), 0.0);
        capability::evaluate(a, jq, jx, SingularityType::Inverse, v);
        QVERIFY(std::isinf(at(v, "force_best")));
        QCOMPARE(at(v, "speed_worst"), 0.0);
        QVERIFY(std::isinf(at(v, "stiffness")));
        for (const char *finite : {"force_worst", "speed_best", "resolution_worst", "stiffness_worst"})
            QVERIFY2(std::isfinite(at(v, finite)) && at(v, finite) > 0.0, finite);

        jq << 1.0, 0.0, 0.0, 1.0;
        jx << 1.0, 2.0, 0.5, 1.0; // the platform gains a freedom
        capability::evaluate(a, jq, jx, SingularityType::Direct, v);
        QCOMPARE(at(v, "force_worst"), 0.0);
        QCOMPARE(at(v, "stiffness_worst"), 0.0);
        QVERIFY(std::isinf(at(v, "speed_best")));
        QVERIFY(std::isinf(at(v, "resolution_worst")));
        for (const char *finite : {"force_best", "speed_worst"})
            QVERIFY2(std::isfinite(at(v, finite)) && at(v, finite) > 0.0, finite);

        // both singular: each quantity is exact by one of its marks (none is 0 by one and ∞ by
        // the other): the weakest direction has nothing, the strongest is unbounded
        jq << 1.0, 0.0, 0.0, 0.0;
        capability::evaluate(a, jq, jx, SingularityType::Combined, v);
        for (const char *zero : {"force_worst", "speed_worst", "stiffness_worst"})
            QVERIFY2(at(v, zero) == 0.0, zero);
        for (const char *unbounded : {"force_best", "speed_best", "resolution_worst", "stiffness"})
            QVERIFY2(std::isinf(at(v, unbounded)), unbounded);
    }

    void nearSingularityIsFiniteAndTendsToTheLimit()
    {
        // approaching the direct singularity above, force_worst falls to 0 continuously
        Actuators a;
        a.count = a.outputs = 2;
        for (int i = 0; i < 2; ++i)
            a.items[std::size_t(i)] = {100.0, 50.0, 0.01, 1e4, false};
        const ReportLayout *layout = capability::layoutFor(a);
        capability::Matrix jq = capability::Matrix::Identity(2, 2), jx(2, 2);
        std::vector<double> v(std::size_t(layout->size), 0.0);
        double previous = std::numeric_limits<double>::infinity();
        for (const double e : {1e-1, 1e-2, 1e-3, 1e-4}) {
            jx << 1.0, 2.0, 0.5 - e, 1.0;
            capability::evaluate(a, jq, jx, SingularityType::None, v);
            const double worst = v[std::size_t(layout->find("force_worst")->offset)];
            QVERIFY(worst > 0.0 && worst < previous);
            previous = worst;
        }
        QVERIFY(previous < 0.1);
    }
};

QTEST_APPLESS_MAIN(TestCapability)
#include "tst_capability.moc"
