// The four-bar's direct and inverse kinematics (docs/mathematics.md, section 4): the rocker
// angle from the crank angle in the design's branch, and the crank angle from the rocker angle.

#include "fourbar.h"
#include "fourbarinternal.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

namespace {
using fourbar::cross;
using fourbar::deg;
using fourbar::degOutside;
using fourbar::deltaOf;
using fourbar::mm;
using fourbar::nan;
using fourbar::perp;
using fourbar::pi;
using fourbar::rockerJoint;
using fourbar::scaleOf;
} // namespace

// -- kinematics ----------------------------------------------------------------------------

Result<Pose> FourBar::solveDirect(const Coordinates &inputs, const Pose *) const
{
    const FourBarDesign &d = m_design;
    const double alpha = inputs[0];
    if (!std::isfinite(alpha))
        return Failure{FailureKind::OutOfRange, "alpha", text::translate("core", "alpha must be a finite number.")};
    if (!m_alphaRange.contains(alpha, 1e-12)) {
        if (m_fullTurn) {
            return Failure{FailureKind::OutOfRange, "alpha",
                           text::format(text::translate("core", "alpha = %1 is outside [0°, 360°]: the crank turns fully, "
                                                                "give its angle within one turn."),
                                        {degOutside(alpha, 0.0, 2.0 * pi)})};
        }
        const bool above = alpha > m_alphaRange.max;
        return Failure{FailureKind::OutOfRange, "alpha",
                       text::format(text::translate("core", "alpha = %1 is outside the range of the crank of this %2 "
                                                            "linkage, [%3, %4]: %5."),
                                    {degOutside(alpha, m_alphaRange.min, m_alphaRange.max),
                                     text::label(fourbar::grashofName(grashof(d))), deg(m_alphaRange.min),
                                     deg(m_alphaRange.max), limitReason(above ? m_alphaRange.max : m_alphaRange.min)})};
    }
    const double a = m_alphaRange.clamp(alpha);
    const fourbar::Position p = fourbar::position(d, a);
    if (!p.valid) {
        if ((Eigen::Vector2d(d.ground, 0.0) - p.B).norm() < 1e-9 * scaleOf(d)) {
            return Failure{FailureKind::Singular, "alpha",
                           text::format(text::translate("core", "At alpha = %1 the crank joint B lies on D: the rocker's "
                                                                "angle is undetermined."),
                                        {deg(a)})};
        }
        return Failure{FailureKind::Unreachable, "alpha",
                       text::format(text::translate("core", "The loop ABCD does not close at alpha = %1."), {deg(a)})};
    }
    Pose pose;
    pose.inputs.resize(1);
    pose.inputs << a;
    pose.outputs.resize(1);
    pose.outputs << m_deltaRange.clamp(wrapDelta(deltaOf(d, p.C)));
    pose.mode = d.branch;
    return pose;
}

Result<Pose> FourBar::solveInverse(const Coordinates &outputs, const Pose *near) const
{
    const FourBarDesign &d = m_design;
    const double delta = outputs[0];
    if (!std::isfinite(delta))
        return Failure{FailureKind::OutOfRange, "delta", text::translate("core", "delta must be a finite number.")};
    if (!m_deltaRange.contains(delta, 1e-12)) {
        return Failure{FailureKind::OutOfRange, "delta",
                       text::format(d.branch == fourbar::crossed
                                        ? text::translate("core", "delta = %1 is outside the range the rocker reaches in "
                                                                  "the crossed branch, [%2, %3]: at its ends the crank "
                                                                  "and the coupler are in line, or the crank is at its "
                                                                  "own limit.")
                                        : text::translate("core", "delta = %1 is outside the range the rocker reaches in "
                                                                  "the open branch, [%2, %3]: at its ends the crank and "
                                                                  "the coupler are in line, or the crank is at its own "
                                                                  "limit."),
                                    {degOutside(delta, m_deltaRange.min, m_deltaRange.max), deg(m_deltaRange.min),
                                     deg(m_deltaRange.max)})};
    }
    const double x = m_deltaRange.clamp(delta);
    const Eigen::Vector2d C = rockerJoint(d, x), D(d.ground, 0.0);
    const double r = C.norm();
    const double a = d.crank, b = d.coupler, scale = scaleOf(d);
    if (r < 1e-12 * scale) {
        return Failure{FailureKind::Singular, "delta",
                       text::format(text::translate("core", "At delta = %1 the rocker joint C lies on A: the crank angle "
                                                            "is undetermined."),
                                    {deg(x)})};
    }
    // circle (A, AB) ∩ circle (C, BC)
    const double along = (a * a - b * b + r * r) / (2.0 * r);
    const double across2 = a * a - along * along;
    if (across2 < -1e-12 * a * a) {
        return Failure{FailureKind::Unreachable, "delta",
                       text::format(text::translate("core", "The crank cannot reach the coupler at delta = %1: |AC| = %2 "
                                                            "is not between |AB − BC| and AB + BC."),
                                    {deg(x), mm(r)})};
    }
    const Eigen::Vector2d u = C / r;
    const double across = std::sqrt(std::max(0.0, across2));
    const double reference = near && near->inputs.size() == 1 && std::isfinite(near->inputs[0]) ? near->inputs[0]
                                                                                                 : m_home.inputs[0];
    double chosen = nan;
    for (const double side : {1.0, -1.0}) {
        const Eigen::Vector2d B = along * u + side * across * perp(u);
        // in the design's branch: C on side σ of B→D
        if (d.branch * cross(D - B, C - B) < -1e-9 * scale * scale)
            continue;
        const double raw = std::atan2(B.y(), B.x());
        for (int k = -1; k <= 2; ++k) {
            const double alpha = raw + 2.0 * pi * k;
            if (!m_alphaRange.contains(alpha, 1e-12))
                continue;
            if (std::isnan(chosen) || std::abs(alpha - reference) < std::abs(chosen - reference))
                chosen = alpha;
        }
    }
    if (std::isnan(chosen)) {
        return Failure{FailureKind::Unreachable, "delta",
                       text::format(d.branch == fourbar::crossed
                                        ? text::translate("core", "The rocker reaches delta = %1 only in the other "
                                                                  "assembly branch; this design is crossed.")
                                        : text::translate("core", "The rocker reaches delta = %1 only in the other "
                                                                  "assembly branch; this design is open."),
                                    {deg(x)})};
    }
    Pose pose;
    pose.inputs.resize(1);
    pose.inputs << m_alphaRange.clamp(chosen);
    pose.outputs.resize(1);
    pose.outputs << x;
    pose.mode = d.branch;
    return pose;
}

} // namespace pkm
