// The five-bar's workspace and singularity maps: the inner loop of every map, the singular
// curves drawn over them and the box that holds the workspace.
#include "fivebar.h"
#include "mapclones.h"
#include "capabilitycell.h"
#include "text.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
/// Samples along each singular curve.
constexpr int curveSamples = 720;
constexpr int boundsCurveSamples = 180; // computeBounds()
/// Relative slack with which a point of a singular curve still counts as a pose: the curves
/// lie where the circles only touch and the modes meet.
constexpr double curveTolerance = 1e-6;

/// One leg's constants for the map loop. G_i = (gx, 0).
struct MapLeg {
    double gx;
    double a2b2;       ///< a² − b²
    double sum2;       ///< (a + b)²
    double difference2;///< (a − b)²
    double b2;         ///< b²
    double twoAB;      ///< 2ab: the inverse margin is √Q/(2ab)
    double working;
    /// The crank range as a slack s·min(u×v, v×w) + offset of the elbow direction v, ≥ 0
    /// inside: an arc of at most 180° is [u, w] (s = +1); a longer one is everything but the
    /// open arc (w, u) (s = −1); the full turn has s = 0 and offset 1.
    double ux, uy, wx, wy, sign, offset;
};

MapLeg legOf(const FiveBarDesign &d, int leg)
{
    const double a = d.crank[leg], b = d.link[leg];
    MapLeg m{fivebar::groundJoint(d, leg).x(), a * a - b * b, (a + b) * (a + b), (a - b) * (a - b), b * b, 2.0 * a * b,
             double(d.working[leg]), 1.0, 0.0, 1.0, 0.0, 0.0, 1.0};
    const Interval &r = d.range[leg];
    if (!fivebar::fullTurn(r)) {
        const bool shortArc = r.max - r.min <= pi;
        const double from = shortArc ? r.min : r.max, to = shortArc ? r.max : r.min;
        m.ux = std::cos(from);
        m.uy = std::sin(from);
        m.wx = std::cos(to);
        m.wy = std::sin(to);
        m.sign = shortArc ? 1.0 : -1.0;
        m.offset = 0.0;
    }
    return m;
}

/// What the map loop knows of one cell, for the quantity it maps.
struct Cell {
    double q[2];    ///< Q_i
    double root[2]; ///< √Q_i
    double lx[2], ly[2]; ///< L_i = C − P_i
    double detJx;   ///< L₁×L₂
    double inverseMargin, directMargin;
};

/// The map row, written so that the compiler can vectorise it: no branches, selects only.
/// Per cell C and leg i, with g = C − G_i, r² = |g|², Q_i = ((a + b)² − r²)(r² − (a − b)²)
/// (16·area² of the triangle G_i P_i C, ≥ 0 where the leg reaches C):
///   P_i − G_i = ((a² − b² + r²)·g + w_i·√Q_i·g⊥)/(2r²)   (the elbow in working mode w_i)
///   k_i = −w_i·√Q_i/2,  L_i = C − P_i
/// then the quantity `value(cell)`.
template <bool Margins, class Value>
[[gnu::always_inline]] inline void mapRow(const FiveBarDesign &d, double y, double x0, double dx, float *values,
                                          float *margins, int count, const Value &value)
{
    const std::array<MapLeg, 2> legs = {legOf(d, 0), legOf(d, 1)};
    const double assembly = d.assembly;
    const double sideTolerance = -1e-9 * d.link[0] * d.link[1];
    const double inverseLinkProduct = 1.0 / (d.link[0] * d.link[1]);
    const double inverseTwoAB[2] = {1.0 / legs[0].twoAB, 1.0 / legs[1].twoAB};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int i = 0; i < count; ++i) {
        const double x = x0 + i * dx;
        Cell cell;
        double range[2], r2[2];
        for (int leg = 0; leg < 2; ++leg) {
            const MapLeg &m = legs[std::size_t(leg)];
            const double gx = x - m.gx, gy = y;
            r2[leg] = gx * gx + gy * gy;
            cell.q[leg] = (m.sum2 - r2[leg]) * (r2[leg] - m.difference2);
            cell.root[leg] = std::sqrt(cell.q[leg] > 0.0 ? cell.q[leg] : 0.0);
            const double half = 0.5 / (r2[leg] > 0.0 ? r2[leg] : 1.0);
            const double along = m.a2b2 + r2[leg], across = m.working * cell.root[leg];
            const double ex = (along * gx - across * gy) * half, ey = (along * gy + across * gx) * half;
            cell.lx[leg] = gx - ex;
            cell.ly[leg] = gy - ey;
            range[leg] = m.sign * std::min(m.ux * ey - m.uy * ex, ex * m.wy - ey * m.wx) + m.offset;
        }
        cell.detJx = cell.lx[0] * cell.ly[1] - cell.ly[0] * cell.lx[1];
        cell.inverseMargin = std::min(cell.root[0] * inverseTwoAB[0], cell.root[1] * inverseTwoAB[1]);
        cell.directMargin = std::abs(cell.detJx) * inverseLinkProduct;
        // the smallest of the slacks is ≥ 0 exactly when every condition holds
        const double slack = std::min(std::min(cell.q[0], cell.q[1]),
                                      std::min(assembly * cell.detJx - sideTolerance, std::min(range[0], range[1])));
        const bool ok = (slack >= 0.0) & (r2[0] > 0.0) & (r2[1] > 0.0);
        values[i] = ok ? static_cast<float>(value(cell)) : nan;
        if constexpr (Margins)
            margins[i] = ok ? static_cast<float>(std::min(cell.inverseMargin, cell.directMargin)) : nan;
    }
}

