// Editing a design of the leg library (core/kinds/planarparallel/planardesign.cpp): only the
// parameters the legs use apply; a leg retyped, or the platform changed (and with it the number
// of legs), gives a design that assembles and keeps the platform where it was; an edit that
// cannot be assembled is refused with one message that names the leg and why.
#include "kinds/planarparallel/planarparallel.h"
#include "registry.h"
#include "support/kinematics.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace pkm;
using namespace pkm::test;

namespace {
constexpr double pi = std::numbers::pi;

std::shared_ptr<const PlanarParallel> build(const ParameterSet &parameters)
{
    return std::dynamic_pointer_cast<const PlanarParallel>(makeKind("planar-parallel", parameters));
}

std::shared_ptr<const PlanarParallel> applied(const PlanarParallel &mechanism, const ParameterSet &changes)
{
    auto made = mechanism.withParameters(changes);
    if (!made) {
        qWarning("%s", made.failure().message.c_str());
        return nullptr;
    }
    return std::dynamic_pointer_cast<const PlanarParallel>(*made);
}

/// The five-bar as two R̲RR legs (the default design).
std::shared_ptr<const PlanarParallel> fiveBar()
{
    return build({});
}

/// A symmetric 3-RPR: base triangle of side 200 mm, platform triangle of circumradius 30 mm.
std::shared_ptr<const PlanarParallel> threeRpr()
{
    ParameterSet p{{"platform", 2}, {"assembly", 1}};
    for (int i = 0; i < 3; ++i) {
        const std::string n = std::to_string(i + 1);
        const double base = pi / 2 + 2 * pi * i / 3 + pi, top = pi / 2 + 2 * pi * i / 3 + pi;
        p[joinText({"leg", n, "_type"})] = 2;
        p[joinText({"A", n, "x"})] = 100 + 115.47 * std::cos(base);
        p[joinText({"A", n, "y"})] = 57.735 + 115.47 * std::sin(base);
        p[joinText({"B", n, "x"})] = 30 * std::cos(top);
        p[joinText({"B", n, "y"})] = 30 * std::sin(top);
        p[joinText({"q", n, "_min"})] = 20;
        p[joinText({"q", n, "_max"})] = 150;
    }
    return build(p);
}

/// The platform of `pose` as (x, y, φ).
Eigen::Vector3d platformOf(const PlanarParallel &m, const Pose &pose)
{
    return m.platformPose(pose.outputs);
}
} // namespace

class TestPlanarDesign : public QObject
{
    Q_OBJECT

private slots:
    void onlyTheLegsParametersApply()
    {
        const auto five = fiveBar();
        QVERIFY(five);
        // two R̲RR legs on a point: cranks, links, crank limits and working modes
        for (const char *name : {"platform", "assembly", "leg1_type", "A1x", "A2y", "r1", "l2", "theta1_min", "working2"})
            QVERIFY2(five->parameterApplies(name), name);
        // nothing of leg 3, no platform points, no guides, П-joints, strokes or map angle
        for (const char *name : {"leg3_type", "A3x", "r3", "B1x", "B2y", "alpha1", "a1", "k2", "q1_min", "phi_map"})
            QVERIFY2(!five->parameterApplies(name), name);
        const auto rpr = threeRpr();
        QVERIFY(rpr);
        for (const char *name : {"leg3_type", "A3x", "B3y", "q3_max", "phi_map"})
            QVERIFY2(rpr->parameterApplies(name), name);
        // a strut has no crank, no distal link, no guide and one working mode
        for (const char *name : {"r1", "l2", "alpha3", "working1", "theta2_max", "a3"})
            QVERIFY2(!rpr->parameterApplies(name), name);
        // every parameter still has a value and a row in the table
        for (const ParameterInfo &info : rpr->parameterInfo())
            QVERIFY(rpr->parameters().count(info.name) == 1);
    }

    void retypedLegsReachThePlatform_data()
    {
        QTest::addColumn<int>("leg");
        QTest::addColumn<int>("type");
        for (int leg = 0; leg < 3; ++leg) {
            for (int type = 0; type < 4; ++type)
                QTest::addRow("leg %d to type %d", leg + 1, type) << leg << type;
        }
    }

