#pragma once
/// One cell of a map of what the actuators deliver, in closed form from the Jacobians of the
/// cell, for the kinds whose map loops already have them (PlanarWorkspace::fillCapabilityRow()).
/// It gives exactly what capability::evaluate() gives for the one entry the map shows —
/// the same formulas (capability.h), written for a diagonal J_q, the form every planar kind's
/// J_q takes (each actuator drives one leg) — but for that entry only, with no matrix solve,
/// and with selects in place of branches, so that a kind's map loop stays vectorised.
///
/// With J_q = diag(q_i), J = J_q⁻¹·J_x has rows J_x,i/q_i and G = J⁻¹ = J_x⁻¹·J_q has columns
/// q_i·(J_x⁻¹)_i. For two actuators, with J_x = [a b; c d] and Δ = ad − bc,
///   G e₁ = q₁·(d, −c)/Δ,  G e₂ = q₂·(−b, a)/Δ,  |J_x,1| = √(a² + b²), |J_x,2| = √(c² + d²).
/// Every quantity depends on the rows' signs not at all (norms, and a maximum over ± steps),
/// so a kind may hand its rows in either orientation.

#include "capability.h"
#include "planarworkspace.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pkm::capability {

/// What a cell needs of the actuators for one map quantity, in the units the Jacobians take
/// (a rotary actuator's torque and stiffness in N·mm and N·mm/rad, as capability.cpp uses them).
struct CellLimits {
    MapQuantity quantity = MapQuantity::ForceWorst;
    int count = 0;
    /// Per actuator: the force, the speed, half the step, or the compliance 1/k, by quantity.
    std::array<double, maxActuators> limit{};
    /// |G·e_i| at the home pose over and times nearSingular: an actuator that moves the
    /// platform less than `negligible` moves it not at all (inverse), one that moves it more
    /// than `excessive` marks a direct singularity (capability::deliveryClass()).
    std::array<double, maxActuators> negligible{};
    std::array<double, maxActuators> excessive{};
};

/// The limits of `actuators` for `quantity` (one of the four capability maps).
CellLimits cellLimits(const Actuators &actuators, MapQuantity quantity);

/// min(n₁/d₁, n₂/d₂) over the i with `use_i` (d_i > 0 there), ∞ if neither: one division, which
/// a vectorised loop pays dearly for.
[[gnu::always_inline]] inline double smallerRatio(double n1, double d1, bool use1, double n2, double d2, bool use2)
{
    const bool both = use1 & use2;
    const double numerator = both ? std::min(n1 * d2, n2 * d1)
                           : use1 ? n1
                           : use2 ? n2
                                  : std::numeric_limits<double>::infinity();
    const double denominator = both ? d1 * d2 : use1 ? d1 : use2 ? d2 : 1.0;
    return numerator / denominator;
}