/// det J = det J_x/(k₁k₄) = 4·(L₁×L₂)/(w₁w₄·√Q₁·√Q₄).
struct Determinant {
    double workings; ///< w₁w₄
    double operator()(const Cell &c) const { return 4.0 * c.detJx / (workings * c.root[0] * c.root[1]); }
};

/// κ from J's rows L_i/k_i, of squared lengths 4b_i²/Q_i.
struct Condition {
    double b2[2];
    double operator()(const Cell &c) const
    {
        const double frobenius = 4.0 * b2[0] / c.q[0] + 4.0 * b2[1] / c.q[1];
        // at a singularity ∞/∞ would give NaN, which means "unreachable": κ is +∞ there
        const bool regular = (c.q[0] > 0.0) & (c.q[1] > 0.0) & (c.detJx != 0.0);
        return regular ? fivebar::conditionNumber(frobenius, 4.0 * std::abs(c.detJx) / (c.root[0] * c.root[1]))
                       : std::numeric_limits<double>::infinity();
    }
};

/// What the actuators deliver (capabilitycell.h): J_q = diag(k_i) with |k_i| = √Q_i/2, J_x
/// rows L_i of length b_i.
template <MapQuantity Q>
struct Delivered {
    capability::CellLimits limits; // a copy: loads the loop may hoist
    double link[2];
    double operator()(const Cell &c) const
    {
        return capability::cell2<Q>(limits, 0.5 * c.root[0], 0.5 * c.root[1], c.lx[0], c.ly[0], c.lx[1], c.ly[1], link[0],
                                    link[1], c.inverseMargin < FiveBar::singularTolerance,
                                    c.directMargin < FiveBar::singularTolerance);
    }
};

template <bool Margins, class Value>
PKM_MAP_CLONES void row(const FiveBarDesign &d, double y, double x0, double dx, float *v, float *m, int n, Value value)
{
    mapRow<Margins>(d, y, x0, dx, v, m, n, value);
}

/// Appends to `curves` the runs of two or more consecutive samples t ∈ [from, to] at which
/// `pointAt(t, point)` finds a point of the curve. `periodic`: t = from and t = to are the
/// same point, so a run through it is one polyline.
template <class PointAt>
void traceRuns(std::vector<SingularCurve> &curves, SingularCurve::Type type, const std::string &label, double from,
               double to, bool periodic, int samples, PointAt &&pointAt)
{
    std::vector<std::vector<Eigen::Vector2d>> runs(1);
    for (int k = 0; k <= samples; ++k) {
        Eigen::Vector2d point;
        if (pointAt(from + (to - from) * k / samples, point))
            runs.back().push_back(point);
        else if (!runs.back().empty())
            runs.emplace_back();
    }
    // a run that ends at t = to goes on with the one that starts at t = from
    const bool wraps = periodic && runs.size() > 1 && !runs.back().empty() && !runs.front().empty();
    if (wraps) {
        runs.back().insert(runs.back().end(), runs.front().begin() + 1, runs.front().end());
        runs.front().clear();
    }
    for (std::vector<Eigen::Vector2d> &run : runs) {
        if (run.size() > 1)
            curves.push_back({type, label, std::move(run)});
    }
}
} // namespace

