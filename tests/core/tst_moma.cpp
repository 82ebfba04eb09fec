// MOMA (docs/mathematics.md) against its own closed forms: kinematics both ways for the presets
// and for random designs in every mode, the Jacobians against finite differences of the
// constraint, singular poses built by hand, the maps against the pose solver, the document's
// statements about configurations 3a–3c, and failures that name their culprit.
#include "kinds/moma/moma.h"
#include "support/kinematics.h"

#include <QTest>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <vector>

using namespace pkm;
using namespace pkm::test;

Q_DECLARE_METATYPE(pkm::ParameterSet)

namespace {
using test::make; // beside the local make() of named values

constexpr double deg = units::degree;
constexpr double pi = std::numbers::pi;
constexpr double notANumber = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

/// The four configurations of the document's fig. 3 in core units (mm, rad), as in
/// resources/presets/moma-3*.pkm.json (which are in degrees).
ParameterSet preset(const QString &name)
{
    if (name == "3a")
        return {};
    if (name == "3b")
        return {{"gamma1", 5 * deg}, {"gamma2", -5 * deg}};
    if (name == "3c") {
        return {{"R1x", 250}, {"R1y", 0}, {"R2x", 0}, {"R2y", 250}, {"alpha1", 180 * deg}, {"alpha2", 270 * deg},
                {"branch1", -1}, {"branch2", -1}, {"assembly", 1}};
    }
    if (name == "3c-") { // 3c in its other assembly mode: the small region near (195, 195) mm
        ParameterSet c = preset("3c");
        c["assembly"] = -1;
        return c;
    }
    if (name == "3d") {
        return {{"R1x", 117}, {"R1y", 0}, {"R2x", 0}, {"R2y", 117}, {"alpha1", 0}, {"alpha2", 90 * deg},
                {"branch1", 1}, {"branch2", 1}, {"assembly", 1}};
    }
    qFatal("no preset %s", qPrintable(name));
}

const QStringList presetNames = {"3a", "3b", "3c", "3d"};

void addPresetRows()
{
    QTest::addColumn<QString>("preset");
    for (const QString &name : presetNames)
        QTest::newRow(qPrintable(name)) << name;
}

std::shared_ptr<const Moma> make(const ParameterSet &parameters)
{
    auto made = Moma::createFrom(parameters);
    if (!made)
        qFatal("%s", made.failure().message.c_str());
    return std::static_pointer_cast<const Moma>(*made);
}

/// The preset of the current data row (addPresetRows).
std::shared_ptr<const Moma> rowMoma()
{
    QFETCH(QString, preset);
    return make(::preset(preset));
}

Eigen::Vector2d platformOf(const Pose &pose)
{
    return pose.outputs.head<2>();
}

Eigen::Vector2d normalOf(double alpha)
{
    return {-std::sin(alpha), std::cos(alpha)};
}

/// The design's length scale, for tolerances.
double scaleOf(const MomaDesign &d)
{
    return std::max({d.length[0], d.length[1], d.reference[0].norm(), d.reference[1].norm(), std::abs(d.strokeMin),
                     std::abs(d.strokeMax)});
}

/// The largest |f_i| (5–6) of the pose, relative to l_i².
double residual(const MomaDesign &d, const Pose &pose)
{
    double worst = 0;
    for (int leg = 0; leg < 2; ++leg) {
        const double f = moma::constraint(d, leg, pose.inputs[leg], platformOf(pose));
        worst = std::max(worst, std::abs(f) / (d.length[leg] * d.length[leg]));
    }
    return worst;
}

/// Does the pose lie in the design's modes: leg i's link component along a_i, B_i − p_i, is
/// −β_i·√(B_i² − C_i), so never of the sign of β_i; P on side σ of Z₁→Z₂; strokes respected.
bool inModes(const MomaDesign &d, const Pose &pose, double tolerance)
{
    const Eigen::Vector2d platform = platformOf(pose);
    const Eigen::Vector2d z1 = moma::sliderJoint(d, 0, pose.inputs[0]), z2 = moma::sliderJoint(d, 1, pose.inputs[1]);
    for (int leg = 0; leg < 2; ++leg) {
        const Eigen::Vector2d z = leg == 0 ? z1 : z2;
        if ((platform - z).dot(moma::direction(d.alpha[leg])) * d.branch[leg] > tolerance * d.length[leg])
            return false;
        if (pose.inputs[leg] < d.strokeMin - tolerance || pose.inputs[leg] > d.strokeMax + tolerance)
            return false;
    }
    return moma::side(z1, z2, platform) * d.assembly >= -tolerance * d.length[0] * d.length[1];
}

bool finite(const Pose &pose)
{
    return pose.inputs.size() == 2 && pose.outputs.size() == 2 && pose.inputs.allFinite() && pose.outputs.allFinite();
}

/// Round-trip tolerance (mm) at a pose of margin m: the solvers are exact to rounding away from
/// singularities; next to one a square root of a near-zero discriminant (inverse) or of a
/// near-zero l² − along² (direct) turns rounding ε into √ε.
double roundTripTolerance(double scale, double margin)
{
    return margin > 1e-3 ? 1e-9 * scale : 1e-6 * scale;
}

/// Random guides, links and strokes (modes left at their defaults).
MomaDesign randomDesign(std::mt19937 &generator)
{
    MomaDesign d;
    d.reference[0] = {uniform(generator, -200, 200), uniform(generator, -200, 200)};
    const double spread = uniform(generator, 0, 2 * pi);
    d.reference[1] = d.reference[0] + uniform(generator, 40, 400) * moma::direction(spread);
    d.alpha = {uniform(generator, -pi, pi), uniform(generator, -pi, pi)};
    d.length = {uniform(generator, 60, 350), uniform(generator, 60, 350)};
    d.strokeMin = uniform(generator, -150, 100);
    d.strokeMax = d.strokeMin + uniform(generator, 40, 300);
    return d;
}

/// The design in mode combination `modes`: bit 0 β₁ = +1, bit 1 β₂ = +1, bit 2 σ = +1, bit 3 one side.
MomaDesign withModes(MomaDesign d, int modes)
{
    d.branch = {modes & 1 ? 1 : -1, modes & 2 ? 1 : -1};
    d.assembly = modes & 4 ? 1 : -1;
    d.oneSide = (modes & 8) != 0;
    return d;
}

struct RoundTripCount {
    int direct = 0;  ///< direct solutions that were round-tripped
    int inverse = 0; ///< inverse solutions that were round-tripped
};

/// p → P → p over an n×n grid of the strokes, and P → p → P over an n×n grid of the workspace
/// bounds. Reports through QVERIFY2 (the caller checks QTest::currentTestFailed()).
void checkRoundTrips(const Moma &m, int n, RoundTripCount &count, const QByteArray &context)
{
    const MomaDesign &d = m.design();
    const double scale = scaleOf(d);
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            const double p1 = d.strokeMin + (d.strokeMax - d.strokeMin) * i / n;
            const double p2 = d.strokeMin + (d.strokeMax - d.strokeMin) * j / n;
            auto pose = m.solveDirect(pair(p1, p2));
            if (!pose) {
                // A failure is a value, never a pose with NaN, and says which input is at fault.
                const Failure &f = pose.failure();
                QVERIFY2(f.kind == FailureKind::Unreachable || f.kind == FailureKind::Singular, context);
                QVERIFY2(f.culprit == "p1" || f.culprit == "p2", context);
                continue;
            }
            const QByteArray where = context + QByteArray(" p = (%1, %2)").replace("%1", QByteArray::number(p1))
                                                   .replace("%2", QByteArray::number(p2));
            QVERIFY2(finite(*pose), where);
            QCOMPARE(pose->inputs[0], p1);
            QCOMPARE(pose->inputs[1], p2);
            QVERIFY2(residual(d, *pose) < 1e-9, where);
            QVERIFY2(inModes(d, *pose, 1e-9), where);
            auto back = m.solveInverse(pose->outputs);
            const double margin = m.singularity(*pose).margin;
            if (!back) {
                // Only at the edge of the modes (on a singularity, within rounding) may the way
                // back refuse the pose the way forth found.
                QVERIFY2(margin < 1e-6, where + " " + QByteArray::fromStdString(back.failure().message));
                continue;
            }
            const double tolerance = roundTripTolerance(scale, margin);
            QVERIFY2((back->inputs - pose->inputs).cwiseAbs().maxCoeff() <= tolerance,
                     where + " back to p = (" + QByteArray::number(back->inputs[0], 'g', 17) + ", "
                         + QByteArray::number(back->inputs[1], 'g', 17) + ")");
            ++count.direct;
        }
    }
    const MapGrid grid{m.workspaceBounds(), n, n};
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            const Eigen::Vector2d target(grid.x(c), grid.y(r));
            auto pose = m.solveInverse(pair(target.x(), target.y()));
            if (!pose) {
                const Failure &f = pose.failure();
                QVERIFY2(f.kind == FailureKind::Unreachable || f.kind == FailureKind::OutOfRange, context);
                QVERIFY2(f.culprit == "x" || f.culprit == "p1" || f.culprit == "p2", context);
                continue;
            }
            const QByteArray where = context + " P = (" + QByteArray::number(target.x()) + ", "
                                   + QByteArray::number(target.y()) + ")";
            QVERIFY2(finite(*pose), where);
            QCOMPARE(pose->outputs[0], target.x());
            QCOMPARE(pose->outputs[1], target.y());
            QVERIFY2(residual(d, *pose) < 1e-9, where);
            QVERIFY2(inModes(d, *pose, 1e-9), where);
            auto back = m.solveDirect(pose->inputs);
            const double margin = m.singularity(*pose).margin;
            if (!back) {
                QVERIFY2(margin < 1e-6, where + " " + QByteArray::fromStdString(back.failure().message));
                continue;
            }
            const double tolerance = roundTripTolerance(scale, margin);
            QVERIFY2((platformOf(*back) - target).cwiseAbs().maxCoeff() <= tolerance,
                     where + " back to P = (" + QByteArray::number(back->outputs[0], 'g', 17) + ", "
                         + QByteArray::number(back->outputs[1], 'g', 17) + ")");
            ++count.inverse;
        }
    }
}

