#include "fivebar.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
/// Relative tolerance of the solvers: circles that touch up to it meet, modes hold up to it.
constexpr double solverTolerance = 1e-9;
constexpr Unit millimetre4{QT_TRANSLATE_NOOP("core", "mm⁴"), 1.0};
constexpr Unit radianPerMillimetre2{QT_TRANSLATE_NOOP("core", "rad²/mm²"), 1.0};

/// The names of a leg's parts, for parameters and messages.
struct LegText {
    const char *number, *ground, *elbow, *crank, *link, *theta, *working, *thetaMin, *thetaMax;
};
constexpr std::array<LegText, 2> legText = {{
    {"1", "A", "B", "AB", "BC", "theta1", "working1", "theta1_min", "theta1_max"},
    {"2", "E", "D", "DE", "CD", "theta4", "working2", "theta4_min", "theta4_max"},
}};

double cross(const Eigen::Vector2d &u, const Eigen::Vector2d &v)
{
    return u.x() * v.y() - u.y() * v.x();
}

Eigen::Vector2d perp(const Eigen::Vector2d &u)
{
    return {-u.y(), u.x()};
}

/// An angle for a message: "12.5°".
std::string deg(double radians)
{
    return joinText({text::number(radians / units::degree, 3), "°"});
}

std::string pointText(const Eigen::Vector2d &p)
{
    return text::format(text::translate("core", "(%1, %2) mm"), {text::number(p.x(), 3), text::number(p.y(), 3)});
}

std::string rangeText(const Interval &range)
{
    return text::format(text::translate("core", "[%1, %2]"), {deg(range.min), deg(range.max)});
}

/// "B left of A→C": where `point` lies from the directed `line`, for a sentence.
std::string sidePhrase(int side, std::string_view point, std::string_view line)
{
    return side == fivebar::right ? text::format(text::translate("core", "%1 right of %2"), {point, line})
                                  : text::format(text::translate("core", "%1 left of %2"), {point, line});
}

double scaleOf(const FiveBarDesign &d)
{
    return std::max({d.ground, d.crank[0], d.crank[1], d.link[0], d.link[1]});
}

/// Of the angles raw + 2πk inside `range` (up to `tolerance`, rad), the one nearest
/// `reference`, clamped into the range; NaN when there is none.
double representative(double raw, const Interval &range, double reference, double tolerance)
{
    double chosen = nan;
    for (int k = -2; k <= 2; ++k) {
        const double theta = raw + 2.0 * pi * k;
        const bool nearer = std::isnan(chosen) || std::abs(theta - reference) < std::abs(chosen - reference);
        if (range.contains(theta, tolerance) && nearer)
            chosen = theta;
    }
    return std::isnan(chosen) ? nan : range.clamp(chosen);
}

/// The vectors of a pose the Jacobians and the margins are made of.
struct Vectors {
    std::array<Eigen::Vector2d, 2> crank; ///< P_i − G_i
    std::array<Eigen::Vector2d, 2> link;  ///< C − P_i (the rows of J_x)
    std::array<double, 2> k{};            ///< J_q's diagonal
    double detJx = 0.0;                   ///< (C − B)×(C − D)
};

Vectors vectorsOf(const FiveBarDesign &d, const std::array<Eigen::Vector2d, 2> &elbows, const Eigen::Vector2d &C)
{
    Vectors v;
    for (int leg = 0; leg < 2; ++leg) {
        v.crank[leg] = elbows[leg] - fivebar::groundJoint(d, leg);
        v.link[leg] = C - elbows[leg];
        v.k[leg] = cross(v.crank[leg], v.link[leg]);
    }
    v.detJx = cross(v.link[0], v.link[1]);
    return v;
}

Vectors vectorsOf(const FiveBarDesign &d, const Pose &pose)
{
    return vectorsOf(d, {fivebar::elbow(d, 0, pose.inputs[0]), fivebar::elbow(d, 1, pose.inputs[1])},
                     pose.outputs.head<2>());
}

