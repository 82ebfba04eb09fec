// The O-X glide (docs/mathematics.md) against its own closed forms, derived again here: the
// kinematics both ways in both forms for the prototype and for random designs, the document's
// "+ s" in the X form's direct kinematics, the form the direct kinematics reports and the
// refusal to cross it, the Jacobians against finite differences, the workspace areas against
// an independent integration, the maps against the pose solver, failures that name their
// culprit, the neighbouring form, dragging, the drawings and the independent z axis.
#include "kinds/oxglide/oxglide.h"
#include "support/kinematics.h"

#include <QTest>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace pkm;
using namespace pkm::test;

Q_DECLARE_METATYPE(pkm::ParameterSet)

namespace {
constexpr double pi = std::numbers::pi;
constexpr double notANumber = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr int formO = oxglide::formO;
constexpr int formX = oxglide::formX;

/// The prototype of the document (l = 80, s = 20, L = 130 mm) in the given form.
OxGlideDesign prototype(int form = formO)
{
    OxGlideDesign d;
    d.rod = 80;
    d.width = 20;
    d.guideLength = 130;
    d.spacing = 15;
    d.zMin = 0;
    d.zMax = 150;
    d.form = form;
    return d;
}

Eigen::Vector2d platformOf(const Pose &pose)
{
    return pose.outputs.head<2>();
}

/// The design's length scale, for tolerances.
double scaleOf(const OxGlideDesign &d)
{
    return std::max(d.rod, d.guideLength);
}

double wOf(const OxGlideDesign &d, double y)
{
    return std::sqrt(std::max(0.0, d.rod * d.rod - y * y));
}

/// The inverse kinematics, written again from docs/mathematics.md, section 3:
///   O: x_AB = x − s/2 − w, x_CD = x + s/2 + w;  X: x_AB = x − s/2 + w, x_CD = x + s/2 − w.
Eigen::Vector2d inverseOf(const OxGlideDesign &d, int form, double x, double y)
{
    const double w = wOf(d, y);
    return form == formO ? Eigen::Vector2d(x - d.width / 2 - w, x + d.width / 2 + w)
                         : Eigen::Vector2d(x - d.width / 2 + w, x + d.width / 2 - w);
}

/// The reachable x at height y in one form: both slider pairs on [0, L]. From the inverse
/// kinematics: O: x ∈ [s/2 + w, L − s/2 − w]; X: x ∈ [|w − s/2|, L − |w − s/2|].
struct Slice {
    double lo = 0;
    double hi = -1;
    double width() const { return std::max(0.0, hi - lo); }
};

Slice sliceOf(const OxGlideDesign &d, int form, double y)
{
    const double w = wOf(d, y), s = d.width, L = d.guideLength;
    if (form == formO)
        return {s / 2 + w, L - s / 2 - w};
    return {std::abs(w - s / 2), L - std::abs(w - s / 2)};
}

/// The lowest height of the workspace of a form: where the slice closes (w = (L ∓ s)/2), or 0.
double lowestHeight(const OxGlideDesign &d, int form)
{
    const double c = form == formO ? (d.guideLength - d.width) / 2 : (d.guideLength + d.width) / 2;
    return c >= d.rod ? 0.0 : std::sqrt(d.rod * d.rod - c * c);
}

/// A random valid design: s < 2l, L > s (by at least 0.3·l, see homePoseOfThinWorkspace).
/// About a third have L − s ≥ 2l, so that even the O form reaches y = 0.
OxGlideDesign randomDesign(std::mt19937 &generator)
{
    OxGlideDesign d;
    d.rod = uniform(generator, 20, 300);
    d.width = uniform(generator, 0.02, 1.95) * d.rod;
    d.guideLength = d.width + uniform(generator, 0.3, 3.2) * d.rod;
    d.spacing = uniform(generator, 3, 30);
    d.zMin = uniform(generator, -200, 200);
    d.zMax = d.zMin + uniform(generator, 10, 500);
    return d;
}

QByteArray describe(const OxGlideDesign &d)
{
    return QByteArray("l = ") + QByteArray::number(d.rod, 'g', 17) + ", s = " + QByteArray::number(d.width, 'g', 17)
        + ", L = " + QByteArray::number(d.guideLength, 'g', 17) + ", form " + oxglide::formName(d.form);
}

QByteArray at(double a, double b)
{
    return " at (" + QByteArray::number(a, 'g', 17) + ", " + QByteArray::number(b, 'g', 17) + ")";
}

/// Round-trip tolerance (mm) at a pose of singularity margin m: exact to rounding away from
/// the singularities; next to y = l the inverse takes √(l² − y²) of a near-zero difference,
/// next to y = 0 the direct one √(4l² − e²), which turn rounding ε into about ε·l/m.
double roundTripTolerance(double scale, double margin)
{
    return 1e-9 * scale + 1e-15 * scale / std::max(margin, 1e-12);
}

struct RoundTripStats {
    int inverse = 0; ///< x → q → x round trips
    int direct = 0; ///< q → x → q round trips
    double worstPoint = 0; ///< x → q → x, relative to the scale
    double worstInputs = 0; ///< q → x → q, relative to the scale
    double worstPointAway = 0; ///< the same, margin > 1e-3
    double worstInputsAway = 0;
};

/// x → q → x over the workspace of the design's form (heights from the lowest one to l,
/// including y → l and the slice ends, i.e. the ends of the strokes), and q → x → q over the
/// slider positions that hold the form (including x_CD − x_AB − s → 0 and → ±2l).
void checkRoundTrips(const OxGlide &m, RoundTripStats &stats, const QByteArray &context)
{
    const OxGlideDesign &d = m.design();
    const double l = d.rod, L = d.guideLength, scale = scaleOf(d);
    const double yLow = lowestHeight(d, d.form);
    std::vector<double> heights = {l, l * (1 - 1e-12), l * (1 - 1e-9), l * (1 - 1e-6), l * (1 - 1e-3), yLow,
        yLow + 1e-9 * l, yLow + 1e-6 * l, yLow + 1e-3 * l};
    for (int i = 1; i < 24; ++i)
        heights.push_back(yLow + (l - yLow) * i / 24.0);
    Pose near = m.homePose();
    near.inputs[2] = 0.25 * d.zMin + 0.75 * d.zMax;
    for (const double y : heights) {
        if (y < 0 || y > l)
            continue;
        const Slice slice = sliceOf(d, d.form, y);
        if (slice.hi < slice.lo)
            continue; // the bottom point itself, lost to rounding
        std::vector<double> xs = {slice.lo, slice.hi, slice.lo + 1e-9 * scale, slice.hi - 1e-9 * scale,
            slice.lo + 1e-4 * scale, slice.hi - 1e-4 * scale};
        for (int i = 1; i < 12; ++i)
            xs.push_back(slice.lo + (slice.hi - slice.lo) * i / 12.0);
        for (const double x : xs) {
            if (x < slice.lo || x > slice.hi)
                continue;
            const QByteArray where = context + at(x, y);
            auto pose = m.solveInverse(pair(x, y), &near);
            QVERIFY2(pose.ok(), where + ": " + (pose ? "" : pose.failure().message.c_str()));
            QCOMPARE(pose->outputs.size(), 2);
            QCOMPARE(pose->inputs.size(), 3);
            QCOMPARE(pose->outputs[0], x);
            QCOMPARE(pose->outputs[1], y);
            QCOMPARE(pose->inputs[2], near.inputs[2]);
            QCOMPARE(pose->mode, d.form);
            // the inputs are the closed form's, on the guides (a slice end is a stroke end)
            const Eigen::Vector2d q = inverseOf(d, d.form, x, y);
            QVERIFY2((pose->inputs.head<2>() - q).cwiseAbs().maxCoeff() <= 1e-12 * scale, where);
            QVERIFY2(
                pose->inputs[0] >= 0 && pose->inputs[0] <= L && pose->inputs[1] >= 0 && pose->inputs[1] <= L, where);
            // … and the direct kinematics gives the point back, keeping the inputs
            auto back = m.solveDirect(pose->inputs, &*pose);
            QVERIFY2(back.ok(), where + ": " + (back ? "" : back.failure().message.c_str()));
            QCOMPARE(back->inputs, pose->inputs);
            const double margin = m.singularity(*pose).margin;
            const double error = (platformOf(*back) - Eigen::Vector2d(x, y)).cwiseAbs().maxCoeff();
            QVERIFY2(error <= roundTripTolerance(scale, margin),
                where + " back to" + at(back->outputs[0], back->outputs[1]));
            stats.worstPoint = std::max(stats.worstPoint, error / scale);
            if (margin > 1e-3)
                stats.worstPointAway = std::max(stats.worstPointAway, error / scale);
            ++stats.inverse;
        }
    }

    // q → x → q: x_CD − x_AB − s = e, with e > 0 (O) or < 0 (X), |e| ≤ 2l
    const int n = 24;
    for (int i = 0; i <= n; ++i) {
        const double xAB = i == n ? L : L * i / n; // (L·n/n may round above L)
        // the interval of x_CD holding the form
        const double from = d.form == formO ? xAB + d.width : std::max(0.0, xAB + d.width - 2 * l);
        const double to = d.form == formO ? std::min(L, xAB + d.width + 2 * l) : std::min(L, xAB + d.width);
        if (from > to)
            continue;
        std::vector<double> xCDs = {from, to};
        for (double step : {1e-9, 1e-6, 1e-3}) {
            xCDs.push_back(from + step * l);
            xCDs.push_back(to - step * l);
        }
        for (int j = 1; j < n; ++j)
            xCDs.push_back(from + (to - from) * j / n);
        for (const double xCD : xCDs) {
            if (xCD < from || xCD > to)
                continue;
            const QByteArray where = context + " q =" + at(xAB, xCD);
            const Coordinates inputs = triple(xAB, xCD, d.zMin);
            auto pose = m.solveDirect(inputs);
            QVERIFY2(pose.ok(), where + ": " + (pose ? "" : pose.failure().message.c_str()));
            QCOMPARE(pose->inputs, inputs);
            QVERIFY2(pose->outputs.allFinite(), where);
            QVERIFY2(pose->outputs[1] >= 0 && pose->outputs[1] <= l, where);
            QCOMPARE(pose->outputs[0], 0.5 * (xAB + xCD));
            auto back = m.solveInverse(pose->outputs, &*pose);
            QVERIFY2(back.ok(), where + ": " + (back ? "" : back.failure().message.c_str()));
            QCOMPARE(back->outputs, pose->outputs);
            QCOMPARE(back->inputs[2], d.zMin);
            const double margin = m.singularity(*pose).margin;
            const double error = (back->inputs - pose->inputs).cwiseAbs().maxCoeff();
            QVERIFY2(error <= roundTripTolerance(scale, margin),
                where + " back to q =" + at(back->inputs[0], back->inputs[1]));
            stats.worstInputs = std::max(stats.worstInputs, error / scale);
            if (margin > 1e-3)
                stats.worstInputsAway = std::max(stats.worstInputsAway, error / scale);
            ++stats.direct;
        }
    }
}

/// The map of `quantity` over a grid.
struct Map {
    MapGrid grid;
    std::vector<float> values;
    std::vector<float> margins;
    MapSummary summary;

