// Mobility (docs/mathematics.md): the structural formulas of Chebyshev and Somov–Malyshev
// against the rank of the loop-closure Jacobian, for every mechanism and for the classroom's
// paradoxical chains (the spatial parallelogram, the Bennett linkage, whose closure is checked
// here with Denavit–Hartenberg matrices), a random spatial 4R that cannot move, the document's
// "+P₁" shown wrong, singular poses (four-bar dead point and change point, MOMA with its links
// in line) where the instantaneous mobility rises, and the independence of the unit of length.
#include "kinds/fivebar/fivebar.h"
#include "kinds/fourbar/fourbar.h"
#include "mobility.h"
#include "kinds/moma/moma.h"
#include "kinds/oxglide/oxglide.h"
#include "kinds/pjoint/pjoint.h"
#include "registry.h"
#include "support/kinematics.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace pkm;
using namespace pkm::test;

Q_DECLARE_METATYPE(pkm::ParameterSet)

namespace {
constexpr double pi = std::numbers::pi;
constexpr double degree = pi / 180.0;

Pose pose(std::initializer_list<double> inputs, std::initializer_list<double> outputs)
{
    Pose p;
    p.inputs.resize(Eigen::Index(inputs.size()));
    p.outputs.resize(Eigen::Index(outputs.size()));
    Eigen::Index i = 0;
    for (double v : inputs)
        p.inputs[i++] = v;
    i = 0;
    for (double v : outputs)
        p.outputs[i++] = v;
    return p;
}

/// The chain moved and scaled: every point p ↦ factor·p + shift, pitches × factor.
KinematicChain transformed(KinematicChain chain, double factor, const Eigen::Vector3d &shift = Eigen::Vector3d::Zero())
{
    for (KinematicPair &pair : chain.pairs) {
        pair.point = factor * pair.point + shift;
        pair.pitch *= factor;
    }
    return chain;
}

/// The numbers a mechanism's report must show at every regular pose.
struct Expected {
    std::optional<int> chebyshev;
    int somovMalyshev;
    int mobility;
    int actuators;
};

void checkRegular(const MobilityReport &r, const Expected &e)
{
    QVERIFY2(r.valid, r.verdict.c_str());
    QCOMPARE(r.chebyshev, e.chebyshev);
    QCOMPARE(r.somovMalyshev, e.somovMalyshev);
    QCOMPARE(r.numerical, e.mobility);
    QCOMPARE(r.mobility, e.mobility);
    QVERIFY(!r.singular);
    QCOMPARE(r.actuators, e.actuators);
    QCOMPARE(r.redundantConstraints, r.mobility - r.somovMalyshev);
    QCOMPARE(r.somovMalyshevFails, e.somovMalyshev != e.mobility);
    if (e.chebyshev) {
        QCOMPARE(*r.planarRedundantConstraints, 0);
        QVERIFY(!r.chebyshevFails);
    }
    QCOMPARE(r.lockedMobility, r.mobility - r.actuators);
}

/// The poses at `steps` + 1 values of input 0 across its range (the others as at home).
std::vector<Pose> posesAcross(const Mechanism &m, int steps)
{
    std::vector<Pose> poses;
    const Interval range = m.variableRange(0);
    for (int i = 0; i <= steps; ++i) {
        // stay off the ends of the range: some are singular (the four-bar's dead points)
        const double v = range.min + (range.max - range.min) * (0.05 + 0.9 * i / steps);
        const auto solved = m.solveWith(m.homePose(), 0, v);
        if (solved)
            poses.push_back(*solved);
    }
    return poses;
}
} // namespace

class TestMobility : public QObject
{
    Q_OBJECT

private slots:
    void formulas()
    {
        QCOMPARE(mobility::chebyshev(3, 4, 0), 1); // four-bar
        QCOMPARE(mobility::chebyshev(4, 5, 0), 2); // five-bar
        QCOMPARE(mobility::chebyshev(2, 2, 1), 1); // cam and follower
        PairClassCounts fourR {};
        fourR[5] = 4;
        QCOMPARE(mobility::somovMalyshev(3, fourR), -2);
        QCOMPARE(mobility::pairClass(PairType::Spherical), 3);
        QCOMPARE(mobility::pairClass(PairType::Cylindrical), 4);
        QCOMPARE(mobility::pairClass(PairType::CamPlanar), 4);
        QCOMPARE(mobility::pairFreedoms(PairType::Screw), 1);
    }

