// The active П-joint against its closed forms, their inverses, finite differences and the
// published prototype numbers (the П-joint document; docs/mathematics.md).
#include "kinds/pjoint/pjoint.h"
#include "support/kinematics.h"
#include "text.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace pkm;
using namespace pkm::test;

namespace {
constexpr double deg = units::degree;

PJointDesign design(double a, double k, double thetaMinDeg = -60, double thetaMaxDeg = 60)
{
    PJointDesign p;
    p.a = a;
    p.b = k * a;
    p.thetaMin = thetaMinDeg * deg;
    p.thetaMax = thetaMaxDeg * deg;
    return p;
}

void addDesignRows()
{
    QTest::addColumn<double>("a");
    QTest::addColumn<double>("k");
    QTest::addColumn<double>("thetaDeg");
    const double ks[] = {0.3, 0.4, 0.5, 1.0, 1.5};
    const double thetas[] = {-89, -75, -60, -30, -5, 0, 12.5, 40, 60, 75, 89};
    for (double k : ks) {
        for (double t : thetas) {
            if (k == 1.0 && t == -89)
                continue; // covered by the singular tests: d → 0 there
            QTest::addRow("a170 k%.1f th%g", k, t) << 170.0 << k << t;
        }
    }
    QTest::addRow("a1000 k0.4 th33") << 1000.0 << 0.4 << 33.0;
}

/// The joint of the current data row (addDesignRows) over θ ±89.95°, posed at the row's θ.
struct RowPose {
    std::shared_ptr<const PJoint> joint;
    Pose pose;
    double a = 0;
    double k = 0;
    double theta = 0; ///< rad
};

RowPose rowPose()
{
    QFETCH(double, a);
    QFETCH(double, k);
    QFETCH(double, thetaDeg);
    RowPose row{make(design(a, k, -89.95, 89.95)), {}, a, k, thetaDeg * deg};
    row.pose = *row.joint->solveInverse(Coordinates::Constant(1, row.theta));
    return row;
}
} // namespace

class TestPJoint : public QObject
{
    Q_OBJECT

private slots:
    void solidModelFollowsTheActuator()
    {
        // fig. 2: two parallel parallelograms (six bars), the motor between them and its screw,
        // whose visible extension is d minus the body: it follows the actuator
        auto joint = make(design(170, 0.4));
        double previousScrew = 0, previousD = 0;
        const Scene3D first = joint->scene3d(joint->homePose());
        for (double thetaDeg = -60; thetaDeg <= 60; thetaDeg += 15) {
            const Pose pose = *joint->solveInverse(Coordinates::Constant(1, thetaDeg * deg));
            const Scene3D model = joint->scene3d(pose);
            int bars = 0, motors = 0;
            double screw = -1;
            for (const Solid &solid : model.solids) {
                bars += solid.role == PartRole::Link ? 1 : 0;
                motors += solid.role == PartRole::Actuator ? 1 : 0;
                if (solid.label == "lead screw")
                    screw = (solid.to - solid.from).norm();
                // every part inside the extent, which does not change with the pose
                const Eigen::AlignedBox3d bounds = solidBounds(solid);
                QVERIFY2(model.extent.contains(bounds), solid.label.c_str());
            }
            QVERIFY(model.extent.isApprox(first.extent));
            QCOMPARE(bars, 6);
            QCOMPARE(motors, 1);
            const double d = pose.inputs[0];
            QVERIFY(std::abs(screw - (d - joint->design().motorLength)) < 1e-9);
            if (thetaDeg > -60)
                QVERIFY(std::abs((screw - previousScrew) - (d - previousD)) < 1e-9);
            previousScrew = screw;
            previousD = d;
            // the two parallelograms lie in parallel planes either side of the motor
            std::vector<double> planes;
            for (const Solid &solid : model.solids) {
                if (solid.role == PartRole::Link)
                    planes.push_back(solid.from.z());
            }
            QVERIFY(*std::min_element(planes.begin(), planes.end()) < -0.5 * joint->design().motorWidth);
            QVERIFY(*std::max_element(planes.begin(), planes.end()) > 0.5 * joint->design().motorWidth);
        }
    }