    float at(int c, int r) const { return values[static_cast<std::size_t>(r) * grid.columns + c]; }
    float marginAt(int c, int r) const { return margins[static_cast<std::size_t>(r) * grid.columns + c]; }
    bool reachable(int c, int r) const
    {
        return c >= 0 && r >= 0 && c < grid.columns && r < grid.rows && !std::isnan(at(c, r));
    }
    /// Is any cell within one of (c, r) (itself included) reachable / unreachable?
    bool nearReachable(int c, int r, bool reachable) const
    {
        for (int dr = -1; dr <= 1; ++dr) {
            for (int dc = -1; dc <= 1; ++dc) {
                const int cc = c + dc, rr = r + dr;
                const bool inside = cc >= 0 && rr >= 0 && cc < grid.columns && rr < grid.rows;
                if ((inside && this->reachable(cc, rr)) == reachable)
                    return true;
            }
        }
        return false;
    }
};

Map computed(const OxGlide &m, MapQuantity quantity, const MapGrid &grid, bool withMargins = true)
{
    Map map;
    map.grid = grid;
    map.values.assign(map.grid.cells(), 0.0f);
    if (withMargins)
        map.margins.assign(map.grid.cells(), 0.0f);
    map.summary = computeMap(m, quantity, map.grid, map.values, map.margins);
    return map;
}

/// The area of one form's workspace by the midpoint rule in φ, y = l·sin φ (dy = l·cos φ dφ
/// takes the square root out of w = l·cos φ), over the slice widths of sliceOf().
double integratedArea(const OxGlideDesign &d, int form, int steps)
{
    double area = 0;
    const double h = 0.5 * pi / steps;
    for (int i = 0; i < steps; ++i) {
        const double phi = (i + 0.5) * h;
        area += sliceOf(d, form, d.rod * std::sin(phi)).width() * d.rod * std::cos(phi) * h;
    }
    return area;
}

/// The perimeter of one form's workspace: the left and right boundary curves traced finely,
/// the top edge at y = l and the bottom edge at the lowest height.
double perimeterOf(const OxGlideDesign &d, int form)
{
    const double y0 = lowestHeight(d, form), l = d.rod;
    const int steps = 200000;
    double length = sliceOf(d, form, l).width() + sliceOf(d, form, y0).width();
    Slice previous = sliceOf(d, form, y0);
    double yPrevious = y0;
    for (int i = 1; i <= steps; ++i) {
        // denser near y = l, where the boundary turns horizontal
        const double t = double(i) / steps;
        const double y = y0 + (l - y0) * (1 - (1 - t) * (1 - t));
        const Slice slice = sliceOf(d, form, y);
        length += std::hypot(slice.lo - previous.lo, y - yPrevious) + std::hypot(slice.hi - previous.hi, y - yPrevious);
        previous = slice;
        yPrevious = y;
    }
    return length;
}

/// Poses across the workspace of the design's form and the whole z travel.
std::vector<Pose> posesAcross(const OxGlide &m, int n)
{
    const OxGlideDesign &d = m.design();
    std::vector<Pose> poses;
    const double y0 = lowestHeight(d, d.form);
    for (int i = 0; i <= n; ++i) {
        const double y = y0 + (d.rod - y0) * i / n;
        const Slice slice = sliceOf(d, d.form, y);
        for (int j = 0; j <= n; ++j) {
            const double x = slice.lo + (slice.hi - slice.lo) * j / n;
            for (double z : {d.zMin, 0.5 * (d.zMin + d.zMax), d.zMax}) {
                Pose near = m.homePose();
                near.inputs[2] = z;
                if (auto pose = m.solveInverse(pair(x, y), &near))
                    poses.push_back(*pose);
            }
        }
    }
    return poses;
}
} // namespace

class TestOxGlide : public QObject
{
    Q_OBJECT

private slots:
    // -- closed forms and kinematics ---------------------------------------------------------------

    void closedFormsMatchDomain()
    {
        // oxglide::inverse / direct are the formulas of docs/mathematics.md, section 3 (with "− s" in both forms).
        const OxGlideDesign d = prototype();
        for (int form : {formO, formX}) {
            for (double y : {0.0, 10.0, 33.3, 60.0, 79.9, 80.0}) {
                for (double x : {20.0, 65.0, 101.5}) {
                    const Eigen::Vector2d q = oxglide::inverse(d.rod, d.width, form, {x, y});
                    QVERIFY((q - inverseOf(d, form, x, y)).norm() < 1e-12);
                    // the rods have length l: |(x ∓ s/2, y) − (x_i, 0)| = l
                    QVERIFY(std::abs(std::hypot(x - d.width / 2 - q[0], y) - d.rod) < 1e-12 * d.rod);
                    QVERIFY(std::abs(std::hypot(x + d.width / 2 - q[1], y) - d.rod) < 1e-12 * d.rod);
                    const auto direct = oxglide::direct(d.rod, d.width, q[0], q[1]);
                    QVERIFY(direct.valid);
                    QVERIFY((direct.platform - Eigen::Vector2d(x, y)).norm() < 1e-9 * d.rod);
                }
            }
        }
        // rods that cannot reach: |x_CD − x_AB − s| > 2l
        QVERIFY(!oxglide::direct(80, 20, 0, 20 + 160.001).valid);
        QVERIFY(!oxglide::direct(80, 20, 130, 130 + 20 - 160.001).valid);
        QVERIFY(oxglide::direct(80, 20, 0, 180).valid);
        QCOMPARE(oxglide::direct(80, 20, 0, 180).platform.y(), 0.0);
        QCOMPARE(QByteArray(oxglide::formName(formO)), QByteArray("O"));
        QCOMPARE(QByteArray(oxglide::formName(formX)), QByteArray("X"));
    }

    void prototypeRoundTrips_data()
    {
        QTest::addColumn<int>("form");
        QTest::newRow("O") << formO;
        QTest::newRow("X") << formX;
    }
    void prototypeRoundTrips()
    {
        QFETCH(int, form);
        auto m = make(prototype(form));
        RoundTripStats stats;
        checkRoundTrips(*m, stats, describe(m->design()));
        if (QTest::currentTestFailed())
            return;
        qInfo("prototype %s: %d x→q→x and %d q→x→q round trips; worst relative errors %.2g and %.2g "
              "(%.2g and %.2g with margin > 1e-3)",
            oxglide::formName(form), stats.inverse, stats.direct, stats.worstPoint, stats.worstInputs,
            stats.worstPointAway, stats.worstInputsAway);
        QVERIFY(stats.inverse > 500 && stats.direct > 300);
        QVERIFY(stats.worstPointAway <= 1e-9 && stats.worstInputsAway <= 1e-9);
        // the home pose is a pose of the design, well away from the singularities
        const Pose home = m->homePose();
        QCOMPARE(home.inputs.size(), 3);
        QCOMPARE(home.mode, form);
        QVERIFY(m->singularity(home).margin > 0.2);
        auto again = m->solveDirect(home.inputs);
        QVERIFY(again.ok());
        QVERIFY((again->outputs - home.outputs).norm() < 1e-9 * 130);
    }

    void randomRoundTrips()
    {
        std::mt19937 generator(20240923);
        RoundTripStats stats;
        int designs = 0, reachingZero[2] = {0, 0};
        for (int k = 0; k < 30; ++k) {
            OxGlideDesign d = randomDesign(generator);
            for (int form : {formO, formX}) {
                d.form = form;
                const QByteArray context = "design " + QByteArray::number(k) + " (" + describe(d) + ")";
                auto made = OxGlide::create(d);
                QVERIFY2(made.ok(), context + ": " + (made ? "" : made.failure().message.c_str()));
                const auto &m = static_cast<const OxGlide &>(**made);
                QVERIFY2(m.homePose().inputs.size() == 3, context);
                checkRoundTrips(m, stats, context);
                if (QTest::currentTestFailed())
                    return;
                ++designs;
                reachingZero[form == formO ? 0 : 1] += lowestHeight(d, form) == 0.0;
            }
        }
        qInfo("random designs: %d (O and X), %d O and %d X workspaces reaching y = 0; %d x→q→x and %d q→x→q round "
              "trips; worst relative errors %.2g and %.2g (%.2g and %.2g with margin > 1e-3)",
            designs, reachingZero[0], reachingZero[1], stats.inverse, stats.direct, stats.worstPoint, stats.worstInputs,
            stats.worstPointAway, stats.worstInputsAway);
        QVERIFY(stats.worstPointAway <= 1e-9 && stats.worstInputsAway <= 1e-9);
        QVERIFY(reachingZero[0] > 0 && reachingZero[1] > reachingZero[0]);
        QVERIFY(stats.inverse > 20000 && stats.direct > 10000);
    }

