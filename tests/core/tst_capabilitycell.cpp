// The closed-form cell of the capability maps (core/capabilitycell.h) against the general
// computation of a pose (capability::evaluate, LU solves of 2×2 and 3×3 matrices): the same
// four values for random Jacobians, linear and rotary actuators, and at poses of every
// singularity class — including an actuator whose leg is stretched (its column of G exactly 0)
// and the exact 0 or ∞ of a singular one.
#include "capabilitycell.h"
#include "capabilitymap.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace pkm;
using capability::Actuators;
using capability::CellLimits;

Q_DECLARE_METATYPE(pkm::SingularityType)

namespace {

constexpr MapQuantity quantities[] = {MapQuantity::ForceWorst, MapQuantity::SpeedWorst, MapQuantity::ResolutionWorst,
                                      MapQuantity::StiffnessWorst};

/// n actuators with limits of different sizes, one of them rotary, each moving the platform by
/// about `transmission` per unit at the home pose.
Actuators actuators(int n, double transmission)
{
    Actuators a;
    a.count = n;
    a.outputs = n;
    for (int i = 0; i < n; ++i) {
        capability::Actuator &item = a.items[std::size_t(i)];
        item.force = 100.0 + 40.0 * i;
        item.speed = 50.0 + 7.0 * i;
        item.step = 0.01 * (1 + i);
        item.stiffness = 2000.0 + 500.0 * i;
        item.rotary = i == 1; // N·m, N·m/rad: entered in N·mm
        a.inputs[std::size_t(i)] = i;
        a.transmission[std::size_t(i)] = transmission;
    }
    return a;
}

/// What evaluate() gives for `quantity`, as a map cell stores it.
float general(const Actuators &a, MapQuantity quantity, const capability::Matrix &jq, const capability::Matrix &jx,
              SingularityType type)
{
    const ReportLayout *layout = capability::layoutFor(a);
    std::vector<double> values(std::size_t(layout->size), std::nan(""));
    capability::evaluate(a, jq, jx, type, values);
    return capability::cellValue(values[std::size_t(layout->find(capability::entryName(quantity))->offset)]);
}

float closed(const Actuators &a, MapQuantity quantity, const capability::Matrix &jq, const capability::Matrix &jx,
             SingularityType type)
{
    const CellLimits limits = capability::cellLimits(a, quantity);
    const bool inverse = type == SingularityType::Inverse || type == SingularityType::Combined;
    const bool direct = type == SingularityType::Direct || type == SingularityType::Combined;
    if (a.count == 3) {
        return capability::cellValue(capability::cell3(limits, jq.diagonal(), Eigen::Matrix3d(jx), inverse, direct));
    }
    return capability::cellValue(capability::cell2(limits, jq(0, 0), jq(1, 1), jx(0, 0), jx(0, 1), jx(1, 0), jx(1, 1),
                                                   jx.row(0).norm(), jx.row(1).norm(), inverse, direct));
}

bool same(float a, float b)
{
    if (std::isinf(a) || std::isinf(b) || a == 0.0f || b == 0.0f)
        return a == b;
    return std::abs(a - b) <= 1e-6f * std::abs(b);
}

} // namespace

class TestCapabilityCell : public QObject
{
    Q_OBJECT

private slots:
    void randomJacobians_data()
    {
        QTest::addColumn<int>("n");
        QTest::addRow("two actuators") << 2;
        QTest::addRow("three actuators") << 3;
    }
    void randomJacobians()
    {
        QFETCH(int, n);
        std::mt19937 random(17);
        std::uniform_real_distribution<double> entry(-100.0, 100.0);
        const Actuators a = actuators(n, 1.0);
        int compared = 0;
        for (int k = 0; k < 500; ++k) {
            capability::Matrix jq = capability::Matrix::Zero(n, n), jx(n, n);
            for (int i = 0; i < n; ++i) {
                jq(i, i) = entry(random);
                for (int j = 0; j < n; ++j)
                    jx(i, j) = entry(random);
            }
            for (const MapQuantity q : quantities) {
                const float expected = general(a, q, jq, jx, SingularityType::None);
                const float cell = closed(a, q, jq, jx, SingularityType::None);
                QVERIFY2(same(cell, expected), qPrintable(QStringLiteral("quantity %1, case %2: %3 against %4")
                                                              .arg(int(q)).arg(k).arg(cell).arg(expected)));
                ++compared;
            }
        }
        QCOMPARE(compared, 2000);
    }

