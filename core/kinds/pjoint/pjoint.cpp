// The active П-joint (docs/mathematics.md, section 1): its closed forms and Jacobians, the
// parameter table, the joint variables and the analysis; the planar drawing is in
// pjointscene.cpp, the solid model in pjoint3d.cpp.

#include "pjoint.h"

#include "actuatorparameters.h"
#include "capability.h"
#include "mobility.h"
#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
constexpr double infinity = std::numeric_limits<double>::infinity();
/// Relative tolerance for "at a limit" and "at a singularity" (scale-free quantities).
constexpr double relativeTolerance = 1e-9;

double radicand(const PJointDesign &p, double theta)
{
    const double k = p.k();
    return 1.0 + k * k + 2.0 * k * std::sin(theta);
}
} // namespace

namespace pjoint {

double constraint(const PJointDesign &p, double theta, double d)
{
    return p.a * p.a * radicand(p, theta) - d * d; // (1)
}

double diagonal(const PJointDesign &p, double theta)
{
    return p.a * std::sqrt(radicand(p, theta)); // (2)
}

double angle(const PJointDesign &p, double d)
{
    const double k = p.k();
    const double s = (d * d - p.a * p.a * (1.0 + k * k)) / (2.0 * p.a * p.a * k); // (3)
    if (s < -1.0 || s > 1.0)
        return std::numeric_limits<double>::quiet_NaN();
    const double c = std::sqrt(1.0 - s * s); // (4): the branch −90° < θ < 90°
    return std::atan2(s, c);                 // (5)
}

double jacobian(const PJointDesign &p, double theta)
{
    return p.a * p.k() * std::cos(theta) / std::sqrt(radicand(p, theta)); // (7)
}

double jacobianD(const PJointDesign &p, double theta)
{
    return 2.0 * diagonal(p, theta); // (10)
}

double jacobianTheta(const PJointDesign &p, double theta)
{
    return 2.0 * p.a * p.a * p.k() * std::cos(theta); // (11)
}

double jacobianDerivative(const PJointDesign &p, double theta)
{
    const double k = p.k();
    const double s = std::sin(theta);
    const double r = radicand(p, theta);
    return -p.a * k * (k + s) * (1.0 + k * s) / (r * std::sqrt(r));
}

double diagonalAcceleration(const PJointDesign &p, double theta, double thetaDot, double thetaDDot)
{
    // (18) with (19–20) corrected: the document drops θ̈ from the first term and writes θ̇
    // where θ̇² belongs in the second (docs/mathematics.md, section 1: the document's (19–20) drop θ̈).
    return jacobian(p, theta) * thetaDDot + jacobianDerivative(p, theta) * thetaDot * thetaDot;
}

double angularAcceleration(const PJointDesign &p, double theta, double thetaDot, double dDDot)
{
    return (dDDot - jacobianDerivative(p, theta) * thetaDot * thetaDot) / jacobian(p, theta);
}

double passiveAngle(const PJointDesign &p, double theta)
{
    return std::atan2(p.a * std::cos(theta), p.b + p.a * std::sin(theta));
}

double transmissionAngle(const PJointDesign &p, double theta)
{
    const double d = diagonal(p, theta);
    const double c = (p.a * p.a + d * d - p.b * p.b) / (2.0 * p.a * d);
    return std::acos(std::clamp(c, -1.0, 1.0));
}

double outputTorque(const PJointDesign &p, double theta, double force)
{
    return jacobian(p, theta) * force * 1e-3; // (13), N·mm → N·m
}

double actuatorForce(const PJointDesign &p, double theta, double torque)
{
    return torque * 1e3 / jacobian(p, theta); // (14)
}

double motorTorque(const PJointDesign &p, double force)
{
    return force * p.lead / (2.0 * pi * p.efficiency) * 1e-3; // (15), N·mm → N·m
}

double outputSpeed(const PJointDesign &p, double theta, double dDot)
{
    return dDot / jacobian(p, theta); // (8)
}

double outputResolution(const PJointDesign &p, double theta, double step)
{
    return step / jacobian(p, theta);
}

Interval recommendedRange(const PJointDesign &p, double share)
{
    // J peaks where sin θ = −k (k < 1) or −1/k (k > 1), and rises before and falls after it.
    const double k = p.k();
    const double peak = std::clamp(std::asin(-std::min(k, 1.0 / k)), p.thetaMin, p.thetaMax);
    const double threshold = share * jacobian(p, peak);
    // Bisection on a monotone stretch for the θ where J crosses the threshold.
    auto crossing = [&](double inside, double outside) {
        if (jacobian(p, outside) >= threshold)
            return outside;
        for (int i = 0; i < 60; ++i) {
            const double middle = 0.5 * (inside + outside);
            (jacobian(p, middle) >= threshold ? inside : outside) = middle;
        }
        return inside;
    };
    return {crossing(peak, p.thetaMin), crossing(peak, p.thetaMax)};
}

} // namespace pjoint

