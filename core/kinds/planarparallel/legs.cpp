// The leg library of the planar parallel mechanism: each leg's circle at a fixed input, its
// inverse kinematics in closed form, its working mode and its inverse-singularity margin.
#include "planarparallel.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace pkm::planar {

namespace {
constexpr double pi = std::numbers::pi;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
/// Relative tolerance: circles that touch up to it meet, limits hold up to it.
constexpr double tolerance = 1e-9;

Eigen::Vector2d perp(const Eigen::Vector2d &u)
{
    return {-u.y(), u.x()};
}

int sign(double v, double zero)
{
    return v > zero ? 1 : (v < -zero ? -1 : 0);
}

/// The elbow of a crank of length `crank` at A whose tip is `link` from P, on side `side` of
/// the directed line A→P (+1: left, the five-bar's working mode "left").
Reach elbow(const Eigen::Vector2d &A, double crank, const Eigen::Vector2d &P, double link, int side, Eigen::Vector2d &E)
{
    const Eigen::Vector2d between = P - A;
    const double distance = between.norm();
    const double scale = crank + link;
    if (distance < tolerance * scale)
        return Reach::Undetermined;
    if (distance > scale * (1.0 + tolerance))
        return Reach::TooFar;
    if (distance < std::abs(crank - link) - tolerance * scale)
        return Reach::TooNear;
    const Eigen::Vector2d u = between / distance;
    const double along = (crank * crank - link * link + distance * distance) / (2.0 * distance);
    const double across = std::sqrt(std::max(0.0, crank * crank - along * along));
    E = A + along * u + side * across * perp(u);
    return Reach::Yes;
}
} // namespace

double pjointAngle(const PlanarLeg &leg, double d)
{
    // (3–5): sin θ = (d² − a²(1 + k²)) / (2a²k), θ on the branch −90° < θ < 90°
    const double a = leg.lever, k = leg.ratio;
    const double s = (d * d - a * a * (1.0 + k * k)) / (2.0 * a * a * k);
    if (!(std::abs(s) <= 1.0))
        return nan;
    return std::asin(s);
}

double pjointDiagonal(const PlanarLeg &leg, double theta)
{
    // (2) d = a·√(1 + k² + 2k·sin θ)
    const double k = leg.ratio;
    return leg.lever * std::sqrt(std::max(0.0, 1.0 + k * k + 2.0 * k * std::sin(theta)));
}

double pjointJacobian(const PlanarLeg &leg, double theta)
{
    // (7) J = ∂d/∂θ = a²k·cos θ / d
    const double d = pjointDiagonal(leg, theta);
    return d > 0.0 ? leg.lever * leg.lever * leg.ratio * std::cos(theta) / d : 0.0;
}

LegCircle circle(const PlanarLeg &leg, double q)
{
    LegCircle c;
    switch (leg.type) {
    case LegType::RRR: {
        const Eigen::Vector2d u = direction(q);
        c.centre = leg.base + leg.crank * u;
        c.centreRate = leg.crank * perp(u);
        c.radius = leg.link;
        break;
    }
    case LegType::PRR:
        c.centre = leg.base + q * leg.guideDirection();
        c.centreRate = leg.guideDirection();
        c.radius = leg.link;
        break;
    case LegType::RPR:
        c.centre = leg.base;
        c.radius = q;
        c.radiusRate = 1.0;
        break;
    case LegType::PiRR: {
        // the crank BA of the П-joint points along ψ = α + 90° − θ (A = B + a·(sin θ, cos θ)
        // in the П-joint's own frame, whose x axis is the base line OB along α)
        c.theta = pjointAngle(leg, q);
        c.valid = std::isfinite(c.theta);
        const double theta = c.valid ? c.theta : 0.0;
        const Eigen::Vector2d u = direction(leg.alpha + 0.5 * pi - theta);
        c.centre = leg.base + leg.lever * u;
        c.centreRate = -leg.lever * perp(u); // ∂/∂θ
        c.radius = leg.link;
        c.pjointRate = pjointJacobian(leg, theta);
        break;
    }
    }
    return c;
}

