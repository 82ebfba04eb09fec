// Tolerances (core/tolerance.h) for every kind: the implicit sensitivities (T2) against central
// differences of the direct kinematics at fixed inputs, the Monte Carlo mean, spread and
// maximum against the first-order prediction for small tolerances, reproducibility of the
// seed, the honest ∞ of a direct singularity, the refusals that name the parameter, and the
// worst-case map against the pose-by-pose computation.
#include "kinds/fourbar/fourbar.h"
#include "support/kinematics.h"
#include "tolerance.h"
#include "tolerancemap.h"

#include <QTest>

#include <cmath>

using namespace pkm;
using namespace pkm::test;
using namespace pkm::tolerance;

namespace {

/// Every parameter of `m` that may carry a tolerance, each ±`relative` of its size (at least
/// ±`relative` mm or rad).
ParameterSet allTolerances(const Mechanism &m, double relative)
{
    ParameterSet tolerances;
    const ParameterSet values = m.parameters();
    for (const ParameterInfo &info : m.parameterInfo()) {
        if (!checkParameter(m, info.name))
            continue;
        const double tol = relative * std::max(1.0, std::abs(values.at(info.name)));
        if (checkTolerance(m, info.name, tol))
            tolerances[info.name] = tol;
    }
    return tolerances;
}

/// A pose a little off the home pose (a generic one), in the home pose's modes.
Pose offHome(const Mechanism &m)
{
    const Pose home = m.homePose();
    Coordinates inputs = home.inputs;
    for (int i = 0; i < m.inputCount(); ++i) {
        const Interval range = m.variableRange(i);
        const double span = std::isfinite(range.max - range.min) ? range.max - range.min : 1.0;
        inputs[i] = range.clamp(inputs[i] + 0.02 * span);
    }
    auto moved = m.solveDirect(inputs, &home);
    return moved ? *moved : home;
}

} // namespace

class TestTolerance : public QObject
{
    Q_OBJECT

private slots:
    void sensitivitiesMatchDirectDifferences_data() { addKindRows(); }
    /// (T2) against the direct solution of the perturbed designs, tracked in the same mode.
    void sensitivitiesMatchDirectDifferences()
    {
        QFETCH(QString, kind);
        const MechanismPtr m = makeKind(kind.toStdString());
        const ParameterSet tolerances = allTolerances(*m, 1e-3);
        QVERIFY2(!tolerances.empty(), "every kind has geometric parameters");
        const auto analysis = Analysis::make(m, tolerances);
        QVERIFY2(analysis.ok(), analysis.ok() ? "" : analysis.failure().message.c_str());
        for (const Pose &pose : {m->homePose(), offHome(*m)}) {
            const FirstOrder f = analysis->firstOrder(pose);
            QVERIFY2(f.finite, f.reason.c_str());
            QCOMPARE(f.parameters.size(), tolerances.size());
            double largest = 0.0;
            for (const Contribution &c : f.parameters)
                largest = std::max(largest, c.derivative.cwiseAbs().maxCoeff());
            for (std::size_t i = 0; i < f.parameters.size(); ++i) {
                // a central difference of the direct kinematics with its own, larger step
                const std::string &name = f.parameters[i].name;
                const double p = m->parameters().at(name), h = 1e-4 * std::max(1.0, std::abs(p));
                const auto plus = (*m->withParameter(name, p + h))->solveDirect(pose.inputs, &pose);
                const auto minus = (*m->withParameter(name, p - h))->solveDirect(pose.inputs, &pose);
                QVERIFY2(plus.ok() && minus.ok(), name.c_str());
                const Coordinates fd = (plus->outputs - minus->outputs) / (2 * h);
                const double error = (fd - f.parameters[i].derivative).cwiseAbs().maxCoeff();
                QVERIFY2(error <= 1e-5 * std::max(1.0, largest),
                         qPrintable(QStringLiteral("%1: ∂x/∂%2 off by %3 (method %4)")
                                        .arg(kind, QString::fromStdString(name))
                                        .arg(error)
                                        .arg(QString::fromStdString(std::string(methodName(f.method))))));
                const auto direct = analysis->directDerivative(pose, i);
                QVERIFY(direct.has_value());
                QVERIFY((*direct - f.parameters[i].derivative).cwiseAbs().maxCoeff() <= 1e-5 * std::max(1.0, largest));
            }
            // (T3) the parts add up, and the shares to one
            double sum = 0.0, shares = 0.0;
            for (const Contribution &c : f.parameters) {
                sum += c.contribution;
                shares += c.share;
            }
            QVERIFY(std::abs(sum - f.worstNorm) <= 1e-12 * std::max(1.0, sum));
            QVERIFY(f.worstNorm == 0.0 || std::abs(shares - 1.0) < 1e-12);
        }
    }