/// The map of `quantity` over a square grid of the design's bounds.
struct Map {
    MapGrid grid;
    std::vector<float> values;
    std::vector<float> margins;
    MapSummary summary;

    float at(int c, int r) const { return values[static_cast<std::size_t>(r) * grid.columns + c]; }
    float marginAt(int c, int r) const { return margins[static_cast<std::size_t>(r) * grid.columns + c]; }
    /// Is any cell within one of (c, r) (itself included) reachable / unreachable?
    bool nearReachable(int c, int r, bool reachable) const
    {
        for (int dr = -1; dr <= 1; ++dr) {
            for (int dc = -1; dc <= 1; ++dc) {
                const int cc = c + dc, rr = r + dr;
                const bool inside = cc >= 0 && rr >= 0 && cc < grid.columns && rr < grid.rows;
                if ((inside && !std::isnan(at(cc, rr))) == reachable)
                    return true;
            }
        }
        return false;
    }
};

Map computed(const Moma &m, MapQuantity quantity, int resolution, bool withMargins = true)
{
    Map map;
    map.grid = squareGrid(m.workspaceBounds(), resolution);
    map.values.assign(map.grid.cells(), 0.0f);
    if (withMargins)
        map.margins.assign(map.grid.cells(), 0.0f);
    map.summary = computeMap(m, quantity, map.grid, map.values, map.margins);
    return map;
}

/// The length of the outline's segments (a staircase, so at least the true perimeter).
double outlineLength(const std::vector<Eigen::Vector2d> &outline)
{
    double length = 0;
    for (std::size_t i = 0; i + 1 < outline.size(); i += 2)
        length += (outline[i + 1] - outline[i]).norm();
    return length;
}

/// A design of 195 mm links and 0…200 mm strokes with the given guides and modes.
MomaDesign customDesign(const Eigen::Vector2d &r1, double alpha1, const Eigen::Vector2d &r2, double alpha2,
                        std::array<int, 2> branch, int assembly)
{
    MomaDesign d;
    d.reference = {r1, r2};
    d.alpha = {alpha1, alpha2};
    d.branch = branch;
    d.assembly = assembly;
    return d;
}
} // namespace

class TestMoma : public QObject
{
    Q_OBJECT

private slots:
    void solidModelFollowsThePose()
    {
        // guides, carriages on them at p_i, two links in neighbouring layers, the platform at P;
        // every part inside an extent that does not change with the pose
        auto made = Moma::create(MomaDesign {});
        QVERIFY(made.ok());
        const auto &m = static_cast<const Moma &>(**made);
        const Eigen::AlignedBox3d extent = m.scene3d(m.homePose()).extent;
        int poses = 0;
        for (double p1 = 0; p1 <= 200; p1 += 25) {
            for (double p2 = 0; p2 <= 200; p2 += 25) {
                Coordinates q(2);
                q << p1, p2;
                auto pose = m.solveDirect(q);
                if (!pose)
                    continue;
                ++poses;
                const Scene3D model = m.scene3d(*pose);
                QVERIFY(model.extent.isApprox(extent));
                int guides = 0, links = 0;
                for (const Solid &solid : model.solids) {
                    QVERIFY2(extent.contains(solidBounds(solid)), solid.label.c_str());
                    guides += solid.role == PartRole::Guide ? 1 : 0;
                    links += solid.role == PartRole::Link ? 1 : 0;
                    if (solid.label == "carriage Z1")
                        QVERIFY((0.5 * (solid.from + solid.to)).head<2>().isApprox(moma::sliderJoint(m.design(), 0, p1)));
                    if (solid.label == "platform")
                        QVERIFY((solid.from.head<2>() - pose->outputs.head<2>()).norm() < 1e-9);
                }
                QCOMPARE(guides, 2);
                QCOMPARE(links, 2);
            }
        }
        QVERIFY(poses > 20);
    }

    // -- the closed forms ---------------------------------------------------------------------

    void closedForms_data() { addPresetRows(); }
    void closedForms()
    {
        // (5–9): the inverse kinematics' roots make f_i vanish, and f_i is |P − Z_i|² − l_i².
        auto m = rowMoma();
        const MomaDesign &d = m->design();
        const Pose home = m->homePose();
        for (int leg = 0; leg < 2; ++leg) {
            const Eigen::Vector2d P = platformOf(home);
            const double B = moma::projection(d, leg, P), D = moma::discriminant(d, leg, P);
            QVERIFY(D > 0);
            const double C = (P - d.reference[leg]).squaredNorm() - d.length[leg] * d.length[leg];
            QCOMPARE(D, B * B - C);
            for (double root : {B - std::sqrt(D), B + std::sqrt(D)})
                QVERIFY(std::abs(moma::constraint(d, leg, root, P)) < 1e-9 * d.length[leg] * d.length[leg]);
            QVERIFY(std::abs(home.inputs[leg] - (B + d.branch[leg] * std::sqrt(D))) < 1e-9 * scaleOf(d));
            // the document's expanded form (5–6)
            const Eigen::Vector2d a = moma::direction(d.alpha[leg]), e = P - d.reference[leg];
            const double p = home.inputs[leg];
            const double expanded = p * p - 2 * p * (a.x() * e.x() + a.y() * e.y()) + e.squaredNorm()
                                  - d.length[leg] * d.length[leg];
            QVERIFY(std::abs(expanded - moma::constraint(d, leg, p, P)) < 1e-9 * d.length[leg] * d.length[leg]);
            QVERIFY(std::abs((moma::sliderJoint(d, leg, p) - P).norm() - d.length[leg]) < 1e-9 * d.length[leg]);
        }
        QVERIFY(m->variableRange(Moma::variableX).contains(home.outputs[0]));
        QVERIFY(m->variableRange(Moma::variableY).contains(home.outputs[1]));
        QCOMPARE(m->variableRange(Moma::variableP1).min, d.strokeMin);
        QCOMPARE(m->variableRange(Moma::variableP2).max, d.strokeMax);
    }

    // -- kinematics -----------------------------------------------------------------------------

    void presetRoundTrips_data() { addPresetRows(); }
    void presetRoundTrips()
    {
        auto m = rowMoma();
        RoundTripCount count;
        checkRoundTrips(*m, 80, count, QTest::currentDataTag());
        if (QTest::currentTestFailed())
            return;
        // Most of the stroke square and of the bounds is workspace for these designs.
        QVERIFY2(count.direct > 81 * 81 / 4, qPrintable(QString::number(count.direct)));
        QVERIFY2(count.inverse > 80 * 80 / 4, qPrintable(QString::number(count.inverse)));
        // The home pose is one of them, away from the singularities.
        const Pose home = m->homePose();
        QVERIFY(inModes(m->design(), home, 1e-9));
        auto again = m->solveDirect(home.inputs);
        QVERIFY(again.ok());
        QVERIFY((again->outputs - home.outputs).norm() < 1e-9 * scaleOf(m->design()));
    }

    void randomRoundTrips()
    {
        // Random guides, links and strokes, in all eight combinations of β₁, β₂ and σ, with and
        // without the one-side constraint.
        std::mt19937 generator(20240611);
        int designs = 0, created = 0;
        RoundTripCount count;
        for (int k = 0; k < 40; ++k) {
            const MomaDesign base = randomDesign(generator);
            for (int modes = 0; modes < 16; ++modes) {
                const MomaDesign d = withModes(base, modes);
                ++designs;
                const QByteArray context = "design " + QByteArray::number(k) + " modes " + QByteArray::number(modes);
                auto made = Moma::create(d);
                if (!made) {
                    // Only an empty workspace is a reason to refuse a design like this.
                    QVERIFY2(made.failure().kind == FailureKind::Unreachable,
                             context + " " + QByteArray::fromStdString(made.failure().message));
                    continue;
                }
                ++created;
                const auto &m = static_cast<const Moma &>(**made);
                QVERIFY2(finite(m.homePose()) && residual(d, m.homePose()) < 1e-9, context);
                checkRoundTrips(m, 30, count, context);
                if (QTest::currentTestFailed())
                    return;
            }
        }
        qInfo("random designs: %d of %d created, %d direct and %d inverse round trips", created, designs,
              count.direct, count.inverse);
        QVERIFY(created >= designs / 4);
        QVERIFY(count.direct > 10000 && count.inverse > 10000);
    }

    void boundsHoldTheWorkspace()
    {
        // workspaceBounds() is "a box that holds the whole workspace" (and variableRange(x, y)
        // comes from it): every pose the direct kinematics finds on a fine grid of the strokes
        // must lie inside.
        auto outside = [](const Moma &m, int n) {
            const MomaDesign &d = m.design();
            const Eigen::AlignedBox2d bounds = m.workspaceBounds();
            int count = 0;
            double worst = 0;
            for (int i = 0; i <= n; ++i) {
                for (int j = 0; j <= n; ++j) {
                    auto pose = m.solveDirect(pair(d.strokeMin + (d.strokeMax - d.strokeMin) * i / n,
                                                   d.strokeMin + (d.strokeMax - d.strokeMin) * j / n));
                    if (pose && bounds.exteriorDistance(platformOf(*pose)) > 1e-9 * scaleOf(d)) {
                        ++count;
                        worst = std::max(worst, bounds.exteriorDistance(platformOf(*pose)));
                    }
                }
            }
            return std::pair(count, worst);
        };
        for (const QString &name : presetNames)
            QCOMPARE(outside(*make(preset(name)), 200).first, 0);
        std::mt19937 generator(20240611);
        int poses = 0, designs = 0;
        double worst = 0;
        for (int k = 0; k < 40; ++k) {
            const MomaDesign base = randomDesign(generator);
            for (int modes = 0; modes < 8; ++modes) {
                auto made = Moma::create(withModes(base, modes));
                if (!made)
                    continue;
                const auto [count, distance] = outside(static_cast<const Moma &>(**made), 120);
                poses += count;
                designs += count > 0;
                worst = std::max(worst, distance);
            }
        }
        qInfo("random designs: %d poses of %d designs outside workspaceBounds(), by up to %.1f mm", poses, designs,
              worst);
        QCOMPARE(poses, 0);
    }