    /// docs/mathematics.md: a body on a spherical joint at O touching a plane at K (a point contact,
    /// class 1: five freedoms) moves with 2 freedoms. −P₁ gives 2, the document's +P₁ gives 4. The
    /// rank confirms 2 on the equivalent chain that replaces the contact by two prismatic pairs
    /// in the plane and a spherical pair at K.
    void somovMalyshevPlusP1IsWrong()
    {
        PairClassCounts real {};
        real[3] = 1;
        real[1] = 1;
        QCOMPARE(mobility::somovMalyshev(1, real), 2);
        QCOMPARE(mobility::documentSomovMalyshev(1, real), 4);

        KinematicChain equivalent;
        equivalent.planar = false;
        equivalent.links = {"ground", "slide x", "slide y", "body"};
        const Eigen::Vector3d O(0, 0, 50), K(30, 10, 0);
        equivalent.pairs = {mobility::makePair(PairType::Prismatic, "x", 0, 1, K, Eigen::Vector3d::UnitX()),
            mobility::makePair(PairType::Prismatic, "y", 1, 2, K, Eigen::Vector3d::UnitY()),
            mobility::makePair(PairType::Spherical, "K", 2, 3, K),
            mobility::makePair(PairType::Spherical, "O", 3, 0, O)};
        const MobilityReport r = analyseMobility(equivalent);
        QVERIFY2(r.valid, r.verdict.c_str());
        QCOMPARE(r.somovMalyshev, 2);
        QCOMPARE(r.numerical, 2);
        QCOMPARE(r.mobility, 2);
        QVERIFY(!r.formulaFails);
        QCOMPARE(r.redundantConstraints, 0);
        QVERIFY(mobility::documentSomovMalyshev(1, real) != r.mobility);
    }

    // -- the mechanisms ---------------------------------------------------------------------

    void fourBar()
    {
        const MechanismPtr m = makeKind("fourbar");
        QVERIFY(posesAcross(*m, 12).size() == 13);
        for (const Pose &p : posesAcross(*m, 12)) {
            const MobilityReport r = analyseMobility(m->kinematicChain(p));
            checkRegular(r, {1, -2, 1, 1});
            QCOMPARE(r.movingLinks, 3);
            QCOMPARE(r.pairsByClass[5], 4);
            QCOMPARE(r.loops, 1);
            QCOMPARE(r.redundantConstraints, 3); // the three a planar loop does not impose
            QVERIFY(r.fullyActuated);
            QVERIFY(r.formulaFails);
        }
        const MobilityReport home = analyseMobility(m->kinematicChain(m->homePose()));
        QVERIFY(home.verdict.find("Chebyshev's W = 1 is right") != std::string::npos);
        QVERIFY(home.verdict.find("Somov–Malyshev's W = −2 is wrong") != std::string::npos);
    }

    void pJoint()
    {
        const MechanismPtr m = makeKind("pjoint");
        QVERIFY(posesAcross(*m, 12).size() == 13);
        for (const Pose &p : posesAcross(*m, 12)) {
            const MobilityReport r = analyseMobility(m->kinematicChain(p));
            checkRegular(r, {1, -5, 1, 1});
            QCOMPARE(r.movingLinks, 5);
            QCOMPARE(r.pairsByClass[5], 7);
            QCOMPARE(r.loops, 2);
            QCOMPARE(r.redundantConstraints, 6);
            QVERIFY(r.fullyActuated);
        }
    }