/// The scale-free margins of a pose: the smaller |sin| of the elbow angles, |k_i|/(a_i·b_i)
/// (inverse), and the |sin| of the angle between the distal links (direct).
std::pair<double, double> marginsOf(const FiveBarDesign &d, const Vectors &v)
{
    const double leg1 = std::abs(v.k[0]) / (d.crank[0] * d.link[0]), leg2 = std::abs(v.k[1]) / (d.crank[1] * d.link[1]);
    return {std::min(leg1, leg2), std::abs(v.detJx) / (d.link[0] * d.link[1])};
}
} // namespace

// -- closed forms --------------------------------------------------------------------------

namespace fivebar {

const char *sideName(int side)
{
    return side == right ? "right" : "left";
}

bool fullTurn(const Interval &range)
{
    return range.max - range.min >= 2.0 * pi * (1.0 - 1e-12);
}

Eigen::Vector2d groundJoint(const FiveBarDesign &design, int leg)
{
    return {leg == 0 ? 0.0 : design.ground, 0.0};
}

Eigen::Vector2d elbow(const FiveBarDesign &design, int leg, double theta)
{
    return groundJoint(design, leg) + design.crank[leg] * Eigen::Vector2d(std::cos(theta), std::sin(theta));
}

double constraint(const FiveBarDesign &design, int leg, double theta, const Eigen::Vector2d &C)
{
    return (C - elbow(design, leg, theta)).squaredNorm() - design.link[leg] * design.link[leg];
}

double inputJacobian(const FiveBarDesign &design, int leg, double theta, const Eigen::Vector2d &C)
{
    const Eigen::Vector2d P = elbow(design, leg, theta);
    return cross(P - groundJoint(design, leg), C - P);
}

Meet circleIntersection(const Eigen::Vector2d &p, double rp, const Eigen::Vector2d &q, double rq, int side,
                        Eigen::Vector2d &X, double tolerance)
{
    const Eigen::Vector2d g = q - p;
    const double e2 = g.squaredNorm(), e = std::sqrt(e2);
    const double sum = rp + rq, difference = std::abs(rp - rq);
    if (e <= tolerance * sum)
        return difference <= tolerance * sum ? Meet::Concentric : Meet::TooNear;
    if (e > sum * (1.0 + tolerance))
        return Meet::TooFar;
    if (e < difference - tolerance * sum)
        return Meet::TooNear;
    // measured along p→q and across it, dividing by |pq|² only: 16·area² of the triangle is
    // ((rp + rq)² − e²)(e² − (rp − rq)²), which does not cancel where the circles touch
    const double along = rp * rp - rq * rq + e2;
    const double across = std::sqrt(std::max(0.0, (sum * sum - e2) * (e2 - difference * difference)));
    X = p + (along * g + side * across * perp(g)) / (2.0 * e2);
    return Meet::Yes;
}

} // namespace fivebar

// -- design --------------------------------------------------------------------------------

namespace {
/// A mode is a side: exactly +1 (left) or −1 (right).
Result<double> sideRule(const ParameterInfo &info, double value)
{
    if (value != 1.0 && value != -1.0) {
        return Failure{FailureKind::InvalidParameter, info.name,
                       text::format(text::translate("core", "%1 = %2 is invalid: it must be +1 (left) or -1 (right)."),
                                    {info.name, text::number(value)})};
    }
    return value;
}
} // namespace