    /// The classes as a kind reports them, with the Jacobians of such a pose: the exact values
    /// where the marks give them, the computed ones (with a stretched leg's actuator moving
    /// nothing) where they do not.
    void singularPoses_data()
    {
        QTest::addColumn<int>("n");
        QTest::addColumn<pkm::SingularityType>("type");
        QTest::addColumn<bool>("allStretched");
        for (const int n : {2, 3}) {
            QTest::addRow("%d, inverse", n) << n << SingularityType::Inverse << false;
            // the platform locked: it holds any force, however weak the actuators
            QTest::addRow("%d, inverse, every leg stretched", n) << n << SingularityType::Inverse << true;
            QTest::addRow("%d, direct", n) << n << SingularityType::Direct << false;
            QTest::addRow("%d, combined", n) << n << SingularityType::Combined << false;
        }
    }
    void singularPoses()
    {
        QFETCH(int, n);
        QFETCH(SingularityType, type);
        QFETCH(bool, allStretched);
        const Actuators a = actuators(n, 1.0);
        capability::Matrix jq = capability::Matrix::Zero(n, n), jx(n, n);
        for (int i = 0; i < n; ++i) {
            jq(i, i) = 30.0 + 10.0 * i;
            for (int j = 0; j < n; ++j)
                jx(i, j) = i == j ? 40.0 : 7.0 * (i + 1) - 3.0 * j;
        }
        if (type != SingularityType::Direct)
            jq(0, 0) = 1e-12; // leg 1 stretched: actuator 1 no longer moves the platform
        if (allStretched)
            jq.diagonal().setConstant(1e-12);
        if (type != SingularityType::Inverse)
            jx.row(n - 1) = jx.row(0); // two legs parallel
        for (const MapQuantity q : quantities) {
            const float expected = general(a, q, jq, jx, type);
            const float cell = closed(a, q, jq, jx, type);
            QVERIFY2(same(cell, expected),
                     qPrintable(QStringLiteral("quantity %1: %2 against %3").arg(int(q)).arg(cell).arg(expected)));
        }
        // what a singular pose means, as the layout marks it
        const float force = closed(a, MapQuantity::ForceWorst, jq, jx, type);
        const float speed = closed(a, MapQuantity::SpeedWorst, jq, jx, type);
        const float resolution = closed(a, MapQuantity::ResolutionWorst, jq, jx, type);
        const float stiffness = closed(a, MapQuantity::StiffnessWorst, jq, jx, type);
        const bool direct = type != SingularityType::Inverse, inverse = type != SingularityType::Direct;
        QCOMPARE(force == 0.0f, direct);
        QCOMPARE(stiffness == 0.0f, direct);
        QCOMPARE(std::isinf(resolution), direct);
        QCOMPARE(speed == 0.0f, inverse);
        if (allStretched) {
            QVERIFY(std::isinf(force));
            QCOMPARE(resolution, 0.0f);
            QVERIFY(std::isinf(stiffness));
        } else if (!direct) {
            QVERIFY(std::isfinite(force) && force > 0.0f);
            QVERIFY(std::isfinite(resolution) && resolution > 0.0f);
        }
    }