    void prototypeStroke()
    {
        // Section 4.2: a = 170 mm, k = 0.4, θ = ±60° → d_max ≈ 231.4, d_min ≈ 116.2, stroke ≈ 115.2 mm.
        auto joint = make(design(170, 0.4));
        QCOMPARE(std::round(joint->dMax() * 10) / 10, 231.4);
        QCOMPARE(std::round(joint->dMin() * 10) / 10, 116.2);
        QCOMPARE(std::round((joint->dMax() - joint->dMin()) * 10) / 10, 115.2);
        // The document rounds them to 232, 117 and 115 mm.
        QVERIFY(std::abs(joint->dMax() - 232) < 1 && std::abs(joint->dMin() - 117) < 1);
        QCOMPARE(joint->design().b, 68.0);
    }

    void constraintHolds_data() { addDesignRows(); }
    void constraintHolds()
    {
        QFETCH(double, a);
        QFETCH(double, k);
        QFETCH(double, thetaDeg);
        const PJointDesign p = design(a, k, -89.9, 89.9);
        const double theta = thetaDeg * deg;
        const double d = pjoint::diagonal(p, theta);
        QVERIFY(std::abs(pjoint::constraint(p, theta, d)) < 1e-9 * a * a); // (1)
        // d is the distance O–A of the drawn parallelogram.
        const Eigen::Vector2d A = Eigen::Vector2d(p.b, 0) + a * Eigen::Vector2d(std::sin(theta), std::cos(theta));
        QCOMPARE(A.norm(), d);
    }

    void directInverseRoundTrip_data() { addDesignRows(); }
    void directInverseRoundTrip()
    {
        QFETCH(double, a);
        QFETCH(double, k);
        QFETCH(double, thetaDeg);
        auto joint = make(design(a, k, -89.95, 89.95));
        const double theta = thetaDeg * deg;
        auto inverse = joint->solveInverse(Coordinates::Constant(1, theta));
        QVERIFY(inverse.ok());
        auto direct = joint->solveDirect(inverse->inputs);
        QVERIFY2(direct.ok(), direct ? "" : direct.failure().message.c_str());
        QVERIFY(std::abs(direct->outputs[0] - theta) < 1e-7);
        // and the other way round, from d
        auto back = joint->solveInverse(direct->outputs);
        QVERIFY(std::abs(back->inputs[0] - inverse->inputs[0]) < 1e-9 * a);
    }

    void roundTripWholeRange()
    {
        auto joint = make(design(170, 0.4));
        const Interval range = joint->variableRange(PJoint::variableD);
        for (int i = 0; i <= 2000; ++i) {
            const double d = range.min + (range.max - range.min) * i / 2000.0;
            auto pose = joint->solveDirect(Coordinates::Constant(1, d));
            QVERIFY(pose.ok());
            QVERIFY(std::abs(pjoint::diagonal(joint->design(), pose->outputs[0]) - d) < 1e-9 * d);
        }
    }

