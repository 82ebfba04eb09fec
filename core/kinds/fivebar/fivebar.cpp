// The planar five-bar (docs/mathematics.md, section 5): its closed forms, the design with its
// checks and home pose, and the joint variables; the kinematics are in fivebarkinematics.cpp, the
// analysis in fivebaranalysis.cpp, the drawing in fivebarscene.cpp and the maps in fivebarmaps.cpp.

#include "fivebar.h"
#include "fivebarinternal.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

namespace {
using fivebar::deg;
using fivebar::legText;
using fivebar::LegText;
using fivebar::marginsOf;
using fivebar::pi;
using fivebar::rangeText;
using fivebar::solverTolerance;
using fivebar::vectorsOf;

Eigen::Vector2d perp(const Eigen::Vector2d &u)
{
    return {-u.y(), u.x()};
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
        return T(rules, joinRows<FiveBarDesign>({
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
        }, {actuatorRows<FiveBarDesign, 0>(ActuatorNames::Rotary, [](auto &d) -> auto & { return d.actuators[0]; }), actuatorRows<FiveBarDesign, 1>(ActuatorNames::Rotary, [](auto &d) -> auto & { return d.actuators[1]; }), loadRows<FiveBarDesign>(LoadNames::Force, [](auto &d) -> auto & { return d.load; })}));
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
    // Home: the crank angles farthest from the singularities (and from the ends of limited
    // crank ranges); none means the loop never closes in the design's modes. A coarse grid,
    // then a pattern search around its best (~450 closures instead of the 73² of a fine grid,
    // which is kept for a loop the coarse grid slips past).
    double best = -1.0;
    std::array<double, 2> bestTheta {};
    const auto consider = [&](const std::array<double, 2> &theta) {
        double centrality = 0.25;
        for (int leg = 0; leg < 2; ++leg) {
            const Interval &r = design.range[leg];
            const double fromEnds = std::min(theta[leg] - r.min, r.max - theta[leg]) / (r.max - r.min);
            if (!fivebar::fullTurn(r))
                centrality = std::min(centrality, fromEnds);
        }
        const Check check = checkDirect(theta[0], theta[1], solverTolerance);
        if (!check.ok())
            return;
        const auto [inverse, direct] = marginsOf(design, vectorsOf(design, check.elbows, check.C));
        const double score = std::min({inverse, direct, 4.0 * centrality}) + 1e-3 * centrality;
        if (score > best) {
            best = score;
            bestTheta = theta;
            m_home.inputs.resize(2);
            m_home.inputs << theta[0], theta[1];
            m_home.outputs.resize(2);
            m_home.outputs << check.C.x(), check.C.y();
        }
    };
    const auto searchGrid = [&](int samples) {
        for (int i = 0; i < samples; ++i) {
            for (int j = 0; j < samples; ++j) {
                const std::array<int, 2> index = {i, j};
                std::array<double, 2> theta {};
                for (int leg = 0; leg < 2; ++leg) {
                    const Interval &r = design.range[leg];
                    theta[leg] = r.min + (r.max - r.min) * index[leg] / (samples - 1);
                }
                consider(theta);
            }
        }
    };
    constexpr int coarse = 19;
    searchGrid(coarse);
    if (!m_home.inputs.size())
        searchGrid(73);
    if (m_home.inputs.size()) {
        const double span = std::max(design.range[0].max - design.range[0].min, design.range[1].max - design.range[1].min);
        for (double step = 0.5 / (coarse - 1); step * span > 1e-3 * span; step /= 2) {
            const std::array<double, 2> around = bestTheta;
            for (int di = -1; di <= 1; ++di) {
                for (int dj = -1; dj <= 1; ++dj) {
                    if (!di && !dj)
                        continue;
                    std::array<double, 2> theta = around;
                    const std::array<int, 2> direction = {di, dj};
                    for (int leg = 0; leg < 2; ++leg) {
                        const Interval &r = design.range[leg];
                        theta[leg] = r.clamp(theta[leg] + direction[leg] * step * (r.max - r.min));
                    }
                    consider(theta);
                }
            }
        }
        m_bounds = computeBounds();
    }
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

} // namespace pkm
