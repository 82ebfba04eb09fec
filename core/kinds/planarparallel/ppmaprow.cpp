// The map rows of the planar parallel mechanism. A 2-DOF platform's row is worked out a block
// of cells at a time: every leg's inverse kinematics in closed form over the block, written
// without branches so that the compiler vectorises it (as MOMA's and the five-bar's rows are),
// then J_q, J_x and the quantity from the distal links. A cell within round-off of one of the
// legs' limits is solved again as a single pose (mapCell), so the map reaches exactly the cells
// solveInverse() reaches and every cell equals evaluate() at its pose. A 3-DOF platform's row
// (the slice at φ = phi_map) is solved cell by cell.
#include "planarparallel.h"

#include "capabilitycell.h"
#include "mapclones.h"

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

namespace {

constexpr int block = 128;
/// Within this of a limit (relative, as the slacks below) a cell is decided by the pose solver:
/// far wider than the round-off by which the closed forms here and in legs.cpp may differ.
constexpr double band = 1e-7;
/// legs.cpp's relative tolerance of the reach and range checks.
constexpr double tolerance = 1e-9;

/// One leg's constants for the row (legs.cpp's inverse(), circle() and inverseMargin()).
struct LegConstants {
    LegType type = LegType::RRR;
    double ax = 0, ay = 0; ///< A_i
    double bx = 0, by = 0; ///< B_i (the platform keeps φ = 0)
    double crank = 0;      ///< r_i (R̲RR) or the П-joint's a_i (П̲RR)
    double link = 0;       ///< l_i
    double gx = 1, gy = 0; ///< the guide (P̲RR) or the П-joint's base line (П̲RR)
    double ratio = 0;      ///< k_i
    double working = 1;
    double qMin = 0, qMax = 0;    ///< a linear input's range, mm
    double rangeSlack = 0;        ///< the tolerance of that range, mm
    double rangeScale = 1;        ///< what makes its slack relative, mm
    double midx = 1, midy = 0;    ///< R̲RR: the middle of the crank's range as a direction
    double cosHalf = -2;          ///< R̲RR: cos of half the range plus its slack; −2: no limit
    double inverseScale = 1;      ///< 1/(crank·link): the inverse margin |C−A × e| without roots
    // reciprocals, so that the loops multiply where a division would cost several times more
    double inverseCrank = 1, inverseLink = 1, inverseRangeScale = 1;
    /// R̲RR, П̲RR: the squares of the distances |P − A| between which the crank and the link
    /// reach P (legs.cpp's elbow() with its tolerance), and 1/(r + l)² to make their slack relative
    double nearestSquared = 0, farthestSquared = 0, undeterminedSquared = 0, inverseReachSquared = 1;
};

LegConstants constantsOf(const PlanarLeg &leg)
{
    LegConstants k;
    k.type = leg.type;
    k.ax = leg.base.x(), k.ay = leg.base.y();
    k.bx = leg.platform.x(), k.by = leg.platform.y();
    k.crank = leg.type == LegType::PiRR ? leg.lever : leg.crank;
    k.link = leg.link;
    const Eigen::Vector2d g = leg.guideDirection();
    k.gx = g.x(), k.gy = g.y();
    k.ratio = leg.ratio;
    k.working = leg.working;
    k.qMin = leg.range.min, k.qMax = leg.range.max;
    switch (leg.type) {
    case LegType::PRR:
        k.rangeScale = std::max({1.0, leg.range.max - leg.range.min, leg.link});
        k.rangeSlack = 1e-7 * k.rangeScale;
        break;
    case LegType::RPR:
    case LegType::PiRR:
        k.rangeScale = std::max(1.0, leg.range.max);
        k.rangeSlack = tolerance * k.rangeScale;
        break;
    case LegType::RRR: {
        // an angle lies in [min − s, max + s] (mod 2π) exactly when its cosine to the middle
        // of the range is at least cos(half the range + s)
        const Interval &r = leg.crankRange;
        const double half = 0.5 * (r.max - r.min) + tolerance * (1.0 + std::abs(r.max - r.min));
        const double middle = 0.5 * (r.max + r.min);
        k.midx = std::cos(middle), k.midy = std::sin(middle);
        k.cosHalf = half >= std::numbers::pi ? -2.0 : std::cos(half);
        break;
    }
    }
    k.inverseScale = 1.0 / (k.crank * k.link);
    k.inverseCrank = 1.0 / k.crank;
    const double reach = k.crank + k.link;
    const double nearest = std::max(0.0, std::abs(k.crank - k.link) - tolerance * reach);
    k.nearestSquared = nearest * nearest;
    k.farthestSquared = reach * (1.0 + tolerance) * reach * (1.0 + tolerance);
    k.undeterminedSquared = tolerance * reach * tolerance * reach;
    k.inverseReachSquared = 1.0 / (reach * reach);
    k.inverseLink = 1.0 / k.link;
    k.inverseRangeScale = 1.0 / k.rangeScale;
    return k;
}

/// One leg over a block of cells.
struct LegBlock {
    double ex[block], ey[block]; ///< e = P_i − C_i, the distal link (the strut of an RP̲R)
    double cx[block], cy[block]; ///< C_i, the centre of the leg's circle
    double jq[block];            ///< ∂g_i/∂q_i (П̲RR: by θ_i, times d_i/a_i)
    double rate[block];          ///< П̲RR: the П-joint's J = ∂d/∂θ (7) times d_i/a_i; 1 for the others
    double radius[block];        ///< ρ_i = |e|
    double inverseRadius[block]; ///< 1/ρ_i (1 where ρ_i = 0)
    double slack[block];         ///< ≥ 0 where the leg reaches in its mode and range (relative)
    double inverse[block];       ///< the leg's inverse margin
    double pjoint[block];        ///< |cos θ_i| of a П-joint, 1 for the others
};

/// legs.cpp's elbow() without branches: v = E − A for the elbow E of the crank at A whose tip
/// is the link's length from P = A + r, on the working side of A→P; returns the slack
/// (relative) of reaching P. Worked in |r|² so that it takes one square root, not three:
/// E − A = along·r/|r| + across·r⊥/|r| with along/|r| = (c² − l² + |r|²)/(2|r|²) and
/// (across/|r|)² = c²/|r|² − (along/|r|)².
[[gnu::always_inline]] inline double elbow(const LegConstants &k, double rx, double ry, double &vx, double &vy)
{
    const double d2 = rx * rx + ry * ry;
    const double inverse = 1.0 / (d2 > 0.0 ? d2 : 1.0);
    const double along = 0.5 * (k.crank * k.crank - k.link * k.link + d2) * inverse;
    const double across2 = k.crank * k.crank * inverse - along * along;
    const double across = k.working * std::sqrt(across2 > 0.0 ? across2 : 0.0);
    vx = along * rx - across * ry;
    vy = along * ry + across * rx;
    const double slack = std::min(std::min(d2 - k.undeterminedSquared, k.farthestSquared - d2), d2 - k.nearestSquared);
    return slack * k.inverseReachSquared;
}

/// Leg `k` over cells x0 + i·dx, i < count, at height y. One loop per leg type, each free of
/// branches.
[[gnu::always_inline]] inline void legBlock(const LegConstants k, double y, double x0, double dx, int count,
                                            LegBlock &o)
{
    // k by value: a store into the block can then not be taken for a change of the constants
    const double ry = y + k.by - k.ay;
    const double rx0 = x0 + k.bx - k.ax;
    switch (k.type) {
    case LegType::RRR:
        for (int i = 0; i < count; ++i) {
            const double rx = rx0 + i * dx;
            double vx, vy;
            const double reach = elbow(k, rx, ry, vx, vy);
            const double arc = (k.midx * vx + k.midy * vy) * k.inverseCrank - k.cosHalf;
            const double ex = rx - vx, ey = ry - vy;
            const double turn = vx * ey - vy * ex; // (C − A) × e
            o.ex[i] = ex, o.ey[i] = ey;
            o.cx[i] = k.ax + vx, o.cy[i] = k.ay + vy;
            o.jq[i] = -turn; // −e·∂C/∂q, ∂C/∂q = r·(−sin q, cos q)
            o.rate[i] = 1.0;
            o.radius[i] = k.link;
            o.inverseRadius[i] = k.inverseLink;
            o.slack[i] = std::min(reach, arc);
            o.inverse[i] = std::abs(turn) * k.inverseScale;
            o.pjoint[i] = 1.0;
        }
        break;
    case LegType::PiRR:
        for (int i = 0; i < count; ++i) {
            const double rx = rx0 + i * dx;
            double vx, vy;
            const double reach = elbow(k, rx, ry, vx, vy);
            // the crank points along ψ = α + 90° − θ: sin θ = u(α)·u(ψ), cos θ = u(α) × u(ψ)
            const double sinTheta = (k.gx * vx + k.gy * vy) * k.inverseCrank;
            const double cosTheta = (k.gx * vy - k.gy * vx) * k.inverseCrank;
            const double inside = 1.0 + k.ratio * k.ratio + 2.0 * k.ratio * sinTheta;
            const double root = std::sqrt(inside > 0.0 ? inside : 0.0);
            const double d = k.crank * root; // (2)
            const double range = std::min(d - (k.qMin - k.rangeSlack), k.qMax + k.rangeSlack - d) * k.inverseRangeScale;
            const double ex = rx - vx, ey = ry - vy;
            const double turn = vx * ey - vy * ex;
            o.ex[i] = ex, o.ey[i] = ey;
            o.cx[i] = k.ax + vx, o.cy[i] = k.ay + vy;
            // ∂C/∂θ = −a·(−sin ψ, cos ψ), and the П-joint's J = a²k·cos θ/d (7): the leg's row of
            // J_q and of J_x both times d/a, which leaves J = J_q⁻¹·J_x and what the actuators
            // deliver as they are and takes the division by d out of the loop
            o.jq[i] = turn * root;
            o.rate[i] = k.crank * k.ratio * cosTheta;
            o.radius[i] = k.link;
            o.inverseRadius[i] = k.inverseLink;
            o.slack[i] = std::min(std::min(reach, range), cosTheta); // |θ| < 90°
            o.inverse[i] = std::abs(turn) * k.inverseScale;
            o.pjoint[i] = std::abs(cosTheta);
        }
        break;
    case LegType::PRR:
        for (int i = 0; i < count; ++i) {
            const double rx = rx0 + i * dx;
            // the MOMA document's (7–9): q = u·r + β·√(l² − (u × r)²)
            const double across = k.gx * ry - k.gy * rx;
            const double D = k.link * k.link - across * across;
            const double q = k.gx * rx + k.gy * ry + k.working * std::sqrt(D > 0.0 ? D : 0.0);
            const double range = std::min(q - (k.qMin - k.rangeSlack), k.qMax + k.rangeSlack - q) * k.inverseRangeScale;
            const double ex = rx - q * k.gx, ey = ry - q * k.gy;
            const double along = ex * k.gx + ey * k.gy;
            o.ex[i] = ex, o.ey[i] = ey;
            o.cx[i] = k.ax + q * k.gx, o.cy[i] = k.ay + q * k.gy;
            o.jq[i] = -along;
            o.rate[i] = 1.0;
            o.radius[i] = k.link;
            o.inverseRadius[i] = k.inverseLink;
            o.slack[i] = std::min(D * k.inverseLink * k.inverseLink + tolerance, range);
            o.inverse[i] = std::abs(along) * k.inverseLink;
            o.pjoint[i] = 1.0;
        }
        break;
    case LegType::RPR:
        for (int i = 0; i < count; ++i) {
            const double rx = rx0 + i * dx;
            const double q = std::sqrt(rx * rx + ry * ry);
            const double range = std::min(q - (k.qMin - k.rangeSlack), k.qMax + k.rangeSlack - q);
            o.ex[i] = rx, o.ey[i] = ry;
            o.cx[i] = k.ax, o.cy[i] = k.ay;
            o.jq[i] = -q; // −ρ·∂ρ/∂q
            o.rate[i] = 1.0;
            o.radius[i] = q;
            o.inverseRadius[i] = 1.0 / (q > 0.0 ? q : 1.0);
            o.slack[i] = std::min(q - k.rangeSlack, range) * k.inverseRangeScale;
            o.inverse[i] = 1.0;
            o.pjoint[i] = 1.0;
        }
        break;
    }
}

struct RowConstants {
    LegConstants a, b;
    double assembly = 1;
};

/// What the row knows of one cell, for the quantity it maps.
struct Cell {
    double jqa, jqb;                 ///< J_q = diag(jqa, jqb)
    double j00, j01, j10, j11;       ///< J_x
    double rowA, rowB;               ///< |J_x rows|
    double inverseMargin, directMargin;
};

/// The block: both legs, then per cell the assembly check, J_q and J_x, the margins and
/// `value(cell)`. `uncertain[i]` is set where a limit is within round-off: the caller solves
/// that cell as a pose.
template <class Value>
[[gnu::always_inline]] inline void twoLegBlock(const RowConstants &k, double y, double x0, double dx, float *values,
                                               float *margins, int *uncertain, int count, const Value &value)
{
    LegBlock a, b;
    legBlock(k.a, y, x0, dx, count, a);
    legBlock(k.b, y, x0, dx, count, b);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const double assembly = k.assembly, bax = k.a.bx, bay = k.a.by, bbx = k.b.bx, bby = k.b.by;
    for (int i = 0; i < count; ++i) {
        // planarparallel.cpp's inverseCheck(): P on the assembly's side of the line C₁→C₂
        // between the circle centres, each taken at its platform point's reference
        const double ox = (b.cx[i] - bbx) - (a.cx[i] - bax), oy = (b.cy[i] - bby) - (a.cy[i] - bay);
        const double radii = a.radius[i] * b.radius[i];
        const double inverseRadii = a.inverseRadius[i] * b.inverseRadius[i];
        const double side = (assembly * (ox * a.ey[i] - oy * a.ex[i]) + 1e-9 * radii) * inverseRadii;
        const double slack = std::min(std::min(a.slack[i], b.slack[i]), side);
        // NaN (which no limit should give) is left to the pose solver too
        uncertain[i] = !(std::abs(slack) >= band);
        const bool ok = slack >= 0.0;
        const double crossLinks = a.ex[i] * b.ey[i] - a.ey[i] * b.ex[i];
        // N's rows are the unit distal links, whose lengths are ρ_i (legs.cpp's e.norm())
        const double direct = std::abs(crossLinks) * inverseRadii * std::min(a.pjoint[i], b.pjoint[i]);
        const Cell cell{a.jq[i],
                        b.jq[i],
                        -a.rate[i] * a.ex[i],
                        -a.rate[i] * a.ey[i],
                        -b.rate[i] * b.ex[i],
                        -b.rate[i] * b.ey[i],
                        std::abs(a.rate[i]) * a.radius[i],
                        std::abs(b.rate[i]) * b.radius[i],
                        std::min(a.inverse[i], b.inverse[i]),
                        radii > 0.0 ? direct : 0.0};
        values[i] = ok ? static_cast<float>(value(cell)) : nan;
        margins[i] = ok ? static_cast<float>(std::min(cell.inverseMargin, cell.directMargin)) : nan;
    }
}

struct Determinant {
    double operator()(const Cell &c) const { return (c.j00 * c.j11 - c.j01 * c.j10) / (c.jqa * c.jqb); }
};

/// planaranalysis.cpp's κ(J) of a 2 × 2 J = J_q⁻¹·J_x: (‖J‖²_F + √(‖J‖⁴_F − 4 det²))/(2|det J|),
/// +∞ where J_q or J_x is singular.
struct Condition {
    double operator()(const Cell &c) const
    {
        const double detJq = c.jqa * c.jqb;
        const double sa = 1.0 / (c.jqa != 0.0 ? c.jqa : 1.0), sb = 1.0 / (c.jqb != 0.0 ? c.jqb : 1.0);
        const double j00 = c.j00 * sa, j01 = c.j01 * sa, j10 = c.j10 * sb, j11 = c.j11 * sb;
        const double f = j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11;
        const double d = std::abs(j00 * j11 - j01 * j10);
        const double spread = std::sqrt(std::max(0.0, f * f - 4.0 * d * d));
        const bool regular = (detJq != 0.0) & (d > 0.0);
        return regular ? (f + spread) / (2.0 * (regular ? d : 1.0)) : std::numeric_limits<double>::infinity();
    }
};

/// What the actuators deliver (capabilitycell.h) with the class of planaranalysis.cpp.
template <MapQuantity Q>
struct Delivered {
    capability::CellLimits limits; // a copy: loads the loop may hoist
    double operator()(const Cell &c) const
    {
        const double value = capability::cell2<Q>(limits, c.jqa, c.jqb, c.j00, c.j01, c.j10, c.j11, c.rowA, c.rowB,
                                                  c.inverseMargin < PlanarParallel::singularTolerance,
                                                  c.directMargin < PlanarParallel::singularTolerance);
        // capability::cellValue(): undefined reads as unbounded
        return std::isnan(value) ? std::numeric_limits<double>::infinity() : value;
    }
};

// The variants, each built for AVX-512 and AVX2 as well as the baseline (mapclones.h).
using BlockFunction = void (*)(const RowConstants &, const capability::CellLimits &, double, double, double, float *,
                               float *, int *, int);
#define PKM_PP_BLOCK(name, functor)                                                                                 \
    PKM_MAP_CLONES void name(const RowConstants &k, const capability::CellLimits &l, double y, double x0, double dx, \
                             float *v, float *m, int *u, int n)                                          \
    {                                                                                                               \
        (void)l;                                                                                                    \
        twoLegBlock(k, y, x0, dx, v, m, u, n, functor);                                                             \
    }
PKM_PP_BLOCK(determinantBlock, Determinant{})
PKM_PP_BLOCK(conditionBlock, Condition{})
PKM_PP_BLOCK(forceBlock, Delivered<MapQuantity::ForceWorst>{l})
PKM_PP_BLOCK(speedBlock, Delivered<MapQuantity::SpeedWorst>{l})
PKM_PP_BLOCK(resolutionBlock, Delivered<MapQuantity::ResolutionWorst>{l})
PKM_PP_BLOCK(stiffnessBlock, Delivered<MapQuantity::StiffnessWorst>{l})
#undef PKM_PP_BLOCK

BlockFunction blockFunction(MapQuantity quantity)
{
    switch (quantity) {
    case MapQuantity::Determinant:
        return determinantBlock;
    case MapQuantity::Condition:
        return conditionBlock;
    case MapQuantity::ForceWorst:
        return forceBlock;
    case MapQuantity::SpeedWorst:
        return speedBlock;
    case MapQuantity::ResolutionWorst:
        return resolutionBlock;
    case MapQuantity::StiffnessWorst:
        return stiffnessBlock;
    default:
        return nullptr;
    }
}

} // namespace