    void slidersVerticallyAligned()
    {
        // docs/mathematics.md, section 2: the document's direct kinematics (10–12) divides by 2(x_Z2 − x_Z1). Two
        // horizontal guides one above the other align the slider joints vertically whenever
        // p₁ = p₂; the robust intersection must not care.
        const MomaDesign d = customDesign({-100, 0}, 0, {-100, 300}, 0, {1, 1}, 1);
        auto m = make(d);
        const double across = std::sqrt(195.0 * 195.0 - 150.0 * 150.0);
        for (double p : {0.0, 37.5, 100.0, 163.0, 200.0}) {
            const Eigen::Vector2d z1 = moma::sliderJoint(d, 0, p), z2 = moma::sliderJoint(d, 1, p);
            QCOMPARE(z2.x() - z1.x(), 0.0); // the document's divisor
            auto pose = m->solveDirect(pair(p, p));
            QVERIFY2(pose.ok(), pose ? "" : pose.failure().message.c_str());
            QVERIFY(finite(*pose));
            // σ = +1: P left of Z₁→Z₂ (upwards), at mid-height
            QVERIFY(std::abs(pose->outputs[0] - (z1.x() - across)) < 1e-9 * 195);
            QVERIFY(std::abs(pose->outputs[1] - 150.0) < 1e-9 * 195);
            QVERIFY(residual(d, *pose) < 1e-12);
            auto back = m->solveInverse(pose->outputs);
            QVERIFY(back.ok());
            QVERIFY((back->inputs - pose->inputs).norm() < 1e-9 * 195);
            // nearly aligned either way: the solution moves continuously through alignment
            for (double offset : {1e-12, 1e-9, 1e-6}) {
                for (double sign : {-1.0, 1.0}) {
                    const double p2 = std::clamp(p + sign * offset, d.strokeMin, d.strokeMax);
                    auto near = m->solveDirect(pair(p, p2));
                    QVERIFY(near.ok() && finite(*near));
                    QVERIFY((platformOf(*near) - platformOf(*pose)).norm() < 10 * offset + 1e-9);
                }
            }
        }
    }

    void coincidentSliderJoints()
    {
        // Crossing guides: at p₁ = p₂ = 100 both slider joints are at the origin and P is
        // undetermined (any point of the circle of radius l). A failure, never NaN.
        bool tried = false;
        for (int modes = 0; modes < 8; ++modes) {
            const MomaDesign d = customDesign({-100, 0}, 0, {0, -100}, 90 * deg,
                                              {modes & 1 ? 1 : -1, modes & 2 ? 1 : -1}, modes & 4 ? 1 : -1);
            auto made = Moma::create(d);
            if (!made)
                continue;
            tried = true;
            const Mechanism &m = **made;
            QVERIFY(moma::sliderJoint(d, 0, 100).norm() < 1e-12 && moma::sliderJoint(d, 1, 100).norm() < 1e-12);
            auto pose = m.solveDirect(pair(100, 100));
            QVERIFY(!pose.ok());
            QCOMPARE(pose.failure().kind, FailureKind::Singular);
            QVERIFY(pose.failure().culprit == "p1" || pose.failure().culprit == "p2");
            QVERIFY(!pose.failure().message.empty());
            QVERIFY(!QString::fromStdString(pose.failure().message).contains(QStringLiteral("nan")));
            // the crossing is worth a warning
            QVERIFY(!m.designWarnings().empty());
            // a hair away the joints are distinct again and the pose is finite (or refused)
            auto near = m.solveDirect(pair(100, 100 + 1e-6));
            QVERIFY(!near.ok() || finite(*near));
        }
        QVERIFY(tried);
    }

    // -- Jacobians --------------------------------------------------------------------------------

    void jacobiansAgainstFiniteDifferences_data() { addPresetRows(); }
    void jacobiansAgainstFiniteDifferences()
    {
        auto m = rowMoma();
        const MomaDesign &d = m->design();
        const double scale = scaleOf(d);
        int checked = 0;
        const int n = 8;
        for (int i = 1; i < n; ++i) {
            for (int j = 1; j < n; ++j) {
                const double p1 = d.strokeMin + (d.strokeMax - d.strokeMin) * i / n;
                const double p2 = d.strokeMin + (d.strokeMax - d.strokeMin) * j / n;
                auto solved = m->solveDirect(pair(p1, p2));
                if (!solved || m->singularity(*solved).margin < 0.02)
                    continue;
                const Pose pose = *solved;
                const Eigen::Vector2d P = platformOf(pose);
                // J_p and J_x of the document (18), (20): derivatives of f_i (5–6). f_i is
                // quadratic, so central differences are exact but for rounding.
                const double h = 1e-3;
                Eigen::Matrix2d jp, jx;
                for (int leg = 0; leg < 2; ++leg) {
                    for (int k = 0; k < 2; ++k) {
                        Coordinates up = pose.inputs, down = pose.inputs;
                        up[k] += h;
                        down[k] -= h;
                        jp(leg, k) = (moma::constraint(d, leg, up[leg], P) - moma::constraint(d, leg, down[leg], P))
                                   / (2 * h);
                        const Eigen::Vector2d step = h * Eigen::Vector2d::Unit(k);
                        jx(leg, k) = (moma::constraint(d, leg, pose.inputs[leg], P + step)
                                      - moma::constraint(d, leg, pose.inputs[leg], P - step))
                                   / (2 * h);
                    }
                }
                const double tolerance = 1e-7 * scale;
                const Jacobians jac = m->jacobians(pose);
                QCOMPARE(jac.inputs.rows(), 2);
                QCOMPARE(jac.outputs.cols(), 2);
                QVERIFY((jac.inputs - jp).cwiseAbs().maxCoeff() < tolerance);
                QCOMPARE(jac.inputs(0, 1), 0.0); // f₁ does not depend on p₂, nor f₂ on p₁
                QCOMPARE(jac.inputs(1, 0), 0.0);
                QVERIFY((jac.outputs + jx).cwiseAbs().maxCoeff() < tolerance); // the interface's J_x is −(20)
                // ṗ = J·Ṗ with J = −J_p⁻¹·J_x; J_q·q̇ = J_x·ẋ in the interface's convention
                const Eigen::Matrix2d full = -jp.inverse() * jx;
                QVERIFY((jac.full - full).cwiseAbs().maxCoeff() < 1e-7 * std::max(1.0, full.norm()));
                QVERIFY((jac.inputs * jac.full - jac.outputs).norm() < 1e-12 * jac.outputs.norm());
                // … and J maps a small step of P to the step of p the inverse kinematics takes.
                const double hp = 1e-5 * scale;
                for (int k = 0; k < 2; ++k) {
                    const std::optional<Eigen::VectorXd> difference = inverseDifference(*m, pose.outputs, k, hp);
                    QVERIFY(difference);
                    const Eigen::Vector2d column = *difference;
                    QVERIFY2((column - jac.full.col(k)).norm() < 1e-6 * std::max(1.0, jac.full.norm()),
                             qPrintable(QStringLiteral("p = (%1, %2)").arg(p1).arg(p2)));
                }
                // the document's (21) J = J_p⁻¹·J_x is the opposite of the velocity map
                QVERIFY((jp.inverse() * jx + jac.full).norm() < 1e-7 * std::max(1.0, full.norm()));

                // The report holds the document's J_p, J_x and the full J; the scalars agree with Eigen.
                Singularity s;
                const std::vector<double> v = evaluated(*m, pose, &s);
                QVERIFY((matrixEntry(*m, v, "Jp") - jac.inputs).norm() < 1e-12 * jac.inputs.norm());
                QVERIFY((matrixEntry(*m, v, "Jx") + jac.outputs).norm() < 1e-12 * jac.outputs.norm());
                QVERIFY((matrixEntry(*m, v, "J") - jac.full).norm() < 1e-12 * jac.full.norm());
                // (computed another way, so to a relative 1e-10 rather than QCOMPARE's 1e-12)
                auto close = [](double a, double b) { return std::abs(a - b) <= 1e-10 * std::abs(b); };
                const Eigen::Matrix2d documentJx = -jac.outputs;
                QVERIFY(close(entry(*m, v, "det_J"), jac.full.determinant()));
                QVERIFY(close(entry(*m, v, "det_Jp"), jac.inputs.determinant()));
                QVERIFY(close(entry(*m, v, "det_Jx"), documentJx.determinant())); // = det(−J_x) for 2×2
                QVERIFY(std::abs(entry(*m, v, "det_Jx") - jx.determinant()) < 1e-8 * std::abs(jx.determinant()));
                QVERIFY(close(entry(*m, v, "det_J"), entry(*m, v, "det_Jx") / entry(*m, v, "det_Jp")));
                Eigen::JacobiSVD<Eigen::Matrix2d> svd(jac.full);
                QVERIFY(close(entry(*m, v, "cond"), svd.singularValues()(0) / svd.singularValues()(1)));
                QVERIFY(entry(*m, v, "cond") >= 1.0);
                QCOMPARE(entry(*m, v, "p1"), pose.inputs[0]);
                QCOMPARE(entry(*m, v, "y"), pose.outputs[1]);
                QCOMPARE(entry(*m, v, "margin"), s.margin);
                // the angles: link–guide ψ_i and between the links
                for (int leg = 0; leg < 2; ++leg) {
                    const Eigen::Vector2d link = P - moma::sliderJoint(d, leg, pose.inputs[leg]);
                    const double angle = std::acos(std::abs(link.normalized().dot(moma::direction(d.alpha[leg]))));
                    QVERIFY(std::abs(entry(*m, v, leg == 0 ? "link_angle1" : "link_angle2") - angle) < 1e-9);
                }
                for (double value : v)
                    QVERIFY(std::isfinite(value));
                ++checked;
            }
        }
        QVERIFY2(checked >= 10, qPrintable(QString::number(checked)));
    }

    // -- singularities ------------------------------------------------------------------------------

    void genericPoseIsNotSingular_data() { addPresetRows(); }
    void genericPoseIsNotSingular()
    {
        auto m = rowMoma();
        Singularity s;
        evaluated(*m, m->homePose(), &s);
        QCOMPARE(s.type, SingularityType::None);
        QVERIFY2(s.margin > 0.1, qPrintable(QString::number(s.margin)));
        QCOMPARE(m->singularity(m->homePose()).type, SingularityType::None);
    }