    void homePoseOfThinWorkspace()
    {
        // Every valid design has a home pose (x_AB, x_CD, z), also when L is only a little
        // longer than s and the O workspace is a thin sliver under y = l: the home search
        // samples the heights the form reaches, not all of (0, l).
        OxGlideDesign d = prototype();
        d.guideLength = d.width + 0.5; // (L − s)/2 = 0.25 mm
        auto made = OxGlide::create(d);
        QVERIFY(made.ok());
        const auto &m = static_cast<const OxGlide &>(**made);
        // the workspace itself exists: T = (L/2, l) is reachable with near given
        Pose near;
        near.inputs = triple(0, 0, 10);
        auto top = m.solveInverse(pair(d.guideLength / 2, d.rod), &near);
        QVERIFY(top.ok());
        QVERIFY(oxglide::exactArea(d, formO) > 0);
        QCOMPARE(m.homePose().inputs.size(), 3);
        QVERIFY(m.solveInverse(m.homePose().outputs).ok());
    }

    // -- the printed X-form formula's error ----------------------------------------------

    void printedXFormDirectKinematicsIsWrong()
    {
        // docs/mathematics.md, section 3: the document writes y = ½√(4l² − (x_CD − x_AB + s)²) for the X form. Its
        // own X inverse kinematics, x_AB = x − s/2 + w, x_CD = x + s/2 − w, gives
        // x_CD − x_AB = s − 2w, so "+ s" leaves 2s − 2w where −2w belongs.
        const OxGlideDesign d = prototype(formX);
        const double l = d.rod, s = d.width;
        auto printed = [&](double xAB, double xCD) {
            const double e = xCD - xAB + s;
            return 0.5 * std::sqrt(4 * l * l - e * e);
        };
        auto m = make(d);
        // T = (65, 60) in the X form: x_AB = 55 + √2800 ≈ 107.92, x_CD ≈ 22.08
        auto pose = m->solveInverse(pair(65, 60));
        QVERIFY(pose.ok());
        const double xAB = pose->inputs[0], xCD = pose->inputs[1];
        QVERIFY(std::abs(xAB - (55 + std::sqrt(2800.0))) < 1e-12);
        const double wrong = printed(xAB, xCD);
        qInfo("X form, T = (65, 60): the document's direct kinematics gives y = %.3f mm", wrong);
        QVERIFY2(std::abs(wrong - 60) > 12, qPrintable(QString::number(wrong))); // ≈ 72.9 mm: off by 12.9 mm
        const auto right = oxglide::direct(l, s, xAB, xCD);
        QVERIFY(right.valid);
        QCOMPARE(right.form, formX);
        QVERIFY((right.platform - Eigen::Vector2d(65, 60)).norm() < 1e-12 * 130);
        auto back = m->solveDirect(pose->inputs);
        QVERIFY(back.ok());
        QVERIFY((platformOf(*back) - Eigen::Vector2d(65, 60)).norm() < 1e-12 * 130);
        // at the crossing (rods parallel and upright, y = l) the document's formula says √(l² − s²)
        QCOMPARE(printed(40, 60), std::sqrt(l * l - s * s));
        QCOMPARE(oxglide::direct(l, s, 40, 60).platform.y(), l);

        // Over the X workspace the document's formula misses every pose but those with (2s − 2w)² = (2w)²,
        // i.e. w = s/2 (the rods cross at the platform joints).
        double worstPrinted = 0, worstOurs = 0;
        int poses = 0;
        for (double y = 1; y < l; y += 1.5) {
            const Slice slice = sliceOf(d, formX, y);
            for (int i = 0; i <= 10 && slice.lo <= slice.hi; ++i) {
                const double x = slice.lo + (slice.hi - slice.lo) * i / 10;
                const Eigen::Vector2d q = inverseOf(d, formX, x, y);
                const double e = q[1] - q[0] + s;
                if (4 * l * l - e * e >= 0)
                    worstPrinted = std::max(worstPrinted, std::abs(printed(q[0], q[1]) - y));
                else
                    worstPrinted = infinity; // the printed formula's rods cannot even reach
                worstOurs = std::max(worstOurs, std::abs(oxglide::direct(l, s, q[0], q[1]).platform.y() - y));
                ++poses;
            }
        }
        qInfo("over %d X poses of the prototype: the document's y is off by up to %g mm, the corrected one by %.2g mm",
            poses, worstPrinted, worstOurs);
        QVERIFY(worstPrinted > 30);
        QVERIFY(worstOurs < 1e-9 * l);
        // … and there it is right
        const double yh = std::sqrt(l * l - s * s / 4);
        const Eigen::Vector2d q = inverseOf(d, formX, 65, yh);
        QVERIFY(std::abs(printed(q[0], q[1]) - yh) < 1e-9 * l);
    }

    // -- the form --------------------------------------------------------------------------------

    void directReportsTheForm()
    {
        const double l = 80, s = 20;
        // x_CD − x_AB > s: O; < s: X; = s: 0 (exactly representable numbers)
        QCOMPARE(oxglide::direct(l, s, 10, 100).form, formO);
        QCOMPARE(oxglide::direct(l, s, 10, 30.5).form, formO);
        QCOMPARE(oxglide::direct(l, s, 10, 29.5).form, formX);
        QCOMPARE(oxglide::direct(l, s, 100, 10).form, formX);
        QCOMPARE(oxglide::direct(l, s, 40, 60).form, 0);
        QCOMPARE(oxglide::direct(l, s, 40, 60).platform, Eigen::Vector2d(50, 80));
        // in between, over a grid: the sign of x_CD − x_AB − s
        for (double xAB = 0; xAB <= 130; xAB += 6.5) {
            for (double xCD = 0; xCD <= 130; xCD += 6.5) {
                const auto solution = oxglide::direct(l, s, xAB, xCD);
                const double e = xCD - xAB - s;
                QCOMPARE(solution.valid, std::abs(e) <= 2 * l);
                if (solution.valid)
                    QCOMPARE(solution.form, e > 0 ? formO : e < 0 ? formX : 0);
            }
        }
    }

    void solveDirectKeepsTheForm_data()
    {
        QTest::addColumn<int>("form");
        QTest::newRow("O design") << formO;
        QTest::newRow("X design") << formX;
    }
    void solveDirectKeepsTheForm()
    {
        QFETCH(int, form);
        auto m = make(prototype(form));
        // inputs of the other form: x_CD − x_AB = 10 (< s: X) or 40 (> s: O)
        const Coordinates other = form == formO ? triple(60, 70, 10) : triple(30, 70, 10);
        auto refused = m->solveDirect(other);
        QVERIFY(!refused.ok());
        QCOMPARE(refused.failure().kind, FailureKind::Singular);
        QCOMPARE(refused.failure().culprit, std::string("x_CD"));
        const QString message = QString::fromStdString(refused.failure().message);
        QVERIFY2(message.contains(QStringLiteral("form")), qPrintable(message));
        QVERIFY2(message.contains(QString::fromUtf8(oxglide::formTitle(-form))), qPrintable(message));
        QVERIFY2(message.contains(QString::fromUtf8(oxglide::formTitle(form))), qPrintable(message));
        // … while the design of that form takes them
        auto otherDesign = make(prototype(-form));
        auto taken = otherDesign->solveDirect(other);
        QVERIFY(taken.ok());
        QCOMPARE(taken->mode, -form);
        // its own form's inputs
        const Coordinates own = form == formO ? triple(30, 70, 10) : triple(60, 70, 10);
        QVERIFY(m->solveDirect(own).ok());
        // at x_CD − x_AB = s exactly both designs accept: y = l, rods parallel and upright
        auto crossing = m->solveDirect(triple(40, 60, 10));
        QVERIFY2(crossing.ok(), crossing ? "" : crossing.failure().message.c_str());
        QCOMPARE(platformOf(*crossing), Eigen::Vector2d(50, 80));
        QCOMPARE(crossing->mode, form);
        QCOMPARE(m->crossingInputs(50), Eigen::Vector2d(40, 60));
        Singularity s;
        const std::vector<double> v = evaluated(*m, *crossing, &s);
        QCOMPARE(s.type, SingularityType::Combined);
        QCOMPARE(m->singularity(*crossing).type, SingularityType::Combined);
        QCOMPARE(s.margin, 0.0);
        QCOMPARE(entry(*m, v, "crossing"), 0.0);
        QCOMPARE(entry(*m, v, "det_Jq"), 0.0);
        QCOMPARE(entry(*m, v, "det_Jx"), 0.0);
        QVERIFY(std::abs(entry(*m, v, "rod_angle") - pi / 2) < 1e-12);
        QVERIFY(!(entry(*m, v, "cond") < 1e12)); // +∞
        // a hair to the own side is fine and no longer singular; to the other side refused
        const double hair = form == formO ? 1e-3 : -1e-3;
        auto inside = m->solveDirect(triple(40, 60 + hair, 10));
        QVERIFY(inside.ok());
        QCOMPARE(m->singularity(*inside).type, SingularityType::None);
        QVERIFY(!m->solveDirect(triple(40, 60 - hair, 10)).ok());
    }

    // -- Jacobians -------------------------------------------------------------------------------