void PlanarParallel::mapCell(MapQuantity quantity, const capability::CellLimits *limits, const Eigen::Vector3d &X,
                             Pose &pose, float &value, float &margin) const
{
    const int n = m_design.legCount();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    int culprit = 0;
    if (inverseCheck(X, nullptr, pose.inputs, culprit) != planar::Reach::Yes) {
        value = margin = nan;
        return;
    }
    pose.outputs.resize(n);
    for (int i = 0; i < n; ++i)
        pose.outputs[i] = X[i];
    Eigen::Matrix3d jq, jx;
    jacobianParts(pose, jq, jx);
    const Singularity s = singularity(pose);
    margin = static_cast<float>(s.margin);
    if (limits) {
        // every leg's J_q is its own: diagonal, as capabilitycell.h takes it
        const bool inverse = s.type == SingularityType::Inverse || s.type == SingularityType::Combined;
        const bool direct = s.type == SingularityType::Direct || s.type == SingularityType::Combined;
        const double delivered = n == 3
            ? capability::cell3(*limits, jq.diagonal(), jx, inverse, direct)
            : capability::cell2(*limits, jq(0, 0), jq(1, 1), jx(0, 0), jx(0, 1), jx(1, 0), jx(1, 1),
                                jx.row(0).head<2>().norm(), jx.row(1).head<2>().norm(), inverse, direct);
        value = capability::cellValue(delivered);
        return;
    }
    const double detJq = jq.diagonal().head(n).prod();
    double result = 0.0;
    if (quantity == MapQuantity::Determinant) {
        result = (n == 2 ? jx.topLeftCorner<2, 2>().determinant() : jx.determinant()) / detJq;
    } else {
        result = std::numeric_limits<double>::infinity();
        if (detJq != 0.0) {
            Eigen::Matrix3d J = jx;
            for (int i = 0; i < n; ++i)
                J.row(i) /= jq(i, i);
            if (n == 2) {
                const Eigen::Matrix2d j2 = J.topLeftCorner<2, 2>();
                const double f = j2.squaredNorm(), d = std::abs(j2.determinant());
                if (d > 0.0)
                    result = (f + std::sqrt(std::max(0.0, f * f - 4.0 * d * d))) / (2.0 * d);
            } else {
                const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix3d>(J).singularValues();
                if (sv[2] > 0.0)
                    result = sv[0] / sv[2];
            }
        }
    }
    value = static_cast<float>(result);
}

