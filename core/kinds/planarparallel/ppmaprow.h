#pragma once
// The leg model of the planar parallel mechanism's map rows (ppmaprow.cpp, ppmaprow3.cpp): each
// leg's inverse kinematics, its row of J_q and J_x and its margins over a block of cells, in
// closed form and without branches, so that the compiler vectorises the loops.
#include "planarparallel.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace pkm::maprow {

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
    double bx = 0, by = 0; ///< B_i turned by the platform's angle φ of the row (0 for 2 DOF)
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

/// Leg `leg`'s constants for a row of platform poses at angle `phi` (rad).
inline LegConstants constantsOf(const PlanarLeg &leg, double phi = 0.0)
{
    LegConstants k;
    k.type = leg.type;
    k.ax = leg.base.x(), k.ay = leg.base.y();
    const Eigen::Vector2d b = planar::platformPoint(leg, Eigen::Vector3d(0.0, 0.0, phi)); // R(φ)·B_i
    k.bx = b.x(), k.by = b.y();
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

/// A row of `values` (and `margins`, or a scratch block) in blocks of cells: `fill(start, size,
/// values, margins, uncertain)` works out a block, and `solve(cell, value, margin)` solves again,
/// as a pose, each cell it marks uncertain.
template <class Fill, class Solve>
void inBlocks(std::span<float> values, std::span<float> margins, const Fill &fill, const Solve &solve)
{
    float scratch[block];
    int uncertain[block];
    const int count = static_cast<int>(values.size());
    for (int start = 0; start < count; start += block) {
        const int size = std::min(block, count - start);
        float *m = margins.empty() ? scratch : margins.data() + start;
        fill(start, size, values.data() + start, m, uncertain);
        for (int i = 0; i < size; ++i) {
            if (uncertain[i])
                solve(start + i, values[std::size_t(start + i)], m[i]);
        }
    }
}

} // namespace pkm::maprow