    void inverseSingularity_data()
    {
        QTest::addColumn<ParameterSet>("parameters");
        QTest::addColumn<int>("leg");
        QTest::newRow("3a leg 1") << preset("3a") << 0;
        QTest::newRow("3a leg 2") << preset("3a") << 1;
        QTest::newRow("3c- leg 1") << preset("3c-") << 0;
        QTest::newRow("3c- leg 2") << preset("3c-") << 1;
    }
    void inverseSingularity()
    {
        // Link i perpendicular to guide i: P = Z_i + s·l_i·n_i. Found along the stroke where the
        // other leg reaches P in the design's modes.
        QFETCH(ParameterSet, parameters);
        QFETCH(int, leg);
        auto m = make(parameters);
        const MomaDesign &d = m->design();
        const double l = d.length[leg];
        const Eigen::Vector2d a = moma::direction(d.alpha[leg]), n = normalOf(d.alpha[leg]);
        const int steps = 400;
        int found = 0, approached = 0;
        for (int k = 0; k <= steps; ++k) {
            const double p = d.strokeMin + (d.strokeMax - d.strokeMin) * k / steps;
            for (double s : {-1.0, 1.0}) {
                const Eigen::Vector2d P = moma::sliderJoint(d, leg, p) + s * l * n;
                auto solved = m->solveInverse(pair(P.x(), P.y()));
                if (!solved)
                    continue;
                ++found;
                // the inverse kinematics finds p back (√ of a discriminant that is 0 but for rounding)
                QVERIFY(std::abs(solved->inputs[leg] - p) < 1e-5 * l);
                Pose exact = *solved;
                exact.inputs[leg] = p;
                Singularity singular;
                const std::vector<double> v = evaluated(*m, exact, &singular);
                QVERIFY(singular.type == SingularityType::Inverse || singular.type == SingularityType::Combined);
                QVERIFY(singular.margin < 1e-12);
                QVERIFY(std::abs(entry(*m, v, "det_Jp")) < 1e-9 * l * l);
                QVERIFY(std::abs(entry(*m, v, leg == 0 ? "link_angle1" : "link_angle2") - 90 * deg) < 1e-9);
                // J has a row −L_i/(2p_i − 2B_i) that blows up: κ(J) is +∞ or huge, unless the other
                // leg is singular as well (at (195, 195) in 3c, both rows blow up together)
                const int other = 1 - leg;
                if (moma::inverseMargin(d, other, exact.inputs[other], P) > 1e-3)
                    QVERIFY(!(entry(*m, v, "cond") < 1e9));
                // Approaching it: the link turned by t from the perpendicular, on the side the
                // working mode allows (B_i − p_i = −β_i·√… : the link component along a_i is −β_i·…).
                // Large turns may leave a small workspace; the small ones must not.
                std::vector<double> margins;
                bool closest = false;
                for (double t : {10.0, 2.0, 0.5, 0.1, 0.01, 1e-3}) {
                    const double angle = t * deg;
                    const Eigen::Vector2d link = l * (std::cos(angle) * s * n - d.branch[leg] * std::sin(angle) * a);
                    const Eigen::Vector2d Q = moma::sliderJoint(d, leg, p) + link;
                    auto near = m->solveInverse(pair(Q.x(), Q.y()));
                    closest = near.ok();
                    if (!near)
                        continue;
                    QVERIFY(std::abs(near->inputs[leg] - p) < 1e-6 * l);
                    Singularity ns;
                    const std::vector<double> nv = evaluated(*m, *near, &ns);
                    // the inverse margin is |cos| between link and guide = sin t
                    QVERIFY(ns.margin <= std::sin(angle) * (1 + 1e-6) + 1e-12);
                    const double psi = entry(*m, nv, leg == 0 ? "link_angle1" : "link_angle2");
                    QVERIFY(std::abs(psi - (90 * deg - angle)) < 1e-6);
                    margins.push_back(ns.margin);
                    if (ns.margin > Moma::singularTolerance)
                        QCOMPARE(ns.type, SingularityType::None);
                }
                if (closest && margins.size() >= 3) {
                    ++approached;
                    QVERIFY(std::is_sorted(margins.rbegin(), margins.rend()));
                    QVERIFY(margins.back() < 2e-5);
                }
            }
        }
        QVERIFY2(found > 0, "no inverse-singular pose in the workspace");
        QVERIFY2(approached > 0, "no inverse-singular pose approachable from inside the workspace");
        // every point of the design's inverse singular curves of this leg is such a pose
        const std::string label = "link " + std::to_string(leg + 1);
        int onCurves = 0;
        for (const SingularCurve &curve : m->singularCurves()) {
            if (curve.type != SingularCurve::Type::Inverse || curve.label.rfind(label, 0) != 0)
                continue;
            for (const Eigen::Vector2d &point : curve.points) {
                auto pose = m->solveInverse(pair(point.x(), point.y()));
                QVERIFY2(pose.ok(), pose ? "" : pose.failure().message.c_str());
                const Eigen::Vector2d link = point - moma::sliderJoint(d, leg, pose->inputs[leg]);
                QVERIFY(std::abs(link.dot(a)) < 1e-5 * l);
                ++onCurves;
            }
        }
        QVERIFY(onCurves > 0);
    }

    void directSingularity()
    {
        // 3d: the links stretched in line, |Z₁Z₂| = l₁ + l₂ = 390 mm; with p₁ = p₂ = p* the
        // slider joints are at (117 + p*, 0) and (0, 117 + p*), so 117 + p* = 390/√2.
        auto m = make(preset("3d"));
        const MomaDesign &d = m->design();
        const double pStar = 390.0 / std::sqrt(2.0) - 117.0;
        QVERIFY(pStar > d.strokeMin && pStar < d.strokeMax);
        auto pose = m->solveDirect(pair(pStar, pStar));
        QVERIFY2(pose.ok(), pose ? "" : pose.failure().message.c_str());
        const double mid = 0.5 * (117.0 + pStar);
        QVERIFY((platformOf(*pose) - Eigen::Vector2d(mid, mid)).norm() < 1e-4);
        Singularity s;
        std::vector<double> v = evaluated(*m, *pose, &s);
        QCOMPARE(s.type, SingularityType::Direct);
        QVERIFY(s.margin < Moma::singularTolerance);
        QVERIFY(std::abs(entry(*m, v, "det_Jx")) < 4 * 195 * 195 * Moma::singularTolerance); // 4·l₁·l₂·sin
        QVERIFY(std::abs(entry(*m, v, "det_J")) < 1e-5);
        QVERIFY(std::abs(entry(*m, v, "links_angle") - pi) < 1e-3); // stretched: 180°
        // approaching: the margin and det J go to 0 monotonically
        std::vector<double> margins, determinants;
        for (double eps : {20.0, 5.0, 1.0, 0.1, 1e-2, 1e-3, 1e-4, 1e-6}) {
            auto near = m->solveDirect(pair(pStar - eps, pStar - eps));
            QVERIFY(near.ok());
            Singularity ns;
            v = evaluated(*m, *near, &ns);
            margins.push_back(ns.margin);
            determinants.push_back(std::abs(entry(*m, v, "det_J")));
            QCOMPARE(ns.type, SingularityType::None);
        }
        QVERIFY(std::is_sorted(margins.rbegin(), margins.rend()));
        QVERIFY(std::is_sorted(determinants.rbegin(), determinants.rend()));
        QVERIFY(margins.back() < 1e-3 && margins.front() > 0.1);
        // just beyond, the links cannot meet
        auto beyond = m->solveDirect(pair(pStar + 1e-3, pStar + 1e-3));
        QVERIFY(!beyond.ok());
        QCOMPARE(beyond.failure().kind, FailureKind::Unreachable);
        // every point of 3d's direct singular curves is such a pose
        int onCurves = 0;
        for (const SingularCurve &curve : m->singularCurves()) {
            if (curve.type != SingularCurve::Type::Direct)
                continue;
            for (const Eigen::Vector2d &point : curve.points) {
                auto onCurve = m->solveInverse(pair(point.x(), point.y()));
                QVERIFY2(onCurve.ok(), onCurve ? "" : onCurve.failure().message.c_str());
                const Singularity cs = m->singularity(*onCurve);
                QVERIFY(cs.type == SingularityType::Direct || cs.type == SingularityType::Combined);
                ++onCurves;
            }
        }
        QVERIFY(onCurves > 0);
    }

    void combinedSingularity()
    {
        // Link 1 perpendicular to a horizontal guide 1 and in line with link 2 on a vertical
        // guide 2: Z₁ = (100, 0), Z₂ = (100, 390), P = (100, 195).
        const MomaDesign d = customDesign({0, 0}, 0, {100, 500}, -90 * deg, {-1, -1}, -1);
        auto m = make(d);
        auto pose = m->solveDirect(pair(100, 110));
        QVERIFY2(pose.ok(), pose ? "" : pose.failure().message.c_str());
        QVERIFY((platformOf(*pose) - Eigen::Vector2d(100, 195)).norm() < 1e-4);
        Singularity s;
        const std::vector<double> v = evaluated(*m, *pose, &s);
        QCOMPARE(s.type, SingularityType::Combined);
        QVERIFY(s.margin < Moma::singularTolerance);
        QCOMPARE(m->singularity(*pose).type, SingularityType::Combined);
        QVERIFY(std::abs(entry(*m, v, "det_Jp")) < 1e-6 * 195 * 195);
        QVERIFY(std::abs(entry(*m, v, "det_Jx")) < 1e-6 * 195 * 195);
        // Approaching along p₂ (Z₂ lower, the links bend): both margins open up continuously.
        std::vector<double> margins;
        for (double eps : {10.0, 1.0, 0.1, 1e-3, 1e-5}) {
            auto near = m->solveDirect(pair(100, 110 + eps));
            QVERIFY(near.ok());
            const Singularity ns = m->singularity(*near);
            QCOMPARE(ns.type, SingularityType::None);
            margins.push_back(ns.margin);
        }
        QVERIFY(std::is_sorted(margins.rbegin(), margins.rend()));
        QVERIFY(margins.back() < 1e-2);
    }