/// The cell of a two-actuator design: J_q = diag(q1, q2), J_x = [a b; c d], and whether the
/// kind classifies the pose inverse- and direct-singular (its margins below its tolerance).
/// The exact 0 or ∞ of a singular pose as capability.cpp's layout marks them.
/// `r1`, `r2` are the lengths of J_x's rows, √(a² + b²) and √(c² + d²): a kind whose rows are
/// links of fixed length knows them without a square root.
template <MapQuantity Q>
[[gnu::always_inline]] inline double cell2(const CellLimits &l, double q1, double q2, double a, double b, double c,
                                           double d, double r1, double r2, bool inverse, bool direct)
{
    constexpr double infinity = std::numeric_limits<double>::infinity();
    // read once, outside every select, so that a vectorised loop loads them unconditionally
    const double limit1 = l.limit[0], limit2 = l.limit[1];
    const double negligible1 = l.negligible[0], negligible2 = l.negligible[1];
    const double excessive1 = l.excessive[0], excessive2 = l.excessive[1];
    const double det = a * d - b * c, absDet = std::abs(det);
    // |G e_i| = |q_i|·|J_x,other|/|Δ|, compared without dividing by Δ: below `negligible` the
    // actuator moves the platform no more (inverse), above `excessive` the pose is as direct-
    // singular (capability::deliveryClass(); at Δ = 0, ∞·0 is NaN and the kind's mark decides)
    const double m1 = std::abs(q1) * r2, m2 = std::abs(q2) * r1;
    const bool zero1 = m1 <= negligible1 * absDet, zero2 = m2 <= negligible2 * absDet;
    inverse = inverse | zero1 | zero2;
    direct = direct | (m1 >= excessive1 * absDet) | (m2 >= excessive2 * absDet);
    // no square root and one division at most beyond the caller's: a vectorised loop pays
    // per square root and division, not per multiplication
    if constexpr (Q == MapQuantity::SpeedWorst) {
        // the velocity slabs |J_i·ẋ| ≤ v_i: inscribed radius min v_i·|q_i|/|J_x,i|; 0 where an
        // actuator's leg is stretched (J unbounded)
        const double v = smallerRatio(limit1 * std::abs(q1), r1, r1 > 0.0, limit2 * std::abs(q2), r2, r2 > 0.0);
        return inverse ? 0.0 : v;
    } else {
        if constexpr (Q == MapQuantity::ForceWorst) {
            // the force slabs |(Gᵀ·F)_i| ≤ F_i: inscribed radius min F_i/|G e_i|, no slab where
            // G e_i is 0; over one denominator, min(F₁m₂, F₂m₁)/(m₁m₂), with m_i = 0 as 1
            const double s1 = m1 > 0.0 ? m1 : 1.0, s2 = m2 > 0.0 ? m2 : 1.0;
            const double f = std::min(zero1 ? infinity : limit1 * s2, zero2 ? infinity : limit2 * s1) / (s1 * s2);
            return direct ? 0.0 : absDet * f;
        } else {
            const double s = 1.0 / det; // ∞ at a direct singularity, where the marks decide
            double g1x = q1 * d * s, g1y = -q1 * c * s, g2x = -q2 * b * s, g2y = q2 * a * s;
            if constexpr (Q == MapQuantity::ResolutionWorst) {
                // the farthest vertex of G·box(±h_i): |h₁·G e₁ ± h₂·G e₂|, the larger
                const double h1 = zero1 ? 0.0 : limit1, h2 = zero2 ? 0.0 : limit2;
                g1x *= h1, g1y *= h1, g2x *= h2, g2y *= h2;
                const double plus = (g1x + g2x) * (g1x + g2x) + (g1y + g2y) * (g1y + g2y);
                const double minus = (g1x - g2x) * (g1x - g2x) + (g1y - g2y) * (g1y - g2y);
                return direct ? infinity : std::sqrt(std::max(plus, minus));
            } else {
                static_assert(Q == MapQuantity::StiffnessWorst);
                // 1/λ_max of the compliance C = Σ c_i·G e_i·(G e_i)ᵀ
                const double c1 = zero1 ? 0.0 : limit1, c2 = zero2 ? 0.0 : limit2;
                const double cxx = c1 * g1x * g1x + c2 * g2x * g2x, cyy = c1 * g1y * g1y + c2 * g2y * g2y;
                const double cxy = c1 * g1x * g1y + c2 * g2x * g2y;
                const double half = 0.5 * (cxx - cyy);
                const double largest = 0.5 * (cxx + cyy) + std::sqrt(half * half + cxy * cxy);
                return direct ? 0.0 : 1.0 / largest;
            }
        }
    }
}

/// The same by a quantity known at run time (a kind's scalar loop).
double cell2(const CellLimits &limits, double q1, double q2, double a, double b, double c, double d, double r1,
             double r2, bool inverse, bool direct);

/// The cell of a three-actuator platform (x, y in mm, φ in rad): J_q = diag(q), J_x 3×3, with
/// the choices of capability.h for mixed units (a pure force, a pure translation, the
/// translational part of the error).
double cell3(const CellLimits &limits, const Eigen::Vector3d &q, const Eigen::Matrix3d &jx, bool inverse, bool direct);