void PlanarParallel::fillRow(MapQuantity quantity, const capability::CellLimits *limits, double y, double x0,
                             double dx, std::span<float> values, std::span<float> margins) const
{
    const int n = m_design.legCount();
    Pose pose;
    const BlockFunction rowBlock = n == 2 ? blockFunction(quantity) : nullptr;
    if (!rowBlock) {
        float unused = 0.0f;
        const double phi = n == 3 ? m_design.mapPhi : 0.0;
        for (std::size_t c = 0; c < values.size(); ++c)
            mapCell(quantity, limits, {x0 + double(c) * dx, y, phi}, pose, values[c], margins.empty() ? unused : margins[c]);
        return;
    }
    RowConstants k{constantsOf(m_design.legs[0]), constantsOf(m_design.legs[1]), double(m_design.assembly)};
    const capability::CellLimits none{};
    float scratch[block];
    int uncertain[block];
    const int count = static_cast<int>(values.size());
    for (int start = 0; start < count; start += block) {
        const int size = std::min(block, count - start);
        float *m = margins.empty() ? scratch : margins.data() + start;
        rowBlock(k, limits ? *limits : none, y, x0 + start * dx, dx, values.data() + start, m, uncertain, size);
        for (int i = 0; i < size; ++i) {
            if (uncertain[i])
                mapCell(quantity, limits, {x0 + double(start + i) * dx, y, 0.0}, pose, values[std::size_t(start + i)], m[i]);
        }
    }
}

void PlanarParallel::fillMapRow(MapQuantity quantity, double y, double x0, double dx, std::span<float> values,
                                std::span<float> margins) const
{
    if (quantity != MapQuantity::OrientationRange) {
        fillRow(quantity, nullptr, y, x0, dx, values, margins);
        return;
    }
    // the total width of the reachable φ at each (x, y); 2-DOF platforms never turn
    const int n = m_design.legCount();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::array<Interval, 8> found;
    for (std::size_t c = 0; c < values.size(); ++c) {
        double margin = 0.0;
        const int count = n == 3 ? orientationIntervals({x0 + double(c) * dx, y}, found, &margin) : 0;
        double width = 0.0;
        for (int k = 0; k < count; ++k)
            width += found[std::size_t(k)].max - found[std::size_t(k)].min;
        values[c] = count > 0 ? static_cast<float>(width) : nan;
        if (!margins.empty())
            margins[c] = count > 0 ? static_cast<float>(margin) : nan;
    }
}

void PlanarParallel::fillCapabilityRow(const capability::CellLimits &limits, double y, double x0, double dx,
                                       std::span<float> values, std::span<float> margins) const
{
    fillRow(limits.quantity, &limits, y, x0, dx, values, margins);
}

} // namespace pkm