const ParameterTable<FiveBarDesign> &FiveBar::table()
{
    using T = ParameterTable<FiveBarDesign>;
    using D = FiveBarDesign;
    static const T table = [] {
        const Interval positive{0.0, 1e5};
        const Interval turn{-2.0 * pi, 2.0 * pi};
        const Interval sign{-1.0, 1.0};
        const Unit length = units::millimetre, angle = units::angle;
        using G = ParameterGroup;
        // the names are keys (files, the command line); the GUI shows them translated
        const std::vector<std::pair<std::string, double>> sides = {{QT_TRANSLATE_NOOP("core", "left"), 1.0},
                                                                   {QT_TRANSLATE_NOOP("core", "right"), -1.0}};
        const ChangeRules rules{.unknownName = QT_TRANSLATE_NOOP("core", "The five-bar linkage has no parameter named '%1'.")};
        return T(rules, {
            {{"AB", "AB", QT_TRANSLATE_NOOP("core", "length of crank 1, driven at A"), length, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.crank[0]; })},
            {{"BC", "BC", QT_TRANSLATE_NOOP("core", "length of distal link 1, from B to C"), length, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.link[0]; })},
            {{"CD", "CD", QT_TRANSLATE_NOOP("core", "length of distal link 2, from C to D"), length, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.link[1]; })},
            {{"DE", "DE", QT_TRANSLATE_NOOP("core", "length of crank 2, driven at E"), length, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.crank[1]; })},
            {{"AE", "AE", QT_TRANSLATE_NOOP("core", "length of the ground, from A to E along +x"), length, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::ground>()},
            {{"theta1_min", "θ₁,min", QT_TRANSLATE_NOOP("core", "lower limit of crank angle θ₁"), angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.range[0].min; })},
            {{"theta1_max", "θ₁,max", QT_TRANSLATE_NOOP("core", "upper limit of crank angle θ₁"), angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.range[0].max; })},
            {{"theta4_min", "θ₄,min", QT_TRANSLATE_NOOP("core", "lower limit of crank angle θ₄"), angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.range[1].min; })},
            {{"theta4_max", "θ₄,max", QT_TRANSLATE_NOOP("core", "upper limit of crank angle θ₄"), angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.range[1].max; })},
            {{"working1", "w₁", QT_TRANSLATE_NOOP("core", "working mode of leg 1: elbow B left (+1) or right (−1) of A→C"), units::none, G::Mode, sign, false, false, true, 0, 2, sides},
             T::sign([](auto &d) -> auto & { return d.working[0]; }), &sideRule},
            {{"working2", "w₂", QT_TRANSLATE_NOOP("core", "working mode of leg 2: elbow D left (+1) or right (−1) of E→C"), units::none, G::Mode, sign, false, false, true, 0, 2, sides},
             T::sign([](auto &d) -> auto & { return d.working[1]; }), &sideRule},
            {{"assembly", "σ", QT_TRANSLATE_NOOP("core", "assembly mode: C left (+1) or right (−1) of B→D"), units::none, G::Mode, sign, false, false, true, 0, 2, sides},
             T::sign<&D::assembly>(), &sideRule},
        });
    }();
    return table;
}

Result<MechanismPtr> FiveBar::create(const FiveBarDesign &d)
{
    if (auto checked = table().checkDesign(d); !checked)
        return checked.failure();
    for (int leg = 0; leg < 2; ++leg) {
        const LegText &t = legText[std::size_t(leg)];
        const Interval &r = d.range[leg];
        if (!(r.min < r.max)) {
            return Failure{FailureKind::InvalidParameter, t.thetaMin,
                           text::format(text::translate("core", "%1 = %2 must be less than %3 = %4."),
                                        {t.thetaMin, deg(r.min), t.thetaMax, deg(r.max)})};
        }
        if (r.max - r.min > 2.0 * pi * (1.0 + 1e-12)) {
            return Failure{FailureKind::InvalidParameter, t.thetaMax,
                           text::format(text::translate("core", "%1 = %2 lies %3 above %4 = %5: a crank's range may "
                                                                "span one turn (360°) at most."),
                                        {t.thetaMax, deg(r.max), deg(r.max - r.min), t.thetaMin, deg(r.min)})};
        }
    }
    // A closed loop ABCDE needs every link shorter than the other four together.
    using Link = std::pair<const char *, double>;
    const std::array<Link, 5> links = {Link{"AB", d.crank[0]}, Link{"BC", d.link[0]}, Link{"CD", d.link[1]},
                                       Link{"DE", d.crank[1]}, Link{"AE", d.ground}};
    const auto longest = std::max_element(links.begin(), links.end(),
                                          [](const auto &x, const auto &y) { return x.second < y.second; });
    const double others = d.crank[0] + d.crank[1] + d.link[0] + d.link[1] + d.ground - longest->second;
    if (!(longest->second < others * (1.0 - 1e-12))) {
        std::string names;
        for (const auto &link : links) {
            if (&link != &*longest)
                names.append(names.empty() ? "" : " + ").append(link.first);
        }
        return Failure{FailureKind::InvalidParameter, longest->first,
                       text::format(text::translate("core", "%1 = %2 is not shorter than %3 = %4: the links cannot "
                                                            "close the loop ABCDE for any crank angles (each link must "
                                                            "be shorter than the other four together)."),
                                    {longest->first, text::millimetres(longest->second), names, text::millimetres(others)})};
    }
    FiveBar candidate(d);
    if (!candidate.m_home.inputs.size()) {
        const bool limited = !fivebar::fullTurn(d.range[0]) || !fivebar::fullTurn(d.range[1]);
        std::string modes;
        for (int leg = 0; leg < 2; ++leg)
            modes.append(joinText({legText[std::size_t(leg)].working, " = ", fivebar::sideName(d.working[leg]), ", "}));
        modes.append(joinText({"assembly = ", fivebar::sideName(d.assembly)}));
        if (!limited) {
            return Failure{FailureKind::Unreachable, "assembly",
                           text::format(text::translate("core", "This five-bar has no workspace: with %1 the loop "
                                                                "ABCDE never closes. Change a mode, a range or a length."),
                                        {modes})};
        }
        std::string ranges;
        for (int leg = 0; leg < 2; ++leg) {
            const LegText &t = legText[std::size_t(leg)];
            ranges.append(joinText({leg == 0 ? "" : ", ", t.thetaMin, "…", t.thetaMax, " = ", rangeText(d.range[leg])}));
        }
        return Failure{FailureKind::Unreachable, "theta1_min",
                       text::format(text::translate("core", "This five-bar has no workspace: with %1 and the crank "
                                                            "ranges %2 the loop ABCDE never closes. Change a mode, a "
                                                            "range or a length."),
                                    {modes, ranges})};
    }
    return MechanismPtr(new FiveBar(candidate));
}