/// cell3() without Eigen or branches, for a loop that works a block of cells at once: J_x⁻¹ by
/// cofactors (as Eigen's closed form for 3×3), G = J_x⁻¹·diag(q), then the same quantities and
/// marks. `j` holds J_x's rows.
template <MapQuantity Q>
[[gnu::always_inline]] inline double cell3(const CellLimits &l, const double q[3], const double j[3][3], bool inverse,
                                           bool direct)
{
    constexpr double infinity = std::numeric_limits<double>::infinity();
    const double limit[3] = {l.limit[0], l.limit[1], l.limit[2]};
    // the adjugate's entries over the determinant, each column scaled by q_c: G, whose columns
    // also decide whether the pose is as singular (capability::deliveryClass())
    const double c00 = j[1][1] * j[2][2] - j[1][2] * j[2][1], c01 = j[1][2] * j[2][0] - j[1][0] * j[2][2];
    const double c02 = j[1][0] * j[2][1] - j[1][1] * j[2][0];
    const double s = 1.0 / (j[0][0] * c00 + j[0][1] * c01 + j[0][2] * c02); // ∞ at a direct singularity
    double g[3][3] = {{c00, j[0][2] * j[2][1] - j[0][1] * j[2][2], j[0][1] * j[1][2] - j[0][2] * j[1][1]},
                      {c01, j[0][0] * j[2][2] - j[0][2] * j[2][0], j[0][2] * j[1][0] - j[0][0] * j[1][2]},
                      {c02, j[0][1] * j[2][0] - j[0][0] * j[2][1], j[0][0] * j[1][1] - j[0][1] * j[1][0]}};
    for (int c = 0; c < 3; ++c) {
        const double scale = s * q[c];
        g[0][c] *= scale, g[1][c] *= scale, g[2][c] *= scale;
        // an actuator that moves the platform less than `negligible` moves it not at all
        const double norm = std::sqrt(g[0][c] * g[0][c] + g[1][c] * g[1][c] + g[2][c] * g[2][c]);
        const bool zero = norm <= l.negligible[std::size_t(c)];
        inverse = inverse | zero;
        direct = direct | !(norm < l.excessive[std::size_t(c)]);
        const double keep = zero ? 0.0 : 1.0;
        g[0][c] *= keep, g[1][c] *= keep, g[2][c] *= keep;
    }
    if constexpr (Q == MapQuantity::SpeedWorst) {
        // J's rows J_x,i/q_i on the translation: min v_i·|q_i|/|J_x,i(x, y)|
        double radius = infinity;
        for (int i = 0; i < 3; ++i) {
            const double norm = std::sqrt(j[i][0] * j[i][0] + j[i][1] * j[i][1]);
            const double ratio = limit[i] * std::abs(q[i]) / (norm > 0.0 ? norm : 1.0);
            radius = norm > 0.0 ? std::min(radius, ratio) : radius;
        }
        return inverse ? 0.0 : radius;
    } else {
        if constexpr (Q == MapQuantity::ForceWorst) {
            // a pure force: the slabs |(Gᵀ·F)_i| ≤ F_i over (F_x, F_y, 0)
            double radius = infinity;
            for (int c = 0; c < 3; ++c) {
                const double norm = std::sqrt(g[0][c] * g[0][c] + g[1][c] * g[1][c]);
                const double ratio = limit[c] / (norm > 0.0 ? norm : 1.0);
                radius = norm > 0.0 ? std::min(radius, ratio) : radius;
            }
            return direct ? 0.0 : radius;
        } else if constexpr (Q == MapQuantity::ResolutionWorst) {
            // the translational part of G·u over the vertices u of the box ±h
            double farthest = 0.0;
            for (int signs = 0; signs < 8; ++signs) {
                double x = 0.0, y = 0.0;
                for (int c = 0; c < 3; ++c) {
                    const double u = (signs >> c & 1) ? limit[c] : -limit[c];
                    x += g[0][c] * u, y += g[1][c] * u;
                }
                farthest = std::max(farthest, x * x + y * y);
            }
            return direct ? infinity : std::sqrt(farthest);
        } else {
            static_assert(Q == MapQuantity::StiffnessWorst);
            // the translational block of the compliance C = G·diag(1/k)·Gᵀ, its largest eigenvalue
            double cxx = 0.0, cyy = 0.0, cxy = 0.0;
            for (int c = 0; c < 3; ++c) {
                cxx += limit[c] * g[0][c] * g[0][c], cyy += limit[c] * g[1][c] * g[1][c];
                cxy += limit[c] * g[0][c] * g[1][c];
            }
            const double half = 0.5 * (cxx - cyy);
            return direct ? 0.0 : 1.0 / (0.5 * (cxx + cyy) + std::sqrt(half * half + cxy * cxy));
        }
    }
}

/// A map cell as capabilitymap.h stores it: undefined (0·∞) reads as ∞, since NaN means
/// unreachable.
inline float cellValue(double value)
{
    return std::isnan(value) ? std::numeric_limits<float>::infinity() : static_cast<float>(value);
}

} // namespace pkm::capability
