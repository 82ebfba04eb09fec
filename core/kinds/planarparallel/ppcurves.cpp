// The singular curves of the planar parallel mechanism over its workspace map, for any leg
// combination (docs/mathematics.md, "Planar parallel mechanisms from a leg library"). Both
// kinds of curve bound the map of the design's modes (a leg's working mode and the 2-DOF
// assembly mode change sign there), so a contour of det J_q or det J_x over the grid would
// not find them: they are traced in closed form, as the five-bar's and MOMA's are.
//
// Inverse (det J_q = 0): leg i's row ∂g_i/∂q_i = −e_i·∂C_i/∂q_i vanishes when the distal link
// e_i = P_i − C_i is perpendicular to the path of its circle centre: for a crank (R̲RR, П̲RR)
// crank and link in line, P_i = C_i ± l_i·(C_i − A_i)/|C_i − A_i|; for a slider (P̲RR) the link
// perpendicular to the guide, P_i = C_i ± l_i·n(α_i). A strut (RP̲R) has J_q = −q_i ≠ 0.
// Traced over q_i; a sample is a point of the curve when the other legs reach it in their
// working modes and ranges (and, for 2 DOF, in the design's assembly mode).
//
// Direct (det J_x = 0, 2 DOF): the two leg circles about C_i − B_i are tangent, |C₁′C₂′| =
// ρ₁ + ρ₂ (links stretched in line) or |ρ₁ − ρ₂| (folded). Traced over q₁: C₂′ is where the
// circle of radius ρ about C₁′ meets the path of leg 2's centre (a circle about A₂′ for a
// crank, the guide line for a slider, the fixed point A₂′ of a strut whose ρ₂ = q₂ follows).
// For a 3-DOF platform the curves are those of the map's slice at φ = phi_map (the
// constant-orientation workspace): the inverse ones as above, the direct ones (the three distal
// lines through one point, or parallel) inside the slice, where det J_x changes sign with no
// mode to keep apart: they are contoured over a grid of the slice (directSlice).
#include "planarparallel.h"

#include <cmath>
#include <unordered_map>
#include <limits>
#include <numbers>
#include <optional>