    // -- maps -----------------------------------------------------------------------------------------

    void workspaceAreaConverges_data() { addPresetRows(); }
    void workspaceAreaConverges()
    {
        // A grid's area errs by the boundary cells it misclassifies, at most about half the
        // perimeter × the cell size; the finest grids agree to better than 0.2 %.
        auto m = rowMoma();
        const Map reference = computed(*m, MapQuantity::Determinant, 1600, false);
        const double area = reference.summary.area;
        const double perimeter = outlineLength(workspaceOutline(reference.grid, reference.values));
        QVERIFY(area > 0 && perimeter > 0);
        // The workspace is a plane region: perimeter² ≥ 4π·area.
        QVERIFY(perimeter * perimeter >= 4 * pi * area);
        std::vector<double> areas, errors;
        for (int n : {100, 200, 400, 800}) {
            const Map map = computed(*m, MapQuantity::Determinant, n, false);
            QVERIFY(!map.summary.cancelled);
            QCOMPARE(map.summary.area, double(map.summary.reachableCells) * map.grid.cellArea());
            const double cell = std::max(map.grid.dx(), map.grid.dy());
            QVERIFY(std::abs(map.grid.dx() - map.grid.dy()) < 1e-9 * cell); // square cells
            // the grid covers the bounds (but for rounding)
            const Eigen::AlignedBox2d covered(map.grid.bounds.min().array() - 1e-9 * cell,
                                              map.grid.bounds.max().array() + 1e-9 * cell);
            QVERIFY(covered.contains(m->workspaceBounds()));
            const double error = std::abs(map.summary.area - area);
            QVERIFY2(error <= 0.5 * perimeter * cell,
                     qPrintable(QStringLiteral("n = %1: area %2, reference %3")
                                    .arg(n).arg(map.summary.area).arg(area)));
            areas.push_back(map.summary.area);
            errors.push_back(error);
        }
        QVERIFY(errors.back() < errors.front());
        const double finest = std::abs(areas[3] - areas[2]) / areas[3];
        QVERIFY2(finest < 2e-3, qPrintable(QString::number(finest)));
        qInfo("%s: area %.1f mm² (n = 1600); n = 100…800 differ from it by %.2f, %.2f, %.2f, %.2f mm²",
              QTest::currentDataTag(), area, errors[0], errors[1], errors[2], errors[3]);
    }

    void mapAgreesWithEvaluate_data()
    {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<int>("quantity");
        for (const QString &name : presetNames) {
            QTest::newRow(qPrintable(name + " det")) << name << int(MapQuantity::Determinant);
            QTest::newRow(qPrintable(name + " cond")) << name << int(MapQuantity::Condition);
        }
        QTest::newRow("3c- det") << "3c-" << int(MapQuantity::Determinant);
        // the one-side constraint cuts the workspace in the map and in the solver alike
        for (const QString &name : presetNames)
            QTest::newRow(qPrintable(name + " one side det")) << name + " one side" << int(MapQuantity::Determinant);
    }
    void mapAgreesWithEvaluate()
    {
        QFETCH(QString, preset);
        QFETCH(int, quantity);
        ParameterSet parameters = ::preset(preset.section(' ', 0, 0));
        if (preset.endsWith(QStringLiteral("one side")))
            parameters["one_side"] = 1;
        auto m = make(parameters);
        const Map map = computed(*m, MapQuantity(quantity), 240);
        QVERIFY(map.summary.reachableCells > 0);
        const char *name = quantity == int(MapQuantity::Condition) ? "cond" : "det_J";
        int compared = 0, unreachable = 0, edge = 0;
        double worst = 0;
        for (int r = 0; r < map.grid.rows; ++r) {
            for (int c = (r * 7) % 3; c < map.grid.columns; c += 3) {
                const float value = map.at(c, r);
                auto pose = m->solveInverse(pair(map.grid.x(c), map.grid.y(r)));
                if (std::isnan(value)) {
                    QVERIFY(std::isnan(map.marginAt(c, r)));
                    ++unreachable;
                    if (pose) {
                        // the map and the solver differ only by rounding at the outline
                        QVERIFY2(map.nearReachable(c, r, true),
                                 qPrintable(QStringLiteral("cell %1, %2").arg(c).arg(r)));
                        ++edge;
                    }
                    continue;
                }
                if (!pose) {
                    QVERIFY2(map.nearReachable(c, r, false), pose.failure().message.c_str());
                    ++edge;
                    continue;
                }
                Singularity s;
                const std::vector<double> v = evaluated(*m, *pose, &s);
                const double expected = entry(*m, v, name);
                const double relative = std::abs(double(value) - expected) / std::abs(expected);
                // float precision, and the cancellation in 2p_i − 2B_i next to an inverse singularity
                const double tolerance = s.margin > 1e-3 ? 1e-6 : 1e-3;
                QVERIFY2(relative <= tolerance, qPrintable(QStringLiteral("cell %1, %2: map %3, evaluate %4")
                                                               .arg(c).arg(r).arg(value).arg(expected)));
                QVERIFY(std::abs(map.marginAt(c, r) - s.margin) <= 1e-6 * std::max(1.0, s.margin));
                if (s.margin > 1e-3)
                    worst = std::max(worst, relative);
                ++compared;
            }
        }
        QVERIFY(compared > 100);
        QVERIFY2(edge <= (compared + unreachable) / 100, qPrintable(QString::number(edge)));
        // summary over the whole map
        auto count = [](const std::vector<float> &values, auto predicate) {
            return std::size_t(std::count_if(values.begin(), values.end(), predicate));
        };
        QCOMPARE(map.summary.reachableCells, count(map.values, [](float f) { return !std::isnan(f); }));
        QCOMPARE(map.summary.nearSingularCells, count(map.margins, [](float f) { return f < nearSingularMargin; }));
        if (quantity == int(MapQuantity::Condition))
            QVERIFY(map.summary.min >= 1.0);
        qInfo("%s: %d cells compared, worst relative difference %.2g; %d cells classified otherwise (outline)",
              QTest::currentDataTag(), compared, worst, edge);
    }

    void mapIsDeterministic()
    {
        // one thread or all: the same values bit for bit (every cell is computed alone)
        auto m = make(preset("3d"));
        const MapGrid grid = squareGrid(m->workspaceBounds(), 301);
        std::vector<float> one(grid.cells()), all(grid.cells());
        const MapSummary a = computeMap(*m, MapQuantity::Condition, grid, one, {}, nullptr, 1);
        const MapSummary b = computeMap(*m, MapQuantity::Condition, grid, all, {}, nullptr, 0);
        QCOMPARE(a.reachableCells, b.reachableCells);
        QCOMPARE(a.area, b.area);
        QVERIFY(std::memcmp(one.data(), all.data(), one.size() * sizeof(float)) == 0);
    }

    void mapCancellation()
    {
        auto m = make(preset("3a"));
        const MapGrid grid = squareGrid(m->workspaceBounds(), 400);
        std::vector<float> values(grid.cells(), 7.0f);
        const std::atomic<bool> cancelled{true};
        const MapSummary stopped = computeMap(*m, MapQuantity::Determinant, grid, values, {}, &cancelled);
        QVERIFY(stopped.cancelled);
        QCOMPARE(stopped.reachableCells, std::size_t(0));
        QVERIFY(std::all_of(values.begin(), values.end(), [](float f) { return f == 7.0f; })); // not a row written
        const std::atomic<bool> running{false};
        const MapSummary done = computeMap(*m, MapQuantity::Determinant, grid, values, {}, &running);
        QVERIFY(!done.cancelled);
        QVERIFY(done.reachableCells > 0);
        // a buffer too small is refused, not overrun
        std::vector<float> small(10);
        const MapSummary refused = computeMap(*m, MapQuantity::Determinant, grid, small);
        QCOMPARE(refused.reachableCells, std::size_t(0));
        QCOMPARE(refused.area, 0.0);
    }

    /// The tally (integer keys for min and max, a row's ends for the box) against a plain
    /// loop over the kept cells, and summariseMap(), which keeps none, against computeMap().
    void summaryWithoutCells_data() { addPresetRows(); }
    void summaryWithoutCells()
    {
        auto m = rowMoma();
        for (const MapQuantity quantity : {MapQuantity::Determinant, MapQuantity::Condition}) {
            const Map map = computed(*m, quantity, 257, true);
            std::size_t reachable = 0, nearSingular = 0;
            double low = std::numeric_limits<double>::infinity(), high = -low;
            Eigen::AlignedBox2d box;
            for (int r = 0; r < map.grid.rows; ++r) {
                for (int c = 0; c < map.grid.columns; ++c) {
                    const std::size_t i = std::size_t(r) * std::size_t(map.grid.columns) + std::size_t(c);
                    const float v = map.values[i];
                    if (std::isnan(v))
                        continue;
                    ++reachable;
                    nearSingular += map.margins[i] < nearSingularMargin;
                    if (std::isfinite(v)) {
                        low = std::min(low, double(v));
                        high = std::max(high, double(v));
                    }
                    const Eigen::Vector2d corner = map.grid.bounds.min() + Eigen::Vector2d(c * map.grid.dx(), r * map.grid.dy());
                    box.extend(corner);
                    box.extend(corner + Eigen::Vector2d(map.grid.dx(), map.grid.dy()));
                }
            }
            QVERIFY(reachable > 0);
            QCOMPARE(map.summary.reachableCells, reachable);
            QCOMPARE(map.summary.nearSingularCells, nearSingular);
            QCOMPARE(map.summary.min, low);
            QCOMPARE(map.summary.max, high);
            QVERIFY(map.summary.reachableBox.isApprox(box, 1e-12));

            const MapSummary streamed = summariseMap(*m, quantity, map.grid);
            QCOMPARE(streamed.reachableCells, reachable);
            QCOMPARE(streamed.nearSingularCells, nearSingular);
            QCOMPARE(streamed.min, low);
            QCOMPARE(streamed.max, high);
            QCOMPARE(streamed.area, map.summary.area);
            QVERIFY(streamed.reachableBox.isApprox(box, 1e-12));
            QCOMPARE(summariseMap(*m, quantity, map.grid, false).nearSingularCells, std::size_t(0));
        }
    }