    void moma_data()
    {
        QTest::addColumn<ParameterSet>("parameters");
        // the configurations of fig. 3, as the presets give them (core units)
        QTest::newRow("3a") << ParameterSet {};
        QTest::newRow("3b") << ParameterSet {{"alpha1", 275 * degree}, {"alpha2", 265 * degree}};
        QTest::newRow("3c") << ParameterSet {{"R1x", 250}, {"R1y", 0}, {"R2x", 0}, {"R2y", 250},
            {"alpha1", 180 * degree}, {"alpha2", 270 * degree}, {"assembly", 1}};
        QTest::newRow("3d") << ParameterSet {{"R1x", 117}, {"R1y", 0}, {"R2x", 0}, {"R2y", 117}, {"alpha1", 0},
            {"alpha2", 90 * degree}, {"branch1", 1}, {"branch2", 1}, {"assembly", 1}};
    }

    void moma()
    {
        QFETCH(ParameterSet, parameters);
        const MechanismPtr m = makeKind("moma", parameters);
        const std::vector<Pose> poses = posesAcross(*m, 8);
        QVERIFY(poses.size() >= 3);
        for (const Pose &p : poses) {
            const MobilityReport r = analyseMobility(m->kinematicChain(p));
            checkRegular(r, {2, -1, 2, 2});
            QCOMPARE(r.movingLinks, 4);
            QCOMPARE(r.pairsByClass[5], 5);
            QVERIFY(r.fullyActuated);
        }
    }

    void fiveBar()
    {
        const MechanismPtr m = makeKind("fivebar");
        const MobilityReport r = analyseMobility(m->kinematicChain(m->homePose()));
        checkRegular(r, {2, -1, 2, 2});
        QVERIFY(r.fullyActuated);
        // the classroom chain at the same joints says the same
        const KinematicChain chain = m->kinematicChain(m->homePose());
        std::array<Eigen::Vector2d, 5> joints;
        for (std::size_t i = 0; i < 5; ++i)
            joints[i] = chain.pairs[i].point.head<2>();
        const MobilityReport example = analyseMobility(mobility::planarFiveBar(joints));
        QCOMPARE(example.chebyshev, r.chebyshev);
        QCOMPARE(example.mobility, r.mobility);
    }

    /// The O-X glide as built (oxglide.h): 8 moving links, 3 prismatic, 4 revolute and 4
    /// spherical pairs, 3 loops. Somov–Malyshev gives 6·8 − 5·7 − 3·4 = 1. The rank gives 4:
    /// z, x_AB, x_CD and one freedom the actuators do not hold — with the sliders locked, rods
    /// AB, the platform and rods CD form a planar four-bar (the rods of a pair lie one behind
    /// the other, so in the plane they act as one link), and the platform swings in its plane.
    /// The planar analysis of the document assumes the platform stays parallel to the guides.
    void oxGlide()
    {
        const MechanismPtr m = makeKind("oxglide");
        QVERIFY(posesAcross(*m, 8).size() >= 3);
        for (const Pose &p : posesAcross(*m, 8)) {
            const KinematicChain chain = m->kinematicChain(p);
            QVERIFY(!chain.planar);
            const MobilityReport r = analyseMobility(chain);
            QVERIFY2(r.valid, r.verdict.c_str());
            QCOMPARE(r.movingLinks, 8);
            QCOMPARE(r.pairsByClass[5], 7);
            QCOMPARE(r.pairsByClass[3], 4);
            QCOMPARE(r.loops, 3);
            QVERIFY(!r.chebyshev);
            QCOMPARE(r.somovMalyshev, 1);
            QCOMPARE(r.actuators, 3);
            QCOMPARE(r.numerical, 4);
            QCOMPARE(r.mobility, 4);
            QCOMPARE(r.redundantConstraints, 3);
            QCOMPARE(r.lockedMobility, 1);
            QCOMPARE(r.lockedMobilityNearby, 1);
            QVERIFY(!r.fullyActuated);
            QVERIFY(r.somovMalyshevFails);
            QVERIFY(r.verdict.find("uncontrolled (under-actuated)") != std::string::npos);
        }
        // The planar part alone, the platform as in the document's fig. 3 (a link of width s
        // on two revolute pairs, one per rod pair): Chebyshev 3·5 − 2·6 = 3 = x, y and the swing;
        // the rank agrees. Its two actuators leave the swing.
        const Pose home = m->homePose();
        const double s = 20.0, xAB = home.inputs[0], xCD = home.inputs[1], x = home.outputs[0], y = home.outputs[1];
        KinematicChain planar;
        planar.links = {"ground", "slider pair AB", "slider pair CD", "rods AB", "rods CD", "platform"};
        const Eigen::Vector2d ux(1, 0);
        planar.pairs = {mobility::planarPrismatic("x_AB", 0, 1, {xAB, 0}, ux, true),
            mobility::planarPrismatic("x_CD", 0, 2, {xCD, 0}, ux, true), mobility::planarRevolute("AB", 1, 3, {xAB, 0}),
            mobility::planarRevolute("CD", 2, 4, {xCD, 0}), mobility::planarRevolute("A′B′", 3, 5, {x - s / 2, y}),
            mobility::planarRevolute("C′D′", 4, 5, {x + s / 2, y})};
        const MobilityReport r = analyseMobility(planar);
        QCOMPARE(r.chebyshev, 3);
        QCOMPARE(r.mobility, 3);
        QCOMPARE(r.lockedMobilityNearby, 1);
    }