FiveBar::FiveBar(const FiveBarDesign &design)
    : m_design(design)
{
    // Home: on a grid of crank angles, the pose farthest from the singularities (and from the
    // ends of limited crank ranges); none means the loop never closes in the design's modes.
    constexpr int samples = 73;
    double best = -1.0;
    for (int i = 0; i < samples; ++i) {
        for (int j = 0; j < samples; ++j) {
            const std::array<int, 2> index = {i, j};
            std::array<double, 2> theta{};
            double centrality = 0.25;
            for (int leg = 0; leg < 2; ++leg) {
                const Interval &r = design.range[leg];
                theta[leg] = r.min + (r.max - r.min) * index[leg] / (samples - 1);
                const double fromEnds = std::min(theta[leg] - r.min, r.max - theta[leg]) / (r.max - r.min);
                if (!fivebar::fullTurn(r))
                    centrality = std::min(centrality, fromEnds);
            }
            const Check check = checkDirect(theta[0], theta[1], solverTolerance);
            if (!check.ok())
                continue;
            const auto [inverse, direct] = marginsOf(design, vectorsOf(design, check.elbows, check.C));
            const double score = std::min({inverse, direct, 4.0 * centrality}) + 1e-3 * centrality;
            if (score > best) {
                best = score;
                m_home.inputs.resize(2);
                m_home.inputs << theta[0], theta[1];
                m_home.outputs.resize(2);
                m_home.outputs << check.C.x(), check.C.y();
            }
        }
    }
    if (m_home.inputs.size())
        m_bounds = computeBounds();
}

std::vector<std::string> FiveBar::designWarnings() const
{
    std::vector<std::string> warnings;
    const std::vector<SingularCurve> curves = singularCurves();
    const auto direct = [](const SingularCurve &c) { return c.type == SingularCurve::Type::Direct; };
    if (std::any_of(curves.begin(), curves.end(), direct)) {
        warnings.push_back(text::translate("core", "The workspace of these modes reaches direct singularities (the "
                                                   "curves where the distal links BC and CD come in line, marked on "
                                                   "the map): there C can move with both cranks held and the "
                                                   "mechanism may switch its assembly mode. Keep the path of C away "
                                                   "from them."));
    }
    return warnings;
}

// -- joint variables -----------------------------------------------------------------------

const std::vector<VariableInfo> &FiveBar::variableInfo() const
{
    static const std::vector<VariableInfo> infos = {
        {"theta1", "θ₁", QT_TRANSLATE_NOOP("core", "crank AB angle at A, from +x counter-clockwise (actuated)"), units::angle, true, 2},
        {"theta4", "θ₄", QT_TRANSLATE_NOOP("core", "crank ED angle at E, from +x counter-clockwise (actuated)"), units::angle, true, 2},
        {"x", "x", QT_TRANSLATE_NOOP("core", "output point C, x"), units::millimetre, false, 2},
        {"y", "y", QT_TRANSLATE_NOOP("core", "output point C, y"), units::millimetre, false, 2},
    };
    return infos;
}