    void outlineIsClosed_data() { addPresetRows(); }
    void outlineIsClosed()
    {
        auto m = rowMoma();
        const Map map = computed(*m, MapQuantity::Determinant, 150, false);
        const std::vector<Eigen::Vector2d> outline = pkm::workspaceOutline(map.grid, map.values);
        QVERIFY(!outline.empty());
        QCOMPARE(outline.size() % 2, std::size_t(0));
        const double x0 = map.grid.bounds.min().x(), y0 = map.grid.bounds.min().y();
        const double dx = map.grid.dx(), dy = map.grid.dy();
        std::map<std::pair<long, long>, int> ends;
        for (std::size_t i = 0; i < outline.size(); i += 2) {
            const Eigen::Vector2d a = outline[i], b = outline[i + 1];
            // axis-parallel, of positive length, on the lines between cells
            QVERIFY((a.x() == b.x()) != (a.y() == b.y()));
            for (const Eigen::Vector2d &point : {a, b}) {
                const double column = (point.x() - x0) / dx, row = (point.y() - y0) / dy;
                QVERIFY(std::abs(column - std::round(column)) < 1e-6 && std::abs(row - std::round(row)) < 1e-6);
                QVERIFY(column > -0.5 && column < map.grid.columns + 0.5 && row > -0.5 && row < map.grid.rows + 0.5);
                ++ends[{std::lround(column), std::lround(row)}];
            }
            // one side of the edge reachable, the other not
            const int c = int(std::lround((std::min(a.x(), b.x()) - x0) / dx));
            const int r = int(std::lround((std::min(a.y(), b.y()) - y0) / dy));
            auto reachable = [&](int cc, int rr) {
                return cc >= 0 && rr >= 0 && cc < map.grid.columns && rr < map.grid.rows && !std::isnan(map.at(cc, rr));
            };
            if (a.y() == b.y())
                QVERIFY(reachable(c, r - 1) != reachable(c, r));
            else
                QVERIFY(reachable(c - 1, r) != reachable(c, r));
        }
        // closed: a boundary turns at every end of a run, so every corner ends two (or four) runs
        for (const auto &[corner, count] : ends)
            QVERIFY2(count % 2 == 0, qPrintable(QStringLiteral("%1, %2").arg(corner.first).arg(corner.second)));
    }

    // -- the document's statements ----------------------------------------------------------

    void noDirectSingularities_data()
    {
        QTest::addColumn<QString>("preset");
        QTest::newRow("3a") << "3a";
        QTest::newRow("3b") << "3b";
    }
    void noDirectSingularities()
    {
        // Fig. 7: 3a and 3b have no direct singularities in their workspaces: no collinear-link
        // curve, and det J stays well away from 0 over a fine map.
        auto m = rowMoma();
        for (const SingularCurve &curve : m->singularCurves())
            QVERIFY(curve.type != SingularCurve::Type::Direct);
        const Map map = computed(*m, MapQuantity::Determinant, 800);
        double smallest = infinity, smallestDirect = infinity;
        for (std::size_t i = 0; i < map.values.size(); ++i) {
            if (std::isnan(map.values[i]))
                continue;
            smallest = std::min(smallest, double(std::abs(map.values[i])));
        }
        for (int r = 0; r < map.grid.rows; r += 4) {
            for (int c = 0; c < map.grid.columns; c += 4) {
                if (std::isnan(map.at(c, r)))
                    continue;
                auto pose = m->solveInverse(pair(map.grid.x(c), map.grid.y(r)));
                if (!pose)
                    continue;
                const Eigen::Vector2d z1 = moma::sliderJoint(m->design(), 0, pose->inputs[0]);
                const Eigen::Vector2d z2 = moma::sliderJoint(m->design(), 1, pose->inputs[1]);
                smallestDirect = std::min(smallestDirect, moma::directMargin(m->design(), z1, z2, platformOf(*pose)));
            }
        }
        qInfo("%s: min |det J| = %.3f, min sin(angle between the links) = %.3f", QTest::currentDataTag(), smallest,
              smallestDirect);
        QVERIFY(smallest > 0.5);
        QVERIFY(smallestDirect > 0.3);
    }

    void configuration3cInverseSingularities_data()
    {
        QTest::addColumn<int>("assembly");
        QTest::newRow("assembly +1") << 1;
        QTest::newRow("assembly -1") << -1;
    }
    void configuration3cInverseSingularities()
    {
        // 3c: every inverse singularity lies on x = 195 or y = 195 mm — the guides lie on the
        // axes, so link i ⟂ guide i puts P at |y| = l₁ or |x| = l₂.
        QFETCH(int, assembly);
        ParameterSet parameters = preset("3c");
        parameters["assembly"] = assembly;
        auto m = make(parameters);
        int points = 0;
        for (const SingularCurve &curve : m->singularCurves()) {
            QVERIFY(curve.type != SingularCurve::Type::Direct); // Z₁ = Z₂ = 0 is beyond the strokes
            for (const Eigen::Vector2d &point : curve.points) {
                const double off = std::min(std::abs(std::abs(point.x()) - 195), std::abs(std::abs(point.y()) - 195));
                QVERIFY2(off < 1e-9 * 195, qPrintable(QStringLiteral("(%1, %2)").arg(point.x()).arg(point.y())));
                ++points;
            }
        }
        if (assembly < 0)
            QVERIFY(points > 0);
        // The map says the same: every cell near an inverse singularity (margin < 0.05, within
        // 0.25 mm of the line for l = 195 mm) lies next to |x| = 195 or |y| = 195.
        const Map map = computed(*m, MapQuantity::Determinant, 400);
        const double cell = std::hypot(map.grid.dx(), map.grid.dy());
        int near = 0;
        for (int r = 0; r < map.grid.rows; ++r) {
            for (int c = 0; c < map.grid.columns; ++c) {
                const float margin = map.marginAt(c, r);
                if (std::isnan(margin) || margin >= nearSingularMargin)
                    continue;
                const double x = map.grid.x(c), y = map.grid.y(r);
                const double off = std::min(std::abs(std::abs(x) - 195), std::abs(std::abs(y) - 195));
                QVERIFY2(off < 0.25 + cell, qPrintable(QStringLiteral("(%1, %2)").arg(x).arg(y)));
                ++near;
            }
        }
        if (assembly < 0)
            QVERIFY(near > 0);
        qInfo("3c assembly %+d: %d singular curve points, %d near-singular cells", assembly, points, near);
    }

    // -- failures ---------------------------------------------------------------------------------

    void invalidDesigns_data()
    {
        QTest::addColumn<ParameterSet>("changes");
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("culprit");
        const int invalid = int(FailureKind::InvalidParameter);
        QTest::newRow("l1 zero") << ParameterSet{{"l1", 0.0}} << invalid << "l1";
        QTest::newRow("l1 negative") << ParameterSet{{"l1", -5.0}} << invalid << "l1";
        QTest::newRow("l2 nan") << ParameterSet{{"l2", notANumber}} << invalid << "l2";
        QTest::newRow("R1x inf") << ParameterSet{{"R1x", infinity}} << invalid << "R1x";
        QTest::newRow("p_min above p_max") << ParameterSet{{"p_min", 250.0}} << invalid << "p_min";
        QTest::newRow("p_min equal p_max") << ParameterSet{{"p_min", 200.0}} << invalid << "p_min";
        QTest::newRow("branch1 half") << ParameterSet{{"branch1", 0.5}} << invalid << "branch1";
        QTest::newRow("branch2 zero") << ParameterSet{{"branch2", 0.0}} << invalid << "branch2";
        QTest::newRow("assembly two") << ParameterSet{{"assembly", 2.0}} << invalid << "assembly";
        QTest::newRow("one_side two") << ParameterSet{{"one_side", 2.0}} << invalid << "one_side";
        QTest::newRow("one_side half") << ParameterSet{{"one_side", 0.5}} << invalid << "one_side";
        QTest::newRow("alpha1 and gamma1") << ParameterSet{{"alpha1", 265 * deg}, {"gamma1", -5 * deg}} << invalid
                                           << "gamma1";
        QTest::newRow("guides on one line, overlapping")
            << ParameterSet{{"R2x", -100.0}, {"R2y", 0.0}, {"alpha2", 265 * deg}} << invalid << "R2x";
        QTest::newRow("guides on one line, end to end")
            << ParameterSet{{"R2x", -100.0 + 150 * std::cos(265 * deg)}, {"R2y", 150 * std::sin(265 * deg)},
                            {"alpha2", 265 * deg}}
            << invalid << "R2x";
        QTest::newRow("empty workspace") << ParameterSet{{"l1", 10.0}, {"l2", 10.0}} << int(FailureKind::Unreachable)
                                         << "l1";
        QTest::newRow("unknown name") << ParameterSet{{"zz", 1.0}} << int(FailureKind::UnknownName) << "zz";
        QTest::newRow("guide width zero") << ParameterSet{{"guide_width", 0.0}} << invalid << "guide_width";
        QTest::newRow("gamma1 beyond half turn") << ParameterSet{{"gamma1", 200 * deg}} << invalid << "gamma1";
        QTest::newRow("gamma1 nan") << ParameterSet{{"gamma1", notANumber}} << invalid << "gamma1";
    }
    void invalidDesigns()
    {
        // The same changes refused from a parameter set and as an edit of 3a; the failure names
        // the culprit, and the old design is untouched.
        QFETCH(ParameterSet, changes);
        QFETCH(int, kind);
        QFETCH(QString, culprit);
        auto check = [&](const Result<MechanismPtr> &made, const char *how) {
            QVERIFY2(!made.ok(), how);
            QCOMPARE(int(made.failure().kind), kind);
            QCOMPARE(QString::fromStdString(made.failure().culprit), culprit);
            const QString message = QString::fromStdString(made.failure().message);
            QVERIFY(!message.isEmpty());
            QVERIFY2(!message.contains(QStringLiteral("nan")) && !message.contains(QStringLiteral("inf")),
                     qPrintable(message));
            if (kind == int(FailureKind::InvalidParameter) && !culprit.startsWith('R')) {
                QVERIFY2(message.contains(culprit), qPrintable(message));
            }
        };
        check(Moma::createFrom(changes), "createFrom");
        if (QTest::currentTestFailed())
            return;
        auto base = make(ParameterSet{});
        const ParameterSet before = base->parameters();
        check(base->withParameters(changes), "withParameters");
        if (QTest::currentTestFailed())
            return;
        if (changes.size() == 1)
            check(base->withParameter(changes.begin()->first, changes.begin()->second), "withParameter");
        QVERIFY(base->parameters() == before);
    }