    /// Every mechanism of the registry describes its chain, and the formulas hold the identity
    /// mobility = W + redundant equations at its home pose.
    void everyMechanismHasAChain()
    {
        for (const MechanismKind &kind : mechanismKinds()) {
            const MechanismPtr m = makeKind(std::string(kind.id).c_str());
            const KinematicChain chain = m->kinematicChain(m->homePose());
            QVERIFY2(!chain.links.empty(), kind.id.data());
            QVERIFY(!chain.description.empty());
            const MobilityReport r = analyseMobility(chain);
            QVERIFY2(r.valid, r.verdict.c_str());
            QCOMPARE(r.mobility, r.somovMalyshev + r.redundantConstraints);
            if (r.chebyshev)
                QCOMPARE(r.mobility, *r.chebyshev + *r.planarRedundantConstraints);
            QVERIFY(r.actuators >= m->inputCount());
        }
    }

    // -- paradoxical chains -----------------------------------------------------------------

    void spatialParallelogram()
    {
        for (double theta : {-60.0, 0.0, 35.0}) {
            const KinematicChain chain = mobility::spatialParallelogram(170.0, 68.0, theta * degree);
            QVERIFY(!chain.planar);
            const MobilityReport r = analyseMobility(chain);
            QVERIFY(!r.chebyshev);
            QCOMPARE(r.somovMalyshev, -2);
            QCOMPARE(r.numerical, 1);
            QCOMPARE(r.mobility, 1);
            QCOMPARE(r.redundantConstraints, 3);
            QVERIFY(r.formulaFails);
            QVERIFY(r.somovMalyshevFails);
        }
    }

    void bennettClosure_data()
    {
        QTest::addColumn<double>("alpha");
        QTest::addColumn<double>("beta");
        QTest::addColumn<double>("theta1");
        QTest::newRow("30/70, 20") << 30.0 << 70.0 << 20.0;
        QTest::newRow("30/70, 100") << 30.0 << 70.0 << 100.0;
        QTest::newRow("60/35, -45") << 60.0 << 35.0 << -45.0;
        QTest::newRow("100/40, 150") << 100.0 << 40.0 << 150.0;
    }