    void jacobianAgainstFiniteDifferences_data() { addDesignRows(); }
    void jacobianAgainstFiniteDifferences()
    {
        QFETCH(double, a);
        QFETCH(double, k);
        QFETCH(double, thetaDeg);
        const PJointDesign p = design(a, k, -89.9, 89.9);
        const double theta = thetaDeg * deg;
        const double scale = a;
        auto d = [&](double t) { return pjoint::diagonal(p, t); };
        QVERIFY(std::abs(pjoint::jacobian(p, theta) - derivative(d, theta)) < 1e-6 * scale); // (7)
        // (9–11): J = J_d⁻¹·J_θ with J_d = −∂F/∂d and J_θ = ∂F/∂θ
        auto Ftheta = [&](double t) { return pjoint::constraint(p, t, d(theta)); };
        auto Fd = [&](double dd) { return pjoint::constraint(p, theta, dd); };
        QVERIFY(std::abs(pjoint::jacobianTheta(p, theta) - derivative(Ftheta, theta)) < 1e-5 * scale * scale);
        QVERIFY(std::abs(pjoint::jacobianD(p, theta) + derivative(Fd, d(theta))) < 1e-5 * scale);
        QVERIFY(std::abs(pjoint::jacobianTheta(p, theta) / pjoint::jacobianD(p, theta) - pjoint::jacobian(p, theta))
                < 1e-12 * scale);
        // ∂J/∂θ
        auto J = [&](double t) { return pjoint::jacobian(p, t); };
        QVERIFY(std::abs(pjoint::jacobianDerivative(p, theta) - derivative(J, theta, 1e-5)) < 1e-5 * scale);
    }

    void jacobianIsASinMu_data() { addDesignRows(); }
    void jacobianIsASinMu()
    {
        QFETCH(double, a);
        QFETCH(double, k);
        QFETCH(double, thetaDeg);
        const PJointDesign p = design(a, k, -89.9, 89.9);
        const double theta = thetaDeg * deg;
        const double mu = pjoint::transmissionAngle(p, theta);
        QVERIFY(std::abs(pjoint::jacobian(p, theta) - a * std::sin(mu)) < 1e-9 * a);
        // μ is the angle at A between the diagonal and the crank, from the drawn triangle O, B, A.
        const Eigen::Vector2d B(p.b, 0);
        const Eigen::Vector2d A = B + a * Eigen::Vector2d(std::sin(theta), std::cos(theta));
        const double geometric = std::acos((-A).normalized().dot((B - A).normalized()));
        QVERIFY(std::abs(mu - geometric) < 1e-7);
        // φ is the direction of OA from the base line.
        QVERIFY(std::abs(pjoint::passiveAngle(p, theta) - std::atan2(A.y(), A.x())) < 1e-12);
    }

    void acceleration_data() { addDesignRows(); }
    void acceleration()
    {
        QFETCH(double, a);
        QFETCH(double, k);
        QFETCH(double, thetaDeg);
        const PJointDesign p = design(a, k, -89.9, 89.9);
        if (std::abs(thetaDeg) > 85)
            return; // the motion below leaves the range there
        const double theta0 = thetaDeg * deg, omega = 1.7, alpha = -2.3;
        // θ(t) = θ₀ + ωt + ½αt²: d̈(0) numerically against (18), corrected.
        auto d = [&](double t) { return pjoint::diagonal(p, theta0 + omega * t + 0.5 * alpha * t * t); };
        const double h = 1e-4;
        const double numeric = (d(h) - 2 * d(0) + d(-h)) / (h * h);
        const double exact = pjoint::diagonalAcceleration(p, theta0, omega, alpha);
        QVERIFY2(std::abs(numeric - exact) < 1e-4 * a, qPrintable(QStringLiteral("%1 vs %2").arg(numeric).arg(exact)));
        // inverse: θ̈ from d̈
        QVERIFY(std::abs(pjoint::angularAcceleration(p, theta0, omega, exact) - alpha) < 1e-9);
    }

    void documentAccelerationIsWrong()
    {
        // docs/mathematics.md, section 1: (19–20) read d̈ = J + (∂J/∂θ)·θ̇, dropping θ̈ and writing θ̇ for θ̇².
        const PJointDesign p = design(170, 0.4);
        const double theta = 20 * deg, omega = 3.0, alpha = 0.5;
        const double seed = pjoint::jacobian(p, theta) + pjoint::jacobianDerivative(p, theta) * omega;
        const double exact = pjoint::diagonalAcceleration(p, theta, omega, alpha);
        auto d = [&](double t) { return pjoint::diagonal(p, theta + omega * t + 0.5 * alpha * t * t); };
        const double h = 1e-4;
        const double numeric = (d(h) - 2 * d(0) + d(-h)) / (h * h);
        QVERIFY(std::abs(numeric - exact) < 1e-3);
        QVERIFY(std::abs(numeric - seed) > 10.0);
    }