namespace pkm {

namespace {
using planar::cross;
constexpr double pi = std::numbers::pi;
constexpr int curveSamples = 720;
/// Relative slack of the mode and range checks on a curve, where a mode is on its border.
constexpr double loose = 1e-6;

Eigen::Vector2d perp(const Eigen::Vector2d &u)
{
    return {-u.y(), u.x()};
}

Eigen::Vector2d rotated(const Eigen::Vector2d &b, double phi)
{
    const double c = std::cos(phi), s = std::sin(phi);
    return {c * b.x() - s * b.y(), s * b.x() + c * b.y()};
}

/// The leg's working mode at circle `c` and distal end P, dimensionless: > 0 agrees with the
/// leg's, 0 on the border (planar::workingOf with a scale).
double workingValue(const PlanarLeg &leg, const planar::LegCircle &c, const Eigen::Vector2d &P)
{
    switch (leg.type) {
    case LegType::RRR:
    case LegType::PiRR: {
        const double crank = leg.type == LegType::RRR ? leg.crank : leg.lever;
        return leg.working * cross(P - leg.base, c.centre - leg.base) / (crank * (crank + leg.link));
    }
    case LegType::PRR:
        return -leg.working * (P - c.centre).dot(leg.guideDirection()) / leg.link;
    case LegType::RPR:
        return 1.0;
    }
    return 0.0;
}

/// q inside the leg's input range (a crank angle on the turn that lies in it), or nothing.
std::optional<double> inRange(const PlanarLeg &leg, double q)
{
    const Interval &range = leg.inputRange();
    const double slack = loose * std::max(1.0, range.max - range.min);
    if (leg.type == LegType::RRR)
        q += 2.0 * pi * std::ceil((range.min - slack - q) / (2.0 * pi));
    if (!range.contains(q, slack))
        return std::nullopt;
    return range.clamp(q);
}

/// The point of the circle of radius ra about a and rb about b on side `side` of a→b.
bool meet(const Eigen::Vector2d &a, double ra, const Eigen::Vector2d &b, double rb, int side, Eigen::Vector2d &out)
{
    const Eigen::Vector2d between = b - a;
    const double d = between.norm(), scale = ra + rb;
    if (d < 1e-12 * scale || d > scale || d < std::abs(ra - rb))
        return false;
    const Eigen::Vector2d u = between / d;
    const double along = (ra * ra - rb * rb + d * d) / (2.0 * d);
    out = a + along * u + side * std::sqrt(std::max(0.0, ra * ra - along * along)) * perp(u);
    return true;
}

/// Appends the runs of two or more consecutive samples t ∈ [from, to] at which `pointAt`
/// finds a point; `periodic`: a run through t = to goes on at t = from.
template <class PointAt>
void traceRuns(std::vector<SingularCurve> &curves, SingularCurve::Type type, const char *label, const Interval &range,
               PointAt &&pointAt)
{
    const bool periodic = range.max - range.min >= 2.0 * pi * (1.0 - 1e-12);
    std::vector<std::vector<Eigen::Vector2d>> runs(1);
    for (int k = 0; k <= curveSamples; ++k) {
        Eigen::Vector2d point;
        if (pointAt(range.min + (range.max - range.min) * k / curveSamples, point))
            runs.back().push_back(point);
        else if (!runs.back().empty())
            runs.emplace_back();
    }
    if (periodic && runs.size() > 1 && !runs.back().empty() && !runs.front().empty()) {
        runs.back().insert(runs.back().end(), runs.front().begin() + 1, runs.front().end());
        runs.front().clear();
    }
    for (std::vector<Eigen::Vector2d> &run : runs) {
        if (run.size() > 1)
            curves.push_back({type, label, std::move(run)});
    }
}
} // namespace

std::vector<SingularCurve> PlanarParallel::singularCurves() const
{
    const PlanarParallelDesign &d = m_design;
    const int n = d.legCount();
    const double phi = n == 3 ? d.mapPhi : 0.0;
    constexpr double none = std::numeric_limits<double>::quiet_NaN();
    // Is the platform at xy (and φ) a pose of the design with the inputs `known` (NaN: the
    // leg's inverse kinematics gives it)?
    auto belongs = [&](const Eigen::Vector2d &xy, const std::array<double, 3> &known) {
        const Eigen::Vector3d X(xy.x(), xy.y(), phi);
        std::array<planar::LegCircle, 3> c;
        for (int i = 0; i < n; ++i) {
            const PlanarLeg &leg = d.legs[std::size_t(i)];
            const Eigen::Vector2d P = planar::platformPoint(leg, X);
            double q = known[std::size_t(i)];
            if (std::isnan(q) && planar::inverse(leg, P, m_home.inputs[i], q) != planar::Reach::Yes)
                return false;
            c[std::size_t(i)] = planar::circle(leg, q);
            if (!c[std::size_t(i)].valid || workingValue(leg, c[std::size_t(i)], P) < -loose)
                return false;
        }
        if (n == 2) {
            const Eigen::Vector2d p = c[0].centre - d.legs[0].platform, o = c[1].centre - d.legs[1].platform;
            if (cross(o - p, xy - p) * d.assembly < -loose * c[0].radius * c[1].radius)
                return false;
        }
        return true;
    };

    std::vector<SingularCurve> curves;
    // fixed labels (the GUI keeps and translates them)
    static constexpr std::array<std::array<const char *, 2>, 3> crankLabels = {{
        {QT_TRANSLATE_NOOP("core", "leg 1 stretched (crank and link in line)"), QT_TRANSLATE_NOOP("core", "leg 1 folded (crank and link in line)")},
        {QT_TRANSLATE_NOOP("core", "leg 2 stretched (crank and link in line)"), QT_TRANSLATE_NOOP("core", "leg 2 folded (crank and link in line)")},
        {QT_TRANSLATE_NOOP("core", "leg 3 stretched (crank and link in line)"), QT_TRANSLATE_NOOP("core", "leg 3 folded (crank and link in line)")},
    }};
    static constexpr std::array<const char *, 3> guideLabels = {QT_TRANSLATE_NOOP("core", "link 1 ⟂ guide 1"),
                                                                QT_TRANSLATE_NOOP("core", "link 2 ⟂ guide 2"),
                                                                QT_TRANSLATE_NOOP("core", "link 3 ⟂ guide 3")};
    for (int i = 0; i < n; ++i) {
        const PlanarLeg &leg = d.legs[std::size_t(i)];
        if (leg.type == LegType::RPR)
            continue;
        const Eigen::Vector2d offset = rotated(leg.platform, phi);
        for (const int sign : {+1, -1}) {
            const char *label = leg.type == LegType::PRR ? guideLabels[std::size_t(i)] : crankLabels[std::size_t(i)][sign > 0 ? 0 : 1];
            if (leg.type != LegType::PRR && sign < 0 && std::abs((leg.type == LegType::RRR ? leg.crank : leg.lever) - leg.link) < 1e-9 * leg.link)
                continue; // folded with crank = link: P on A, a point
            traceRuns(curves, SingularCurve::Type::Inverse, label, leg.inputRange(), [&](double q, Eigen::Vector2d &xy) {
                const planar::LegCircle c = planar::circle(leg, q);
                if (!c.valid)
                    return false;
                const Eigen::Vector2d w = leg.type == LegType::PRR ? perp(leg.guideDirection())
                                                                   : Eigen::Vector2d((c.centre - leg.base).normalized());
                xy = c.centre + sign * c.radius * w - offset;
                std::array<double, 3> known{none, none, none};
                known[std::size_t(i)] = q;
                return belongs(xy, known);
            });
        }
    }
    if (n == 3) {
        directSlice(curves);
        return curves;
    }

    const PlanarLeg &first = d.legs[0], &second = d.legs[1];
    for (const bool stretched : {true, false}) {
        for (const int branch : {+1, -1}) {
            if (second.type == LegType::RPR && stretched && branch < 0)
                continue; // a strut meets the stretched tangency once
            traceRuns(curves, SingularCurve::Type::Direct, QT_TRANSLATE_NOOP("core", "distal links in line"), first.inputRange(),
                      [&](double q1, Eigen::Vector2d &xy) {
                const planar::LegCircle c1 = planar::circle(first, q1);
                if (!c1.valid)
                    return false;
                const Eigen::Vector2d C1 = c1.centre - first.platform, A2 = second.base - second.platform;
                const double r1 = c1.radius;
                double q2 = none;
                switch (second.type) {
                case LegType::RRR:
                case LegType::PiRR: {
                    const double rho = stretched ? r1 + second.link : std::abs(r1 - second.link);
                    if (rho < 1e-9 * (r1 + second.link))
                        return false;
                    Eigen::Vector2d C2;
                    if (!meet(C1, rho, A2, second.type == LegType::RRR ? second.crank : second.lever, branch, C2))
                        return false;
                    const double psi = std::atan2(C2.y() - A2.y(), C2.x() - A2.x());
                    if (second.type == LegType::RRR) {
                        q2 = psi;
                    } else {
                        const double theta = std::remainder(second.alpha + 0.5 * pi - psi, 2.0 * pi);
                        if (std::abs(theta) >= 0.5 * pi)
                            return false;
                        q2 = planar::pjointDiagonal(second, theta);
                    }
                    break;
                }
                case LegType::PRR: {
                    // |A₂′ + s·u − C₁′|² = ρ²: s² + 2s·u·(A₂′ − C₁′) + |A₂′ − C₁′|² − ρ² = 0
                    const double rho = stretched ? r1 + second.link : std::abs(r1 - second.link);
                    if (rho < 1e-9 * (r1 + second.link))
                        return false;
                    const Eigen::Vector2d u = second.guideDirection(), r = A2 - C1;
                    const double half = u.dot(r), disc = half * half - (r.squaredNorm() - rho * rho);
                    if (disc < 0.0)
                        return false;
                    q2 = -half + branch * std::sqrt(disc);
                    break;
                }
                case LegType::RPR: {
                    // ρ₂ = q₂: |A₂′C₁′| = ρ₁ + q₂, or |ρ₁ − q₂| (q₂ = ρ₁ ± |A₂′C₁′|)
                    const double between = (A2 - C1).norm();
                    q2 = stretched ? between - r1 : r1 + branch * between;
                    break;
                }
                }
                const std::optional<double> held = inRange(second, q2);
                if (!held)
                    return false;
                const planar::LegCircle c2 = planar::circle(second, *held);
                const Eigen::Vector2d C2 = c2.centre - second.platform;
                const double between = (C2 - C1).norm();
                if (!c2.valid || between < 1e-9 * (r1 + c2.radius))
                    return false;
                const Eigen::Vector2d u = (C2 - C1) / between;
                xy = stretched || r1 > c2.radius ? Eigen::Vector2d(C1 + r1 * u) : Eigen::Vector2d(C1 - r1 * u);
                return belongs(xy, {q1, *held, none});
            });
        }
    }
    return curves;
}

void PlanarParallel::directSlice(std::vector<SingularCurve> &curves) const
{
    const double phi = m_design.mapPhi;
    const MapGrid grid = squareGrid(m_bounds, 200);
    const int columns = grid.columns, rows = grid.rows;
    // det J_x over the product of its rows' norms at (x, y, φ): its sign flips across a direct
    // singularity; false where the legs cannot hold the platform
    auto directValue = [&](const Eigen::Vector2d &xy, double &value) {
        const Eigen::Vector3d X(xy.x(), xy.y(), phi);
        Pose pose;
        int culprit = 0;
        if (inverseCheck(X, nullptr, pose.inputs, culprit) != planar::Reach::Yes)
            return false;
        pose.outputs = Eigen::Vector3d(X);
        Eigen::Matrix3d jq, jx;
        jacobianParts(pose, jq, jx);
        const double norms = jx.row(0).norm() * jx.row(1).norm() * jx.row(2).norm();
        value = norms > 0.0 ? jx.determinant() / norms : 0.0;
        return norms > 0.0;
    };
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> node(std::size_t(columns) * std::size_t(rows), nan);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            double v = nan;
            if (!directValue({grid.x(c), grid.y(r)}, v))
                v = nan;
            node[std::size_t(r) * std::size_t(columns) + std::size_t(c)] = v;
        }
    }
    auto at = [&](int c, int r) { return node[std::size_t(r) * std::size_t(columns) + std::size_t(c)]; };
    // the zero on the grid edge from node a to node b, by bisection (the sign change is known)
    std::unordered_map<long long, Eigen::Vector2d> crossings;
    auto crossing = [&](int c0, int r0, int c1, int r1, long long id) {
        if (crossings.count(id))
            return true;
        Eigen::Vector2d a(grid.x(c0), grid.y(r0)), b(grid.x(c1), grid.y(r1));
        double va = at(c0, r0);
        for (int k = 0; k < 48; ++k) {
            const Eigen::Vector2d m = 0.5 * (a + b);
            double vm = 0.0;
            if (!directValue(m, vm))
                return false;
            if ((vm < 0.0) == (va < 0.0)) {
                a = m;
                va = vm;
            } else {
                b = m;
            }
        }
        crossings.emplace(id, 0.5 * (a + b));
        return true;
    };
    const long long vertical = (long long)columns * rows;
    auto horizontalId = [&](int c, int r) { return (long long)r * columns + c; };
    auto verticalId = [&](int c, int r) { return vertical + (long long)r * columns + c; };
    // marching squares: per cell the edges whose ends differ in sign, paired in order
    std::vector<std::pair<long long, long long>> segments;
    for (int r = 0; r + 1 < rows; ++r) {
        for (int c = 0; c + 1 < columns; ++c) {
            const double v00 = at(c, r), v10 = at(c + 1, r), v01 = at(c, r + 1), v11 = at(c + 1, r + 1);
            if (std::isnan(v00) || std::isnan(v10) || std::isnan(v01) || std::isnan(v11))
                continue;
            std::array<long long, 4> found{};
            int count = 0;
            auto edge = [&](double va, double vb, int c0, int r0, int c1, int r1, long long id) {
                if ((va < 0.0) != (vb < 0.0) && crossing(c0, r0, c1, r1, id))
                    found[std::size_t(count++)] = id;
            };
            edge(v00, v10, c, r, c + 1, r, horizontalId(c, r));
            edge(v10, v11, c + 1, r, c + 1, r + 1, verticalId(c + 1, r));
            edge(v01, v11, c, r + 1, c + 1, r + 1, horizontalId(c, r + 1));
            edge(v00, v01, c, r, c, r + 1, verticalId(c, r));
            if (count >= 2)
                segments.emplace_back(found[0], found[1]);
            if (count == 4)
                segments.emplace_back(found[2], found[3]);
        }
    }
    // chain the segments into polylines through their shared crossings
    std::unordered_map<long long, std::vector<std::size_t>> touching;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        touching[segments[i].first].push_back(i);
        touching[segments[i].second].push_back(i);
    }
    std::vector<bool> used(segments.size(), false);
    auto extend = [&](std::vector<long long> &chain) {
        for (;;) {
            const long long end = chain.back();
            bool grown = false;
            for (const std::size_t i : touching[end]) {
                if (used[i])
                    continue;
                used[i] = true;
                chain.push_back(segments[i].first == end ? segments[i].second : segments[i].first);
                grown = true;
                break;
            }
            if (!grown)
                return;
        }
    };
    for (std::size_t i = 0; i < segments.size(); ++i) {
        if (used[i])
            continue;
        used[i] = true;
        std::vector<long long> forward{segments[i].first, segments[i].second};
        extend(forward);
        std::vector<long long> backward{segments[i].first};
        extend(backward);
        SingularCurve curve{SingularCurve::Type::Direct, QT_TRANSLATE_NOOP("core", "distal lines through one point"), {}};
        for (auto k = backward.rbegin(); k != backward.rend(); ++k)
            curve.points.push_back(crossings.at(*k));
        for (std::size_t k = 1; k < forward.size(); ++k)
            curve.points.push_back(crossings.at(forward[k]));
        if (curve.points.size() > 1)
            curves.push_back(std::move(curve));
    }
}

} // namespace pkm