    void jacobians_data()
    {
        QTest::addColumn<int>("form");
        QTest::newRow("O") << formO;
        QTest::newRow("X") << formX;
    }
    void jacobians()
    {
        QFETCH(int, form);
        std::vector<OxGlideDesign> designs = {prototype(form)};
        std::mt19937 generator(7);
        for (int k = 0; k < 4; ++k) {
            designs.push_back(randomDesign(generator));
            designs.back().form = form;
        }
        int checked = 0;
        double worstDifference = 0;
        for (const OxGlideDesign &d : designs) {
            auto m = make(d);
            const double y0 = lowestHeight(d, form), scale = scaleOf(d);
            for (int i = 1; i < 8; ++i) {
                const double y = y0 + (d.rod - y0) * i / 8;
                const Slice slice = sliceOf(d, form, y);
                for (int j = 1; j < 6; ++j) {
                    const double x = slice.lo + (slice.hi - slice.lo) * j / 6;
                    auto solved = m->solveInverse(pair(x, y));
                    QVERIFY(solved.ok());
                    const Pose pose = *solved;
                    const QByteArray where = describe(d) + at(x, y);
                    const Jacobians jac = m->jacobians(pose);
                    QCOMPARE(jac.full.rows(), 3);
                    QCOMPARE(jac.full.cols(), 2);
                    QCOMPARE(jac.inputs.rows(), 3);
                    QCOMPARE(jac.inputs.cols(), 3);
                    QCOMPARE(jac.outputs.rows(), 3);
                    QCOMPARE(jac.outputs.cols(), 2);
                    // z does not depend on the platform's x, y
                    QCOMPARE(jac.full(2, 0), 0.0);
                    QCOMPARE(jac.full(2, 1), 0.0);
                    // J = dq/dx from central differences of the inverse kinematics
                    const double h = 1e-5 * scale;
                    Eigen::Matrix2d numeric;
                    for (int c = 0; c < 2; ++c) {
                        Coordinates up = pose.outputs, down = pose.outputs;
                        up[c] += h;
                        down[c] -= h;
                        // (by the closed form: a step may leave the workspace at its edge)
                        numeric.col(c)
                            = (inverseOf(d, form, up[0], up[1]) - inverseOf(d, form, down[0], down[1])) / (2 * h);
                        if (const auto solved = inverseDifference(*m, pose.outputs, c, h))
                            QVERIFY2((solved->head<2>() - numeric.col(c)).norm() < 1e-9 * std::max(1.0, numeric.norm()),
                                where);
                    }
                    const Eigen::Matrix2d J = jac.full.topRows<2>();
                    const double difference = (J - numeric).norm() / std::max(1.0, J.norm());
                    QVERIFY2(difference < 1e-6, where + " difference " + QByteArray::number(difference));
                    worstDifference = std::max(worstDifference, difference);
                    // J_q·J = J_x (the interface's convention)
                    QVERIFY2((jac.inputs * jac.full - jac.outputs).norm() < 1e-12 * std::max(1.0, jac.outputs.norm()),
                        where);
                    // det J = −2y/w (O), +2y/w (X); the columns are orthogonal: κ = max(y/w, w/y)
                    const double w = wOf(d, y);
                    const double det = (form == formO ? -2.0 : 2.0) * y / w;
                    QVERIFY2(std::abs(J.determinant() - det) <= 1e-9 * std::abs(det), where);
                    Eigen::JacobiSVD<Eigen::Matrix2d> svd(J);
                    const double kappa = svd.singularValues()(0) / svd.singularValues()(1);
                    QVERIFY2(std::abs(kappa - std::max(y / w, w / y)) <= 1e-9 * kappa, where);
                    // the report agrees
                    Singularity s;
                    const std::vector<double> v = evaluated(*m, pose, &s);
                    auto close = [](double a, double b) { return std::abs(a - b) <= 1e-10 * std::abs(b); };
                    QVERIFY2((matrixEntry(*m, v, "J") - J).norm() <= 1e-12 * J.norm(), where);
                    QVERIFY2((matrixEntry(*m, v, "Jq") - jac.inputs.topLeftCorner<2, 2>()).norm()
                            <= 1e-12 * jac.inputs.norm(),
                        where);
                    QVERIFY2(close(entry(*m, v, "det_J"), J.determinant()), where);
                    QVERIFY2(close(entry(*m, v, "det_J"), det), where);
                    QVERIFY2(close(entry(*m, v, "det_J"), entry(*m, v, "det_Jx") / entry(*m, v, "det_Jq")), where);
                    QVERIFY2(close(entry(*m, v, "det_Jq"), jac.inputs.topLeftCorner<2, 2>().determinant()), where);
                    QVERIFY2(close(entry(*m, v, "cond"), kappa), where);
                    QVERIFY(entry(*m, v, "cond") >= 1.0);
                    QVERIFY2(close(entry(*m, v, "rod_angle"), std::atan2(y, w)), where);
                    QCOMPARE(entry(*m, v, "x_AB"), pose.inputs[0]);
                    QCOMPARE(entry(*m, v, "z"), pose.inputs[2]);
                    QCOMPARE(entry(*m, v, "y"), y);
                    QCOMPARE(entry(*m, v, "margin"), s.margin);
                    QVERIFY2(std::abs(s.margin - std::min(y, w) / d.rod) < 1e-12, where);
                    QCOMPARE(s.type, SingularityType::None);
                    for (double value : v)
                        QVERIFY2(std::isfinite(value), where);
                    ++checked;
                }
            }
        }
        qInfo("form %s: %d poses, J against finite differences to %.2g (relative)", oxglide::formName(form), checked,
            worstDifference);
        QVERIFY(checked >= 150);
    }

    void singularityClasses_data()
    {
        QTest::addColumn<int>("form");
        QTest::addColumn<double>("guideLength");
        // (L + s)/2 ≥ l: the X workspace reaches y = 0; (L − s)/2 ≥ l: the O one as well
        QTest::newRow("X, L = 150") << formX << 150.0;
        QTest::newRow("O, L = 200") << formO << 200.0;
    }
    void singularityClasses()
    {
        QFETCH(int, form);
        QFETCH(double, guideLength);
        OxGlideDesign d = prototype(form);
        d.guideLength = guideLength;
        auto m = make(d);
        QCOMPARE(lowestHeight(d, form), 0.0);
        const Slice bottom = sliceOf(d, form, 0.0);
        QVERIFY(bottom.hi > bottom.lo);
        const double x = 0.5 * (bottom.lo + bottom.hi);
        // y = 0: the rods along the guides, a direct singularity (det J = 0)
        auto flat = m->solveInverse(pair(x, 0));
        QVERIFY2(flat.ok(), flat ? "" : flat.failure().message.c_str());
        Singularity s;
        std::vector<double> v = evaluated(*m, *flat, &s);
        QCOMPARE(s.type, SingularityType::Direct);
        QCOMPARE(entry(*m, v, "det_J"), 0.0);
        QCOMPARE(entry(*m, v, "det_Jx"), 0.0);
        QVERIFY(entry(*m, v, "det_Jq") != 0.0);
        QVERIFY(!(entry(*m, v, "cond") < 1e12));
        // the direct kinematics gets there too: |x_CD − x_AB − s| = 2l
        auto direct = m->solveDirect(flat->inputs);
        QVERIFY(direct.ok());
        QVERIFY(std::abs(direct->outputs[1]) < 1e-6);
        // approaching it: det J and the margin go to 0 monotonically, the class stays None
        std::vector<double> margins, determinants;
        for (double y : {20.0, 5.0, 1.0, 0.1, 1e-3, 1e-5}) {
            auto near = m->solveInverse(pair(x, y));
            QVERIFY(near.ok());
            v = evaluated(*m, *near, &s);
            QCOMPARE(s.type, SingularityType::None);
            margins.push_back(s.margin);
            determinants.push_back(std::abs(entry(*m, v, "det_J")));
            QVERIFY(std::abs(s.margin - y / d.rod) < 1e-12);
        }
        QVERIFY(std::is_sorted(margins.rbegin(), margins.rend()));
        QVERIFY(std::is_sorted(determinants.rbegin(), determinants.rend()));
        // y = l: rods upright and parallel, the combined singularity (det J_q = det J_x = 0)
        auto top = m->solveInverse(pair(0.5 * d.guideLength, d.rod));
        QVERIFY(top.ok());
        v = evaluated(*m, *top, &s);
        QCOMPARE(s.type, SingularityType::Combined);
        QCOMPARE(entry(*m, v, "det_Jq"), 0.0);
        QCOMPARE(entry(*m, v, "det_Jx"), 0.0);
        // approaching y = l: |det J| = 2y/w grows without bound
        determinants.clear();
        for (double gap : {10.0, 1.0, 1e-2, 1e-4, 1e-6}) {
            auto near = m->solveInverse(pair(0.5 * d.guideLength, d.rod - gap));
            QVERIFY(near.ok());
            v = evaluated(*m, *near, &s);
            QCOMPARE(s.type, SingularityType::None);
            determinants.push_back(std::abs(entry(*m, v, "det_J")));
        }
        QVERIFY(std::is_sorted(determinants.begin(), determinants.end()));
        QVERIFY(determinants.back() > 1e3);
        // the singular curves: y = l (inverse and direct) and y = 0 (direct) where reached
        int top2 = 0, bottom2 = 0;
        for (const SingularCurve &curve : m->singularCurves()) {
            for (const Eigen::Vector2d &point : curve.points) {
                auto pose = m->solveInverse(pair(point.x(), point.y()));
                QVERIFY2(pose.ok(), pose ? "" : pose.failure().message.c_str());
                const SingularityType type = m->singularity(*pose).type;
                if (point.y() == d.rod) {
                    QCOMPARE(type, SingularityType::Combined);
                    ++top2;
                } else {
                    QCOMPARE(point.y(), 0.0);
                    QCOMPARE(curve.type, SingularCurve::Type::Direct);
                    QCOMPARE(type, SingularityType::Direct);
                    ++bottom2;
                }
            }
        }
        QVERIFY(top2 >= 4 && bottom2 >= 2);
    }

    // -- workspace and areas ---------------------------------------------------------------------

