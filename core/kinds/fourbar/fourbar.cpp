// The planar four-bar (docs/mathematics.md, section 4): its closed forms, the Grashof class,
// the design with its checks, ranges and home pose, and the joint variables; the kinematics are
// in fourbarkinematics.cpp, the analysis in fourbaranalysis.cpp, the drawing in fourbarscene.cpp.

#include "fourbar.h"
#include "fourbarinternal.h"

#include "text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>

namespace pkm {

namespace {
using fourbar::crankJoint;
using fourbar::cross;
using fourbar::deg;
using fourbar::deltaOf;
using fourbar::mm;
using fourbar::nan;
using fourbar::nearestTurn;
using fourbar::perp;
using fourbar::pi;
using fourbar::rangeSamples;
using fourbar::rockerJoint;
using fourbar::scaleOf;
} // namespace

// -- closed forms --------------------------------------------------------------------------

namespace fourbar {

const char *branchName(int branch)
{
    // words of the reports and JSON (also the parameter's choices): English, translated where shown
    return branch == crossed ? QT_TRANSLATE_NOOP("core", "crossed") : QT_TRANSLATE_NOOP("core", "open");
}

Grashof classify(double AB, double BC, double CD, double AD)
{
    const std::array<double, 4> links = {AB, BC, CD, AD};
    const auto [shortest, longest] = std::minmax_element(links.begin(), links.end());
    const double s = *shortest, l = *longest;
    const double p_q = AB + BC + CD + AD - s - l;
    if (std::abs(s + l - p_q) <= 1e-9 * l)
        return Grashof::ChangePoint;
    if (s + l > p_q)
        return Grashof::TripleRocker;
    switch (shortest - links.begin()) {
    case 0: return Grashof::CrankRocker;
    case 1: return Grashof::DoubleRocker;
    case 2: return Grashof::RockerCrank;
    default: return Grashof::DoubleCrank;
    }
}

const char *grashofName(Grashof g)
{
    switch (g) {
    // words of the reports and JSON: English, translated where shown (text::label, coreLabel)
    case Grashof::CrankRocker: return QT_TRANSLATE_NOOP("core", "crank-rocker");
    case Grashof::RockerCrank: return QT_TRANSLATE_NOOP("core", "rocker-crank");
    case Grashof::DoubleCrank: return QT_TRANSLATE_NOOP("core", "double-crank");
    case Grashof::DoubleRocker: return QT_TRANSLATE_NOOP("core", "double-rocker");
    case Grashof::TripleRocker: return QT_TRANSLATE_NOOP("core", "triple-rocker");
    case Grashof::ChangePoint: return QT_TRANSLATE_NOOP("core", "change-point");
    }
    return "";
}

Position position(const FourBarDesign &d, double alpha)
{
    Position p;
    p.B = crankJoint(d, alpha);
    const Eigen::Vector2d D(d.ground, 0.0);
    const Eigen::Vector2d diagonal = D - p.B;
    const double e = diagonal.norm();
    const double b = d.coupler, c = d.rocker;
    if (e < 1e-12 * scaleOf(d))
        return p; // B on D: C anywhere on a circle
    // circle (B, BC) ∩ circle (D, CD), measured along B→D: no division but by |BD|
    const double along = (b * b - c * c + e * e) / (2.0 * e);
    const double across2 = b * b - along * along;
    if (across2 < -1e-12 * b * b)
        return p;
    const Eigen::Vector2d u = diagonal / e;
    p.C = p.B + along * u + d.branch * std::sqrt(std::max(0.0, across2)) * perp(u);
    p.valid = true;
    return p;
}

Angles angles(const FourBarDesign &d, double alpha, double delta)
{
    const Eigen::Vector2d A(0.0, 0.0), D(d.ground, 0.0);
    const Eigen::Vector2d B = crankJoint(d, alpha), C = rockerJoint(d, delta);
    Angles a;
    const Eigen::Vector2d cb = B - C, cd = D - C;
    a.gamma = std::atan2(cross(cb, cd), cb.dot(cd));
    const Eigen::Vector2d ba = A - B, bc = C - B;
    a.beta = std::atan2(cross(ba, bc), ba.dot(bc));
    if (a.beta < 0.0)
        a.beta += 2.0 * pi;
    a.delta1 = std::atan2(d.crank * std::sin(alpha), d.ground - d.crank * std::cos(alpha)); // (4)
    return a;
}

Motion motion(const FourBarDesign &d, double alpha, double delta, double omega1)
{
    const Eigen::Vector2d D(d.ground, 0.0);
    const Eigen::Vector2d B = crankJoint(d, alpha), C = rockerJoint(d, delta);
    const Eigen::Vector2d coupler = C - B, rocker = C - D;
    // ω₁·⊥AB + ω₂·⊥BC − θ̇₃·⊥DC = 0 (the loop AB + BC − DC − AD = 0 differentiated), θ₃ = π − δ
    const Eigen::Vector2d p = perp(coupler), q = -perp(rocker);
    const double det = cross(p, q); // = −cross(BC, DC): 0 at the direct singularity
    const Eigen::Vector2d r = -omega1 * perp(B);
    Motion m;
    m.omega2 = cross(r, q) / det;
    const double theta3Dot = cross(p, r) / det;
    // differentiated again at constant ω₁: ε₂·⊥BC − θ̈₃·⊥DC = ω₁²·AB + ω₂²·BC − θ̇₃²·DC
    const Eigen::Vector2d s = omega1 * omega1 * B + m.omega2 * m.omega2 * coupler - theta3Dot * theta3Dot * rocker;
    m.epsilon2 = cross(s, q) / det;
    const double theta3DDot = cross(p, s) / det;
    m.omega3 = -theta3Dot;
    m.epsilon3 = -theta3DDot;
    return m;
}

Eigen::Vector2d instantCentre(const FourBarDesign &d, double alpha, double delta)
{
    const Eigen::Vector2d D(d.ground, 0.0);
    const Eigen::Vector2d B = crankJoint(d, alpha), C = rockerJoint(d, delta);
    const Eigen::Vector2d crank = B, rocker = C - D;
    // A + s·AB = D + t·DC
    const double den = cross(crank, rocker);
    if (std::abs(den) <= 1e-12 * d.crank * d.rocker)
        return {nan, nan};
    const double s = cross(D, rocker) / den;
    return s * crank;
}

double documentCosGamma(double AB, double BC, double CD, double AD, double alpha)
{
    return (BC * BC + CD * CD - AB * AB - AD * AD) / (2.0 * BC * CD) + (AB * AD) / (BC * CD) * std::cos(alpha);
}

double documentOmega3(double AB, double CD, double omega1, double beta, double gamma)
{
    return omega1 * (AB / CD) * std::sin(beta) / std::sin(gamma);
}

double documentI31(double AB, double CD, double beta, double gamma)
{
    return AB * std::sin(beta) / (CD * std::sin(gamma));
}

double documentEpsilon3(double AB, double BC, double CD, double AD, double omega1, double alpha, double beta,
                        double gamma, double delta)
{
    const double sinGamma = std::sin(gamma);
    const double cotGamma = std::cos(gamma) / sinGamma;
    return omega1 * omega1 * (AB * AD) / (BC * CD)
         * (std::sin(delta) * std::cos(beta) - (AB / CD) * std::sin(alpha) * std::cos(beta) * cotGamma)
         / (sinGamma * sinGamma);
}

} // namespace fourbar

// -- design --------------------------------------------------------------------------------

namespace {
/// The branch is a sign: exactly +1 (open) or −1 (crossed).
Result<double> branchRule(const ParameterInfo &, double value)
{
    if (value != 1.0 && value != -1.0) {
        return Failure{FailureKind::InvalidParameter, "branch",
                       text::format(text::translate("core", "branch = %1 is invalid: it must be +1 (open) or -1 (crossed)."),
                                    {text::number(value)})};
    }
    return value;
}
} // namespace

const ParameterTable<FourBarDesign> &FourBar::table()
{
    using T = ParameterTable<FourBarDesign>;
    using D = FourBarDesign;
    static const T table = [] {
        const Interval positive{0.0, 1e5};
        using G = ParameterGroup;
        const ChangeRules rules{.unknownName = QT_TRANSLATE_NOOP("core", "The four-bar linkage has no parameter named '%1'.")};
        return T(rules, joinRows<FourBarDesign>({
            {{"AB", "AB", QT_TRANSLATE_NOOP("core", "crank (input link) length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::crank>()},
            {{"BC", "BC", QT_TRANSLATE_NOOP("core", "coupler length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::coupler>()},
            {{"CD", "CD", QT_TRANSLATE_NOOP("core", "rocker (output link) length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::rocker>()},
            {{"AD", "AD", QT_TRANSLATE_NOOP("core", "ground (frame) length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::ground>()},
            {{"omega1", "ω₁", QT_TRANSLATE_NOOP("core", "crank angular velocity, constant (positive: α grows, counter-clockwise)"),
              units::radianPerSecond, G::Actuator, Interval{-1e4, 1e4}, false, false, true, 3, 0.1}, T::real<&D::omega1>()},
            {{"coupler_point", "λ", QT_TRANSLATE_NOOP("core", "coupler point M on BC: BM/BC (0 at B, 1 at C)"), units::none, G::Geometry,
              Interval{0.0, 1.0}, false, false, true, 3, 0.05}, T::real<&D::couplerPoint>()},
            {{"branch", "σ", QT_TRANSLATE_NOOP("core", "assembly branch: +1 open (C left of B→D), −1 crossed"), units::none,
              G::Mode, Interval{-1.0, 1.0}, false, false, true, 0, 2, {{"open", 1.0}, {"crossed", -1.0}}}, T::sign<&D::branch>(), &branchRule},
        }, {actuatorRows<FourBarDesign, 0>(ActuatorNames::Rotary, [](auto &d) -> auto & { return d.actuators[0]; }), loadRows<FourBarDesign>(LoadNames::Torque, [](auto &d) -> auto & { return d.load; })}));
    }();
    return table;
}

fourbar::Grashof FourBar::grashof(const FourBarDesign &d)
{
    return fourbar::classify(d.crank, d.coupler, d.rocker, d.ground);
}

Result<MechanismPtr> FourBar::create(const FourBarDesign &d)
{
    // the branch, the last row, is checked after every domain
    if (auto checked = table().checkDesign(d); !checked)
        return checked.failure();
    // A closed loop needs every link shorter than the other three together.
    const std::array<std::pair<const char *, double>, 4> links = {
        std::pair{"AB", d.crank}, std::pair{"BC", d.coupler}, std::pair{"CD", d.rocker}, std::pair{"AD", d.ground}};
    const auto longest = std::max_element(links.begin(), links.end(),
                                          [](const auto &x, const auto &y) { return x.second < y.second; });
    const double total = d.crank + d.coupler + d.rocker + d.ground;
    const double others = total - longest->second;
    if (!(longest->second < others * (1.0 - 1e-12))) {
        std::string names;
        for (const auto &link : links) {
            if (&link != &*longest)
                names.append(names.empty() ? "" : " + ").append(link.first);
        }
        return Failure{FailureKind::InvalidParameter, longest->first,
                       text::format(text::translate("core", "%1 = %2 is not shorter than %3 = %4: the links cannot close "
                                                            "the loop ABCD for any crank angle α (each link must be "
                                                            "shorter than the other three together)."),
                                    {longest->first, mm(longest->second), names, mm(others)})};
    }
    return MechanismPtr(new FourBar(d));
}

FourBar::FourBar(const FourBarDesign &design)
    : m_design(design)
{
    const double a = design.crank, b = design.coupler, c = design.rocker, d = design.ground;
    // BD² = a² + d² − 2ad·cos α must stay within [(b − c)², (b + c)²]: cos α ∈ [k1, k2]
    double k1 = (a * a + d * d - (b + c) * (b + c)) / (2.0 * a * d);
    double k2 = (a * a + d * d - (b - c) * (b - c)) / (2.0 * a * d);
    if (std::abs(k1 + 1.0) < 1e-9)
        k1 = -1.0; // a change point: the links fold flat at α = 180°, the crank still turns
    if (std::abs(k2 - 1.0) < 1e-9)
        k2 = 1.0;
    const bool freeBelow = k1 <= -1.0, freeAbove = k2 >= 1.0;
    const double acos1 = std::acos(std::clamp(k1, -1.0, 1.0)), acos2 = std::acos(std::clamp(k2, -1.0, 1.0));
    m_fullTurn = freeBelow && freeAbove;
    if (m_fullTurn)
        m_alphaRange = {0.0, 2.0 * pi};
    else if (freeAbove)
        m_alphaRange = {-acos1, acos1}; // around 0°: |BD| reaches BC + CD at both ends
    else if (freeBelow)
        m_alphaRange = {acos2, 2.0 * pi - acos2}; // around 180°: |BD| falls to |BC − CD|
    else
        m_alphaRange = {acos2, acos1}; // the upper of two mirror-image intervals

    // Sample the input range: the output, lifted continuously, the home pose and the curve.
    const double lo = m_alphaRange.min, hi = m_alphaRange.max;
    // The drawing's extent: the ground, and B, C and M over the motion in both branches (a
    // mode switch keeps the view). The rocker's whole circle made the linkage small in its view.
    FourBarDesign otherBranch = design;
    otherBranch.branch = -design.branch;
    m_motionBox.extend(Eigen::Vector2d(0.0, 0.0));
    m_motionBox.extend(Eigen::Vector2d(d, 0.0));
    std::vector<double> deltas(rangeSamples + 1, 0.0);
    std::vector<double> alphas(rangeSamples + 1, 0.0);
    double previous = nan;
    double best = -1.0;
    for (int i = 0; i <= rangeSamples; ++i) {
        const double alpha = lo + (hi - lo) * i / rangeSamples;
        alphas[std::size_t(i)] = alpha;
        for (const FourBarDesign *branch : {&design, static_cast<const FourBarDesign *>(&otherBranch)}) {
            if (const fourbar::Position q = fourbar::position(*branch, alpha); q.valid) {
                m_motionBox.extend(q.B);
                m_motionBox.extend(q.C);
                m_motionBox.extend(q.B + design.couplerPoint * (q.C - q.B));
            }
        }
        const fourbar::Position p = fourbar::position(design, alpha);
        if (!p.valid) {
            deltas[std::size_t(i)] = previous; // B on D: a single singular point
            continue;
        }
        const double raw = deltaOf(design, p.C);
        const double delta = std::isnan(previous) ? std::remainder(raw, 2.0 * pi) : nearestTurn(raw, previous);
        deltas[std::size_t(i)] = previous = delta;
        m_curve.push_back(p.B + design.couplerPoint * (p.C - p.B));
        if (i == 0 || i == rangeSamples)
            continue; // home is interior
        const fourbar::Angles angle = fourbar::angles(design, alpha, delta);
        const double margin = std::min(std::abs(std::sin(angle.gamma)), std::abs(std::sin(angle.beta)));
        const double centrality = m_fullTurn ? 0.25 : std::min(alpha - lo, hi - alpha) / (hi - lo);
        const double score = std::min(margin, 4.0 * centrality) + 1e-3 * centrality;
        if (score > best) {
            best = score;
            m_home.inputs.resize(1);
            m_home.inputs << alpha;
            m_home.outputs.resize(1);
            m_home.outputs << delta;
            m_home.mode = design.branch;
        }
    }
    if (m_fullTurn && !m_curve.empty())
        m_curve.pop_back(); // the last point is the first again
    // fill a singular sample (B on D) at the start from the next one
    for (int i = rangeSamples; i >= 0; --i) {
        if (std::isnan(deltas[std::size_t(i)]))
            deltas[std::size_t(i)] = i < rangeSamples ? deltas[std::size_t(i) + 1] : 0.0;
    }
    m_outputFullTurn = m_fullTurn && std::abs(deltas.back() - deltas.front()) > pi;
    if (m_outputFullTurn) {
        m_deltaRange = {0.0, 2.0 * pi};
    } else {
        // the extremes of the samples, refined by golden-section search between the neighbours
        auto refine = [&](std::size_t i, double sign) {
            double x0 = alphas[i > 0 ? i - 1 : 0], x1 = alphas[std::min(i + 1, alphas.size() - 1)];
            const double reference = deltas[i];
            auto f = [&](double alpha) {
                const fourbar::Position p = fourbar::position(design, alpha);
                return p.valid ? sign * nearestTurn(deltaOf(design, p.C), reference) : -std::numeric_limits<double>::infinity();
            };
            double extreme = sign * reference;
            const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
            double u = x1 - ratio * (x1 - x0), v = x0 + ratio * (x1 - x0);
            double fu = f(u), fv = f(v);
            for (int k = 0; k < 80; ++k) {
                if (fu > fv) {
                    x1 = v;
                    v = u;
                    fv = fu;
                    u = x1 - ratio * (x1 - x0);
                    fu = f(u);
                } else {
                    x0 = u;
                    u = v;
                    fu = fv;
                    v = x0 + ratio * (x1 - x0);
                    fv = f(v);
                }
            }
            extreme = std::max({extreme, fu, fv});
            return sign * extreme;
        };
        const auto [minIt, maxIt] = std::minmax_element(deltas.begin(), deltas.end());
        double low = refine(std::size_t(minIt - deltas.begin()), -1.0);
        double high = refine(std::size_t(maxIt - deltas.begin()), 1.0);
        // the convention: the middle of the output range in (−180°, 180°]
        const double shift = -2.0 * pi * std::round(0.5 * (low + high) / (2.0 * pi));
        low += shift;
        high += shift;
        m_deltaRange = {low, high};
    }
    if (m_home.outputs.size())
        m_home.outputs[0] = wrapDelta(m_home.outputs[0]);
}

double FourBar::wrapDelta(double delta) const
{
    if (m_outputFullTurn) {
        const double wrapped = std::fmod(delta, 2.0 * pi);
        return wrapped < 0.0 ? wrapped + 2.0 * pi : wrapped;
    }
    return nearestTurn(delta, 0.5 * (m_deltaRange.min + m_deltaRange.max));
}

std::string FourBar::rangeLimitReason(int variable, bool upper) const
{
    if (variable != variableAlpha || m_fullTurn)
        return {};
    return limitReason(upper ? m_alphaRange.max : m_alphaRange.min);
}

std::string FourBar::limitReason(double limit) const
{
    const FourBarDesign &d = m_design;
    const double e = (Eigen::Vector2d(d.ground, 0.0) - crankJoint(d, limit)).norm();
    const double sum = d.coupler + d.rocker, difference = std::abs(d.coupler - d.rocker);
    if (std::abs(e - sum) <= std::abs(e - difference)) {
        return text::format(text::translate("core", "at α = %1 the diagonal |BD| reaches BC + CD = %2: the coupler and "
                                                    "the rocker are stretched in line (a dead point), and beyond it "
                                                    "they cannot reach each other"),
                            {deg(limit), mm(sum)});
    }
    return text::format(text::translate("core", "at α = %1 the diagonal |BD| falls to |BC − CD| = %2: the coupler and "
                                                "the rocker are folded in line (a dead point), and beyond it they "
                                                "cannot close the loop"),
                        {deg(limit), mm(difference)});
}

std::vector<std::string> FourBar::designWarnings() const
{
    std::vector<std::string> warnings;
    const FourBarDesign &d = m_design;
    const fourbar::Grashof g = grashof(d);
    if (g == fourbar::Grashof::ChangePoint) {
        warnings.push_back(text::translate("core", "s + l = p + q (a change-point linkage): the links fold flat in line "
                                                   "somewhere in the motion, where the open and crossed branches meet "
                                                   "and a real linkage may switch branch."));
    }
    if (!m_fullTurn) {
        warnings.push_back(text::format(text::translate("core", "The crank cannot turn fully: α is limited to [%1, %2], "
                                                                "at whose ends the coupler and the rocker are in line "
                                                                "(dead points where the crank cannot drive the rocker)."),
                                        {deg(m_alphaRange.min), deg(m_alphaRange.max)}));
        return warnings;
    }
    double worst = pi, worstAlpha = 0.0;
    for (int i = 0; i < 720; ++i) {
        const double alpha = 2.0 * pi * i / 720;
        const fourbar::Position p = fourbar::position(d, alpha);
        if (!p.valid)
            continue;
        const double gamma = std::abs(fourbar::angles(d, alpha, deltaOf(d, p.C)).gamma);
        const double mu = std::min(gamma, pi - gamma);
        if (mu < worst) {
            worst = mu;
            worstAlpha = alpha;
        }
    }
    if (worst < poorTransmission * units::degree) {
        warnings.push_back(text::format(text::translate("core", "The transmission angle falls to %1 at α = %2 (below "
                                                                "%3°): the crank drives the rocker poorly there."),
                                        {deg(worst), deg(worstAlpha), text::number(poorTransmission)}));
    }
    return warnings;
}

// -- joint variables -----------------------------------------------------------------------

const std::vector<VariableInfo> &FourBar::variableInfo() const
{
    static const std::vector<VariableInfo> infos = {
        {"alpha", "α", QT_TRANSLATE_NOOP("core", "crank angle at A, from AD counter-clockwise (actuated)"), units::angle, true, 2},
        {"delta", "δ", QT_TRANSLATE_NOOP("core", "rocker angle at D, from DA clockwise (output)"), units::angle, false, 2},
    };
    return infos;
}

Interval FourBar::variableRange(int variable) const
{
    return variable == variableAlpha ? m_alphaRange : m_deltaRange;
}

} // namespace pkm