// -- design ------------------------------------------------------------------------------

namespace {
/// k and b given together: both would size the coupler.
Failure couplerClash(double k, double b)
{
    return Failure{FailureKind::InvalidParameter, "k",
                   text::format(text::translate("core", "k = %1 and b = %2 mm both set the coupler: give b or "
                                                        "k, not both."),
                                {text::number(k, 6), text::number(b, 6)})};
}
} // namespace

const ParameterTable<PJointDesign> &PJoint::table()
{
    using T = ParameterTable<PJointDesign>;
    using D = PJointDesign;
    static const T table = [] {
        const Interval positive{0.0, infinity};
        const Interval halfTurn{-90.0 * units::degree, 90.0 * units::degree};
        // as every other kind's actuators (actuatorparameters.h): beyond 1e9 a limit is no
        // actuator's, and its products would leave the range a report prints
        const Interval actuator{0.0, 1e9};
        using G = ParameterGroup;
        // k = b/a is kept as a ratio: it sizes the coupler from the crank (the new one, since
        // derived values are written after the stored ones)
        const FieldAccess<D> ratio{[](const D &d) { return d.k(); }, [](D &d, double k) { d.b = k * d.a; }};
        // createFrom() leaves every check to create(), which checks the design as a whole (a bad
        // k is named as the b it makes); withParameter() blames a change in its own words
        const ChangeRules rules{.unknownName = QT_TRANSLATE_NOOP("core", "The П-joint has no parameter named '%1'."),
                                .checkGiven = false,
                                .blameSingle = false};
        return T(rules, joinRows<D>({
            {{"a", "a", QT_TRANSLATE_NOOP("core", "crank (lever) length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::a>()},
            {{"b", "b", QT_TRANSLATE_NOOP("core", "base and coupler length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::b>()},
            {{"k", "k", QT_TRANSLATE_NOOP("core", "ratio k = b/a"), units::none, G::Geometry, positive, true, false, false, 4, 0.01}, ratio, nullptr, "b", &couplerClash},
            {{"theta_min", "θ_min", QT_TRANSLATE_NOOP("core", "lower limit of θ"), units::angle, G::Range, halfTurn, true, true, true, 2, 1}, T::real<&D::thetaMin>()},
            {{"theta_max", "θ_max", QT_TRANSLATE_NOOP("core", "upper limit of θ"), units::angle, G::Range, halfTurn, true, true, true, 2, 1}, T::real<&D::thetaMax>()},
            {{"lead", "h", QT_TRANSLATE_NOOP("core", "lead of the screw"), units::millimetrePerRevolution, G::Actuator, actuator, true, false, true, 4, 0.1}, T::real<&D::lead>()},
            {{"step", "Δd", QT_TRANSLATE_NOOP("core", "linear step"), units::millimetrePerStep, G::Actuator, actuator, true, false, true, 5, 0.001}, T::real<&D::step>()},
            {{"speed_max", "ḋ_max", QT_TRANSLATE_NOOP("core", "max. linear speed"), units::millimetrePerSecond, G::Actuator, actuator, true, false, true, 2, 1}, T::real<&D::speedMax>()},
            {{"force_max", "F_max", QT_TRANSLATE_NOOP("core", "max. thrust force"), units::newton, G::Actuator, actuator, true, false, true, 1, 5}, T::real<&D::forceMax>()},
            {{"efficiency", "η", QT_TRANSLATE_NOOP("core", "screw efficiency"), units::none, G::Actuator, Interval{0.0, 1.0}, true, false, true, 3, 0.01}, T::real<&D::efficiency>()},
            {{"stiffness", "k_d", QT_TRANSLATE_NOOP("core", "axial stiffness of the actuator"), units::newtonPerMillimetre, G::Actuator, actuator, true, false, true, 0, 100}, T::real<&D::stiffness>()},
            {{"stiffness_measured", "K_m", QT_TRANSLATE_NOOP("core", "measured static stiffness of the joint"), units::newtonMetrePerRadian, G::Actuator, actuator, true, false, true, 0, 1000}, T::real<&D::stiffnessMeasured>()},
            {{"motor_length", "L_M", QT_TRANSLATE_NOOP("core", "motor body length"), units::millimetre, G::Drawing, positive, true, false, true, 1, 1}, T::real<&D::motorLength>()},
            {{"motor_width", "W_M", QT_TRANSLATE_NOOP("core", "motor body width"), units::millimetre, G::Drawing, positive, true, false, true, 1, 1}, T::real<&D::motorWidth>()},
            {{"screw_diameter", "d_s", QT_TRANSLATE_NOOP("core", "screw diameter"), units::millimetre, G::Drawing, positive, true, false, true, 4, 0.1}, T::real<&D::screwDiameter>()},
        }, {loadRows<D>(LoadNames::Torque, [](auto &d) -> auto & { return d.load; })}));
    }();
    return table;
}

Result<MechanismPtr> PJoint::create(const PJointDesign &design)
{
    // A design far outside any real proportion (a = 1e-300 mm) would give k, d or J that are
    // not finite numbers: refuse it rather than show them. Before the fields are checked, so
    // that a k of 1e308 is blamed as itself, not as the b = ∞ it makes.
    const double k = design.k();
    const bool sized = std::isfinite(design.a) && design.a > 0.0 && design.b > 0.0; // else a and b are blamed below
    if (sized && !(k >= 1e-6 && k <= 1e6)) {
        return Failure{FailureKind::InvalidParameter, "k",
                       text::format(text::translate("core", "k = b/a = %1 is out of proportion: it must lie between 1e-6 "
                                                            "and 1e6."),
                                    {std::isnan(k) ? std::string("?") : std::isinf(k) ? std::string("∞") : text::number(k, 6)})};
    }
    if (auto checked = table().checkDesign(design); !checked)
        return checked.failure();
    if (!(design.thetaMin < design.thetaMax)) {
        return Failure{FailureKind::InvalidParameter, "theta_min",
                       text::format(text::translate("core", "theta_min = %1° must be less than theta_max = %2°."),
                                    {text::number(units::angle.toDisplay(design.thetaMin)),
                                     text::number(units::angle.toDisplay(design.thetaMax))})};
    }
    return MechanismPtr(new PJoint(design));
}

PJoint::PJoint(const PJointDesign &design)
    : m_design(design)
    , m_recommended(pjoint::recommendedRange(design))
{
}

Result<MechanismPtr> PJoint::withParameter(std::string_view name, double value) const
{
    auto made = withParameters({{std::string(name), value}});
    // A failure of a check across parameters (θ_min < θ_max, a computable k) is about the
    // parameter that was just changed.
    if (!made && made.failure().kind == FailureKind::InvalidParameter && made.failure().culprit != name) {
        Failure f = made.failure();
        f.culprit = std::string(name);
        if (name == "theta_max" && made.failure().culprit == "theta_min") {
            f.message = text::format(text::translate("core", "theta_max = %1° must be greater than theta_min = %2°."),
                                     {text::number(units::angle.toDisplay(value)),
                                      text::number(units::angle.toDisplay(m_design.thetaMin))});
        } else {
            f.message = joinText({name, ": ", f.message});
        }
        return f;
    }
    return made;
}

std::vector<std::string> PJoint::designWarnings() const
{
    std::vector<std::string> warnings;
    if (m_design.motorLength >= dMin()) {
        warnings.push_back(text::format(text::translate("core", "The motor body (%1 mm) is longer than d_min = %2 mm: "
                                                                "the diagonal cannot retract that far."),
                                        {text::number(m_design.motorLength, 1), text::number(dMin(), 1)}));
    }
    return warnings;
}

// -- joint variables ---------------------------------------------------------------------

const std::vector<VariableInfo> &PJoint::variableInfo() const
{
    static const std::vector<VariableInfo> infos = {
        {"d", "d", QT_TRANSLATE_NOOP("core", "diagonal length (actuated)"), units::millimetre, true, 2},
        {"theta", "θ", QT_TRANSLATE_NOOP("core", "output angle"), units::angle, false, 2},
    };
    return infos;
}

double PJoint::dMin() const
{
    return pjoint::diagonal(m_design, m_design.thetaMin);
}

double PJoint::dMax() const
{
    return pjoint::diagonal(m_design, m_design.thetaMax);
}

Interval PJoint::variableRange(int variable) const
{
    if (variable == variableD)
        return {dMin(), dMax()};
    return {m_design.thetaMin, m_design.thetaMax};
}

Pose PJoint::homePose() const
{
    const double theta = std::clamp(0.0, m_design.thetaMin, m_design.thetaMax);
    return *solveInverse(Coordinates::Constant(1, theta));
}

Result<Pose> PJoint::solveDirect(const Coordinates &inputs, const Pose *) const
{
    const double d = inputs[0];
    const PJointDesign &p = m_design;
    if (!std::isfinite(d))
        return Failure{FailureKind::OutOfRange, "d", text::format(text::translate("core", "%1 must be a finite number."), {"d"})};
    // The stroke, d(θ_min)…d(θ_max), is what the user may ask for; past |a − b|…a + b the
    // parallelogram could not even close, which makes it unreachable rather than out of range.
    const Interval range = variableRange(variableD);
    const double tolerance = relativeTolerance * (p.a + p.b);
    if (!range.contains(d, tolerance)) {
        const bool closes = d >= std::abs(p.a - p.b) && d <= p.a + p.b;
        return Failure{closes ? FailureKind::OutOfRange : FailureKind::Unreachable, "d",
                       text::format(text::translate("core", "d = %1 mm is outside the stroke [%2, %3] mm that the θ "
                                                            "range allows."),
                                    {text::number(d), text::number(range.min), text::number(range.max)})};
    }
    const double theta = std::clamp(pjoint::angle(p, range.clamp(d)), p.thetaMin, p.thetaMax);
    Pose pose;
    pose.inputs = Coordinates::Constant(1, d);
    pose.outputs = Coordinates::Constant(1, theta);
    return pose;
}

Result<Pose> PJoint::solveInverse(const Coordinates &outputs, const Pose *) const
{
    const double theta = outputs[0];
    if (!std::isfinite(theta))
        return Failure{FailureKind::OutOfRange, "theta",
                       text::format(text::translate("core", "%1 must be a finite number."), {"θ"})};
    const Interval range = variableRange(variableTheta);
    if (!range.contains(theta, relativeTolerance)) {
        return Failure{FailureKind::OutOfRange, "theta",
                       text::format(text::translate("core", "θ = %1° is outside the design range [%2, %3]°."),
                                    {text::numberOutside(units::angle.toDisplay(theta), units::angle.toDisplay(range.min),
                                                         units::angle.toDisplay(range.max)),
                                     text::number(units::angle.toDisplay(range.min)),
                                     text::number(units::angle.toDisplay(range.max))})};
    }
    const double clamped = range.clamp(theta);
    Pose pose;
    pose.outputs = Coordinates::Constant(1, clamped);
    pose.inputs = Coordinates::Constant(1, pjoint::diagonal(m_design, clamped));
    return pose;
}

// -- analysis ----------------------------------------------------------------------------

namespace {
enum Slot {
    SlotTheta, SlotD, SlotPhi, SlotMu,
    SlotJ, SlotJInv, SlotJd, SlotJTheta, SlotDJ,
    SlotTorque, SlotSpeed, SlotResolution, SlotMotorTorque, SlotDMin, SlotDMax, SlotStroke,
    SlotRecommendedMin, SlotRecommendedMax,
    SlotCount
};
} // namespace

const ReportLayout &PJoint::reportLayout() const
{
    static const ReportLayout layout = [] {
        using G = ReportGroup;
        ReportLayout l;
        l.add(G::Pose, "theta", "θ", QT_TRANSLATE_NOOP("core", "output angle"), units::angle, 2);
        l.add(G::Pose, "d", "d", QT_TRANSLATE_NOOP("core", "diagonal length"), units::millimetre, 2);
        l.add(G::Pose, "phi", "φ", QT_TRANSLATE_NOOP("core", "passive angle of the diagonal"), units::angle, 2);
        l.add(G::Pose, "mu", "μ", QT_TRANSLATE_NOOP("core", "transmission angle"), units::angle, 2);
        l.add(G::Jacobian, "J", "J", QT_TRANSLATE_NOOP("core", "Jacobian ḋ = J·θ̇"), units::millimetrePerRadian, 3);
        l.add(G::Jacobian, "J_inv", "J⁻¹", QT_TRANSLATE_NOOP("core", "inverse Jacobian θ̇ = J⁻¹·ḋ"), units::radianPerMillimetre, 5);
        l.add(G::Jacobian, "J_d", "J_d", QT_TRANSLATE_NOOP("core", "J_d = 2d"), units::millimetre, 2);
        l.add(G::Jacobian, "J_theta", "J_θ", QT_TRANSLATE_NOOP("core", "J_θ = 2a²k·cos θ"), units::squareMillimetrePerRadian, 1);
        l.add(G::Jacobian, "dJ_dtheta", "∂J/∂θ", QT_TRANSLATE_NOOP("core", "derivative of J"), units::millimetrePerRadian2, 3);
        l.add(G::Derived, "torque", "T", QT_TRANSLATE_NOOP("core", "output torque at F_max"), units::newtonMetre, 3);
        l.add(G::Derived, "speed", "ω", QT_TRANSLATE_NOOP("core", "output speed θ̇ at ḋ_max"), units::radianPerSecond, 4);
        l.add(G::Derived, "resolution", "Δθ", QT_TRANSLATE_NOOP("core", "output resolution per step"), units::anglePerStep, 5);
        l.add(G::Derived, "motor_torque", "T_M", QT_TRANSLATE_NOOP("core", "motor torque at F_max"), units::newtonMetre, 4);
        l.add(G::Derived, "d_min", "d_min", QT_TRANSLATE_NOOP("core", "diagonal at θ_min"), units::millimetre, 2);
        l.add(G::Derived, "d_max", "d_max", QT_TRANSLATE_NOOP("core", "diagonal at θ_max"), units::millimetre, 2);
        l.add(G::Derived, "stroke", "d_max − d_min", QT_TRANSLATE_NOOP("core", "actuator stroke"), units::millimetre, 2);
        l.add(G::Derived, "recommended_min", "θ_rec,min", QT_TRANSLATE_NOOP("core", "recommended range from (J ≥ 60 % of best)"), units::angle, 1);
        l.add(G::Derived, "recommended_max", "θ_rec,max", QT_TRANSLATE_NOOP("core", "recommended range to (J ≥ 60 % of best)"), units::angle, 1);
        // exact values at singular poses (mechanism.h: AtSingularity)
        using S = AtSingularity;
        l.atSingularity("J", S::Infinite, S::Zero);
        l.atSingularity("J_inv", S::Zero, S::Infinite);
        l.atSingularity("J_d", S::Zero, S::Computed);
        l.atSingularity("J_theta", S::Computed, S::Zero);
        l.atSingularity("torque", S::Infinite, S::Zero);
        l.atSingularity("speed", S::Zero, S::Infinite);
        l.atSingularity("resolution", S::Zero, S::Infinite);
        return l;
    }();
    return layout;
}

Singularity PJoint::singularity(double theta) const
{
    // Scale-free measures: |J_θ|/(2a²k) = |cos θ| and |J_d|/(2(a+b)) = d/(a+b).
    const double directMeasure = std::abs(std::cos(theta));
    const double inverseMeasure = pjoint::diagonal(m_design, theta) / (m_design.a + m_design.b);
    const bool direct = directMeasure < relativeTolerance;
    const bool inverse = inverseMeasure < relativeTolerance;
    Singularity s;
    s.type = direct && inverse ? SingularityType::Combined
           : direct            ? SingularityType::Direct
           : inverse           ? SingularityType::Inverse
                               : SingularityType::None;
    // Every singularity of the П-joint lies at θ = ±90° (the inverse one only together with the
    // direct one, for k = 1): |cos θ| is the distance to the nearest.
    s.margin = directMeasure;
    s.directMargin = directMeasure;
    return s;
}

Singularity PJoint::evaluate(const Pose &pose, std::span<double> v) const
{
    const PJointDesign &p = m_design;
    const double theta = pose.outputs[0];
    const double d = pose.inputs[0];
    const double J = pjoint::jacobian(p, theta);
    v[SlotTheta] = theta;
    v[SlotD] = d;
    v[SlotPhi] = pjoint::passiveAngle(p, theta);
    v[SlotMu] = pjoint::transmissionAngle(p, theta);
    v[SlotJ] = J;
    v[SlotJInv] = 1.0 / J;
    v[SlotJd] = 2.0 * d;
    v[SlotJTheta] = pjoint::jacobianTheta(p, theta);
    v[SlotDJ] = pjoint::jacobianDerivative(p, theta);
    v[SlotTorque] = pjoint::outputTorque(p, theta, p.forceMax);
    v[SlotSpeed] = pjoint::outputSpeed(p, theta, p.speedMax);
    v[SlotResolution] = pjoint::outputResolution(p, theta, p.step);
    v[SlotMotorTorque] = pjoint::motorTorque(p, p.forceMax);
    v[SlotDMin] = dMin();
    v[SlotDMax] = dMax();
    v[SlotStroke] = v[SlotDMax] - v[SlotDMin];
    v[SlotRecommendedMin] = m_recommended.min;
    v[SlotRecommendedMax] = m_recommended.max;
    const Singularity s = singularity(theta);
    settleSingularValues(reportLayout(), v, s.type);
    return s;
}

Jacobians PJoint::jacobians(const Pose &pose) const
{
    const double theta = pose.outputs[0];
    Jacobians j;
    j.inputs = Eigen::MatrixXd::Constant(1, 1, pjoint::jacobianD(m_design, theta));
    j.outputs = Eigen::MatrixXd::Constant(1, 1, pjoint::jacobianTheta(m_design, theta));
    j.full = Eigen::MatrixXd::Constant(1, 1, pjoint::jacobian(m_design, theta));
    return j;
}

KinematicChain PJoint::kinematicChain(const Pose &pose) const
{
    const double theta = pose.outputs[0];
    const Eigen::Vector2d crank = m_design.a * Eigen::Vector2d(std::sin(theta), std::cos(theta));
    const Eigen::Vector2d o(0.0, 0.0), b(m_design.b, 0.0), a = b + crank, c = o + crank;
    enum { Ground, CrankBA, CrankOC, Coupler, Motor, Screw };
    KinematicChain chain;
    chain.links = {text::translate("core", "ground OB"), text::translate("core", "crank BA"),
                   text::translate("core", "crank OC"), text::translate("core", "coupler CA"),
                   text::translate("core", "motor body"), text::translate("core", "screw")};
    chain.pairs = {mobility::planarRevolute("O", Ground, CrankOC, o), mobility::planarRevolute("B", Ground, CrankBA, b),
        mobility::planarRevolute("C", CrankOC, Coupler, c), mobility::planarRevolute("A", CrankBA, Coupler, a),
        mobility::planarRevolute(text::translate("core", "O (motor)"), Ground, Motor, o),
        mobility::planarRevolute(text::translate("core", "A (screw)"), CrankBA, Screw, a),
        mobility::planarPrismatic("d", Motor, Screw, o, a - o, true)};
    chain.description = text::translate("core", "active П-joint: hinged parallelogram OBAC with the telescopic "
                                                "diagonal OA (motor body and screw)");
    return chain;
}

} // namespace pkm