    void exactAreas()
    {
        // The prototype: O ≈ 753.3 mm², X ≈ 2125.3 mm²; the X form is the larger (fig. 5).
        const OxGlideDesign d = prototype();
        const double areaO = oxglide::exactArea(d, formO), areaX = oxglide::exactArea(d, formX);
        const double integratedO = integratedArea(d, formO, 2000000), integratedX = integratedArea(d, formX, 2000000);
        qInfo("prototype: exact areas O %.4f, X %.4f mm²; integrated O %.4f, X %.4f mm²", areaO, areaX, integratedO,
            integratedX);
        QVERIFY(std::abs(areaO - integratedO) < 1e-6 * areaO);
        QVERIFY(std::abs(areaX - integratedX) < 1e-6 * areaX);
        QVERIFY(std::abs(areaO - 753.3) < 0.05);
        QVERIFY(std::abs(areaX - 2125.3) < 0.05);
        QVERIFY(areaX > areaO);
        // random designs, either form, including workspaces that reach y = 0 and those where
        // w = s/2 lies below the X workspace
        std::mt19937 generator(99);
        for (int k = 0; k < 30; ++k) {
            const OxGlideDesign r = randomDesign(generator);
            for (int form : {formO, formX}) {
                const double exact = oxglide::exactArea(r, form), integrated = integratedArea(r, form, 400000);
                QVERIFY2(std::abs(exact - integrated) < 1e-6 * std::max(exact, 1.0),
                    describe(r) + " form " + oxglide::formName(form) + ": exact " + QByteArray::number(exact)
                        + ", integrated " + QByteArray::number(integrated));
            }
            // O ⊂ X for every design: s/2 + w ≥ |w − s/2|
            QVERIFY(oxglide::exactArea(r, formX) > oxglide::exactArea(r, formO));
        }
    }

    void mapAreasConverge_data()
    {
        QTest::addColumn<int>("form");
        QTest::newRow("O") << formO;
        QTest::newRow("X") << formX;
    }
    void mapAreasConverge()
    {
        QFETCH(int, form);
        const OxGlideDesign d = prototype(form);
        auto m = make(d);
        const double exact = oxglide::exactArea(d, form);
        const double perimeter = perimeterOf(d, form);
        QVERIFY(perimeter * perimeter >= 4 * pi * exact);
        // the bounds hold the workspace
        const Eigen::AlignedBox2d bounds = m->workspaceBounds();
        QVERIFY(bounds.min().y() <= lowestHeight(d, form) && bounds.max().y() >= d.rod);
        QVERIFY(bounds.min().x() <= sliceOf(d, form, d.rod).lo && bounds.max().x() >= sliceOf(d, form, d.rod).hi);
        // The grids `pkm workspace` uses (squareGrid of the bounds): a cell-counting area errs
        // by the boundary cells it misclassifies, at most about perimeter × cell size. The top
        // edge y = l is a straight line across the grid (110 mm long in O), so the error also
        // depends on where y = l falls within a row: it shrinks with the cell, but not
        // monotonically (measured: O 0.86, 14.7, 7.1, 2.9 mm² for n = 200…1600).
        std::vector<double> errors, alignedErrors;
        QString report, alignedReport;
        for (int n : {200, 400, 800, 1600}) {
            const MapGrid grid = squareGrid(bounds, n);
            const Map map = computed(*m, MapQuantity::Determinant, grid, false);
            QVERIFY(!map.summary.cancelled);
            const double cell = std::max(map.grid.dx(), map.grid.dy());
            QVERIFY(std::abs(map.grid.dx() - map.grid.dy()) < 1e-9 * cell); // square cells
            const double error = std::abs(map.summary.area - exact);
            report
                += QStringLiteral(" %1: %2 (error %3);").arg(n).arg(map.summary.area, 0, 'f', 2).arg(error, 0, 'f', 3);
            QVERIFY2(error <= perimeter * cell, qPrintable(report));
            QCOMPARE(map.summary.area, double(map.summary.reachableCells) * map.grid.cellArea());
            // the map counts exactly the cells whose centre lies in the independent slice
            std::size_t inSlices = 0;
            for (int r = 0; r < grid.rows; ++r) {
                const double y = grid.y(r);
                const Slice slice = sliceOf(d, form, y);
                for (int c = 0; c < grid.columns; ++c)
                    inSlices += y > 0 && y <= d.rod && grid.x(c) >= slice.lo && grid.x(c) <= slice.hi;
            }
            QCOMPARE(map.summary.reachableCells, inSlices);
            errors.push_back(error);

            // The same cells, shifted so that y = l is a row boundary: then the error comes from
            // the curved and slanted edges only, and it does fall with every refinement.
            const double rowsBelow = std::round((d.rod - grid.bounds.min().y()) / grid.dy());
            const double shift = d.rod - (grid.bounds.min().y() + rowsBelow * grid.dy());
            const MapGrid aligned {Eigen::AlignedBox2d(grid.bounds.min() + Eigen::Vector2d(0, shift),
                                       grid.bounds.max() + Eigen::Vector2d(0, shift)),
                grid.columns, grid.rows};
            const Map alignedMap = computed(*m, MapQuantity::Determinant, aligned, false);
            const double alignedError = std::abs(alignedMap.summary.area - exact);
            alignedReport += QStringLiteral(" %1: %2 (error %3);")
                                 .arg(n)
                                 .arg(alignedMap.summary.area, 0, 'f', 2)
                                 .arg(alignedError, 0, 'f', 3);
            QVERIFY2(alignedError <= perimeter * cell, qPrintable(alignedReport));
            alignedErrors.push_back(alignedError);
        }
        qInfo("form %s: exact %.2f mm², perimeter %.1f mm; squareGrid n =%s y = l on a row boundary:%s",
            oxglide::formName(form), exact, perimeter, qPrintable(report), qPrintable(alignedReport));
        QVERIFY2(errors.back() < errors[1] && errors.back() < errors[2], qPrintable(report));
        QVERIFY2(errors.back() < 0.005 * exact, qPrintable(report)); // within 0.5 % at n = 1600
        for (std::size_t i = 1; i < alignedErrors.size(); ++i)
            QVERIFY2(alignedErrors[i] < alignedErrors[i - 1], qPrintable(alignedReport));
    }

    void oWorkspaceInsideX()
    {
        // On one grid over the X bounds, every cell the O form reaches the X form reaches: the
        // union of the two workspaces is the X workspace, so area_union = area_X (as `pkm
        // workspace` reports). Analytically: the O slice [s/2 + w, L − s/2 − w] lies inside the
        // X slice [|w − s/2|, L − |w − s/2|].
        auto o = make(prototype(formO));
        auto x = make(prototype(formX));
        QVERIFY(x->workspaceBounds().contains(o->workspaceBounds()));
        QCOMPARE(o->unionBounds().min(), x->workspaceBounds().min());
        QCOMPARE(o->unionBounds().max(), x->workspaceBounds().max());
        const MapGrid grid = squareGrid(x->workspaceBounds(), 600);
        const Map mapO = computed(*o, MapQuantity::Condition, grid, false);
        const Map mapX = computed(*x, MapQuantity::Condition, grid, false);
        std::size_t inO = 0, inX = 0, inBoth = 0, inUnion = 0;
        for (std::size_t i = 0; i < grid.cells(); ++i) {
            const bool a = !std::isnan(mapO.values[i]), b = !std::isnan(mapX.values[i]);
            inO += a;
            inX += b;
            inBoth += a && b;
            inUnion += a || b;
        }
        QCOMPARE(inBoth, inO);
        QCOMPARE(inUnion, inX);
        QVERIFY(inX > 2 * inO);
        qInfo("600 grid over the X bounds: %zu O cells, %zu X cells, all O cells in X", inO, inX);
        // where both reach, the conditioning is the same (it depends on y only), det J flips sign
        for (int r = 0; r < grid.rows; r += 7) {
            for (int c = 0; c < grid.columns; c += 5) {
                if (!std::isnan(mapO.at(c, r)))
                    QCOMPARE(mapO.at(c, r), mapX.at(c, r));
            }
        }
    }

