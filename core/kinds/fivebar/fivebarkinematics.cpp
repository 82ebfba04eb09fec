// The five-bar's direct and inverse kinematics (docs/mathematics.md, section 5): the checks of
// a pose against the design's modes and crank ranges, the words that explain a refusal, and the
// solvers built on them.

#include "fivebar.h"
#include "fivebarinternal.h"

#include "text.h"

#include <algorithm>
#include <cmath>

namespace pkm {

namespace {
using fivebar::cross;
using fivebar::deg;
using fivebar::legText;
using fivebar::LegText;
using fivebar::pi;
using fivebar::rangeText;
using fivebar::representative;
using fivebar::solverTolerance;

std::string pointText(const Eigen::Vector2d &p)
{
    // to the hundredth, as the fields and the values panel give a position
    return text::format(text::translate("core", "(%1, %2) mm"), {text::number(p.x(), 2), text::number(p.y(), 2)});
}

/// "B left of A→C": where `point` lies from the directed `line`, for a sentence.
std::string sidePhrase(int side, std::string_view point, std::string_view line)
{
    return side == fivebar::right ? text::format(text::translate("core", "%1 right of %2"), {point, line})
                                  : text::format(text::translate("core", "%1 left of %2"), {point, line});
}
} // namespace

// -- kinematics ----------------------------------------------------------------------------

FiveBar::Check FiveBar::checkDirect(double theta1, double theta4, double tolerance) const
{
    const FiveBarDesign &d = m_design;
    Check check;
    check.thetas = {theta1, theta4};
    check.elbows = {fivebar::elbow(d, 0, theta1), fivebar::elbow(d, 1, theta4)};
    // C on side σ of B→D (no division but by |BD|²: as MOMA's, docs/mathematics.md, the same circles)
    switch (fivebar::circleIntersection(check.elbows[0], d.link[0], check.elbows[1], d.link[1], d.assembly, check.C,
                                        tolerance)) {
    case fivebar::Meet::TooFar: check.reason = Check::Reason::LinksApart; return check;
    case fivebar::Meet::TooNear: check.reason = Check::Reason::LinksClose; return check;
    case fivebar::Meet::Concentric: check.reason = Check::Reason::ElbowsMeet; return check;
    case fivebar::Meet::Yes: break;
    }
    // each leg in its working mode: sign k_i = −working_i (0 at the singularity is both)
    for (int leg = 0; leg < 2; ++leg) {
        const double k = cross(check.elbows[leg] - fivebar::groundJoint(d, leg), check.C - check.elbows[leg]);
        if (d.working[leg] * k > tolerance * d.crank[leg] * d.link[leg]) {
            check.reason = Check::Reason::WorkingMode;
            check.leg = leg;
            return check;
        }
    }
    return check;
}

FiveBar::Check FiveBar::checkInverse(const Eigen::Vector2d &C, double tolerance,
                                     const std::array<double, 2> &reference) const
{
    const FiveBarDesign &d = m_design;
    Check check;
    check.C = C;
    for (int leg = 0; leg < 2; ++leg) {
        check.leg = leg;
        const Eigen::Vector2d G = fivebar::groundJoint(d, leg);
        Eigen::Vector2d &P = check.elbows[leg];
        // the elbow on side working_i of G_i→C
        switch (fivebar::circleIntersection(G, d.crank[leg], C, d.link[leg], d.working[leg], P, tolerance)) {
        case fivebar::Meet::TooFar: check.reason = Check::Reason::LegTooShort; return check;
        case fivebar::Meet::TooNear: check.reason = Check::Reason::LegTooLong; return check;
        case fivebar::Meet::Concentric: check.reason = Check::Reason::OnGroundJoint; return check;
        case fivebar::Meet::Yes: break;
        }
        const Interval &range = d.range[leg];
        const double raw = std::atan2(P.y() - G.y(), P.x() - G.x());
        check.thetas[leg] = representative(raw, range, reference[leg], tolerance);
        if (std::isnan(check.thetas[leg])) {
            check.reason = Check::Reason::CrankRange;
            check.theta = raw + 2.0 * pi * std::round((0.5 * (range.min + range.max) - raw) / (2.0 * pi));
            return check;
        }
    }
    const std::array<Eigen::Vector2d, 2> &e = check.elbows;
    if (d.assembly * cross(e[1] - e[0], C - e[0]) < -tolerance * d.link[0] * d.link[1])
        check.reason = Check::Reason::AssemblyMode;
    return check;
}

Failure FiveBar::explain(const Check &check, bool direct, const std::string &culprit) const
{
    const FiveBarDesign &d = m_design;
    const LegText &t = legText[std::size_t(check.leg)];
    const std::string theta1 = deg(check.thetas[0]), theta4 = deg(check.thetas[1]);
    const std::string point = pointText(check.C);
    const double distance = (check.C - fivebar::groundJoint(d, check.leg)).norm();
    const double bd = (check.elbows[1] - check.elbows[0]).norm();
    const double a = d.crank[check.leg], b = d.link[check.leg];
    using R = Check::Reason;
    switch (check.reason) {
    case R::LinksApart:
        return Failure{FailureKind::Unreachable, culprit,
                       text::format(text::translate("core", "At theta1 = %1, theta4 = %2 the distal links cannot meet: "
                                                            "|BD| = %3 is more than BC + CD = %4 (past the dead point "
                                                            "where BC and CD are stretched in line, a direct singularity)."),
                                    {theta1, theta4, text::millimetres(bd), text::millimetres(d.link[0] + d.link[1])})};
    case R::LinksClose:
        return Failure{FailureKind::Unreachable, culprit,
                       text::format(text::translate("core", "At theta1 = %1, theta4 = %2 the distal links cannot meet: "
                                                            "|BD| = %3 is less than |BC − CD| = %4 (past the dead point "
                                                            "where BC and CD fold in line, a direct singularity)."),
                                    {theta1, theta4, text::millimetres(bd),
                                     text::millimetres(std::abs(d.link[0] - d.link[1]))})};
    case R::ElbowsMeet:
        return Failure{FailureKind::Singular, culprit,
                       text::format(text::translate("core", "At theta1 = %1, theta4 = %2 the elbows B and D coincide and "
                                                            "BC = CD: the position of C is undetermined."),
                                    {theta1, theta4})};
    case R::WorkingMode:
        return Failure{FailureKind::Unreachable, direct ? culprit : t.working,
                       text::format(text::translate("core", "At theta1 = %1, theta4 = %2 leg %3 would be in its other "
                                                            "working mode (%4): crank %5 and link %6 pass through in line "
                                                            "(an inverse singularity) on the way; switch %7 to go on."),
                                    {theta1, theta4, t.number,
                                     sidePhrase(-d.working[check.leg], t.elbow, joinText({t.ground, "→C"})), t.crank,
                                     t.link, t.working})};
    case R::LegTooShort: {
        // with the decimals that show the difference: a point a hair beyond the reach is not
        // "200 mm from A, more than 200 mm"
        const auto [far, reach] = text::millimetresApart(distance, a + b);
        return Failure{FailureKind::Unreachable, culprit,
                       text::format(text::translate("core", "C cannot reach %1: it lies %2 from %3, more than %4 + %5 = %6."),
                                    {point, far, t.ground, t.crank, t.link, reach})};
    }
    case R::LegTooLong: {
        const auto [near, reach] = text::millimetresApart(distance, std::abs(a - b));
        return Failure{FailureKind::Unreachable, culprit,
                       text::format(text::translate("core", "C cannot reach %1: it lies %2 from %3, less than |%4 − %5| = %6."),
                                    {point, near, t.ground, t.crank, t.link, reach})};
    }
    case R::OnGroundJoint:
        return Failure{FailureKind::Singular, culprit,
                       text::format(text::translate("core", "C = %1 lies on %2 and %3 = %4: the crank angle %5 is undetermined."),
                                    {point, t.ground, t.crank, t.link, t.theta})};
    case R::CrankRange:
        return Failure{FailureKind::OutOfRange, t.theta,
                       text::format(text::translate("core", "C cannot reach %1: crank %2 would have to be at %3 = %4, "
                                                            "outside its range %5."),
                                    {point, t.crank, t.theta, deg(check.theta), rangeText(d.range[check.leg])})};
    case R::AssemblyMode:
        return Failure{FailureKind::Unreachable, culprit,
                       text::format(text::translate("core", "C cannot reach %1 in this assembly mode (%2): it would cross "
                                                            "the line BD, where the distal links are in line (a direct "
                                                            "singularity); switch to the other assembly mode to go on."),
                                    {point, sidePhrase(d.assembly, "C", "B→D")})};
    case R::None: break;
    }
    return Failure{FailureKind::Unreachable, culprit, text::translate("core", "No failure.")};
}

std::array<double, 2> FiveBar::referenceAngles(const Pose *near) const
{
    if (near && near->inputs.size() == 2 && near->inputs.allFinite())
        return {near->inputs[0], near->inputs[1]};
    if (m_home.inputs.size() == 2)
        return {m_home.inputs[0], m_home.inputs[1]};
    const std::array<Interval, 2> &r = m_design.range;
    return {0.5 * (r[0].min + r[0].max), 0.5 * (r[1].min + r[1].max)};
}

namespace {
/// The variable a failure is about: the one of the pair that differs from `near`'s (the one
/// the user moved), else the first.
std::string movedVariable(const Coordinates &values, const Coordinates *near, const char *first, const char *second)
{
    const bool secondMoved = near && near->size() == 2 && values[0] == (*near)[0] && values[1] != (*near)[1];
    return secondMoved ? second : first;
}

Pose poseOf(const FiveBar::Check &check)
{
    Pose pose;
    pose.inputs.resize(2);
    pose.inputs << check.thetas[0], check.thetas[1];
    pose.outputs.resize(2);
    pose.outputs << check.C.x(), check.C.y();
    return pose;
}
} // namespace

Result<Pose> FiveBar::solveDirect(const Coordinates &inputs, const Pose *near) const
{
    for (int leg = 0; leg < 2; ++leg) {
        const LegText &t = legText[std::size_t(leg)];
        const Interval &range = m_design.range[leg];
        if (!std::isfinite(inputs[leg]))
            return Failure{FailureKind::OutOfRange, t.theta,
                           text::format(text::translate("core", "%1 must be a finite number."), {t.theta})};
        if (!range.contains(inputs[leg], 1e-12)) {
            return Failure{FailureKind::OutOfRange, t.theta,
                           fivebar::fullTurn(range)
                               ? text::format(text::translate("core", "%1 = %2 is outside the range of crank %3, %4: the "
                                                                      "crank turns fully, give its angle within it."),
                                              {t.theta, fivebar::degOutside(inputs[leg], range), t.crank, rangeText(range)})
                               : text::format(text::translate("core", "%1 = %2 is outside the range of crank %3, %4."),
                                              {t.theta, fivebar::degOutside(inputs[leg], range), t.crank, rangeText(range)})};
        }
    }
    const std::array<Interval, 2> &r = m_design.range;
    const Check check = checkDirect(r[0].clamp(inputs[0]), r[1].clamp(inputs[1]), solverTolerance);
    if (!check.ok())
        return explain(check, true, movedVariable(inputs, near ? &near->inputs : nullptr, "theta1", "theta4"));
    return poseOf(check);
}

Result<Pose> FiveBar::solveInverse(const Coordinates &outputs, const Pose *near) const
{
    for (int i = 0; i < 2; ++i) {
        if (!std::isfinite(outputs[i])) {
            const std::string name = i == 0 ? "x" : "y";
            return Failure{FailureKind::OutOfRange, name,
                           text::format(text::translate("core", "%1 must be a finite number."), {name})};
        }
    }
    const Check check = checkInverse(outputs.head<2>(), solverTolerance, referenceAngles(near));
    if (!check.ok())
        return explain(check, false, movedVariable(outputs, near ? &near->outputs : nullptr, "x", "y"));
    return poseOf(check);
}

} // namespace pkm