    void implicitWhereRegular_data() { addKindRows(); }
    /// Away from singularities a square kind takes the implicit method (T2).
    void implicitWhereRegular()
    {
        QFETCH(QString, kind);
        const MechanismPtr m = makeKind(kind.toStdString());
        const auto analysis = Analysis::make(m, allTolerances(*m, 1e-3));
        QVERIFY(analysis.ok());
        const FirstOrder f = analysis->firstOrder(offHome(*m));
        QCOMPARE(std::string(methodName(f.method)), std::string("implicit"));
    }

    void monteCarloMatchesFirstOrder_data() { addKindRows(); }
    /// For small tolerances the error is linear in them: mean ≈ 0, the spread of each output is
    /// that of the uniform sum (T4), and no sample passes the worst case (T3).
    void monteCarloMatchesFirstOrder()
    {
        QFETCH(QString, kind);
        const MechanismPtr m = makeKind(kind.toStdString());
        const auto analysis = Analysis::make(m, allTolerances(*m, 1e-4));
        QVERIFY(analysis.ok());
        const Pose pose = offHome(*m);
        const FirstOrder f = analysis->firstOrder(pose);
        QVERIFY(f.finite);
        for (const Distribution distribution : {Distribution::Uniform, Distribution::Normal}) {
            const MonteCarlo mc = analysis->monteCarlo(pose, {1500, defaultSeed, distribution});
            QCOMPARE(mc.samples, 1500);
            QCOMPARE(mc.failed, 0);
            QCOMPARE(int(mc.norms.size()), 1500);
            const Coordinates &sigma = distribution == Distribution::Uniform ? f.sigmaUniform : f.sigmaNormal;
            for (int k = 0; k < m->outputCount(); ++k) {
                if (sigma[k] < 1e-12)
                    continue; // an output the tolerances do not move
                // the standard error of the mean is σ/√N ≈ 0.026σ; of σ itself ≈ 1.8 %
                QVERIFY2(std::abs(mc.mean[k]) < 0.1 * sigma[k],
                         qPrintable(QStringLiteral("%1: mean %2 vs σ %3").arg(kind).arg(mc.mean[k]).arg(sigma[k])));
                QVERIFY2(std::abs(mc.deviation[k] / sigma[k] - 1.0) < 0.06,
                         qPrintable(QStringLiteral("%1: σ %2 predicted %3").arg(kind).arg(mc.deviation[k]).arg(sigma[k])));
                if (distribution == Distribution::Uniform)
                    QVERIFY(mc.maxAbs[k] <= f.worst[k] * (1 + 1e-3));
            }
            if (distribution == Distribution::Uniform)
                QVERIFY2(mc.normMax <= f.worstNorm * (1 + 1e-3),
                         qPrintable(QStringLiteral("%1: max %2 > worst %3").arg(kind).arg(mc.normMax).arg(f.worstNorm)));
        }
    }

    /// A seed gives the same samples every time, on any number of threads; another seed others.
    void seedIsReproducible()
    {
        const MechanismPtr m = makeKind("fivebar");
        const auto analysis = Analysis::make(m, allTolerances(*m, 1e-3));
        QVERIFY(analysis.ok());
        const Pose pose = m->homePose();
        const MonteCarlo a = analysis->monteCarlo(pose, {300, 7, Distribution::Uniform, 1});
        const MonteCarlo b = analysis->monteCarlo(pose, {300, 7, Distribution::Uniform, 2});
        const MonteCarlo c = analysis->monteCarlo(pose, {300, 8, Distribution::Uniform});
        QVERIFY(a.norms == b.norms);
        QVERIFY(a.norms != c.norms);
    }

    /// Cancelling stops the run and says so.
    void monteCarloCancels()
    {
        const MechanismPtr m = makeKind("moma");
        const auto analysis = Analysis::make(m, allTolerances(*m, 1e-3));
        const std::atomic<bool> cancel{true};
        const MonteCarlo r = analysis->monteCarlo(m->homePose(), {}, &cancel);
        QVERIFY(r.cancelled);
        QCOMPARE(r.samples, 0);
        QVERIFY(std::isnan(r.normMean)); // no sample: undefined, not 0
    }

    /// At a dead point of a four-bar (coupler and rocker in line) the crank does not hold the
    /// rocker: the first-order error is ∞ with a reason, never a huge number.
    void directSingularityIsInfinite()
    {
        const MechanismPtr m = make(tripleRockerFourBar());
        const auto dead = m->solveWith(m->homePose(), FourBar::variableAlpha, m->variableRange(FourBar::variableAlpha).max);
        QVERIFY(dead.ok());
        const auto analysis = Analysis::make(m, {{"AB", 0.01}, {"CD", 0.01}});
        QVERIFY2(analysis.ok(), analysis.ok() ? "" : analysis.failure().message.c_str());
        const FirstOrder f = analysis->firstOrder(*dead);
        QVERIFY(!f.finite);
        QVERIFY(std::isinf(f.worstNorm));
        QVERIFY(f.reason.find("direct singularity") != std::string::npos);
        // a hair inside, finite and large, as the half-degree neighbour of a dead point is
        const auto inside = m->solveWith(*dead, FourBar::variableAlpha, dead->inputs[0] - 0.5 * units::degree);
        const FirstOrder g = analysis->firstOrder(*inside);
        QVERIFY(g.finite && g.worstNorm > 0.0);
    }