    void mapAgreesWithEvaluate_data()
    {
        QTest::addColumn<int>("form");
        QTest::addColumn<int>("quantity");
        QTest::addColumn<double>("guideLength");
        for (int form : {formO, formX}) {
            const QByteArray name = oxglide::formName(form);
            QTest::newRow((name + " det").constData()) << form << int(MapQuantity::Determinant) << 130.0;
            QTest::newRow((name + " cond").constData()) << form << int(MapQuantity::Condition) << 130.0;
            QTest::newRow((name + " det, L = 200").constData()) << form << int(MapQuantity::Determinant) << 200.0;
        }
    }
    void mapAgreesWithEvaluate()
    {
        QFETCH(int, form);
        QFETCH(int, quantity);
        QFETCH(double, guideLength);
        OxGlideDesign d = prototype(form);
        d.guideLength = guideLength;
        auto m = make(d);
        const Map map = computed(*m, MapQuantity(quantity), squareGrid(m->workspaceBounds(), 240));
        QVERIFY(map.summary.reachableCells > 0);
        // computeMap fills its rows with fillMapRow(): called directly, a row is the same
        std::vector<float> rowValues(std::size_t(map.grid.columns)), rowMargins(std::size_t(map.grid.columns));
        for (int r = 0; r < map.grid.rows; r += 11) {
            m->fillMapRow(MapQuantity(quantity), map.grid.y(r), map.grid.x(0), map.grid.dx(), rowValues, rowMargins);
            for (int c = 0; c < map.grid.columns; ++c) {
                const float value = rowValues[std::size_t(c)], margin = rowMargins[std::size_t(c)];
                QVERIFY(std::isnan(value) ? std::isnan(map.at(c, r)) : value == map.at(c, r));
                QVERIFY(std::isnan(margin) ? std::isnan(map.marginAt(c, r)) : margin == map.marginAt(c, r));
            }
        }
        const char *name = quantity == int(MapQuantity::Condition) ? "cond" : "det_J";
        int compared = 0, unreachable = 0, edge = 0;
        double worst = 0;
        for (int r = 0; r < map.grid.rows; ++r) {
            for (int c = (r * 7) % 3; c < map.grid.columns; c += 3) {
                const float value = map.at(c, r);
                const double x = map.grid.x(c), y = map.grid.y(r);
                auto pose = m->solveInverse(pair(x, y));
                // the independent slice says the same as the solver (but for rounding at its ends)
                const Slice slice = sliceOf(d, form, y);
                const bool inSlice = y > 0 && y <= d.rod && x >= slice.lo && x <= slice.hi;
                const bool onEdge = std::min(std::abs(x - slice.lo), std::abs(slice.hi - x)) < 1e-9 * d.guideLength;
                if (std::isnan(value)) {
                    QVERIFY(std::isnan(map.marginAt(c, r)));
                    ++unreachable;
                    QVERIFY(!inSlice || onEdge);
                    if (pose) {
                        QVERIFY2(
                            map.nearReachable(c, r, true), qPrintable(QStringLiteral("cell %1, %2").arg(c).arg(r)));
                        ++edge;
                    }
                    continue;
                }
                QVERIFY(inSlice || onEdge);
                if (!pose) {
                    QVERIFY2(map.nearReachable(c, r, false), pose.failure().message.c_str());
                    ++edge;
                    continue;
                }
                Singularity s;
                const std::vector<double> v = evaluated(*m, *pose, &s);
                const double expected = entry(*m, v, name);
                const double relative = std::abs(double(value) - expected) / std::abs(expected);
                QVERIFY2(relative <= 1e-6,
                    qPrintable(
                        QStringLiteral("cell %1, %2: map %3, evaluate %4").arg(c).arg(r).arg(value).arg(expected)));
                QVERIFY(std::abs(map.marginAt(c, r) - s.margin) <= 1e-6 * std::max(1.0, s.margin));
                worst = std::max(worst, relative);
                ++compared;
            }
        }
        QVERIFY(compared > 500);
        QVERIFY2(edge <= (compared + unreachable) / 100, qPrintable(QString::number(edge)));
        auto count = [](const std::vector<float> &values, auto predicate) {
            return std::size_t(std::count_if(values.begin(), values.end(), predicate));
        };
        QCOMPARE(map.summary.reachableCells, count(map.values, [](float f) { return !std::isnan(f); }));
        QCOMPARE(map.summary.nearSingularCells, count(map.margins, [](float f) { return f < nearSingularMargin; }));
        if (quantity == int(MapQuantity::Condition))
            QVERIFY(map.summary.min >= 1.0);
        else if (form == formO)
            QVERIFY(map.summary.max < 0); // det J = −2y/w
        else
            QVERIFY(map.summary.min > 0); // det J = +2y/w
        qInfo("%s: %d cells compared, worst relative difference %.2g; %d cells on the outline classified otherwise",
            QTest::currentDataTag(), compared, worst, edge);
    }

    // -- failures --------------------------------------------------------------------------------

    void invalidDesigns_data()
    {
        QTest::addColumn<ParameterSet>("changes");
        QTest::addColumn<QString>("culprit");
        QTest::newRow("s = 2l") << ParameterSet {{"s", 160.0}} << "s";
        QTest::newRow("s > 2l") << ParameterSet {{"s", 200.0}, {"L", 300.0}} << "s";
        QTest::newRow("L = s") << ParameterSet {{"L", 20.0}} << "L";
        QTest::newRow("L < s") << ParameterSet {{"L", 10.0}} << "L";
        QTest::newRow("z_min = z_max") << ParameterSet {{"z_min", 150.0}} << "z_min";
        QTest::newRow("z_min > z_max") << ParameterSet {{"z_min", 10.0}, {"z_max", 5.0}} << "z_min";
        QTest::newRow("l zero") << ParameterSet {{"l", 0.0}} << "l";
        QTest::newRow("l negative") << ParameterSet {{"l", -80.0}} << "l";
        QTest::newRow("l nan") << ParameterSet {{"l", notANumber}} << "l";
        QTest::newRow("s zero") << ParameterSet {{"s", 0.0}} << "s";
        QTest::newRow("L inf") << ParameterSet {{"L", infinity}} << "L";
        QTest::newRow("a zero") << ParameterSet {{"a", 0.0}} << "a";
        QTest::newRow("mode zero") << ParameterSet {{"mode", 0.0}} << "mode";
        QTest::newRow("mode half") << ParameterSet {{"mode", 0.5}} << "mode";
        QTest::newRow("mode two") << ParameterSet {{"mode", 2.0}} << "mode";
        QTest::newRow("mode nan") << ParameterSet {{"mode", notANumber}} << "mode";
        QTest::newRow("unknown name") << ParameterSet {{"zz", 1.0}} << "zz";
    }
    void invalidDesigns()
    {
        // Refused from a parameter set and as an edit of the prototype: one failure naming the
        // culprit in its message, and nothing created; the old design is untouched.
        QFETCH(ParameterSet, changes);
        QFETCH(QString, culprit);
        auto check = [&](const Result<MechanismPtr> &made, const char *how) {
            QVERIFY2(!made.ok(), how);
            QCOMPARE(QString::fromStdString(made.failure().culprit), culprit);
            QCOMPARE(made.failure().kind,
                culprit == QLatin1String("zz") ? FailureKind::UnknownName : FailureKind::InvalidParameter);
            const QString message = QString::fromStdString(made.failure().message);
            QVERIFY(!message.isEmpty());
            QVERIFY2(message.contains(culprit), qPrintable(message));
            QVERIFY2(!message.contains(QStringLiteral("nan")) && !message.contains(QStringLiteral("inf")),
                qPrintable(message));
            QCOMPARE(message.count(QLatin1Char('\n')), 0);
        };
        check(OxGlide::createFrom(changes), "createFrom");
        if (QTest::currentTestFailed())
            return;
        auto base = make(prototype());
        const ParameterSet before = base->parameters();
        const Pose homeBefore = base->homePose();
        check(base->withParameters(changes), "withParameters");
        if (QTest::currentTestFailed())
            return;
        if (changes.size() == 1)
            check(base->withParameter(changes.begin()->first, changes.begin()->second), "withParameter");
        QVERIFY(base->parameters() == before);
        QCOMPARE(base->homePose().inputs, homeBefore.inputs);
        QCOMPARE(base->design().form, formO);
    }

    void invalidDesignStruct()
    {
        // create() validates an OxGlideDesign filled in directly, too.
        OxGlideDesign d = prototype();
        d.form = 0;
        auto made = OxGlide::create(d);
        QVERIFY(!made.ok());
        QCOMPARE(made.failure().culprit, std::string("mode"));
        d = prototype();
        d.width = 2 * d.rod;
        made = OxGlide::create(d);
        QVERIFY(!made.ok());
        QCOMPARE(made.failure().culprit, std::string("s"));
        QVERIFY(QString::fromStdString(made.failure().message).contains(QStringLiteral("2l")));
        d = prototype();
        d.guideLength = d.width;
        made = OxGlide::create(d);
        QVERIFY(!made.ok());
        QCOMPARE(made.failure().culprit, std::string("L"));
        d = prototype();
        d.zMax = d.zMin;
        made = OxGlide::create(d);
        QVERIFY(!made.ok());
        QCOMPARE(made.failure().culprit, std::string("z_min"));
        d = prototype();
        d.rod = -1;
        made = OxGlide::create(d);
        QVERIFY(!made.ok());
        QCOMPARE(made.failure().culprit, std::string("l"));
        // an edit that breaks a relation names the parameter that was edited
        auto base = make(prototype());
        auto shorter = base->withParameter("l", 9.0); // s = 20 ≥ 2l = 18
        QVERIFY(!shorter.ok());
        QCOMPARE(shorter.failure().culprit, std::string("l"));
        auto lower = base->withParameter("z_max", -1.0);
        QVERIFY(!lower.ok());
        QCOMPARE(lower.failure().culprit, std::string("z_max"));
        QVERIFY(QString::fromStdString(lower.failure().message).contains(QStringLiteral("z_max")));
        QCOMPARE(base->design().rod, 80.0);
        QCOMPARE(base->design().zMax, 150.0);
        // just inside the limits is fine
        auto wide = base->withParameter("s", 159.9); // < 2l, but L = 130 ≤ s
        QVERIFY(!wide.ok());
        QCOMPARE(wide.failure().culprit, std::string("s"));
        QVERIFY(base->withParameters({{"s", 159.9}, {"L", 160.0}}).ok());
        QVERIFY(base->withParameter("L", 20.001).ok());
    }