    /// DH(θ₁,0,a,α)·DH(θ₂,0,b,β)·DH(θ₃,0,a,α)·DH(θ₄,0,b,β) = I with b = a·sin β/sin α and the
    /// angles of bennettAngles(); the chain built there has Somov–Malyshev −2 and rank mobility 1.
    void bennettClosure()
    {
        QFETCH(double, alpha);
        QFETCH(double, beta);
        QFETCH(double, theta1);
        const double a = 100.0, al = alpha * degree, be = beta * degree, b = a * std::sin(be) / std::sin(al);
        const std::array<double, 4> t = mobility::bennettAngles(al, be, theta1 * degree);
        QCOMPARE(t[0], theta1 * degree);
        const Eigen::Isometry3d loop = mobility::denavitHartenberg(t[0], 0, a, al)
            * mobility::denavitHartenberg(t[1], 0, b, be) * mobility::denavitHartenberg(t[2], 0, a, al)
            * mobility::denavitHartenberg(t[3], 0, b, be);
        QVERIFY2((loop.matrix() - Eigen::Matrix4d::Identity()).norm() < 1e-12 * a,
            qPrintable(QString::number((loop.matrix() - Eigen::Matrix4d::Identity()).norm())));
        // the closure equation itself
        QVERIFY(std::abs(std::tan(t[0] / 2) * std::tan(t[1] / 2) - std::sin((be + al) / 2) / std::sin((be - al) / 2))
            < 1e-9);

        const MobilityReport r = analyseMobility(mobility::bennettLinkage(a, al, be, theta1 * degree));
        QVERIFY2(r.valid, r.verdict.c_str());
        QCOMPARE(r.somovMalyshev, -2);
        QCOMPARE(r.numerical, 1);
        QCOMPARE(r.mobility, 1);
        QCOMPARE(r.redundantConstraints, 3);
        QVERIFY(r.formulaFails);
        QVERIFY(!r.singular);
    }

    /// Without the Bennett condition four revolute axes lock: a random 4R, or a Bennett linkage
    /// with one axis tilted by 1°.
    void spatial4RIsRigid()
    {
        for (unsigned seed : {1u, 2u, 3u, 7u, 42u}) {
            const MobilityReport r = analyseMobility(mobility::randomSpatial4R(seed));
            QCOMPARE(r.somovMalyshev, -2);
            QCOMPARE(r.rank, 4);
            QCOMPARE(r.numerical, 0);
            QCOMPARE(r.mobility, 0);
            QCOMPARE(r.redundantConstraints, 2);
        }
        KinematicChain tilted = mobility::bennettLinkage(100.0, 30 * degree, 70 * degree, 20 * degree);
        tilted.pairs[2].axis
            = (Eigen::AngleAxisd(1.0 * degree, Eigen::Vector3d::UnitX()) * tilted.pairs[2].axis).eval();
        QCOMPARE(analyseMobility(tilted).mobility, 0);
    }

    /// Planar chains where Chebyshev itself fails, and a higher pair.
    void planarSpecialCases()
    {
        // double parallelogram: a third crank parallel to the two of a parallelogram. W = 0,
        // but it moves.
        KinematicChain dp;
        dp.links = {"ground", "crank 1", "crank 2", "crank 3", "coupler"};
        const Eigen::Vector2d up(30, 80);
        for (int i = 0; i < 3; ++i) {
            const Eigen::Vector2d base(60.0 * i, 0.0);
            dp.pairs.push_back(mobility::planarRevolute("ground " + std::to_string(i), 0, 1 + i, base, i == 0));
            dp.pairs.push_back(mobility::planarRevolute("coupler " + std::to_string(i), 1 + i, 4, base + up));
        }
        MobilityReport r = analyseMobility(dp);
        QCOMPARE(r.chebyshev, 0);
        QCOMPARE(r.mobility, 1);
        QCOMPARE(r.planarRedundantConstraints, 1);
        QVERIFY(r.chebyshevFails);
        QVERIFY(r.verdict.find("Chebyshev's W = 0 is wrong") != std::string::npos);

        // a crank and a rocker touching at a cam contact K (common normal n): W = 3·2 − 2·2 − 1 = 1
        KinematicChain cam;
        cam.links = {"ground", "cam", "follower"};
        cam.pairs = {mobility::planarRevolute("A", 0, 1, {0, 0}, true), mobility::planarRevolute("D", 2, 0, {100, 0}),
            mobility::makePair(PairType::CamPlanar, "K", 1, 2, {40, 30, 0}, {1, 0.5, 0})};
        r = analyseMobility(cam);
        QCOMPARE(r.chebyshev, 1);
        QCOMPARE(r.pairsByClass[4], 1);
        QCOMPARE(r.freedoms, 4);
        QCOMPARE(r.mobility, 1);
        QVERIFY(!r.chebyshevFails);

        // an open chain (a two-link arm): no loop, every freedom is a mobility
        KinematicChain arm;
        arm.links = {"ground", "upper arm", "forearm"};
        arm.pairs = {mobility::planarRevolute("shoulder", 0, 1, {0, 0}, true),
            mobility::planarRevolute("elbow", 1, 2, {50, 20}, true)};
        r = analyseMobility(arm);
        QCOMPARE(r.loops, 0);
        QCOMPARE(r.chebyshev, 2);
        QCOMPARE(r.somovMalyshev, 2);
        QCOMPARE(r.mobility, 2);
        QVERIFY(!r.formulaFails);
        QVERIFY(r.fullyActuated);
    }