    void invalidDesignStruct()
    {
        // create() validates a MomaDesign filled in directly, too.
        MomaDesign d;
        d.length[1] = -1;
        auto made = Moma::create(d);
        QVERIFY(!made.ok());
        QCOMPARE(made.failure().culprit, std::string("l2"));
        d = MomaDesign{};
        d.branch[0] = 0;
        made = Moma::create(d);
        QVERIFY(!made.ok());
        QCOMPARE(made.failure().culprit, std::string("branch1"));
        d = MomaDesign{};
        d.strokeMax = d.strokeMin;
        made = Moma::create(d);
        QVERIFY(!made.ok());
        QCOMPARE(made.failure().culprit, std::string("p_min"));
        d = MomaDesign{};
        d.reference = {Eigen::Vector2d(0, 0), Eigen::Vector2d(5000, 0)}; // far apart, short links
        d.length = {10, 10};
        made = Moma::create(d);
        QVERIFY(!made.ok());
        QCOMPARE(made.failure().kind, FailureKind::Unreachable);
        // an edit that moves p_max below p_min names p_max, the parameter that was edited
        auto edited = make(ParameterSet{})->withParameter("p_max", -10);
        QVERIFY(!edited.ok());
        QCOMPARE(edited.failure().culprit, std::string("p_max"));
    }

    void poseFailures_data()
    {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<bool>("inputs"); ///< solveDirect (p₁, p₂), else solveInverse (x, y)
        QTest::addColumn<double>("a");
        QTest::addColumn<double>("b");
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("culprit");
        const int outOfRange = int(FailureKind::OutOfRange), unreachable = int(FailureKind::Unreachable);
        QTest::newRow("P far away") << "3a" << false << 1000.0 << 1000.0 << unreachable << "x";
        QTest::newRow("P beyond stroke 1") << "3a" << false << 0.0 << -420.0 << outOfRange << "p1";
        QTest::newRow("P above the sliders") << "3a" << false << 0.0 << 150.0 << -1 << "";
        QTest::newRow("P nan") << "3a" << false << notANumber << -250.0 << outOfRange << "x";
        QTest::newRow("P y -inf") << "3a" << false << 0.0 << -infinity << outOfRange << "y";
        QTest::newRow("p1 above stroke") << "3a" << true << 250.0 << 100.0 << outOfRange << "p1";
        QTest::newRow("p2 below stroke") << "3a" << true << 100.0 << -1.0 << outOfRange << "p2";
        QTest::newRow("p1 nan") << "3a" << true << notANumber << 100.0 << outOfRange << "p1";
        QTest::newRow("p2 inf") << "3a" << true << 100.0 << infinity << outOfRange << "p2";
        QTest::newRow("links cannot meet") << "3d" << true << 200.0 << 200.0 << unreachable << "p1";
    }
    void poseFailures()
    {
        QFETCH(QString, preset);
        QFETCH(bool, inputs);
        QFETCH(double, a);
        QFETCH(double, b);
        QFETCH(int, kind);
        QFETCH(QString, culprit);
        auto m = make(::preset(preset));
        const Pose home = m->homePose();
        auto pose = inputs ? m->solveDirect(pair(a, b), &home) : m->solveInverse(pair(a, b), &home);
        QVERIFY(!pose.ok());
        const QString message = QString::fromStdString(pose.failure().message);
        QVERIFY(!message.isEmpty() && !message.contains(QStringLiteral("nan")));
        if (kind < 0) {
            // any refusal naming a variable will do
            QVERIFY(pose.failure().culprit == "x" || pose.failure().culprit == "p1" || pose.failure().culprit == "p2");
            return;
        }
        QCOMPARE(int(pose.failure().kind), kind);
        QCOMPARE(QString::fromStdString(pose.failure().culprit), culprit);
        // the generic entry point says the same
        const int variable = inputs ? Moma::variableP1 : Moma::variableX;
        auto with = m->solveWith(home, variable, a);
        if (!std::isfinite(a))
            QVERIFY(!with.ok());
    }

    void reasonableEdits()
    {
        auto base = make(ParameterSet{});
        const MomaDesign before = base->design();
        const Pose homeBefore = base->homePose();
        auto turned = base->withParameter("gamma1", base->parameters().at("gamma1") + 3 * deg);
        QVERIFY2(turned.ok(), turned ? "" : turned.failure().message.c_str());
        const auto &t = static_cast<const Moma &>(**turned);
        QVERIFY(std::abs(std::remainder(t.design().alpha[0] - (before.alpha[0] + 3 * deg), 2 * pi)) < 1e-12);
        QCOMPARE(t.design().alpha[1], before.alpha[1]);
        QVERIFY(std::abs(t.parameters().at("gamma1") - (-2 * deg)) < 1e-12);
        QVERIFY(residual(t.design(), t.homePose()) < 1e-9);
        auto longer = base->withParameter("l1", 230);
        QVERIFY(longer.ok());
        const auto &l = static_cast<const Moma &>(**longer);
        QCOMPARE(l.design().length[0], 230.0);
        QVERIFY(residual(l.design(), l.homePose()) < 1e-9);
        QVERIFY(l.workspaceBounds().volume() > 0);
        // several at once, the order of the set does not matter
        auto both = base->withParameters({{"l2", 210.0}, {"p_max", 250.0}});
        QVERIFY(both.ok());
        QCOMPARE((*both)->parameters().at("l2"), 210.0);
        QCOMPARE((*both)->parameters().at("p_max"), 250.0);
        // the old design is unchanged
        QCOMPARE(base->design().alpha[0], before.alpha[0]);
        QCOMPARE(base->design().length[0], before.length[0]);
        QCOMPARE(base->homePose().outputs, homeBefore.outputs);
    }

    void parametersRoundTrip_data() { addPresetRows(); }
    void parametersRoundTrip()
    {
        // Every parameter (gamma_i included) accepts its own current value, and createFrom of
        // parameters() rebuilds the design.
        auto m = rowMoma();
        const ParameterSet values = m->parameters();
        for (const ParameterInfo &info : m->parameterInfo())
            QVERIFY2(values.count(info.name), info.name.c_str());
        for (const auto &[name, value] : values) {
            auto same = m->withParameter(name, value);
            QVERIFY2(same.ok(), (name + ": " + (same ? "" : same.failure().message)).c_str());
            QVERIFY((static_cast<const Moma &>(**same).homePose().outputs - m->homePose().outputs).norm() < 1e-9);
        }
        ParameterSet stored;
        for (const ParameterInfo &info : m->parameterInfo()) {
            if (info.stored)
                stored[info.name] = values.at(info.name);
        }
        auto rebuilt = Moma::createFrom(stored);
        QVERIFY(rebuilt.ok());
        QVERIFY((*rebuilt)->parameters() == values);
    }

    void guideTurnsShowAsTyped()
    {
        // γᵢ = αᵢ − 270° is derived: computed in radians, αᵢ − 3π/2 cancelled two digits and
        // γ₁ of α₁ = 265° read −4.99999999999999° in every report. In degrees it keeps them.
        const Unit angle = units::angle;
        const std::pair<double, double> alphaGamma[] = {{265, -5}, {262.5, -7.5}, {266.25, -3.75}, {264.9, -5.1},
                                                        {267.7, -2.3}, {265.123456789, -4.876543211}};
        for (const auto &[alphaDeg, expected] : alphaGamma) {
            auto m = make(ParameterSet {})->withParameter("alpha1", angle.fromDisplay(alphaDeg));
            QVERIFY(m.ok());
            const double gammaDeg = angle.toDisplay((*m)->parameters().at("gamma1"));
            // as reports print it (15 significant digits), not QCOMPARE's fuzzy equality
            QCOMPARE(QByteArray::number(gammaDeg, 'g', 15), QByteArray::number(expected, 'g', 15));
        }
        for (double gammaDeg : {-5.0, -7.5, -2.25, -4.1, -6.3}) {
            auto byGamma = make(ParameterSet {})->withParameter("gamma1", angle.fromDisplay(gammaDeg));
            QVERIFY(byGamma.ok());
            const double shown = angle.toDisplay((*byGamma)->parameters().at("gamma1"));
            QCOMPARE(QByteArray::number(shown, 'g', 15), QByteArray::number(gammaDeg, 'g', 15));
        }
    }

    void gammaBeyondQuarterTurn_data()
    {
        QTest::addColumn<double>("gammaDeg");
        QTest::newRow("95") << 95.0;
        QTest::newRow("100") << 100.0;
        QTest::newRow("120") << 120.0;
    }
    void gammaBeyondQuarterTurn()
    {
        // γ₁ is documented as any turn in [−180°, 180°] with α₁ = 270° + γ₁. Turning guide 1 of 3a
        // by γ₁ = 95° must give the design that α₁ = 5° gives.
        QFETCH(double, gammaDeg);
        auto base = make(ParameterSet{});
        const double alpha = std::remainder(270 * deg + gammaDeg * deg, 2 * pi);
        auto byAlpha = base->withParameter("alpha1", alpha);
        QVERIFY2(byAlpha.ok(), byAlpha ? "" : byAlpha.failure().message.c_str());
        auto byGamma = base->withParameter("gamma1", gammaDeg * deg);
        QVERIFY2(byGamma.ok(), byGamma ? "" : byGamma.failure().message.c_str());
        if (byGamma) {
            const Eigen::Vector2d a = moma::direction(static_cast<const Moma &>(**byGamma).design().alpha[0]);
            QVERIFY((a - moma::direction(alpha)).norm() < 1e-12);
        }
        auto fromSet = Moma::createFrom({{"gamma1", gammaDeg * deg}});
        QVERIFY(fromSet.ok());
    }

    // -- modes, dragging, drawing ------------------------------------------------------------