    /// Poses a hair from a singularity that the kind classifies as regular: an actuator that
    /// moves the platform less than 1/1000 of what it does at home counts as not moving it
    /// (speeds 0, as at an inverse singularity), one that moves it more than 1000 times as much
    /// marks a direct singularity (forces 0, errors ∞) — in the map cell and in evaluate()
    /// alike — while a factor 100 either way still gives the computed, finite values.
    void nearSingularPoses_data()
    {
        QTest::addColumn<int>("n");
        QTest::addColumn<double>("factor");
        QTest::addColumn<bool>("parallel");
        QTest::addColumn<pkm::SingularityType>("expected");
        for (const int n : {2, 3}) {
            QTest::addRow("%d, leg 1 nearly stretched", n) << n << 1e-4 << false << SingularityType::Inverse;
            QTest::addRow("%d, leg 1 within the band", n) << n << 1e-2 << false << SingularityType::None;
            QTest::addRow("%d, legs nearly parallel", n) << n << 1e-5 << true << SingularityType::Direct;
            QTest::addRow("%d, legs within the band", n) << n << 1e-1 << true << SingularityType::None;
        }
    }
    void nearSingularPoses()
    {
        QFETCH(int, n);
        QFETCH(double, factor);
        QFETCH(bool, parallel);
        QFETCH(SingularityType, expected);
        capability::Matrix jq = capability::Matrix::Zero(n, n), jx(n, n);
        for (int i = 0; i < n; ++i) {
            jq(i, i) = 30.0 + 10.0 * i;
            for (int j = 0; j < n; ++j)
                jx(i, j) = i == j ? 40.0 : 7.0 * (i + 1) - 3.0 * j;
        }
        // the home pose: each actuator's transmission is its column of G = J_x⁻¹·J_q there
        const capability::Matrix home = jx.partialPivLu().solve(jq);
        Actuators a = actuators(n, 1.0);
        for (int i = 0; i < n; ++i)
            a.transmission[std::size_t(i)] = home.col(i).norm();
        if (parallel) // the last row moves towards the first, the determinant with it
            jx.row(n - 1) = jx.row(0) + factor * (jx.row(n - 1) - jx.row(0));
        else
            jq(0, 0) *= factor;

        const ReportLayout *layout = capability::layoutFor(a);
        std::vector<double> values(std::size_t(layout->size));
        QCOMPARE(capability::evaluate(a, jq, jx, SingularityType::None, values), expected);
        for (const MapQuantity q : quantities) {
            const float cell = closed(a, q, jq, jx, SingularityType::None);
            QVERIFY2(same(cell, general(a, q, jq, jx, SingularityType::None)),
                     qPrintable(QStringLiteral("quantity %1: %2").arg(int(q)).arg(cell)));
            // what the class reports, as at a pose the kind itself calls singular
            if (expected != SingularityType::None)
                QVERIFY(same(cell, general(a, q, jq, jx, expected)));
        }
        const float force = closed(a, MapQuantity::ForceWorst, jq, jx, SingularityType::None);
        const float speed = closed(a, MapQuantity::SpeedWorst, jq, jx, SingularityType::None);
        const float resolution = closed(a, MapQuantity::ResolutionWorst, jq, jx, SingularityType::None);
        QCOMPARE(speed == 0.0f, expected == SingularityType::Inverse);
        QCOMPARE(force == 0.0f, expected == SingularityType::Direct);
        QCOMPARE(std::isinf(resolution), expected == SingularityType::Direct);
        if (expected == SingularityType::None)
            QVERIFY(std::isfinite(force) && force > 0.0f && speed > 0.0f && std::isfinite(resolution));
        // the sentence a report prints beside such values, none where the kind agrees
        QCOMPARE(capability::nearSingularReason(expected, SingularityType::None) != nullptr,
                 expected != SingularityType::None);
        QVERIFY(capability::nearSingularReason(expected, expected) == nullptr);
    }

    /// Every quantity is the same whichever way a kind orients its rows.
    void signsOfTheRowsDoNotMatter()
    {
        const Actuators a = actuators(2, 1.0);
        const CellLimits limits[] = {capability::cellLimits(a, MapQuantity::ForceWorst),
                                     capability::cellLimits(a, MapQuantity::SpeedWorst),
                                     capability::cellLimits(a, MapQuantity::ResolutionWorst),
                                     capability::cellLimits(a, MapQuantity::StiffnessWorst)};
        for (const CellLimits &l : limits) {
            const double r1 = std::hypot(30.0, -12.0), r2 = std::hypot(5.0, 44.0);
            const double base = capability::cell2(l, 20.0, -15.0, 30.0, -12.0, 5.0, 44.0, r1, r2, false, false);
            QVERIFY(base > 0.0 && std::isfinite(base));
            QCOMPARE(capability::cell2(l, -20.0, -15.0, 30.0, -12.0, 5.0, 44.0, r1, r2, false, false), base);
            QCOMPARE(capability::cell2(l, 20.0, -15.0, -30.0, 12.0, 5.0, 44.0, r1, r2, false, false), base);
            QCOMPARE(capability::cell2(l, -20.0, 15.0, -30.0, 12.0, -5.0, -44.0, r1, r2, false, false), base);
        }
    }
};

QTEST_APPLESS_MAIN(TestCapabilityCell)
#include "tst_capabilitycell.moc"