    void statics_data() { addDesignRows(); }
    void statics()
    {
        QFETCH(double, a);
        QFETCH(double, k);
        QFETCH(double, thetaDeg);
        const PJointDesign p = design(a, k, -89.9, 89.9);
        const double theta = thetaDeg * deg, F = 130.0;
        // (13) T = J·F by virtual work: T·δθ = F·δd.
        const double T = pjoint::outputTorque(p, theta, F);
        const double h = 1e-6;
        const double virtualWork = F * (pjoint::diagonal(p, theta + h) - pjoint::diagonal(p, theta - h)) / (2 * h);
        QVERIFY(std::abs(T - virtualWork * 1e-3) < 1e-6 * std::max(1.0, std::abs(T)));
        // (14) F = T/J
        if (std::abs(thetaDeg) < 89)
            QVERIFY(std::abs(pjoint::actuatorForce(p, theta, T) - F) < 1e-9 * F);
        // (15) one revolution: T_M·2π·η = F·h
        const double TM = pjoint::motorTorque(p, F);
        QVERIFY(std::abs(TM * 2 * std::numbers::pi * p.efficiency - F * p.lead * 1e-3) < 1e-12);
    }

    void prototypeOutputCharacteristics()
    {
        // Figs 15–17 at θ = 0: J = a·k/√(1+k²).
        auto joint = make(design(170, 0.4));
        auto pose = joint->solveInverse(Coordinates::Constant(1, 0.0));
        std::vector<double> v(joint->reportLayout().size);
        joint->evaluate(*pose, v);
        const auto value = [&](const char *name) { return v[joint->reportLayout().find(name)->offset]; };
        const double J = 170 * 0.4 / std::sqrt(1.16);
        QCOMPARE(value("J"), J);
        QCOMPARE(value("torque"), J * 130 * 1e-3);
        QCOMPARE(value("speed"), 50 / J);
        QCOMPARE(value("resolution"), 0.0127 / J);
        QCOMPARE(value("J_inv"), 1 / J);
        QCOMPARE(value("stroke"), value("d_max") - value("d_min"));
        // The characteristics change steeply in 40°…60°: J falls by more there than over −60°…40°.
        const PJointDesign &p = joint->design();
        const double dropSteep = pjoint::jacobian(p, 40 * deg) - pjoint::jacobian(p, 60 * deg);
        QVERIFY(dropSteep > 0.3 * pjoint::jacobian(p, 40 * deg));
    }

    void recommendedRange_data()
    {
        QTest::addColumn<double>("k");
        QTest::addColumn<double>("thetaMin");
        QTest::addColumn<double>("thetaMax");
        QTest::newRow("prototype") << 0.4 << -60.0 << 60.0;
        QTest::newRow("k 0.3 wide") << 0.3 << -89.0 << 89.0;
        QTest::newRow("k 1.5") << 1.5 << -80.0 << 80.0;
        QTest::newRow("k 1") << 1.0 << -80.0 << 80.0;
        QTest::newRow("peak outside range") << 0.4 << 10.0 << 70.0;
    }
    void recommendedRange()
    {
        QFETCH(double, k);
        QFETCH(double, thetaMin);
        QFETCH(double, thetaMax);
        const PJointDesign p = design(170, k, thetaMin, thetaMax);
        const Interval r = pjoint::recommendedRange(p);
        QVERIFY(r.min >= p.thetaMin && r.max <= p.thetaMax && r.min < r.max);
        // J ≥ 60 % of its best inside, below it just outside (unless at the design's limit)
        double best = 0;
        for (int i = 0; i <= 4000; ++i)
            best = std::max(best, pjoint::jacobian(p, p.thetaMin + (p.thetaMax - p.thetaMin) * i / 4000.0));
        for (int i = 0; i <= 100; ++i)
            QVERIFY(pjoint::jacobian(p, r.min + (r.max - r.min) * i / 100.0) >= 0.6 * best * (1 - 1e-6));
        if (r.max < p.thetaMax)
            QVERIFY(std::abs(pjoint::jacobian(p, r.max) - 0.6 * best) < 1e-6 * best);
        if (r.min > p.thetaMin)
            QVERIFY(std::abs(pjoint::jacobian(p, r.min) - 0.6 * best) < 1e-6 * best);
    }