    void poseFailures_data()
    {
        QTest::addColumn<int>("form");
        QTest::addColumn<bool>("inputs"); ///< solveDirect (x_AB, x_CD, z), else solveInverse (x, y)
        QTest::addColumn<double>("a");
        QTest::addColumn<double>("b");
        QTest::addColumn<double>("z");
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("culprit");
        QTest::addColumn<QString>("mentions");
        const int outOfRange = int(FailureKind::OutOfRange), unreachable = int(FailureKind::Unreachable);
        QTest::newRow("x_AB = -1") << formO << true << -1.0 << 100.0 << 10.0 << outOfRange << "x_AB"
                                   << "guides";
        QTest::newRow("x_AB = 131") << formX << true << 131.0 << 100.0 << 10.0 << outOfRange << "x_AB"
                                    << "guides";
        QTest::newRow("x_CD = 130.5") << formO << true << 10.0 << 130.5 << 10.0 << outOfRange << "x_CD"
                                      << "guides";
        QTest::newRow("x_AB nan") << formO << true << notANumber << 100.0 << 10.0 << outOfRange << "x_AB"
                                  << "finite";
        QTest::newRow("x_CD inf") << formO << true << 10.0 << infinity << 10.0 << outOfRange << "x_CD"
                                  << "finite";
        QTest::newRow("z nan") << formO << true << 10.0 << 100.0 << notANumber << outOfRange << "z"
                               << "finite";
        QTest::newRow("z below travel") << formO << true << 10.0 << 100.0 << -0.5 << outOfRange << "z"
                                        << "travel";
        QTest::newRow("z above travel") << formX << true << 100.0 << 10.0 << 150.5 << outOfRange << "z"
                                        << "travel";
        QTest::newRow("O: T left of the workspace") << formO << false << 5.0 << 70.0 << 0.0 << outOfRange << "x_AB"
                                                    << "extended (O)";
        QTest::newRow("O: T right of the workspace") << formO << false << 125.0 << 70.0 << 0.0 << outOfRange << "x_CD"
                                                     << "extended (O)";
        QTest::newRow("O: T below the workspace") << formO << false << 65.0 << 40.0 << 0.0 << outOfRange << "x_AB"
                                                  << "extended (O)";
        QTest::newRow("X: T right of the workspace") << formX << false << 128.0 << 40.0 << 0.0 << outOfRange << "x_AB"
                                                     << "crossed (X)";
        QTest::newRow("X: T left of the workspace") << formX << false << 2.0 << 40.0 << 0.0 << outOfRange << "x_CD"
                                                    << "crossed (X)";
        QTest::newRow("y > l") << formO << false << 65.0 << 80.5 << 0.0 << unreachable << "y"
                               << "rod length";
        QTest::newRow("y < 0") << formX << false << 65.0 << -1.0 << 0.0 << unreachable << "y"
                               << "y = 0";
        QTest::newRow("x nan") << formO << false << notANumber << 70.0 << 0.0 << outOfRange << "x"
                               << "finite";
        QTest::newRow("y nan") << formX << false << 65.0 << notANumber << 0.0 << outOfRange << "y"
                               << "finite";
        QTest::newRow("y -inf") << formX << false << 65.0 << -infinity << 0.0 << outOfRange << "y"
                                << "finite";
    }
    void poseFailures()
    {
        QFETCH(int, form);
        QFETCH(bool, inputs);
        QFETCH(double, a);
        QFETCH(double, b);
        QFETCH(double, z);
        QFETCH(int, kind);
        QFETCH(QString, culprit);
        QFETCH(QString, mentions);
        auto m = make(prototype(form));
        const Pose home = m->homePose();
        auto pose = inputs ? m->solveDirect(triple(a, b, z), &home) : m->solveInverse(pair(a, b), &home);
        QVERIFY(!pose.ok());
        QCOMPARE(int(pose.failure().kind), kind);
        QCOMPARE(QString::fromStdString(pose.failure().culprit), culprit);
        const QString message = QString::fromStdString(pose.failure().message);
        QVERIFY2(message.contains(culprit), qPrintable(message));
        QVERIFY2(message.contains(mentions), qPrintable(message));
        QVERIFY2(
            !message.contains(QStringLiteral("nan")) && !message.contains(QStringLiteral("inf")), qPrintable(message));
        QCOMPARE(message.count(QLatin1Char('\n')), 0);
        // the generic entry point refuses a value that is wrong on its own, naming it
        const std::string name = culprit.toStdString();
        double alone = notANumber;
        if (inputs && kind == int(FailureKind::OutOfRange))
            alone = name == "x_AB" ? a : name == "x_CD" ? b : z;
        else if (name == "x" || name == "y")
            alone = name == "x" ? a : b;
        else
            return; // a slider off its guide for a platform point: both outputs are at fault
        auto with = m->solveWith(home, m->variableIndex(name), alone);
        QVERIFY(!with.ok());
        QCOMPARE(with.failure().culprit, name);
    }

    // -- modes, dragging, drawing ----------------------------------------------------------------

    void modeNeighbours()
    {
        auto o = make(prototype(formO));
        const std::vector<ModeAlternative> neighbours = o->modeNeighbours();
        QCOMPARE(neighbours.size(), std::size_t(1));
        const ModeAlternative &n = neighbours.front();
        QVERIFY(!n.label.empty());
        QVERIFY(QString::fromStdString(n.label).contains(QStringLiteral("crossed (X)")));
        QVERIFY(!n.sameInputs);
        QCOMPARE(n.changes, (ParameterSet {{"mode", -1.0}}));
        QVERIFY(n.mechanism);
        QCOMPARE(n.mechanism->kind(), std::string_view("oxglide"));
        const auto &x = static_cast<const OxGlide &>(*n.mechanism);
        QCOMPARE(x.design().form, formX);
        // everything else is the same design
        ParameterSet expected = o->parameters();
        expected["mode"] = -1;
        QVERIFY(x.parameters() == expected);
        // and back
        const auto back = x.modeNeighbours();
        QCOMPARE(back.size(), std::size_t(1));
        QCOMPARE(static_cast<const OxGlide &>(*back.front().mechanism).design().form, formO);

        // every O pose has its X pose (O ⊂ X): same outputs, other inputs, z kept
        int solved = 0;
        for (double y : {60.0, 70.0, 75.0, 79.0}) {
            const Slice slice = sliceOf(o->design(), formO, y);
            for (int i = 0; i <= 4; ++i) {
                Pose near = o->homePose();
                near.inputs[2] = 42;
                auto pose = o->solveInverse(pair(slice.lo + (slice.hi - slice.lo) * i / 4, y), &near);
                QVERIFY(pose.ok());
                const auto alternatives = Mechanism::solveAlternatives(neighbours, *pose);
                QCOMPARE(alternatives.size(), std::size_t(1));
                const Pose &other = alternatives.front().pose;
                QCOMPARE(other.outputs, pose->outputs);
                QCOMPARE(other.mode, formX);
                QCOMPARE(other.inputs[2], 42.0);
                QVERIFY((other.inputs.head<2>() - pose->inputs.head<2>()).norm() > 1.0);
                QVERIFY(
                    (other.inputs.head<2>() - inverseOf(o->design(), formX, pose->outputs[0], y)).norm() < 1e-12 * 130);
                // x_AB and x_CD swap sides of the crossing: e changes sign, |e| the same
                const double e = pose->inputs[1] - pose->inputs[0] - 20, f = other.inputs[1] - other.inputs[0] - 20;
                QVERIFY(e > 0 && f < 0 && std::abs(e + f) < 1e-9);
                ++solved;
            }
        }
        QCOMPARE(solved, 20);
        QCOMPARE(o->modeAlternatives(o->homePose()).size(), std::size_t(1));
        // an X pose outside the O workspace has no O alternative
        auto wide = x.solveInverse(pair(65, 35));
        QVERIFY(wide.ok());
        QVERIFY(!o->solveInverse(pair(65, 35)).ok());
        QVERIFY(Mechanism::solveAlternatives(x.modeNeighbours(), *wide).empty());
    }

    void dragHandles_data()
    {
        QTest::addColumn<int>("form");
        QTest::newRow("O") << formO;
        QTest::newRow("X") << formX;
    }
    void dragHandles()
    {
        QFETCH(int, form);
        auto m = make(prototype(form));
        Pose home = m->homePose();
        home.inputs[2] = 33;
        const Scene scene = m->scene(home);
        QCOMPARE(scene.handles.size(), std::size_t(3));
        // handle 0: the platform follows the pointer (inverse kinematics), z kept
        const Eigen::Vector2d target = platformOf(home) + Eigen::Vector2d(1.5, -2.0);
        auto moved = m->dragHandle(home, 0, target);
        QVERIFY2(moved.ok(), moved ? "" : moved.failure().message.c_str());
        QCOMPARE(platformOf(*moved), target);
        QCOMPARE(moved->inputs[2], 33.0);
        QVERIFY((moved->inputs.head<2>() - inverseOf(m->design(), form, target.x(), target.y())).norm() < 1e-12 * 130);
        // handles 1 and 2: one slider pair moves along the guides to the pointer's x, the other stays
        for (int k = 0; k < 2; ++k) {
            const double to = home.inputs[k] + (k == 0 ? -3.0 : 4.0) * form;
            auto slid = m->dragHandle(home, 1 + k, Eigen::Vector2d(to, 17.0));
            QVERIFY2(slid.ok(), slid ? "" : slid.failure().message.c_str());
            QCOMPARE(slid->inputs[k], to);
            QCOMPARE(slid->inputs[1 - k], home.inputs[1 - k]);
            QCOMPARE(slid->inputs[2], 33.0);
            auto direct = m->solveDirect(slid->inputs);
            QVERIFY(direct.ok());
            QCOMPARE(platformOf(*direct), platformOf(*slid));
            // far past the guide's end: the pair stops there, or the pose is refused
            auto past = m->dragHandle(home, 1 + k, Eigen::Vector2d(k == 0 ? -500.0 : 500.0, 0.0));
            if (past)
                QCOMPARE(past->inputs[k], k == 0 ? 0.0 : 130.0);
            else
                QVERIFY(past.failure().culprit == "x_AB" || past.failure().culprit == "x_CD");
        }
        // the handles sit on the joints they move
        QCOMPARE(scene.joints[std::size_t(scene.handles[0].joint)].position.head<2>(), platformOf(home));
        QCOMPARE(
            scene.joints[std::size_t(scene.handles[1].joint)].position.head<2>(), Eigen::Vector2d(home.inputs[0], 0));
        QCOMPARE(
            scene.joints[std::size_t(scene.handles[2].joint)].position.head<2>(), Eigen::Vector2d(home.inputs[1], 0));
        QVERIFY(!m->dragHandle(home, 3, target).ok());
        QVERIFY(!m->dragHandle(home, 1, Eigen::Vector2d(notANumber, 0)).ok());
        QVERIFY(!m->dragHandle(home, 0, Eigen::Vector2d(65, 90)).ok());
    }