    void modeAlternatives_data()
    {
        addPresetRows();
        QTest::newRow("3c-") << "3c-";
    }
    void modeAlternatives()
    {
        // At the home pose and over a grid of the strokes: every alternative is a pose of its
        // own design, keeps the inputs (assembly) or the outputs (working mode), and its design
        // differs from ours by exactly the flipped mode parameters. The grid reuses the
        // neighbouring designs (building them is what costs), as the GUI does.
        auto m = rowMoma();
        const MomaDesign &d = m->design();
        const ParameterSet ours = m->parameters();
        std::vector<Pose> poses = {m->homePose()};
        for (int i = 1; i < 10; ++i) {
            for (int j = 1; j < 10; ++j) {
                auto pose = m->solveDirect(pair(d.strokeMin + (d.strokeMax - d.strokeMin) * i / 10,
                                                d.strokeMin + (d.strokeMax - d.strokeMin) * j / 10));
                if (pose)
                    poses.push_back(*pose);
            }
        }
        const std::vector<ModeAlternative> neighbours = m->modeNeighbours();
        int assemblySwitches = 0, branchSwitches = 0, atHome = 0;
        for (std::size_t k = 0; k < poses.size(); ++k) {
            const Pose &pose = poses[k];
            std::vector<std::string> labels;
            const std::vector<ModeAlternative> alternatives =
                k == 0 ? m->modeAlternatives(pose) : Mechanism::solveAlternatives(neighbours, pose);
            for (const ModeAlternative &alternative : alternatives) {
                QVERIFY(!alternative.label.empty());
                QVERIFY(alternative.mechanism);
                QCOMPARE(alternative.mechanism->kind(), std::string_view("moma"));
                const auto &other = static_cast<const Moma &>(*alternative.mechanism);
                const ParameterSet theirs = other.parameters();
                for (const auto &[name, value] : theirs) {
                    if (alternative.changes.count(name)) {
                        QCOMPARE(value, alternative.changes.at(name));
                        QCOMPARE(value, -ours.at(name)); // flipped
                    } else {
                        QCOMPARE(value, ours.at(name));
                    }
                }
                QVERIFY(finite(alternative.pose));
                QVERIFY(residual(other.design(), alternative.pose) < 1e-9);
                QVERIFY(inModes(other.design(), alternative.pose, 1e-9));
                if (alternative.sameInputs) {
                    // the platform mirrored across Z₁Z₂ (the working modes may flip with it)
                    QVERIFY(alternative.changes.count("assembly"));
                    QCOMPARE(alternative.pose.inputs, pose.inputs);
                    QVERIFY((alternative.pose.outputs - pose.outputs).norm() > 1e-6); // really another pose
                    ++assemblySwitches;
                } else {
                    // a slider at the other root (the assembly mode may flip with it)
                    QVERIFY(alternative.changes.count("branch1") || alternative.changes.count("branch2"));
                    QCOMPARE(alternative.pose.outputs, pose.outputs);
                    QVERIFY((alternative.pose.inputs - pose.inputs).norm() > 1e-6);
                    ++branchSwitches;
                }
                labels.push_back(alternative.label);
                if (k == 0)
                    ++atHome;
            }
            // one alternative per label
            std::sort(labels.begin(), labels.end());
            QVERIFY(std::adjacent_find(labels.begin(), labels.end()) == labels.end());
        }
        qInfo("%s: %d assembly and %d working-mode alternatives over %d poses (%d at home)", QTest::currentDataTag(),
              assemblySwitches, branchSwitches, int(poses.size()), atHome);
        QVERIFY(assemblySwitches + branchSwitches > 0);
        if (QString(QTest::currentDataTag()) == "3c-") {
            // 3c's other assembly mode, at home, has all three: the mirrored platform and
            // either slider at its other root.
            QCOMPARE(atHome, 3);
        }
    }

    void modeWordsDescribeThePose_data() { addPresetRows(); }
    void modeWordsDescribeThePose()
    {
        // The modes' words, shown in the mode bar and accepted in files, say what is true of
        // every pose of the mode: "behind" has the platform's foot on guide i behind its
        // slider (p_i = B_i + √…, (7–9)), "left" the platform left of Z₁→Z₂.
        const auto preset = rowMoma();
        const auto word = [](const ParameterInfo &info, double value) {
            for (const auto &[name, choice] : info.choices)
                if (choice == value)
                    return name;
            return std::string();
        };
        int poses = 0, designs = 0;
        for (int mode = 0; mode < 8; ++mode) {
            const ParameterSet values = {{"branch1", mode & 1 ? 1.0 : -1.0},
                                         {"branch2", mode & 2 ? 1.0 : -1.0},
                                         {"assembly", mode & 4 ? 1.0 : -1.0}};
            auto made = preset->withParameters(values);
            if (!made)
                continue; // no workspace in this combination of modes
            ++designs;
            const auto &m = static_cast<const Moma &>(**made);
            std::map<std::string, std::string> words;
            for (const ParameterInfo &info : m.parameterInfo())
                if (info.group == ParameterGroup::Mode && info.name != "one_side")
                    words[info.name] = word(info, values.at(info.name));
            QCOMPARE(words.size(), std::size_t(3));
            const MomaDesign &d = m.design();
            for (int i = 1; i < 10; ++i) {
                for (int j = 1; j < 10; ++j) {
                    auto pose = m.solveDirect(pair(d.strokeMin + (d.strokeMax - d.strokeMin) * i / 10,
                                                   d.strokeMin + (d.strokeMax - d.strokeMin) * j / 10));
                    if (!pose)
                        continue;
                    const Eigen::Vector2d platform = pose->outputs.head<2>();
                    for (int leg = 0; leg < 2; ++leg) {
                        const double foot = moma::projection(d, leg, platform), slider = pose->inputs[leg];
                        QCOMPARE(words.at(leg == 0 ? "branch1" : "branch2"), std::string(foot < slider ? "behind" : "ahead"));
                    }
                    const Eigen::Vector2d z1 = moma::sliderJoint(d, 0, pose->inputs[0]), z2 = moma::sliderJoint(d, 1, pose->inputs[1]);
                    const Eigen::Vector2d a = z2 - z1, b = platform - z1;
                    QCOMPARE(words.at("assembly"), std::string(a.x() * b.y() - a.y() * b.x() > 0 ? "left" : "right"));
                    ++poses;
                }
            }
        }
        QVERIFY(designs >= 2);
        QVERIFY(poses > 50);
        qInfo("%d of 8 mode combinations with a workspace, %d poses", designs, poses);
    }

    void dragHandle_data() { addPresetRows(); }
    void dragHandle()
    {
        auto m = rowMoma();
        const MomaDesign &d = m->design();
        const Pose home = m->homePose();
        // handle 0: the platform follows the pointer (inverse kinematics)
        const Eigen::Vector2d target = platformOf(home) + Eigen::Vector2d(1.5, -2.0);
        auto moved = m->dragHandle(home, 0, target);
        QVERIFY(moved.ok());
        QCOMPARE(platformOf(*moved), target);
        QVERIFY((moved->inputs - m->solveInverse(moved->outputs)->inputs).norm() == 0);
        // handles 1 and 2: slider i moves along its guide to the pointer's projection; the other stays
        for (int leg = 0; leg < 2; ++leg) {
            const double p = home.inputs[leg] + 4.0;
            const Eigen::Vector2d pointer = moma::sliderJoint(d, leg, p) + 35.0 * normalOf(d.alpha[leg]);
            auto slid = m->dragHandle(home, 1 + leg, pointer);
            QVERIFY2(slid.ok(), slid ? "" : slid.failure().message.c_str());
            QVERIFY(std::abs(slid->inputs[leg] - p) < 1e-9 * scaleOf(d));
            QCOMPARE(slid->inputs[1 - leg], home.inputs[1 - leg]);
            auto direct = m->solveDirect(slid->inputs);
            QVERIFY((platformOf(*direct) - platformOf(*slid)).norm() == 0);
            QVERIFY(residual(d, *slid) < 1e-9);
            // far past the end of the stroke: the slider stops there (or the pose is refused)
            auto past = m->dragHandle(home, 1 + leg, moma::sliderJoint(d, leg, d.strokeMax + 500));
            if (past)
                QCOMPARE(past->inputs[leg], d.strokeMax);
            else
                QCOMPARE(QString::fromStdString(past.failure().culprit).left(1), QStringLiteral("p"));
        }
        auto none = m->dragHandle(home, 3, target);
        QVERIFY(!none.ok());
        auto nowhere = m->dragHandle(home, 1, Eigen::Vector2d(notANumber, 0));
        QVERIFY(!nowhere.ok());
    }

    void sceneMatchesPose_data() { addPresetRows(); }
    void sceneMatchesPose()
    {
        auto m = rowMoma();
        const MomaDesign &d = m->design();
        const Pose home = m->homePose();
        const Scene s = m->scene(home);
        QCOMPARE(s.joints.size(), std::size_t(5));
        QVERIFY((s.joints[0].position.head<2>() - platformOf(home)).norm() < 1e-12);
        for (int leg = 0; leg < 2; ++leg) {
            const Eigen::Vector2d z = moma::sliderJoint(d, leg, home.inputs[leg]);
            QVERIFY((s.joints[1 + leg].position.head<2>() - z).norm() < 1e-12);
            const SceneBar &bar = s.bars[static_cast<std::size_t>(leg)];
            QVERIFY(std::abs((s.joints[bar.to].position - s.joints[bar.from].position).norm() - d.length[leg])
                    < 1e-9 * d.length[leg]);
            const SceneGuide &guide = s.guides[static_cast<std::size_t>(leg)];
            QVERIFY((guide.start.head<2>() - moma::sliderJoint(d, leg, d.strokeMin)).norm() < 1e-12);
            QVERIFY((guide.end.head<2>() - moma::sliderJoint(d, leg, d.strokeMax)).norm() < 1e-12);
        }
        for (const SceneJoint &joint : s.joints)
            QVERIFY(s.extent.contains(joint.position));
        QCOMPARE(s.handles.size(), std::size_t(3));
    }
};

QTEST_APPLESS_MAIN(TestMoma)
#include "tst_moma.moc"