    void prototypeRecommendedRangeMatchesDocument()
    {
        // Section 4.2: "the most favourable range would be θ = [−60°, 40°]".
        const Interval r = pjoint::recommendedRange(design(170, 0.4));
        QCOMPARE(r.min, -60 * deg);
        QVERIFY(std::abs(r.max / deg - 40) < 1.0);
    }

    void singularities()
    {
        // (9–11): all singularities lie on θ = ±90°; J_θ = 0 is direct, J_d = 0 inverse.
        auto joint = make(design(170, 0.4, -89, 89));
        QCOMPARE(joint->singularity(0).type, SingularityType::None);
        QCOMPARE(joint->singularity(60 * deg).type, SingularityType::None);
        QCOMPARE(joint->singularity(90 * deg).type, SingularityType::Direct);
        QCOMPARE(joint->singularity(-90 * deg).type, SingularityType::Direct);
        QVERIFY(joint->singularity(89.9 * deg).margin < joint->singularity(60 * deg).margin);
        QCOMPARE(joint->singularity(-60 * deg).margin, 0.5); // |cos θ|: the distance to θ = ±90°
        // k = 1, folded flat: d = 0 as well → combined.
        auto square = make(design(170, 1.0, -89, 89));
        QCOMPARE(square->singularity(-90 * deg).type, SingularityType::Combined);
        QCOMPARE(square->singularity(90 * deg).type, SingularityType::Direct);
    }

