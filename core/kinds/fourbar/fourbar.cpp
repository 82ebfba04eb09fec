#include "fourbar.h"

#include "mobility.h"
#include "text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr Unit radianPerSecond2{QT_TRANSLATE_NOOP("core", "rad/s²"), 1.0};
/// Samples of the input range for the output range, the home pose and the coupler curve.
constexpr int rangeSamples = 720;

double cross(const Eigen::Vector2d &u, const Eigen::Vector2d &v)
{
    return u.x() * v.y() - u.y() * v.x();
}

Eigen::Vector2d perp(const Eigen::Vector2d &u)
{
    return {-u.y(), u.x()};
}

/// A length for a sentence, up to three decimals.
std::string mm(double value)
{
    return text::format(text::translate("core", "%1 mm"), {text::number(value, 3)});
}

/// An angle for a sentence, in degrees.
std::string deg(double radians)
{
    return joinText({text::number(radians / units::degree, 3), "°"});
}

double scaleOf(const FourBarDesign &d)
{
    return std::max({d.crank, d.coupler, d.rocker, d.ground});
}

/// C from δ: C = D + CD·(−cos δ, sin δ).
Eigen::Vector2d rockerJoint(const FourBarDesign &d, double delta)
{
    return {d.ground - d.rocker * std::cos(delta), d.rocker * std::sin(delta)};
}

Eigen::Vector2d crankJoint(const FourBarDesign &d, double alpha)
{
    return {d.crank * std::cos(alpha), d.crank * std::sin(alpha)};
}

/// δ of a rocker joint C, in (−π, π]… up to a turn: π − θ₃.
double deltaOf(const FourBarDesign &d, const Eigen::Vector2d &c)
{
    return pi - std::atan2(c.y(), c.x() - d.ground);
}

