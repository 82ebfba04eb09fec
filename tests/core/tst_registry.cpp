// The registry and the generic parts of the Mechanism interface.
#include "registry.h"
#include "support/kinematics.h"

#include <QTest>

using namespace pkm;
using namespace pkm::test;

class TestRegistry : public QObject
{
    Q_OBJECT

private slots:
    void kindsAreCreatable()
    {
        QVERIFY(!mechanismKinds().empty());
        for (const MechanismKind &kind : mechanismKinds()) {
            auto made = createMechanism(kind.id, {});
            QVERIFY(made.ok());
            QCOMPARE((*made)->kind(), kind.id);
            const Mechanism &m = **made;
            // the layout is consistent and every value of the home pose is finite
            std::vector<double> values(m.reportLayout().size);
            m.evaluate(m.homePose(), values);
            for (double v : values)
                QVERIFY(std::isfinite(v));
            int expected = 0;
            for (const ReportEntry &e : m.reportLayout().entries) {
                QCOMPARE(e.offset, expected);
                expected += e.rows * e.cols;
            }
            QCOMPARE(expected, m.reportLayout().size);
            QVERIFY(m.inputCount() >= 1 && m.outputCount() >= 1);
            // every parameter round-trips through withParameter at its current value
            for (const auto &[name, value] : m.parameters())
                QVERIFY2(m.withParameter(name, value).ok(), name.c_str());
        }
    }

    void jacobiansAgainstFiniteDifferences()
    {
        // For every kind, at its home pose: J = J_q⁻¹·J_x, and J maps a small output step to
        // the input step the inverse kinematics gives.
        for (const MechanismKind &kind : mechanismKinds()) {
            auto made = createMechanism(kind.id, {});
            const Mechanism &m = **made;
            const Pose home = m.homePose();
            const Jacobians j = m.jacobians(home);
            QVERIFY((j.inputs * j.full - j.outputs).norm() <= 1e-9 * j.outputs.norm());
            const double h = 1e-6;
            for (int c = 0; c < m.outputCount(); ++c) {
                const std::optional<Eigen::VectorXd> difference = inverseDifference(m, home.outputs, c, h, &home);
                QVERIFY(difference);
                const Eigen::VectorXd column = *difference;
                QVERIFY((column - j.full.col(c)).norm() <= 1e-5 * std::max(1.0, j.full.norm()));
            }
        }
    }

    void unknownKindAndParameter()
    {
        auto none = createMechanism("nosuch", {});
        QVERIFY(!none.ok());
        QCOMPARE(none.failure().kind, FailureKind::UnknownName);
        auto bad = createMechanism("pjoint", {{"zz", 1.0}});
        QVERIFY(!bad.ok());
        QCOMPARE(bad.failure().culprit, std::string("zz"));
    }

    void formatting_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<int>("decimals");
        QTest::addColumn<QString>("text");
        QTest::newRow("trim") << 231.40 << 2 << "231.4";
        QTest::newRow("integer") << 170.0 << 3 << "170";
        QTest::newRow("negative zero") << -0.0001 << 2 << "0";
        QTest::newRow("rounding") << 116.1999 << 1 << "116.2";
        QTest::newRow("nan") << std::nan("") << 2 << "nan";
        QTest::newRow("huge") << 6.8e301 << 6 << "6.8e+301";
        QTest::newRow("tiny") << 1.5e-9 << 3 << "1.5e-09";
    }
    void formatting()
    {
        QFETCH(double, value);
        QFETCH(int, decimals);
        QFETCH(QString, text);
        QCOMPARE(QString::fromStdString(formatNumber(value, decimals)), text);
    }

    void singularityNames()
    {
        QCOMPARE(singularityName(SingularityType::None), std::string_view("none"));
        QCOMPARE(singularityName(SingularityType::Inverse), std::string_view("inverse"));
        QCOMPARE(singularityName(SingularityType::Direct), std::string_view("direct"));
        QCOMPARE(singularityName(SingularityType::Combined), std::string_view("combined"));
    }
};

QTEST_APPLESS_MAIN(TestRegistry)
#include "tst_registry.moc"
