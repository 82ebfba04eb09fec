// MOMA's workspace and singularity maps (the MOMA document's figs. 6–10): the inner loop
// of every map, and the singular curves drawn over them.
#include "moma.h"
#include "mapclones.h"
#include "capabilitycell.h"
#include "text.h"

#include <cmath>
#include <limits>

namespace pkm {

namespace {

/// One leg's constants for the map loop.
struct Leg {
    double rx, ry;  ///< R_i
    double ax, ay;  ///< a_i
    double lengthSquared, length;
    double branch;  ///< β_i
    double oneSide; ///< the inner side (±1) when the one-side constraint is on, else 0
};

Leg legOf(const MomaDesign &d, int i)
{
    const double oneSide = d.oneSide ? double(moma::innerSide(d, i)) : 0.0;
    return {d.reference[i].x(), d.reference[i].y(), std::cos(d.alpha[i]), std::sin(d.alpha[i]),
            d.length[i] * d.length[i], d.length[i], double(d.branch[i]), oneSide};
}

/// What the map loop knows of one cell, for the quantity it maps.
struct Cell {
    double sa, sb;            ///< β_i√D_i without the sign: |L_i·a_i|
    double Da, Db;            ///< D_i of (9)
    double lax, lay, lbx, lby;///< L_i = P − Z_i
    double crossLinks;        ///< L₁×L₂
    double inverseMargin, directMargin;
};

/// The map row, written so that the compiler vectorises it: no branches, selects only.
/// Per cell: inverse kinematics of both legs (7–9), the link vectors L_i = P − Z_i, then the
/// quantity `value(cell)`: for det J = det J_x / det J_p = (L₁×L₂) / (β₁√D₁ · β₂√D₂), because
/// 2p_i − 2B_i = 2β_i√D_i and the side of P from the line Z₁Z₂ is (Z₂ − Z₁)×(P − Z₁) = L₁×L₂.
template <bool Margins, class Value>
[[gnu::always_inline]] inline void mapRow(const MomaDesign &d, double y, double x0, double dx, float *values, float *margins,
                                          int count, const Value &value)
{
    const Leg a = legOf(d, 0), b = legOf(d, 1);
    const double pMin = d.strokeMin, pMax = d.strokeMax;
    const double assembly = d.assembly;
    const double sideTolerance = -1e-9 * a.length * b.length;
    const double oneSideTolerance = -1e-9 * std::max(a.length, b.length);
    const double inverseLengthProduct = 1.0 / (a.length * b.length);
    const double inverseA = 1.0 / a.length, inverseB = 1.0 / b.length;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const double eya = y - a.ry, eyb = y - b.ry;
    for (int i = 0; i < count; ++i) {
        const double x = x0 + i * dx;
        const double exa = x - a.rx, exb = x - b.rx;
        const double Ba = a.ax * exa + a.ay * eya, Bb = b.ax * exb + b.ay * eyb;
        // B² − C = l² − (distance of P from the guide line)²: the same number as (9) without
        // the cancellation between B² and C
        const double perpendicularA = a.ax * eya - a.ay * exa, perpendicularB = b.ax * eyb - b.ay * exb;
        const double Da = a.lengthSquared - perpendicularA * perpendicularA;
        const double Db = b.lengthSquared - perpendicularB * perpendicularB;
        const double sa = std::sqrt(Da > 0.0 ? Da : 0.0), sb = std::sqrt(Db > 0.0 ? Db : 0.0);
        const double pa = Ba + a.branch * sa, pb = Bb + b.branch * sb;
        const double lax = exa - pa * a.ax, lay = eya - pa * a.ay;
        const double lbx = exb - pb * b.ax, lby = eyb - pb * b.ay;
        const double crossLinks = lax * lby - lay * lbx;
        const double sideA = a.oneSide * (a.ax * lay - a.ay * lax), sideB = b.oneSide * (b.ax * lby - b.ay * lbx);
        // the smallest of the slacks is ≥ 0 exactly when every condition holds
        const double slack = std::min(std::min(std::min(Da, Db), std::min(std::min(pa - pMin, pMax - pa), std::min(pb - pMin, pMax - pb))),
                                      std::min(assembly * crossLinks - sideTolerance,
                                               std::min(sideA - oneSideTolerance, sideB - oneSideTolerance)));
        const bool ok = slack >= 0.0;
        const Cell cell{sa, sb, Da, Db, lax, lay, lbx, lby, crossLinks,
                        std::min(sa * inverseA, sb * inverseB), std::abs(crossLinks) * inverseLengthProduct};
        values[i] = ok ? static_cast<float>(value(cell)) : nan;
        if constexpr (Margins)
            margins[i] = ok ? static_cast<float>(std::min(cell.inverseMargin, cell.directMargin)) : nan;
    }
}

/// σ_max/σ_min of J with rows −L_i/(β_i√D_i), |L_i| = l_i: (T + √(T² − 4δ²))/(2|δ|).
struct Condition {
    double lengthSquaredA, lengthSquaredB;
    double operator()(const Cell &c) const
    {
        const double frobenius = lengthSquaredA / c.Da + lengthSquaredB / c.Db;
        const double det = std::abs(c.crossLinks) / (c.sa * c.sb);
        const double spread = std::sqrt(std::max(0.0, frobenius * frobenius - 4.0 * det * det));
        // at a singularity ∞/∞ would give NaN, which means "unreachable": κ is +∞ there
        const bool regular = (c.Da > 0.0) & (c.Db > 0.0) & (c.crossLinks != 0.0);
        return regular ? (frobenius + spread) / (2.0 * det) : std::numeric_limits<double>::infinity();
    }
};

struct Determinant {
    double branches; ///< β₁β₂
    double operator()(const Cell &c) const { return branches * c.crossLinks / (c.sa * c.sb); }
};

/// What the actuators deliver (capabilitycell.h): J_p = diag(2β_i√D_i), J_x rows 2L_i (18, 20),
/// whose signs the cell does not need.
template <MapQuantity Q>
struct Delivered {
    capability::CellLimits limits; // a copy: loads the loop may hoist
    double rowA, rowB;             // |J_x,i| = 2l_i: the links have their length
    double operator()(const Cell &c) const
    {
        return capability::cell2<Q>(limits, 2.0 * c.sa, 2.0 * c.sb, 2.0 * c.lax, 2.0 * c.lay, 2.0 * c.lbx, 2.0 * c.lby,
                                    rowA, rowB, c.inverseMargin < Moma::singularTolerance,
                                    c.directMargin < Moma::singularTolerance);
    }
};

// The variants, each built for AVX-512 and AVX2 as well as the baseline (mapclones.h).
PKM_MAP_CLONES void determinantRow(const MomaDesign &d, double y, double x0, double dx, float *v, float *, int n)
{
    mapRow<false>(d, y, x0, dx, v, nullptr, n, Determinant{double(d.branch[0] * d.branch[1])});
}
PKM_MAP_CLONES void determinantMarginRow(const MomaDesign &d, double y, double x0, double dx, float *v, float *m, int n)
{
    mapRow<true>(d, y, x0, dx, v, m, n, Determinant{double(d.branch[0] * d.branch[1])});
}
PKM_MAP_CLONES void conditionRow(const MomaDesign &d, double y, double x0, double dx, float *v, float *, int n)
{
    mapRow<false>(d, y, x0, dx, v, nullptr, n, Condition{d.length[0] * d.length[0], d.length[1] * d.length[1]});
}
PKM_MAP_CLONES void conditionMarginRow(const MomaDesign &d, double y, double x0, double dx, float *v, float *m, int n)
{
    mapRow<true>(d, y, x0, dx, v, m, n, Condition{d.length[0] * d.length[0], d.length[1] * d.length[1]});
}
#define PKM_MOMA_DELIVERED(name, quantity)                                                                             \
    PKM_MAP_CLONES void name(const MomaDesign &d, const capability::CellLimits &l, double y, double x0, double dx,     \
                             float *v, float *m, int n)                                                                \
    {                                                                                                                  \
        mapRow<true>(d, y, x0, dx, v, m, n, Delivered<quantity>{l, 2.0 * d.length[0], 2.0 * d.length[1]}); \
    }
PKM_MOMA_DELIVERED(forceRow, MapQuantity::ForceWorst)
PKM_MOMA_DELIVERED(speedRow, MapQuantity::SpeedWorst)
PKM_MOMA_DELIVERED(resolutionRow, MapQuantity::ResolutionWorst)
PKM_MOMA_DELIVERED(stiffnessRow, MapQuantity::StiffnessWorst)
#undef PKM_MOMA_DELIVERED

} // namespace

void Moma::fillMapRow(MapQuantity quantity, double y, double x0, double dx, std::span<float> values,
                      std::span<float> margins) const
{
    const int count = static_cast<int>(values.size());
    const bool withMargins = !margins.empty();
    float *m = withMargins ? margins.data() : nullptr;
    if (quantity == MapQuantity::Condition) {
        withMargins ? conditionMarginRow(m_design, y, x0, dx, values.data(), m, count)
                    : conditionRow(m_design, y, x0, dx, values.data(), m, count);
    } else {
        withMargins ? determinantMarginRow(m_design, y, x0, dx, values.data(), m, count)
                    : determinantRow(m_design, y, x0, dx, values.data(), m, count);
    }
}

void Moma::fillCapabilityRow(const capability::CellLimits &limits, double y, double x0, double dx,
                             std::span<float> values, std::span<float> margins) const
{
    const auto row = limits.quantity == MapQuantity::ForceWorst        ? forceRow
                   : limits.quantity == MapQuantity::SpeedWorst        ? speedRow
                   : limits.quantity == MapQuantity::ResolutionWorst   ? resolutionRow
                                                                       : stiffnessRow;
    row(m_design, limits, y, x0, dx, values.data(), margins.data(), static_cast<int>(values.size()));
}

std::vector<SingularCurve> Moma::singularCurves() const
{
    const MomaDesign &d = m_design;
    constexpr int samples = 600;
    std::vector<SingularCurve> curves;
    // A polyline broken wherever the pose leaves the design's workspace.
    auto trace = [&](SingularCurve::Type type, const std::string &label, auto &&pointAt) {
        SingularCurve current{type, label, {}};
        for (int k = 0; k <= samples; ++k) {
            const double p = d.strokeMin + (d.strokeMax - d.strokeMin) * k / samples;
            Eigen::Vector2d point;
            if (pointAt(p, point)) {
                current.points.push_back(point);
            } else if (!current.points.empty()) {
                if (current.points.size() > 1)
                    curves.push_back(current);
                current.points.clear();
            }
        }
        if (current.points.size() > 1)
            curves.push_back(current);
    };
    // Is P, with leg `fixed` at slider position p (its link at the singular direction), a pose
    // of the design? The other leg must reach P in its branch and inside its stroke.
    auto belongs = [&](const Eigen::Vector2d &platform, int fixed, double p) {
        std::array<double, 2> q{};
        q[fixed] = p;
        const int other = 1 - fixed;
        const double D = moma::discriminant(d, other, platform);
        const double l = d.length[other];
        if (D < -1e-9 * l * l)
            return false;
        q[other] = moma::projection(d, other, platform) + d.branch[other] * std::sqrt(std::max(0.0, D));
        if (q[other] < d.strokeMin || q[other] > d.strokeMax)
            return false;
        const std::array<Eigen::Vector2d, 2> z = {moma::sliderJoint(d, 0, q[0]), moma::sliderJoint(d, 1, q[1])};
        if (moma::side(z[0], z[1], platform) * d.assembly < -1e-6 * d.length[0] * d.length[1])
            return false;
        // the fixed leg's working mode: its link must not point along β·a
        const double w = (platform - z[fixed]).dot(moma::direction(d.alpha[fixed]));
        if (w * d.branch[fixed] > 1e-6 * d.length[fixed])
            return false;
        return oneSideViolation(platform, z).empty();
    };
    // Inverse singularities: link i perpendicular to its guide, P = Z_i ± l_i·n_i.
    for (int leg = 0; leg < 2; ++leg) {
        const Eigen::Vector2d a = moma::direction(d.alpha[leg]);
        const Eigen::Vector2d n(-a.y(), a.x());
        for (double sign : {1.0, -1.0}) {
            trace(SingularCurve::Type::Inverse,
                  leg == 0 ? QT_TRANSLATE_NOOP("core", "link 1 ⟂ guide 1") : QT_TRANSLATE_NOOP("core", "link 2 ⟂ guide 2"),
                  [&](double p, Eigen::Vector2d &point) {
                      point = moma::sliderJoint(d, leg, p) + sign * d.length[leg] * n;
                      return belongs(point, leg, p);
                  });
        }
    }
    // Direct singularities: the links collinear, |Z₁Z₂| = l₁ + l₂ (stretched) or |l₁ − l₂|
    // (folded; for equal links only where Z₁ = Z₂, which leaves P undetermined).
    const double l1 = d.length[0], l2 = d.length[1];
    const Eigen::Vector2d a2 = moma::direction(d.alpha[1]);
    for (bool stretched : {true, false}) {
        const double rho = stretched ? l1 + l2 : std::abs(l1 - l2);
        if (rho < 1e-9 * std::max(l1, l2))
            continue;
        for (double root : {1.0, -1.0}) {
            trace(SingularCurve::Type::Direct, QT_TRANSLATE_NOOP("core", "links collinear"), [&](double p1, Eigen::Vector2d &point) {
                const Eigen::Vector2d z1 = moma::sliderJoint(d, 0, p1);
                // |R₂ + p₂a₂ − Z₁|² = ρ²: p₂² + 2p₂·a₂·(R₂ − Z₁) + |R₂ − Z₁|² − ρ² = 0
                const Eigen::Vector2d r = d.reference[1] - z1;
                const double half = a2.dot(r), c = r.squaredNorm() - rho * rho;
                const double disc = half * half - c;
                if (disc < 0)
                    return false;
                const double p2 = -half + root * std::sqrt(disc);
                if (p2 < d.strokeMin || p2 > d.strokeMax)
                    return false;
                const Eigen::Vector2d z2 = moma::sliderJoint(d, 1, p2);
                const Eigen::Vector2d u = (z2 - z1) / rho;
                point = stretched || l1 > l2 ? Eigen::Vector2d(z1 + l1 * u) : Eigen::Vector2d(z2 - l2 * u);
                // leg 2 in its working mode at this p₂ (then its inverse kinematics gives p₂)
                if ((point - z2).dot(a2) * d.branch[1] > 1e-6 * l2)
                    return false;
                return belongs(point, 0, p1);
            });
        }
    }
    return curves;
}

} // namespace pkm