    void retypedLegsReachThePlatform()
    {
        QFETCH(int, leg);
        QFETCH(int, type);
        const auto rpr = threeRpr();
        const Pose pose = rpr->homePose();
        std::array<LegType, 3> types{LegType::RPR, LegType::RPR, LegType::RPR};
        types[std::size_t(leg)] = LegType(type);
        const ParameterSet changes = rpr->restructure(pose, PlatformType::Free, types);
        if (type == int(LegType::RPR)) {
            QVERIFY(changes.empty()); // nothing to change
            return;
        }
        const auto retyped = applied(*rpr, changes);
        QVERIFY(retyped);
        QCOMPARE(int(retyped->design().legs[std::size_t(leg)].type), type);
        // the platform stays where it was
        auto kept = retyped->solveInverse(pose.outputs);
        QVERIFY2(kept.ok(), kept ? "" : kept.failure().message.c_str());
        QVERIFY(retyped->singularity(*kept).type == SingularityType::None);
    }

    void thePlatformDecidesTheNumberOfLegs()
    {
        const auto five = fiveBar();
        const Pose pose = five->homePose();
        const Eigen::Vector3d X = platformOf(*five, pose);
        // a third leg: a free body on three legs, the platform where it was at φ = 0
        const ParameterSet grow = five->restructure(pose, PlatformType::Free, {LegType::RRR, LegType::RRR, LegType::RPR});
        const auto three = applied(*five, grow);
        QVERIFY(three);
        QCOMPARE(three->design().legCount(), 3);
        Coordinates outputs(3);
        outputs << X.x(), X.y(), 0.0;
        QVERIFY(three->solveInverse(outputs).ok());
        // and back to two: a point again, its platform points zero
        const Pose there = *three->solveInverse(outputs);
        const auto two = applied(*three, three->restructure(there, PlatformType::Point, {LegType::RRR, LegType::RRR, LegType::RPR}));
        QVERIFY(two);
        QCOMPARE(two->design().legCount(), 2);
        QCOMPARE(two->design().legs[0].platform, Eigen::Vector2d::Zero().eval());
        QVERIFY(two->solveInverse(pose.outputs).ok());
        // constant orientation: R̲RR legs cannot hold it, they become П̲RR
        const auto translating = applied(*five, five->restructure(pose, PlatformType::Translating, {LegType::RRR, LegType::PRR, LegType::RPR}));
        QVERIFY(translating);
        QCOMPARE(translating->design().legs[0].type, LegType::PiRR);
        QCOMPARE(translating->design().legs[1].type, LegType::PRR);
        QVERIFY(translating->solveInverse(pose.outputs).ok());
    }

    void aLegThatCannotReachIsNamed()
    {
        const auto five = fiveBar();
        // a crank of 1 mm and a link of 1 mm cannot reach the platform 120 mm away
        auto refused = five->withParameters({{"r2", 1.0}, {"l2", 1.0}});
        QVERIFY(!refused);
        const std::string &message = refused.failure().message;
        QVERIFY2(message.find("leg 2") != std::string::npos, message.c_str());
        QVERIFY2(message.find("too far") != std::string::npos, message.c_str());
        // a single change is blamed on that parameter
        auto moved = five->withParameter("A1x", -500.0);
        QVERIFY(!moved);
        QCOMPARE(moved.failure().culprit, std::string("A1x"));
        QVERIFY2(moved.failure().message.find("leg 1") != std::string::npos, moved.failure().message.c_str());
    }

    void attachmentPointsAreHandlesThatEditTheDesign()
    {
        const auto rpr = threeRpr();
        const Pose pose = rpr->homePose();
        const Scene scene = rpr->scene(pose);
        // the platform, then A_i and B_i of each leg
        QCOMPARE(scene.handles.size(), std::size_t(7));
        QVERIFY(!scene.handles[0].editsDesign());
        const SceneHandle &b2 = scene.handles[4];
        QCOMPARE(b2.xParameter, std::string("B2x"));
        // the platform point's own position gives the design's B₂ back
        const Eigen::Vector2d at = scene.joints[std::size_t(b2.joint)].position.head<2>();
        QVERIFY((b2.designPoint(at) - rpr->design().legs[1].platform).norm() < 1e-9);
        const SceneHandle &a1 = scene.handles[1];
        QCOMPARE(a1.yParameter, std::string("A1y"));
        QVERIFY((scene.joints[std::size_t(a1.joint)].position.head<2>() - rpr->design().legs[0].base).norm() < 1e-12);
        // a point platform has only base points besides its own handle
        QCOMPARE(fiveBar()->scene(fiveBar()->homePose()).handles.size(), std::size_t(3));
    }
};

QTEST_APPLESS_MAIN(TestPlanarDesign)
#include "tst_planardesign.moc"