void FiveBar::fillMapRow(MapQuantity quantity, double y, double x0, double dx, std::span<float> values,
                         std::span<float> margins) const
{
    const int count = static_cast<int>(values.size());
    float *v = values.data();
    float *m = margins.empty() ? nullptr : margins.data();
    const FiveBarDesign &d = m_design;
    const Condition condition{{d.link[0] * d.link[0], d.link[1] * d.link[1]}};
    const Determinant determinant{double(d.working[0] * d.working[1])};
    if (quantity == MapQuantity::Condition)
        m ? row<true>(d, y, x0, dx, v, m, count, condition) : row<false>(d, y, x0, dx, v, m, count, condition);
    else
        m ? row<true>(d, y, x0, dx, v, m, count, determinant) : row<false>(d, y, x0, dx, v, m, count, determinant);
}

void FiveBar::fillCapabilityRow(const capability::CellLimits &limits, double y, double x0, double dx,
                                std::span<float> values, std::span<float> margins) const
{
    const int count = static_cast<int>(values.size());
    const FiveBarDesign &d = m_design;
    const double link[2] = {d.link[0], d.link[1]};
    float *v = values.data(), *m = margins.data();
    switch (limits.quantity) {
    case MapQuantity::ForceWorst:
        return row<true>(d, y, x0, dx, v, m, count, Delivered<MapQuantity::ForceWorst>{limits, {link[0], link[1]}});
    case MapQuantity::SpeedWorst:
        return row<true>(d, y, x0, dx, v, m, count, Delivered<MapQuantity::SpeedWorst>{limits, {link[0], link[1]}});
    case MapQuantity::ResolutionWorst:
        return row<true>(d, y, x0, dx, v, m, count, Delivered<MapQuantity::ResolutionWorst>{limits, {link[0], link[1]}});
    default:
        return row<true>(d, y, x0, dx, v, m, count, Delivered<MapQuantity::StiffnessWorst>{limits, {link[0], link[1]}});
    }
}

std::vector<SingularCurve> FiveBar::singularCurves() const
{
    return tracedCurves(curveSamples);
}

std::vector<SingularCurve> FiveBar::tracedCurves(int samples) const
{
    const FiveBarDesign &d = m_design;
    const std::array<double, 2> reference = referenceAngles(nullptr);
    std::vector<SingularCurve> curves;
    // Inverse: leg i stretched or folded, C on the circle of radius a_i ± b_i about G_i (the
    // other leg, the ranges and the assembly mode decide which arcs are poses).
    for (int leg = 0; leg < 2; ++leg) {
        const Eigen::Vector2d G = fivebar::groundJoint(d, leg);
        const double a = d.crank[leg], b = d.link[leg];
        for (const bool stretched : {true, false}) {
            const double rho = stretched ? a + b : std::abs(a - b);
            if (rho < 1e-9 * (a + b))
                continue; // folded with a = b: C on G_i, a point
            // fixed labels (the GUI keeps and translates them)
            static constexpr std::array<std::array<const char *, 2>, 2> labels = {{
                {QT_TRANSLATE_NOOP("core", "leg 1 stretched (AB, BC in line)"),
                 QT_TRANSLATE_NOOP("core", "leg 1 folded (AB, BC in line)")},
                {QT_TRANSLATE_NOOP("core", "leg 2 stretched (DE, CD in line)"),
                 QT_TRANSLATE_NOOP("core", "leg 2 folded (DE, CD in line)")},
            }};
            const std::string label = labels[std::size_t(leg)][stretched ? 0 : 1];
            traceRuns(curves, SingularCurve::Type::Inverse, label, -pi, pi, true, samples, [&](double t, Eigen::Vector2d &C) {
                C = G + rho * Eigen::Vector2d(std::cos(t), std::sin(t));
                return checkInverse(C, curveTolerance, reference).ok();
            });
        }
    }
    // Direct: the distal links in line, |BD| = BC + CD (stretched) or |BC − CD| (folded; for
    // equal links only where B = D, which leaves C undetermined). Traced over θ₁: D is where
    // the circle of radius |BD| about B meets crank DE's circle, on either side of B→E.
    const double b1 = d.link[0], b2 = d.link[1];
    const double match = 1e-5 * std::max({d.ground, d.crank[0], d.crank[1], b1, b2});
    const Eigen::Vector2d E = fivebar::groundJoint(d, 1);
    for (const bool stretched : {true, false}) {
        const double rho = stretched ? b1 + b2 : std::abs(b1 - b2);
        if (rho < 1e-9 * (b1 + b2))
            continue;
        for (const int side : {fivebar::left, fivebar::right}) {
            traceRuns(curves, SingularCurve::Type::Direct, QT_TRANSLATE_NOOP("core", "distal links in line"), d.range[0].min,
                      d.range[0].max,
                      fivebar::fullTurn(d.range[0]), samples, [&](double theta1, Eigen::Vector2d &C) {
                          const Eigen::Vector2d B = fivebar::elbow(d, 0, theta1);
                          Eigen::Vector2d D;
                          if (fivebar::circleIntersection(B, rho, E, d.crank[1], side, D, 0.0) != fivebar::Meet::Yes)
                              return false;
                          const Eigen::Vector2d u = (D - B) / rho;
                          C = stretched || b1 > b2 ? Eigen::Vector2d(B + b1 * u) : Eigen::Vector2d(B - b1 * u);
                          // a pose of the design whose elbows are these (the working modes agree)
                          const Check check = checkInverse(C, curveTolerance, reference);
                          return check.ok() && (check.elbows[0] - B).norm() <= match
                              && (check.elbows[1] - D).norm() <= match;
                      });
        }
    }
    return curves;
}