Interval FiveBar::variableRange(int variable) const
{
    switch (variable) {
    case variableTheta1: return m_design.range[0];
    case variableTheta4: return m_design.range[1];
    case variableX: return {m_bounds.min().x(), m_bounds.max().x()};
    default: return {m_bounds.min().y(), m_bounds.max().y()};
    }
}

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
    case R::LegTooShort:
        return Failure{FailureKind::Unreachable, culprit,
                       text::format(text::translate("core", "C cannot reach %1: it lies %2 from %3, more than %4 + %5 = %6."),
                                    {point, text::millimetres(distance), t.ground, t.crank, t.link,
                                     text::millimetres(a + b)})};
    case R::LegTooLong:
        return Failure{FailureKind::Unreachable, culprit,
                       text::format(text::translate("core", "C cannot reach %1: it lies %2 from %3, less than |%4 − %5| = %6."),
                                    {point, text::millimetres(distance), t.ground, t.crank, t.link,
                                     text::millimetres(std::abs(a - b))})};
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
                                                            "singularity); switch assembly to go on."),
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
                                              {t.theta, deg(inputs[leg]), t.crank, rangeText(range)})
                               : text::format(text::translate("core", "%1 = %2 is outside the range of crank %3, %4."),
                                              {t.theta, deg(inputs[leg]), t.crank, rangeText(range)})};
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

// -- analysis ------------------------------------------------------------------------------

namespace {
enum Slot {
    SlotTheta1, SlotTheta4, SlotX, SlotY,
    SlotJq, SlotJx = SlotJq + 4, SlotJ = SlotJx + 4, SlotDetJ = SlotJ + 4, SlotDetJq, SlotDetJx, SlotCond,
    SlotElbowAngle1, SlotElbowAngle2, SlotLinksAngle, SlotTransmission, SlotMarginInverse, SlotMarginDirect, SlotMargin,
    SlotCount
};
} // namespace