    void sceneMatchesPose_data()
    {
        QTest::addColumn<int>("form");
        QTest::newRow("O") << formO;
        QTest::newRow("X") << formX;
    }
    void sceneMatchesPose()
    {
        QFETCH(int, form);
        auto m = make(prototype(form));
        const OxGlideDesign &d = m->design();
        int poses = 0;
        for (const Pose &pose : posesAcross(*m, 6)) {
            const Scene s = m->scene(pose);
            int rods = 0;
            for (const SceneBar &bar : s.bars) {
                if (bar.kind != BarKind::Rod)
                    continue;
                const double length
                    = (s.joints[std::size_t(bar.to)].position - s.joints[std::size_t(bar.from)].position).norm();
                QVERIFY(std::abs(length - d.rod) < 1e-9 * d.rod);
                ++rods;
            }
            QCOMPARE(rods, 2);
            QCOMPARE(s.guides.size(), std::size_t(4));
            for (const SceneJoint &joint : s.joints)
                QVERIFY(s.extent.contains(joint.position));
            ++poses;
        }
        QVERIFY(poses > 50);
    }

    void scene3dHoldsTheModel_data()
    {
        QTest::addColumn<int>("form");
        QTest::newRow("O") << formO;
        QTest::newRow("X") << formX;
    }
    void scene3dHoldsTheModel()
    {
        QFETCH(int, form);
        auto m = make(prototype(form));
        const OxGlideDesign &d = m->design();
        const std::vector<Pose> poses = posesAcross(*m, 8);
        QVERIFY(poses.size() > 100);
        Eigen::AlignedBox3d extent;
        double worstOutside = 0;
        std::string worstSolid = "none";
        for (const Pose &pose : poses) {
            const Scene3D model = m->scene3d(pose);
            if (extent.isEmpty())
                extent = model.extent;
            // the extent does not depend on the pose (the view does not jump)
            QCOMPARE(model.extent.min(), extent.min());
            QCOMPARE(model.extent.max(), extent.max());
            int rods = 0, compensation = 0;
            for (const Solid &solid : model.solids) {
                if (solid.role == PartRole::Rod) {
                    ++rods;
                    // a rod from its rod joint in y = 0 to the platform, of length l, at the pose's z ± depth
                    QVERIFY(std::abs((solid.to - solid.from).norm() - d.rod) < 1e-9 * d.rod);
                    QCOMPARE(solid.from.y(), 0.0);
                    QCOMPARE(solid.to.y(), pose.outputs[1]);
                    QVERIFY(std::abs(solid.from.z() - pose.inputs[2]) <= 2 * d.spacing);
                }
                if (solid.role == PartRole::Compensation) {
                    ++compensation;
                    QCOMPARE(solid.to.y(), 0.0); // up to the rod-joint plane
                    QVERIFY(solid.from.y() < 0.0);
                }
                for (const Eigen::Vector3d &point : {solid.from, solid.to})
                    QVERIFY2(model.extent.contains(point), qPrintable(QString::fromStdString(solid.label)));
                const Eigen::AlignedBox3d box = solidBounds(solid);
                const Eigen::Vector3d below = (model.extent.min() - box.min()).cwiseMax(0.0);
                const Eigen::Vector3d above = (box.max() - model.extent.max()).cwiseMax(0.0);
                const double outside = std::max(below.maxCoeff(), above.maxCoeff());
                if (outside > worstOutside) {
                    worstOutside = outside;
                    worstSolid = solid.label;
                }
            }
            QCOMPARE(rods, 4);
            QCOMPARE(compensation, 3);
            // the platform's marker is at T, at the pose's z
            bool marker = false;
            for (const Solid &solid : model.solids) {
                if (solid.role == PartRole::Marker) {
                    QCOMPARE(solid.from.x(), pose.outputs[0]);
                    QCOMPARE(solid.from.z(), pose.inputs[2]);
                    marker = true;
                }
            }
            QVERIFY(marker);
        }
        qInfo("form %s: %zu poses; solids reach up to %.2f mm beyond the extent (%s)", oxglide::formName(form),
            poses.size(), worstOutside, worstSolid.c_str());
        // the whole solids, not only their end points, lie in the extent
        QVERIFY2(worstOutside < 1e-9, qPrintable(QString::number(worstOutside)));
    }

    void rodsCannotReach()
    {
        // With guides longer than 2l + s the pairs can be too far apart for the rods:
        // |x_CD − x_AB − s| > 2l. (The prototype's guides are too short for that.)
        for (int form : {formO, formX}) {
            OxGlideDesign d = prototype(form);
            d.guideLength = 250;
            auto m = make(d);
            // x_CD − x_AB − s = ±161 mm
            const Coordinates inputs = form == formO ? triple(0, 181, 10) : triple(200, 59, 10);
            auto pose = m->solveDirect(inputs);
            QVERIFY(!pose.ok());
            QCOMPARE(pose.failure().kind, FailureKind::Unreachable);
            QCOMPARE(pose.failure().culprit, std::string("x_CD"));
            const QString message = QString::fromStdString(pose.failure().message);
            QVERIFY2(message.contains(QStringLiteral("2l")) && message.contains(QStringLiteral("x_AB")),
                qPrintable(message));
            // exactly 2l apart: the rods lie along the guides, y = 0
            const Coordinates stretched = form == formO ? triple(0, 180, 10) : triple(200, 60, 10);
            auto flat = m->solveDirect(stretched);
            QVERIFY2(flat.ok(), flat ? "" : flat.failure().message.c_str());
            QCOMPARE(flat->outputs[1], 0.0);
            QCOMPARE(m->singularity(*flat).type, SingularityType::Direct);
        }
    }

    // -- the z axis ------------------------------------------------------------------------------

    void zIsIndependent()
    {
        auto m = make(prototype());
        const OxGlideDesign &d = m->design();
        // solveInverse keeps z from `near`, else takes the home pose's
        Pose near = m->homePose();
        QCOMPARE(near.inputs[2], 0.5 * (d.zMin + d.zMax));
        for (double z : {d.zMin, 12.5, d.zMax}) {
            near.inputs[2] = z;
            auto pose = m->solveInverse(pair(60, 70), &near);
            QVERIFY(pose.ok());
            QCOMPARE(pose->inputs[2], z);
        }
        auto free = m->solveInverse(pair(60, 70));
        QVERIFY(free.ok());
        QCOMPARE(free->inputs[2], m->homePose().inputs[2]);
        // solveDirect validates z against [z_min, z_max] and the outputs do not depend on it
        auto a = m->solveDirect(triple(15, 115, d.zMin)), b = m->solveDirect(triple(15, 115, d.zMax));
        QVERIFY(a.ok() && b.ok());
        QCOMPARE(a->outputs, b->outputs);
        QCOMPARE(b->inputs[2], d.zMax);
        for (double z : {d.zMin - 1e-9, d.zMax + 1e-6, -infinity}) {
            auto refused = m->solveDirect(triple(15, 115, z));
            QVERIFY(!refused.ok());
            QCOMPARE(refused.failure().culprit, std::string("z"));
            QCOMPARE(refused.failure().kind, FailureKind::OutOfRange);
        }
        QCOMPARE(m->variableRange(OxGlide::variableZ).min, d.zMin);
        QCOMPARE(m->variableRange(OxGlide::variableZ).max, d.zMax);
        QCOMPARE(m->variableRange(OxGlide::variableXAB).max, d.guideLength);
        // z is an actuated, independent variable; x_AB, x_CD actuated; x, y outputs
        const auto &infos = m->variableInfo();
        QCOMPARE(infos.size(), std::size_t(5));
        auto info = [&](int variable) { return infos[static_cast<std::size_t>(variable)]; };
        QVERIFY(info(OxGlide::variableZ).actuated && info(OxGlide::variableZ).independent);
        QVERIFY(info(OxGlide::variableXAB).actuated && !info(OxGlide::variableXAB).independent);
        QVERIFY(info(OxGlide::variableXCD).actuated);
        QVERIFY(!info(OxGlide::variableX).actuated && !info(OxGlide::variableY).actuated);
        QCOMPARE(m->variableIndex("z"), OxGlide::variableZ);
        QCOMPARE(m->inputCount(), 3);
        QCOMPARE(m->outputCount(), 2);
        // the generic entry point: moving z alone keeps the platform
        auto moved = m->solveWith(*a, OxGlide::variableZ, 99.0);
        QVERIFY(moved.ok());
        QCOMPARE(moved->inputs[2], 99.0);
        QCOMPARE(moved->outputs, a->outputs);
        // changing the travel changes nothing of the planar workspace
        auto longer = m->withParameters({{"z_min", -500.0}, {"z_max", 500.0}});
        QVERIFY(longer.ok());
        QCOMPARE(static_cast<const OxGlide &>(**longer).workspaceBounds().min(), m->workspaceBounds().min());
        QCOMPARE(static_cast<const OxGlide &>(**longer).workspaceBounds().max(), m->workspaceBounds().max());
    }

    void parametersRoundTrip()
    {
        // parameters() names every parameter, createFrom of them rebuilds the design, and
        // every parameter accepts its own value.
        auto m = make(prototype(formX));
        const ParameterSet values = m->parameters();
        for (const ParameterInfo &info : m->parameterInfo())
            QVERIFY2(values.count(info.name), info.name.c_str());
        QCOMPARE(values.at("mode"), -1.0);
        QCOMPARE(values.at("l"), 80.0);
        auto rebuilt = OxGlide::createFrom(values);
        QVERIFY(rebuilt.ok());
        QVERIFY((*rebuilt)->parameters() == values);
        for (const auto &[name, value] : values) {
            auto same = m->withParameter(name, value);
            QVERIFY2(same.ok(), name.c_str());
            QCOMPARE((*same)->homePose().outputs, m->homePose().outputs);
        }
        // the mode parameter has named values O and X
        const auto info = std::find_if(m->parameterInfo().begin(), m->parameterInfo().end(),
            [](const ParameterInfo &i) { return i.name == "mode"; });
        QVERIFY(info != m->parameterInfo().end());
        QCOMPARE(info->group, ParameterGroup::Mode);
        QCOMPARE(info->choices.size(), std::size_t(2));
        QCOMPARE(m->reportText(m->homePose()).front().text, std::string("X"));
    }
};

QTEST_APPLESS_MAIN(TestOxGlide)
#include "tst_oxglide.moc"