/// The value of `angle` + 2πk nearest `reference`.
double nearestTurn(double angle, double reference)
{
    return angle + 2.0 * pi * std::round((reference - angle) / (2.0 * pi));
}
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
        return T(rules, {
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
        });
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
    std::vector<double> deltas(rangeSamples + 1, 0.0);
    std::vector<double> alphas(rangeSamples + 1, 0.0);
    double previous = nan;
    double best = -1.0;
    for (int i = 0; i <= rangeSamples; ++i) {
        const double alpha = lo + (hi - lo) * i / rangeSamples;
        alphas[std::size_t(i)] = alpha;
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
                                        {deg(alpha)})};
        }
        const bool above = alpha > m_alphaRange.max;
        return Failure{FailureKind::OutOfRange, "alpha",
                       text::format(text::translate("core", "alpha = %1 is outside the range of the crank of this %2 "
                                                            "linkage, [%3, %4]: %5."),
                                    {deg(alpha), text::label(fourbar::grashofName(grashof(d))), deg(m_alphaRange.min),
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
                                    {deg(delta), deg(m_deltaRange.min), deg(m_deltaRange.max)})};
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

// -- analysis ------------------------------------------------------------------------------

namespace {
enum Slot {
    SlotAlpha, SlotDelta, SlotGamma, SlotDelta1, SlotBeta,
    SlotJq, SlotJx, SlotJ, SlotDetJ,
    SlotI31, SlotOmega1, SlotOmega2, SlotOmega3, SlotEpsilon2, SlotEpsilon3, SlotTransmission, SlotMargin,
    SlotBD, SlotMx, SlotMy, SlotPx, SlotPy,
    SlotCount
};

/// J_q = ∂F/∂α and J_x = −∂F/∂δ of F = |C − B|² − BC².
std::pair<double, double> jacobianParts(const FourBarDesign &d, double alpha, double delta)
{
    const Eigen::Vector2d D(d.ground, 0.0);
    const Eigen::Vector2d B = crankJoint(d, alpha), C = rockerJoint(d, delta);
    const Eigen::Vector2d dB = perp(B);         // dB/dα
    const Eigen::Vector2d dC = -perp(C - D);    // dC/dδ
    const double jq = -2.0 * (C - B).dot(dB);   // = 2·AB·BC·sin β
    const double jx = -2.0 * (C - B).dot(dC);   // = −2·BC·CD·sin γ
    return {jq, jx};
}
} // namespace

const ReportLayout &FourBar::reportLayout() const
{
    static const ReportLayout layout = [] {
        using G = ReportGroup;
        ReportLayout l;
        l.add(G::Pose, "alpha", "α", QT_TRANSLATE_NOOP("core", "crank angle at A, from AD counter-clockwise"), units::angle, 2);
        l.add(G::Pose, "delta", "δ", QT_TRANSLATE_NOOP("core", "rocker angle at D, from DA clockwise"), units::angle, 2);
        l.add(G::Pose, "gamma", "γ", QT_TRANSLATE_NOOP("core", "transmission angle at C, from CB to CD counter-clockwise (< 0: crossed)"), units::angle, 2);
        l.add(G::Pose, "delta1", "δ₁", QT_TRANSLATE_NOOP("core", "angle at D from DA to DB (4)"), units::angle, 2);
        l.add(G::Pose, "beta", "β", QT_TRANSLATE_NOOP("core", "angle at B from BA to BC, 360° − (α + γ + δ)"), units::angle, 2);
        l.add(G::Jacobian, "Jq", "J_q", QT_TRANSLATE_NOOP("core", "J_q = ∂F/∂α = 2·AB·BC·sin β (0: inverse singularity)"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "Jx", "J_x", QT_TRANSLATE_NOOP("core", "J_x = −∂F/∂δ = −2·BC·CD·sin γ (0: direct singularity)"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "J", "J", QT_TRANSLATE_NOOP("core", "α̇ = J·δ̇, J = J_q⁻¹·J_x = dα/dδ"), units::none, 4);
        l.add(G::Jacobian, "det_J", "det J", QT_TRANSLATE_NOOP("core", "determinant of J (0: direct, ∞: inverse singularity)"), units::none, 4);
        l.add(G::Derived, "i31", "i₃₁", QT_TRANSLATE_NOOP("core", "transfer function dδ/dα = ω₃/ω₁ = −(9)"), units::none, 4);
        l.add(G::Derived, "omega1", "ω₁", QT_TRANSLATE_NOOP("core", "crank angular velocity (constant)"), units::radianPerSecond, 3);
        l.add(G::Derived, "omega2", "ω₂", QT_TRANSLATE_NOOP("core", "coupler angular velocity, counter-clockwise"), units::radianPerSecond, 3);
        l.add(G::Derived, "omega3", "ω₃", QT_TRANSLATE_NOOP("core", "dδ/dt, exact (the document's (8) with the opposite sign)"), units::radianPerSecond, 3);
        l.add(G::Derived, "epsilon2", "ε₂", QT_TRANSLATE_NOOP("core", "coupler angular acceleration, counter-clockwise"), radianPerSecond2, 3);
        l.add(G::Derived, "epsilon3", "ε₃", QT_TRANSLATE_NOOP("core", "d²δ/dt² at constant ω₁, exact (not the document's (14))"), radianPerSecond2, 3);
        l.add(G::Derived, "transmission", "μ", QT_TRANSLATE_NOOP("core", "acute transmission angle min(|γ|, 180° − |γ|) (below 40°: poor)"), units::angle, 2);
        l.add(G::Derived, "margin", "m", QT_TRANSLATE_NOOP("core", "distance from the nearest singularity, min(|sin β|, |sin γ|)"), units::none, 4);
        l.add(G::Derived, "BD", "BD", QT_TRANSLATE_NOOP("core", "diagonal |BD|"), units::millimetre, 2);
        l.add(G::Derived, "M_x", "x_M", QT_TRANSLATE_NOOP("core", "coupler point M, x"), units::millimetre, 2);
        l.add(G::Derived, "M_y", "y_M", QT_TRANSLATE_NOOP("core", "coupler point M, y"), units::millimetre, 2);
        l.add(G::Derived, "P_x", "x_P", QT_TRANSLATE_NOOP("core", "instantaneous centre P of the coupler, x (none: AB ∥ DC)"), units::millimetre, 2);
        l.add(G::Derived, "P_y", "y_P", QT_TRANSLATE_NOOP("core", "instantaneous centre P of the coupler, y (none: AB ∥ DC)"), units::millimetre, 2);
        // exact values at singular poses (mechanism.h: AtSingularity)
        using S = AtSingularity;
        l.atSingularity("Jq", S::Zero, S::Computed);
        l.atSingularity("Jx", S::Computed, S::Zero);
        l.atSingularity("J", S::Infinite, S::Zero);
        l.atSingularity("det_J", S::Infinite, S::Zero);
        l.atSingularity("i31", S::Zero, S::Infinite);
        l.atSingularity("omega2", S::Computed, S::Infinite);
        l.atSingularity("omega3", S::Computed, S::Infinite);
        l.atSingularity("epsilon2", S::Computed, S::Infinite);
        l.atSingularity("epsilon3", S::Computed, S::Infinite);
        return l;
    }();
    return layout;
}

Singularity FourBar::singularity(const Pose &pose) const
{
    const fourbar::Angles a = fourbar::angles(m_design, pose.inputs[0], pose.outputs[0]);
    return classifySingularity(std::abs(std::sin(a.beta)), std::abs(std::sin(a.gamma)), singularTolerance);
}

Jacobians FourBar::jacobians(const Pose &pose) const
{
    const auto [jq, jx] = jacobianParts(m_design, pose.inputs[0], pose.outputs[0]);
    Jacobians j;
    j.inputs = Eigen::MatrixXd::Constant(1, 1, jq);
    j.outputs = Eigen::MatrixXd::Constant(1, 1, jx);
    j.full = Eigen::MatrixXd::Constant(1, 1, jx / jq);
    return j;
}

Singularity FourBar::evaluate(const Pose &pose, std::span<double> v) const
{
    const FourBarDesign &d = m_design;
    const double alpha = pose.inputs[0], delta = pose.outputs[0];
    const fourbar::Angles a = fourbar::angles(d, alpha, delta);
    v[SlotAlpha] = alpha;
    v[SlotDelta] = delta;
    v[SlotGamma] = a.gamma;
    v[SlotDelta1] = a.delta1;
    v[SlotBeta] = a.beta;
    const auto [jq, jx] = jacobianParts(d, alpha, delta);
    v[SlotJq] = jq;
    v[SlotJx] = jx;
    v[SlotJ] = jx / jq;
    v[SlotDetJ] = jx / jq;
    v[SlotI31] = jq / jx;
    const fourbar::Motion m = fourbar::motion(d, alpha, delta, d.omega1);
    v[SlotOmega1] = d.omega1;
    v[SlotOmega2] = m.omega2;
    v[SlotOmega3] = m.omega3;
    v[SlotEpsilon2] = m.epsilon2;
    v[SlotEpsilon3] = m.epsilon3;
    const double gamma = std::abs(a.gamma);
    v[SlotTransmission] = std::min(gamma, pi - gamma);
    const Eigen::Vector2d B = crankJoint(d, alpha), C = rockerJoint(d, delta);
    v[SlotBD] = (Eigen::Vector2d(d.ground, 0.0) - B).norm();
    const Eigen::Vector2d M = B + d.couplerPoint * (C - B);
    v[SlotMx] = M.x();
    v[SlotMy] = M.y();
    const Eigen::Vector2d P = fourbar::instantCentre(d, alpha, delta);
    v[SlotPx] = P.x();
    v[SlotPy] = P.y();
    const Singularity s = classifySingularity(std::abs(std::sin(a.beta)), std::abs(std::sin(a.gamma)), singularTolerance);
    v[SlotMargin] = s.margin;
    settleSingularValues(reportLayout(), v, s.type);
    return s;
}

std::vector<ReportText> FourBar::reportText(const Pose &) const
{
    return {{ReportGroup::Pose, "branch", fourbar::branchName(m_design.branch),
             QT_TRANSLATE_NOOP("core", "assembly branch: open (C left of B→D) or crossed")},
            {ReportGroup::Derived, "grashof", fourbar::grashofName(grashof(m_design)),
             QT_TRANSLATE_NOOP("core", "Grashof class from s + l against p + q")}};
}

std::vector<ModeAlternative> FourBar::modeNeighbours() const
{
    std::vector<ModeAlternative> neighbours;
    const int other = -m_design.branch;
    const ParameterSet changes = {{"branch", double(other)}};
    if (auto made = withParameters(changes))
        neighbours.push_back({other == fourbar::crossed ? QT_TRANSLATE_NOOP("core", "crossed branch (same crank angle)")
                                                        : QT_TRANSLATE_NOOP("core", "open branch (same crank angle)"),
                              changes, *made, true, {}});
    return neighbours;
}

KinematicChain FourBar::kinematicChain(const Pose &pose) const
{
    KinematicChain chain;
    chain.links = {text::translate("core", "ground AD"), text::translate("core", "crank AB"),
                   text::translate("core", "coupler BC"), text::translate("core", "rocker CD")};
    chain.pairs = {mobility::planarRevolute("A", 0, 1, Eigen::Vector2d(0.0, 0.0), true),
        mobility::planarRevolute("B", 1, 2, crankJoint(m_design, pose.inputs[0])),
        mobility::planarRevolute("C", 2, 3, rockerJoint(m_design, pose.outputs[0])),
        mobility::planarRevolute("D", 3, 0, Eigen::Vector2d(m_design.ground, 0.0))};
    chain.description
        = text::translate("core", "planar four-bar: ground AD, crank AB (driven at A), coupler BC, rocker CD");
    return chain;
}

// -- drawing -------------------------------------------------------------------------------

Scene FourBar::scene(const Pose &pose) const
{
    const FourBarDesign &d = m_design;
    const double alpha = pose.inputs[0], delta = pose.outputs[0];
    auto to3 = [](const Eigen::Vector2d &p) { return Eigen::Vector3d(p.x(), p.y(), 0.0); };
    const Eigen::Vector2d A(0.0, 0.0), D(d.ground, 0.0);
    const Eigen::Vector2d B = crankJoint(d, alpha), C = rockerJoint(d, delta);
    const Eigen::Vector2d M = B + d.couplerPoint * (C - B);
    const Eigen::Vector2d P = fourbar::instantCentre(d, alpha, delta);
    const fourbar::Angles a = fourbar::angles(d, alpha, delta);
    Scene s;
    s.joints.push_back({to3(A), "A", JointKind::Ground});
    s.joints.push_back({to3(D), "D", JointKind::Ground});
    s.joints.push_back({to3(B), "B", JointKind::Revolute});
    s.joints.push_back({to3(C), "C", JointKind::Revolute});
    s.joints.push_back({to3(M), "M", JointKind::Point});
    const bool parallel = !std::isfinite(P.x());
    if (!parallel)
        s.joints.push_back({to3(P), "P", JointKind::Point});
    s.bars.push_back({0, 1, BarKind::Ground, "AD"});
    s.bars.push_back({0, 2, BarKind::Crank, "AB"});
    s.bars.push_back({2, 3, BarKind::Coupler,
                      parallel ? text::translate("core", "BC (P at infinity: AB ∥ DC, the coupler translates)")
                               : std::string("BC")});
    s.bars.push_back({1, 3, BarKind::Link, "CD"});
    const double shortest = std::min({d.crank, d.coupler, d.rocker, d.ground});
    s.angles.push_back({0, 0.0, alpha, 0.3 * std::min(d.crank, d.ground), joinText({"α = ", text::number(alpha / units::degree, 1), "°"})});
    s.angles.push_back({1, pi, -delta, 0.3 * std::min(d.rocker, d.ground), joinText({"δ = ", text::number(delta / units::degree, 1), "°"})});
    const Eigen::Vector2d cb = B - C;
    s.angles.push_back({3, std::atan2(cb.y(), cb.x()), a.gamma, 0.3 * shortest,
                        joinText({"γ = ", text::number(a.gamma / units::degree, 1), "°"})});
    s.handles.push_back({2, text::translate("core", "drag to turn the crank (sets α, direct kinematics)")});
    s.handles.push_back({3, text::translate("core", "drag to swing the rocker (sets δ, inverse kinematics)")});
    ScenePolyline curve;
    curve.closed = m_fullTurn;
    curve.label = d.branch == fourbar::crossed ? text::translate("core", "coupler curve of M (crossed branch)")
                                               : text::translate("core", "coupler curve of M (open branch)");
    curve.points.reserve(m_curve.size());
    for (const Eigen::Vector2d &p : m_curve)
        curve.points.push_back(to3(p));
    s.polylines.push_back(std::move(curve));
    // constant over the motion: the crank's and the rocker's circles and the ground
    Eigen::AlignedBox3d extent;
    extent.extend(Eigen::Vector3d(-d.crank, -d.crank, 0.0));
    extent.extend(Eigen::Vector3d(d.crank, d.crank, 0.0));
    extent.extend(Eigen::Vector3d(d.ground - d.rocker, -d.rocker, 0.0));
    extent.extend(Eigen::Vector3d(d.ground + d.rocker, d.rocker, 0.0));
    for (const Eigen::Vector2d &p : m_curve)
        extent.extend(to3(p));
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(0.08 * scaleOf(d));
    s.extent = Eigen::AlignedBox3d(extent.min() - pad, extent.max() + pad);
    s.extent.min().z() = s.extent.max().z() = 0.0;
    return s;
}

Result<Pose> FourBar::dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const
{
    auto representative = [](double angle, double reference, const Interval &range) {
        // the turn of `angle` inside the range nearest the reference, else the nearest at all
        double best = nearestTurn(angle, reference);
        for (int k = -2; k <= 2; ++k) {
            const double candidate = nearestTurn(angle, reference) + 2.0 * pi * k;
            if (range.contains(candidate) && (!range.contains(best) || std::abs(candidate - reference) < std::abs(best - reference)))
                best = candidate;
        }
        return best;
    };
    if (handle == 0) {
        if (target.norm() < 1e-12 * scaleOf(m_design))
            return current;
        Coordinates inputs(1);
        inputs << representative(std::atan2(target.y(), target.x()), current.inputs[0], m_alphaRange);
        return solveDirect(inputs, &current);
    }
    if (handle == 1) {
        const Eigen::Vector2d fromD = target - Eigen::Vector2d(m_design.ground, 0.0);
        if (fromD.norm() < 1e-12 * scaleOf(m_design))
            return current;
        Coordinates outputs(1);
        outputs << representative(pi - std::atan2(fromD.y(), fromD.x()), current.outputs[0], m_deltaRange);
        return solveInverse(outputs, &current);
    }
    return Failure{FailureKind::UnknownName, {}, text::translate("core", "No handle with that index.")};
}

} // namespace pkm