const ReportLayout &FiveBar::reportLayout() const
{
    static const ReportLayout layout = [] {
        using G = ReportGroup;
        ReportLayout l;
        l.add(G::Pose, "theta1", "θ₁", QT_TRANSLATE_NOOP("core", "crank AB angle at A, from +x counter-clockwise"), units::angle, 2);
        l.add(G::Pose, "theta4", "θ₄", QT_TRANSLATE_NOOP("core", "crank ED angle at E, from +x counter-clockwise"), units::angle, 2);
        l.add(G::Pose, "x", "x", QT_TRANSLATE_NOOP("core", "output point C, x"), units::millimetre, 2);
        l.add(G::Pose, "y", "y", QT_TRANSLATE_NOOP("core", "output point C, y"), units::millimetre, 2);
        l.add(G::Jacobian, "Jq", "J_q", "J_q = diag((B − A)×(C − B), (D − E)×(C − D))", units::squareMillimetre, 1, 2, 2);
        l.add(G::Jacobian, "Jx", "J_x", QT_TRANSLATE_NOOP("core", "J_x rows (C − B)ᵀ, (C − D)ᵀ"), units::millimetre, 2, 2, 2);
        l.add(G::Jacobian, "J", "J", "θ̇ = J·Ċ, J = J_q⁻¹·J_x", units::radianPerMillimetre, 5, 2, 2);
        l.add(G::Jacobian, "det_J", "det J", QT_TRANSLATE_NOOP("core", "determinant of J (0: direct, ∞: inverse singularity)"), radianPerMillimetre2, 8);
        l.add(G::Jacobian, "det_Jq", "det J_q", QT_TRANSLATE_NOOP("core", "0 at an inverse singularity (a leg stretched or folded)"), millimetre4, 0);
        l.add(G::Jacobian, "det_Jx", "det J_x", QT_TRANSLATE_NOOP("core", "0 at a direct singularity (the distal links in line)"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "cond", "κ(J)", QT_TRANSLATE_NOOP("core", "condition number of J"), units::none, 3);
        l.add(G::Derived, "elbow_angle1", "φ₁", QT_TRANSLATE_NOOP("core", "angle ABC between crank AB and link BC (0°, 180°: inverse singularity)"), units::angle, 2);
        l.add(G::Derived, "elbow_angle2", "φ₂", QT_TRANSLATE_NOOP("core", "angle EDC between crank ED and link DC (0°, 180°: inverse singularity)"), units::angle, 2);
        l.add(G::Derived, "links_angle", "ψ", QT_TRANSLATE_NOOP("core", "angle BCD between the distal links (0°, 180°: direct singularity)"), units::angle, 2);
        l.add(G::Derived, "transmission", "μ", QT_TRANSLATE_NOOP("core", "transmission angle between the distal links, min(ψ, 180° − ψ)"), units::angle, 2);
        l.add(G::Derived, "margin_inverse", "m_inv", QT_TRANSLATE_NOOP("core", "distance from the inverse singularities, min |sin φ_i| (0 … 1)"), units::none, 4);
        l.add(G::Derived, "margin_direct", "m_dir", QT_TRANSLATE_NOOP("core", "distance from the direct singularities, |sin ψ| (0 … 1)"), units::none, 4);
        l.add(G::Derived, "margin", "m", QT_TRANSLATE_NOOP("core", "distance from the nearest singularity (0 … 1)"), units::none, 4);
        // exact values at singular poses (mechanism.h: AtSingularity)
        using S = AtSingularity;
        l.atSingularity("J", S::Infinite, S::Computed);
        l.atSingularity("det_J", S::Infinite, S::Zero);
        l.atSingularity("cond", S::Infinite, S::Infinite);
        l.atSingularity("det_Jq", S::Zero, S::Computed);
        l.atSingularity("det_Jx", S::Computed, S::Zero);
        return l;
    }();
    return layout;
}

Singularity FiveBar::singularity(const Pose &pose) const
{
    const auto [inverse, direct] = marginsOf(m_design, vectorsOf(m_design, pose));
    return classifySingularity(inverse, direct, singularTolerance);
}

Jacobians FiveBar::jacobians(const Pose &pose) const
{
    const Vectors v = vectorsOf(m_design, pose);
    Eigen::Matrix2d jq = Eigen::Matrix2d::Zero(), jx, full;
    for (int leg = 0; leg < 2; ++leg) {
        jq(leg, leg) = v.k[leg];
        jx.row(leg) = v.link[leg].transpose();
        full.row(leg) = v.link[leg].transpose() / v.k[leg];
    }
    return {jq, jx, full};
}

Singularity FiveBar::evaluate(const Pose &pose, std::span<double> values) const
{
    const FiveBarDesign &d = m_design;
    const Vectors v = vectorsOf(d, pose);
    values[SlotTheta1] = pose.inputs[0];
    values[SlotTheta4] = pose.inputs[1];
    values[SlotX] = pose.outputs[0];
    values[SlotY] = pose.outputs[1];
    double frobenius = 0.0;
    for (int leg = 0; leg < 2; ++leg) {
        values[SlotJq + 3 * leg] = v.k[leg];
        values[SlotJq + 1 + leg] = 0.0; // the off-diagonal zeros: slots 1 and 2 of the row-major 2×2
        for (int c = 0; c < 2; ++c) {
            values[SlotJx + 2 * leg + c] = v.link[leg][c];
            values[SlotJ + 2 * leg + c] = v.link[leg][c] / v.k[leg];
        }
        frobenius += v.link[leg].squaredNorm() / (v.k[leg] * v.k[leg]);
        // the elbow angle between P→G and P→C: |sin| = |k|/(a·b)
        values[SlotElbowAngle1 + leg] = std::atan2(std::abs(v.k[leg]), -v.crank[leg].dot(v.link[leg]));
    }
    const double detJq = v.k[0] * v.k[1];
    values[SlotDetJq] = detJq;
    values[SlotDetJx] = v.detJx;
    values[SlotDetJ] = v.detJx / detJq;
    values[SlotCond] = fivebar::conditionNumber(frobenius, std::abs(v.detJx / detJq));
    const double psi = std::atan2(std::abs(v.detJx), v.link[0].dot(v.link[1]));
    values[SlotLinksAngle] = psi;
    values[SlotTransmission] = std::min(psi, pi - psi);
    const auto [inverseMargin, directMargin] = marginsOf(d, v);
    values[SlotMarginInverse] = inverseMargin;
    values[SlotMarginDirect] = directMargin;
    const Singularity s = classifySingularity(inverseMargin, directMargin, singularTolerance);
    values[SlotMargin] = s.margin;
    settleSingularValues(reportLayout(), values, s.type);
    return s;
}

std::vector<ModeAlternative> FiveBar::modeNeighbours() const
{
    const FiveBarDesign &d = m_design;
    std::vector<ModeAlternative> neighbours;
    auto add = [&](const std::string &label, const ParameterSet &changes, bool sameInputs) {
        if (auto other = withParameters(changes))
            neighbours.push_back({label, changes, *other, sameInputs, {}});
    };
    // C mirrored across BD turns both distal links about that line: where that carries a leg
    // past its stretched or folded pose, its working mode flips along with the assembly.
    const std::string mirrored = -d.assembly == fivebar::right
        ? QT_TRANSLATE_NOOP("core", "other assembly mode (C right of B→D, same crank angles)")
        : QT_TRANSLATE_NOOP("core", "other assembly mode (C left of B→D, same crank angles)");
    for (int flips = 0; flips < 4; ++flips) {
        ParameterSet changes = {{"assembly", -double(d.assembly)}};
        for (int leg = 0; leg < 2; ++leg) {
            if (flips & (1 << leg))
                changes[legText[std::size_t(leg)].working] = -double(d.working[leg]);
        }
        add(mirrored, changes, true);
    }
    // Moving elbow i to its mirror image across G_i→C may carry it across the line through
    // the other elbow and C: then the assembly mode flips with it.
    for (int leg = 0; leg < 2; ++leg) {
        const LegText &t = legText[std::size_t(leg)];
        // fixed labels (the GUI keeps and translates them): leg × the side the elbow goes to
        static constexpr std::array<std::array<const char *, 2>, 2> labels = {{
            {QT_TRANSLATE_NOOP("core", "leg 1: other working mode (B left of A→C, same C)"),
             QT_TRANSLATE_NOOP("core", "leg 1: other working mode (B right of A→C, same C)")},
            {QT_TRANSLATE_NOOP("core", "leg 2: other working mode (D left of E→C, same C)"),
             QT_TRANSLATE_NOOP("core", "leg 2: other working mode (D right of E→C, same C)")},
        }};
        const std::string label = labels[std::size_t(leg)][-d.working[leg] == fivebar::right ? 1 : 0];
        const ParameterSet changes = {{t.working, -double(d.working[leg])}};
        add(label, changes, false);
        ParameterSet both = changes;
        both["assembly"] = -double(d.assembly);
        add(label, both, false);
    }
    return neighbours;
}

KinematicChain FiveBar::kinematicChain(const Pose &pose) const
{
    auto at = [](const Eigen::Vector2d &p) { return Eigen::Vector3d(p.x(), p.y(), 0.0); };
    const Eigen::Vector2d A = fivebar::groundJoint(m_design, 0), E = fivebar::groundJoint(m_design, 1);
    const Eigen::Vector2d B = fivebar::elbow(m_design, 0, pose.inputs[0]);
    const Eigen::Vector2d D = fivebar::elbow(m_design, 1, pose.inputs[1]);
    const Eigen::Vector2d C = pose.outputs.head<2>();
    KinematicChain chain;
    chain.links = {text::translate("core", "ground"), text::translate("core", "crank AB"),
                   text::translate("core", "link BC"), text::translate("core", "link CD"),
                   text::translate("core", "crank DE")};
    const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
    chain.pairs = {{"A", PairType::Revolute, 0, 1, at(A), z, 0.0, true},
                   {"B", PairType::Revolute, 1, 2, at(B), z, 0.0, false},
                   {"C", PairType::Revolute, 2, 3, at(C), z, 0.0, false},
                   {"D", PairType::Revolute, 3, 4, at(D), z, 0.0, false},
                   {"E", PairType::Revolute, 4, 0, at(E), z, 0.0, true}};
    chain.planar = true;
    chain.description = text::translate("core", "planar five-bar: ground AE, cranks AB and DE (driven at A and E), "
                                                "distal links BC and CD");
    return chain;
}

// -- drawing -------------------------------------------------------------------------------

Scene FiveBar::scene(const Pose &pose) const
{
    const FiveBarDesign &d = m_design;
    auto to3 = [](const Eigen::Vector2d &p) { return Eigen::Vector3d(p.x(), p.y(), 0.0); };
    const std::array<Eigen::Vector2d, 2> G = {fivebar::groundJoint(d, 0), fivebar::groundJoint(d, 1)};
    const Eigen::Vector2d B = fivebar::elbow(d, 0, pose.inputs[0]), D = fivebar::elbow(d, 1, pose.inputs[1]);
    const Eigen::Vector2d C = pose.outputs.head<2>();
    Scene s;
    s.joints.push_back({to3(G[0]), "A", JointKind::Ground});
    s.joints.push_back({to3(G[1]), "E", JointKind::Ground});
    s.joints.push_back({to3(B), "B", JointKind::Revolute});
    s.joints.push_back({to3(D), "D", JointKind::Revolute});
    s.joints.push_back({to3(C), "C", JointKind::Revolute});
    s.bars.push_back({0, 1, BarKind::Ground, "AE"});
    s.bars.push_back({0, 2, BarKind::Crank, "AB"});
    s.bars.push_back({1, 3, BarKind::Crank, "DE"});
    s.bars.push_back({2, 4, BarKind::Link, "BC"});
    s.bars.push_back({3, 4, BarKind::Link, "CD"});
    for (int leg = 0; leg < 2; ++leg) {
        const double theta = pose.inputs[leg];
        s.angles.push_back({leg, 0.0, theta, 0.3 * std::min(d.crank[leg], d.ground),
                            joinText({leg == 0 ? "θ₁ = " : "θ₄ = ", text::number(theta / units::degree, 1), "°"})});
    }
    s.handles.push_back({4, text::translate("core", "drag to move C (inverse kinematics)")});
    s.handles.push_back({2, text::translate("core", "drag to turn crank AB (sets θ₁, direct kinematics)")});
    s.handles.push_back({3, text::translate("core", "drag to turn crank DE (sets θ₄, direct kinematics)")});
    // constant over the motion: the cranks' circles and the workspace
    Eigen::AlignedBox3d extent;
    for (int leg = 0; leg < 2; ++leg) {
        extent.extend(to3(G[leg] - Eigen::Vector2d::Constant(d.crank[leg])));
        extent.extend(to3(G[leg] + Eigen::Vector2d::Constant(d.crank[leg])));
    }
    extent.extend(to3(m_bounds.min()));
    extent.extend(to3(m_bounds.max()));
    extent.extend(to3(C));
    const Eigen::Vector3d pad(0.08 * scaleOf(d), 0.08 * scaleOf(d), 0.0);
    s.extent = Eigen::AlignedBox3d(extent.min() - pad, extent.max() + pad);
    return s;
}

Result<Pose> FiveBar::dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const
{
    if (handle == 0)
        return solveInverse(target, &current);
    if (handle == 1 || handle == 2) {
        const int leg = handle - 1;
        const Eigen::Vector2d fromGround = target - fivebar::groundJoint(m_design, leg);
        if (fromGround.norm() < 1e-12 * scaleOf(m_design))
            return current;
        // the turn of the target's direction inside the range nearest the current angle, or
        // else the end of the range nearest to it
        const Interval &range = m_design.range[leg];
        const double raw = std::atan2(fromGround.y(), fromGround.x());
        double theta = representative(raw, range, current.inputs[leg], 0.0);
        if (std::isnan(theta)) {
            auto gap = [&](double end) { return std::abs(std::remainder(raw - end, 2.0 * pi)); };
            theta = gap(range.min) <= gap(range.max) ? range.min : range.max;
        }
        Coordinates inputs = current.inputs;
        inputs[leg] = theta;
        return solveDirect(inputs, &current);
    }
    return Failure{FailureKind::UnknownName, {}, text::translate("core", "No handle with that index.")};
}

} // namespace pkm