    /// One clear refusal naming the parameter.
    void refusesNonGeometricParameters()
    {
        const MechanismPtr pjoint = makeKind("pjoint");
        const auto unknown = Analysis::make(pjoint, {{"nonsense", 0.1}});
        QVERIFY(!unknown.ok());
        QCOMPARE(unknown.failure().culprit, std::string("nonsense"));
        const auto actuator = Analysis::make(pjoint, {{"lead", 0.1}});
        QVERIFY(!actuator.ok());
        QVERIFY(actuator.failure().message.find("not a geometric parameter") != std::string::npos);
        const auto derived = Analysis::make(pjoint, {{"k", 0.01}});
        QVERIFY(!derived.ok());
        QVERIFY(derived.failure().message.find("derived") != std::string::npos);
        const auto range = Analysis::make(pjoint, {{"theta_min", 0.01}});
        QVERIFY(!range.ok());
        const auto negative = Analysis::make(pjoint, {{"a", -1.0}});
        QVERIFY(!negative.ok());
        const double a = pjoint->parameters().at("a");
        const auto tooLarge = Analysis::make(pjoint, {{"a", 2 * a}});
        QVERIFY(!tooLarge.ok());
        QCOMPARE(tooLarge.failure().culprit, std::string("a"));
        QVERIFY(Analysis::make(pjoint, {{"a", 0.05}, {"b", 0.05}}).ok());
    }

    /// Which tolerance dominates: the П-joint's θ depends on a and b; their shares say how much.
    void contributionsRankTheParameters()
    {
        const MechanismPtr m = makeKind("pjoint");
        const auto analysis = Analysis::make(m, {{"a", 0.05}, {"b", 0.0}});
        QVERIFY(analysis.ok());
        const FirstOrder f = analysis->firstOrder(offHome(*m));
        QVERIFY(f.finite);
        QCOMPARE(f.parameters[0].name, std::string("a"));
        QCOMPARE(f.parameters[0].share, 1.0); // b has no tolerance: a is the whole error
        QCOMPARE(f.parameters[1].contribution, 0.0);
    }

    void mapMatchesPoses_data()
    {
        QTest::addColumn<QString>("kind");
        for (const char *kind : {"fivebar", "moma", "oxglide", "planar-parallel"})
            QTest::newRow(kind) << QString(kind);
    }
    /// Each reachable cell of the map is the pose-by-pose bound at that cell.
    void mapMatchesPoses()
    {
        QFETCH(QString, kind);
        const MechanismPtr m = makeKind(kind.toStdString());
        QVERIFY(m->planarWorkspace());
        const auto analysis = Analysis::make(m, allTolerances(*m, 1e-3));
        QVERIFY(analysis.ok());
        const MapGrid grid = squareGrid(m->planarWorkspace()->workspaceBounds(), 16);
        std::vector<float> values(grid.cells());
        int lastProgress = 0;
        const Pose near = m->homePose();
        const MapSummary s = computeMap(*analysis, near, grid, values, nullptr,
                                        [&](int done, int) { lastProgress = std::max(lastProgress, done); }, 2);
        QVERIFY(s.reachableCells > 0);
        QCOMPARE(lastProgress, grid.rows);
        QVERIFY(s.max >= s.min && s.min > 0.0);
        int checked = 0;
        for (int r = 0; r < grid.rows; ++r) {
            for (int c = 0; c < grid.columns; ++c) {
                const float v = values[std::size_t(r * grid.columns + c)];
                if (!std::isfinite(v) || checked > 10)
                    continue;
                Coordinates outputs = near.outputs;
                outputs[0] = grid.x(c);
                outputs[1] = grid.y(r);
                const auto pose = m->solveInverse(outputs, &near);
                QVERIFY(pose.ok());
                QVERIFY(std::abs(analysis->firstOrder(*pose).worstNorm - v) <= 1e-5 * v);
                ++checked;
            }
        }
        QVERIFY(checked > 0);
        const std::atomic<bool> cancel{true};
        QVERIFY(computeMap(*analysis, near, grid, values, &cancel).cancelled);
    }
};

QTEST_GUILESS_MAIN(TestTolerance)
#include "tst_tolerance.moc"