Reach inverse(const PlanarLeg &leg, const Eigen::Vector2d &P, double reference, double &q)
{
    const Interval &range = leg.inputRange();
    switch (leg.type) {
    case LegType::RRR: {
        Eigen::Vector2d E;
        if (const Reach r = elbow(leg.base, leg.crank, P, leg.link, leg.working, E); r != Reach::Yes)
            return r;
        const double angle = std::atan2(E.y() - leg.base.y(), E.x() - leg.base.x());
        // the representative of the angle inside the range nearest to the reference
        const double slack = tolerance * (1.0 + std::abs(range.max - range.min));
        double best = nan;
        const double first = angle + 2.0 * pi * std::ceil((range.min - slack - angle) / (2.0 * pi));
        for (double candidate = first; candidate <= range.max + slack; candidate += 2.0 * pi) {
            if (std::isnan(best) || std::abs(candidate - reference) < std::abs(best - reference))
                best = candidate;
        }
        if (std::isnan(best))
            return Reach::Range;
        q = range.clamp(best);
        return Reach::Yes;
    }
    case LegType::PiRR: {
        Eigen::Vector2d E;
        if (const Reach r = elbow(leg.base, leg.lever, P, leg.link, leg.working, E); r != Reach::Yes)
            return r;
        const double psi = std::atan2(E.y() - leg.base.y(), E.x() - leg.base.x());
        const double theta = std::remainder(leg.alpha + 0.5 * pi - psi, 2.0 * pi);
        if (std::abs(theta) >= 0.5 * pi)
            return Reach::Range; // the parallelogram cannot turn its crank there
        const double d = pjointDiagonal(leg, theta);
        const double slack = tolerance * std::max(1.0, range.max);
        if (!range.contains(d, slack))
            return Reach::Range;
        q = range.clamp(d);
        return Reach::Yes;
    }
    case LegType::PRR: {
        // the MOMA document's (7–9): q = B + β·√(B² − C), B² − C = l² − (distance from the guide)²
        const Eigen::Vector2d u = leg.guideDirection(), r = P - leg.base;
        const double across = cross(u, r);
        const double D = leg.link * leg.link - across * across;
        if (D < -tolerance * leg.link * leg.link)
            return Reach::TooFar;
        const double value = u.dot(r) + leg.working * std::sqrt(std::max(0.0, D));
        const double slack = 1e-7 * std::max({1.0, range.max - range.min, leg.link});
        if (!range.contains(value, slack))
            return Reach::Range;
        q = range.clamp(value);
        return Reach::Yes;
    }
    case LegType::RPR: {
        const double value = (P - leg.base).norm();
        if (value < tolerance * std::max(1.0, range.max))
            return Reach::Undetermined;
        if (!range.contains(value, tolerance * std::max(1.0, range.max)))
            return Reach::Range;
        q = range.clamp(value);
        return Reach::Yes;
    }
    }
    return Reach::Undetermined;
}

int workingOf(const PlanarLeg &leg, double q, const Eigen::Vector2d &P)
{
    const LegCircle c = circle(leg, q);
    switch (leg.type) {
    case LegType::RRR:
    case LegType::PiRR: {
        const double crank = leg.type == LegType::RRR ? leg.crank : leg.lever;
        return sign(cross(P - leg.base, c.centre - leg.base), tolerance * crank * (crank + leg.link));
    }
    case LegType::PRR:
        // (P − Z)·u = B − q = −β·√(B² − C): the link's component along the guide is −β
        return -sign((P - c.centre).dot(leg.guideDirection()), tolerance * leg.link);
    case LegType::RPR:
        return leg.working;
    }
    return 0;
}

double inverseMargin(const PlanarLeg &leg, double q, const Eigen::Vector2d &P)
{
    const LegCircle c = circle(leg, q);
    const Eigen::Vector2d e = P - c.centre;
    const double length = e.norm();
    if (!(length > 0.0))
        return 0.0;
    switch (leg.type) {
    case LegType::RRR:
    case LegType::PiRR:
        // |sin| of the angle between the crank and the distal link (the five-bar's margin)
        return std::abs(cross((c.centre - leg.base).normalized(), e / length));
    case LegType::PRR:
        // |cos| between link and guide (MOMA's margin)
        return std::abs(leg.guideDirection().dot(e)) / length;
    case LegType::RPR:
        return 1.0; // J_q = −q never vanishes for a strut of positive length
    }
    return 0.0;
}

Eigen::Vector2d platformPoint(const PlanarLeg &leg, const Eigen::Vector3d &X)
{
    const Eigen::Vector2d &b = leg.platform;
    if (X.z() == 0.0) // a 2-DOF platform keeps φ = 0: the same numbers without the sine and cosine
        return {X.x() + b.x(), X.y() + b.y()};
    const double c = std::cos(X.z()), s = std::sin(X.z());
    return {X.x() + c * b.x() - s * b.y(), X.y() + s * b.x() + c * b.y()};
}

} // namespace pkm::planar