    /// A triangle folded flat (40 + 60 = 100): the apex C has a first-order motion across the
    /// line, but the triangle is rigid — the chain comes back to the pose from every step.
    void flatTriangleIsRigid()
    {
        KinematicChain triangle;
        triangle.links = {"ground AB", "AC", "CB"};
        triangle.pairs = {mobility::planarRevolute("A", 0, 1, {0, 0}), mobility::planarRevolute("C", 1, 2, {40, 0}),
            mobility::planarRevolute("B", 2, 0, {100, 0})};
        const MobilityReport r = analyseMobility(triangle);
        QCOMPARE(r.chebyshev, 0);
        QCOMPARE(r.numerical, 1);
        QCOMPARE(r.mobility, 0);
        QVERIFY(r.singular);
        QVERIFY(!r.chebyshevFails);
        QVERIFY(r.verdict.find("no pair is actuated") != std::string::npos);
    }

    // -- singular poses ---------------------------------------------------------------------

    /// A triple-rocker four-bar at the end of its crank range: coupler and rocker in line, the
    /// dead point. The chain still has mobility 1, but with the crank locked it can move
    /// instantaneously: a direct singularity.
    void fourBarDeadPoint()
    {
        const MechanismPtr m = make(tripleRockerFourBar());
        const auto dead
            = m->solveWith(m->homePose(), FourBar::variableAlpha, m->variableRange(FourBar::variableAlpha).max);
        QVERIFY(dead.ok());
        const MobilityReport r = analyseMobility(m->kinematicChain(*dead));
        QCOMPARE(r.numerical, 1);
        QCOMPARE(r.mobility, 1);
        QCOMPARE(r.lockedMobility, 1);
        QCOMPARE(r.lockedMobilityNearby, 0);
        QVERIFY(r.verdict.find("direct singularity") != std::string::npos);
        // and half a degree inside the range, nothing of it
        const auto inside = m->solveWith(*dead, FourBar::variableAlpha, dead->inputs[0] - 0.5 * degree);
        QVERIFY(inside.ok());
        QCOMPARE(analyseMobility(m->kinematicChain(*inside)).lockedMobility, 0);
    }

    /// A change-point four-bar (40 + 120 = 100 + 60) folded flat: all four joints in line, the
    /// rank drops and the instantaneous mobility is 2 (the two branches cross); next to the
    /// pose the mobility is 1.
    void fourBarChangePoint()
    {
        FourBarDesign d;
        d.crank = 40;
        d.coupler = 120;
        d.rocker = 100;
        d.ground = 60;
        const MechanismPtr m = *FourBar::create(d);
        const KinematicChain flat = m->kinematicChain(pose({0.0}, {pi}));
        QVERIFY((flat.pairs[2].point - Eigen::Vector3d(160, 0, 0)).norm() < 1e-9);
        const MobilityReport r = analyseMobility(flat);
        QCOMPARE(r.rank, 2);
        QCOMPARE(r.numerical, 2);
        QCOMPARE(r.mobility, 1);
        QVERIFY(r.singular);
        QVERIFY(!r.chebyshevFails);
        QVERIFY(r.verdict.find("instantaneous mobility is 2") != std::string::npos);
    }