Eigen::AlignedBox2d FiveBar::computeBounds() const
{
    const FiveBarDesign &d = m_design;
    // C lies within reach of both legs: the boxes of their discs.
    Eigen::AlignedBox2d box;
    for (int leg = 0; leg < 2; ++leg) {
        const Eigen::Vector2d G = fivebar::groundJoint(d, leg);
        const Eigen::Vector2d reach = Eigen::Vector2d::Constant(d.crank[leg] + d.link[leg]);
        const Eigen::AlignedBox2d disc(G - reach, G + reach);
        box = leg == 0 ? disc : box.intersection(disc);
    }
    // The reachable cells of a coarse map, and the curves a coarse grid can slip between: the
    // workspace is bounded by the singular curves and by the poses at the ends of the ranges.
    const MapGrid grid = squareGrid(box, 256);
    std::vector<float> row(static_cast<std::size_t>(grid.columns));
    Eigen::AlignedBox2d reached(m_home.outputs.head<2>());
    for (int r = 0; r < grid.rows; ++r) {
        fillMapRow(MapQuantity::Determinant, grid.y(r), grid.x(0), grid.dx(), row, {});
        for (int c = 0; c < grid.columns; ++c) {
            if (!std::isnan(row[static_cast<std::size_t>(c)]))
                reached.extend(Eigen::Vector2d(grid.x(c), grid.y(r)));
        }
    }
    // A quarter of the drawn curves' samples: a point between two of them lies within
    // ρ·(1 − cos(π/boundsCurveSamples)) ≈ 1.5e-4·ρ of the box, far inside the two cells of pad
    // (and a design for an optimiser is built in about half the time).
    for (const SingularCurve &curve : tracedCurves(boundsCurveSamples)) {
        for (const Eigen::Vector2d &point : curve.points)
            reached.extend(point);
    }
    for (int held = 0; held < 2; ++held) {
        const Interval &heldRange = d.range[held], &swept = d.range[1 - held];
        if (fivebar::fullTurn(heldRange))
            continue; // a full turn has no ends
        for (const double end : {heldRange.min, heldRange.max}) {
            for (int k = 0; k <= curveSamples; ++k) {
                std::array<double, 2> theta{};
                theta[held] = end;
                theta[1 - held] = swept.min + (swept.max - swept.min) * k / curveSamples;
                if (const Check check = checkDirect(theta[0], theta[1], curveTolerance); check.ok())
                    reached.extend(check.C);
            }
        }
    }
    const Eigen::Vector2d pad(2.0 * grid.dx(), 2.0 * grid.dy());
    return Eigen::AlignedBox2d(reached.min() - pad, reached.max() + pad).intersection(box);
}

} // namespace pkm