    void invalidDesigns_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("value");
        QTest::newRow("a zero") << "a" << 0.0;
        QTest::newRow("a negative") << "a" << -5.0;
        QTest::newRow("b zero") << "b" << 0.0;
        QTest::newRow("k negative") << "k" << -0.4;
        QTest::newRow("theta_min -90") << "theta_min" << -90 * deg;
        QTest::newRow("theta_max 95") << "theta_max" << 95 * deg;
        QTest::newRow("theta_min above max") << "theta_min" << 61 * deg;
        QTest::newRow("theta_max below min") << "theta_max" << -61 * deg;
        QTest::newRow("theta_max equal min") << "theta_max" << -60 * deg;
        QTest::newRow("lead zero") << "lead" << 0.0;
        QTest::newRow("step negative") << "step" << -0.01;
        QTest::newRow("speed zero") << "speed_max" << 0.0;
        QTest::newRow("force zero") << "force_max" << 0.0;
        QTest::newRow("efficiency above one") << "efficiency" << 1.5;
        QTest::newRow("efficiency zero") << "efficiency" << 0.0;
        QTest::newRow("a nan") << "a" << std::nan("");
        QTest::newRow("a inf") << "a" << HUGE_VAL;
    }
    void invalidDesigns()
    {
        QFETCH(QString, name);
        QFETCH(double, value);
        auto joint = make(design(170, 0.4));
        auto changed = joint->withParameter(name.toStdString(), value);
        QVERIFY(!changed.ok());
        QCOMPARE(QString::fromStdString(changed.failure().culprit), name);
        QCOMPARE(changed.failure().kind, FailureKind::InvalidParameter);
        QVERIFY(QString::fromStdString(changed.failure().message).startsWith(name));
        QVERIFY(!QString::fromStdString(changed.failure().message).contains(QStringLiteral("nan")));
        // the old design is untouched
        QCOMPARE(joint->design().a, 170.0);
    }

    void unknownParameter()
    {
        auto changed = make(design(170, 0.4))->withParameter("zz", 1);
        QVERIFY(!changed.ok());
        QCOMPARE(changed.failure().kind, FailureKind::UnknownName);
    }

    void settingKResizesCoupler()
    {
        auto changed = make(design(170, 0.4))->withParameter("k", 0.5);
        QVERIFY(changed.ok());
        QCOMPARE((*changed)->parameters().at("b"), 85.0);
        auto fromSet = PJoint::createFrom({{"a", 200.0}, {"k", 0.3}});
        QVERIFY(fromSet.ok());
        QCOMPARE((*fromSet)->parameters().at("b"), 60.0);
        auto conflicting = PJoint::createFrom({{"a", 200.0}, {"b", 50.0}, {"k", 0.3}});
        QVERIFY(!conflicting.ok());
        QCOMPARE(conflicting.failure().culprit, std::string("k"));
    }

    void severalParametersAtOnce()
    {
        auto joint = make(design(170, 0.4));
        // k with a: b = k·a with the new a, whatever the order in the set
        auto both = joint->withParameters({{"k", 0.5}, {"a", 200.0}});
        QVERIFY(both.ok());
        QCOMPARE((*both)->parameters().at("b"), 100.0);
        // a range moved past the old one in one step
        auto moved = joint->withParameters({{"theta_min", 70 * deg}, {"theta_max", 80 * deg}});
        QVERIFY(moved.ok());
        // b and k together contradict each other
        auto conflict = joint->withParameters({{"b", 70.0}, {"k", 0.5}});
        QVERIFY(!conflict.ok());
        QCOMPARE(conflict.failure().culprit, std::string("k"));
        auto unknown = joint->withParameters({{"zz", 1.0}});
        QVERIFY(!unknown.ok());
        QCOMPARE(unknown.failure().kind, FailureKind::UnknownName);
    }

    void outOfProportionRefused()
    {
        auto joint = make(design(170, 0.4));
        auto tiny = joint->withParameter("a", 1e-300);
        QVERIFY(!tiny.ok());
        QCOMPARE(tiny.failure().culprit, std::string("a"));
        QVERIFY(QString::fromStdString(tiny.failure().message).contains(QStringLiteral("out of proportion")));
    }

    void jacobianMatrices_data() { addDesignRows(); }
    void jacobianMatrices()
    {
        const RowPose row = rowPose();
        const Jacobians j = row.joint->jacobians(row.pose);
        QCOMPARE(j.full(0, 0), pjoint::jacobian(row.joint->design(), row.theta));
        QVERIFY(std::abs(j.inputs(0, 0) * j.full(0, 0) - j.outputs(0, 0)) < 1e-9 * j.outputs.norm() + 1e-12);
    }

    void outOfReach_data()
    {
        QTest::addColumn<QString>("variable");
        QTest::addColumn<double>("value");
        QTest::addColumn<int>("kind");
        QTest::newRow("theta above range") << "theta" << 75 * deg << int(FailureKind::OutOfRange);
        QTest::newRow("theta below range") << "theta" << -61 * deg << int(FailureKind::OutOfRange);
        QTest::newRow("d above stroke") << "d" << 235.0 << int(FailureKind::OutOfRange);
        QTest::newRow("d below stroke") << "d" << 110.0 << int(FailureKind::OutOfRange);
        QTest::newRow("d beyond a+b") << "d" << 500.0 << int(FailureKind::Unreachable);
        QTest::newRow("d below a-b") << "d" << 50.0 << int(FailureKind::Unreachable);
        QTest::newRow("d nan") << "d" << std::nan("") << int(FailureKind::OutOfRange);
    }
    void outOfReach()
    {
        QFETCH(QString, variable);
        QFETCH(double, value);
        QFETCH(int, kind);
        auto joint = make(design(170, 0.4));
        auto pose = joint->solveWith(joint->homePose(), joint->variableIndex(variable.toStdString()), value);
        QVERIFY(!pose.ok());
        QCOMPARE(int(pose.failure().kind), kind);
        QCOMPARE(QString::fromStdString(pose.failure().culprit), variable);
    }

    void limitsAreReachable()
    {
        auto joint = make(design(170, 0.4));
        for (int v = 0; v < 2; ++v) {
            const Interval r = joint->variableRange(v);
            QVERIFY(joint->solveWith(joint->homePose(), v, r.min).ok());
            QVERIFY(joint->solveWith(joint->homePose(), v, r.max).ok());
        }
    }

    void dragStopsAtLimit()
    {
        auto joint = make(design(170, 0.4));
        const Pose home = joint->homePose();
        const Scene scene = joint->scene(home);
        // drag A to where the crank would be at 30°
        const Eigen::Vector2d B(68, 0);
        auto pose = joint->dragHandle(home, 0, B + 100 * Eigen::Vector2d(std::sin(30 * deg), std::cos(30 * deg)));
        QVERIFY(pose.ok());
        QVERIFY(std::abs(pose->outputs[0] - 30 * deg) < 1e-12);
        // far past the upper limit: stops at 60°
        pose = joint->dragHandle(home, 0, B + Eigen::Vector2d(100, -5));
        QVERIFY(pose.ok());
        QCOMPARE(pose->outputs[0], 60 * deg);
        QCOMPARE(scene.handles.size(), std::size_t(2));
    }

    /// The drawing's pose values keep one decimal whatever the pose: "d = 183.1 mm" at rest
    /// became "d = 216.42 mm" and "φ = 40°" while playing, the labels jumping in width.
    void sceneLabelsKeepTheirDecimals()
    {
        auto joint = make(design(170, 0.4));
        const auto texts = [&](double thetaDegrees) {
            const Pose pose = *joint->solveInverse(Coordinates::Constant(1, thetaDegrees * deg));
            const Scene s = joint->scene(pose);
            std::vector<std::string> all;
            for (const SceneAngle &angle : s.angles)
                all.push_back(angle.label);
            for (const SceneDimension &dimension : s.dimensions)
                all.push_back(dimension.text);
            return all;
        };
        const auto has = [](const std::vector<std::string> &all, const std::string &text) {
            return std::find(all.begin(), all.end(), text) != all.end();
        };
        const std::vector<std::string> home = texts(0.0);
        QVERIFY(has(home, "θ = 0.0°"));
        QVERIFY(has(home, "d = 183.1 mm"));
        QVERIFY(has(home, "b = 68 mm")); // the design's own lengths as given
        const std::vector<std::string> turned = texts(30.0);
        QVERIFY(has(turned, "θ = 30.0°"));
        QVERIFY(has(turned, "d = 212.3 mm"));
        // below −0.05°, θ is no "−0.0°"
        QVERIFY(has(texts(-0.04), "θ = 0.0°"));
        QCOMPARE(text::fixed(-0.04, 1), std::string("0.0"));
        QCOMPARE(text::fixed(-12.25, 2), std::string("-12.25"));
        QCOMPARE(text::fixed(40.0, 1), std::string("40.0"));
    }

    void sceneMatchesPose_data() { addDesignRows(); }
    void sceneMatchesPose()
    {
        const RowPose row = rowPose();
        const double a = row.a, k = row.k;
        const Scene s = row.joint->scene(row.pose);
        auto length = [&](const SceneBar &bar) {
            return (s.joints[bar.to].position - s.joints[bar.from].position).norm();
        };
        for (const SceneBar &bar : s.bars)
            QVERIFY(std::abs(length(bar) - (bar.kind == BarKind::Crank ? a : k * a)) < 1e-9 * a);
        const SceneActuator &act = s.actuators.front();
        QVERIFY(std::abs((s.joints[act.to].position - s.joints[act.from].position).norm() - row.pose.inputs[0]) < 1e-9 * a);
        for (const SceneJoint &joint : s.joints)
            QVERIFY(s.extent.contains(joint.position));
    }
};

QTEST_APPLESS_MAIN(TestPJoint)
#include "tst_pjoint.moc"