    /// MOMA 3b (guides closing downwards) with links of 100 mm: at p₁ = p₂ = 0 the links lie
    /// in line along the base, P = (0, 0): a direct singularity (det J_x = 0; docs/mathematics.md).
    void momaDirectSingularity()
    {
        MomaDesign d;
        d.alpha = {275.0 * degree, 265.0 * degree};
        d.length = {100.0, 100.0};
        const auto made = Moma::create(d);
        QVERIFY2(made.ok(), made ? "" : made.failure().message.c_str());
        const Moma &m = static_cast<const Moma &>(**made);
        const Pose singular = pose({0.0, 0.0}, {0.0, 0.0});
        QCOMPARE(m.singularity(singular).type, SingularityType::Direct);
        const MobilityReport r = analyseMobility(m.kinematicChain(singular));
        QCOMPARE(r.numerical, 2);
        QCOMPARE(r.mobility, 2);
        QCOMPARE(r.lockedMobility, 1);
        QCOMPARE(r.lockedMobilityNearby, 0);
        QVERIFY(r.fullyActuated);
        QVERIFY(r.verdict.find("direct singularity") != std::string::npos);
    }

    // -- units and robustness ---------------------------------------------------------------

    /// Millimetres or metres (or kilometres), anywhere in space: the same numbers.
    void independentOfUnits()
    {
        const MechanismPtr pj = makeKind("pjoint"), ox = makeKind("oxglide");
        const std::vector<KinematicChain> chains = {pj->kinematicChain(pj->homePose()),
            ox->kinematicChain(ox->homePose()), mobility::bennettLinkage(100.0, 30 * degree, 70 * degree, 20 * degree),
            mobility::randomSpatial4R(5), mobility::spatialParallelogram(170.0, 68.0, 0.3)};
        for (const KinematicChain &chain : chains) {
            const MobilityReport mm = analyseMobility(chain);
            for (double factor : {1e-3, 1e3}) {
                const KinematicChain scaled = transformed(chain, factor, Eigen::Vector3d(5e3, -2e3, 0.0) * factor);
                const MobilityReport r = analyseMobility(scaled);
                QCOMPARE(r.rank, mm.rank);
                QCOMPARE(r.mobility, mm.mobility);
                QCOMPARE(r.lockedMobility, mm.lockedMobility);
                QCOMPARE(r.verdict, mm.verdict);
                const double difference
                    = (mobility::constraintJacobian(scaled).matrix - mobility::constraintJacobian(chain).matrix).norm();
                QVERIFY2(difference < 1e-9, qPrintable(QString::number(difference)));
            }
        }
        // a screw pair: the pitch is a length too
        KinematicChain screw = mobility::spatialParallelogram(170.0, 68.0, 0.3);
        screw.pairs[1].type = PairType::Screw;
        screw.pairs[1].pitch = 2.54 / (2 * pi);
        const MobilityReport mm = analyseMobility(screw);
        QCOMPARE(analyseMobility(transformed(screw, 1e-3)).rank, mm.rank);
        QCOMPARE(mm.mobility, 0); // the screw's advance along z does not fit the parallel axes
    }

    void invalidChains()
    {
        MobilityReport r = analyseMobility(KinematicChain {});
        QVERIFY(!r.valid);
        QVERIFY(r.verdict.find("no kinematic chain") != std::string::npos);
        KinematicChain broken = mobility::spatialParallelogram(1, 1, 0);
        broken.pairs[1].link2 = 9;
        r = analyseMobility(broken);
        QVERIFY(!r.valid);
        QVERIFY(r.verdict.find("'C'") != std::string::npos);
        KinematicChain notPlanar = mobility::spatialParallelogram(1, 1, 0);
        notPlanar.planar = true;
        notPlanar.pairs[0].axis = Eigen::Vector3d(1, 0, 1).normalized();
        QVERIFY(!analyseMobility(notPlanar).valid);
        QVERIFY(mobility::constraintJacobian(broken).matrix.size() == 0);
    }
};

QTEST_APPLESS_MAIN(TestMobility)
#include "tst_mobility.moc"
