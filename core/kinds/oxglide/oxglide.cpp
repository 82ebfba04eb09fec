// The O-X glide hybrid (docs/mathematics.md, section 3): its direct and inverse closed forms,
// the design and its checks, the joint variables, the kinematics and the analysis; the
// workspace area and maps are in oxglidemaps.cpp, the drawings in oxglidescene.cpp.

#include "oxglide.h"
#include "oxglideinternal.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

namespace {
using oxglide::heightWhereW;

std::string mm(double value)
{
    return formatMillimetres(value);
}

std::string point(const Eigen::Vector2d &p)
{
    return text::format(text::translate("core", "(%1, %2) mm"), {text::number(p.x(), 2), text::number(p.y(), 2)});
}
} // namespace

// -- closed forms --------------------------------------------------------------------------

namespace oxglide {

const char *formName(int form)
{
    return form == formX ? "X" : "O";
}

const char *formTitle(int form)
{
    return form == formX ? QT_TRANSLATE_NOOP("core", "crossed (X)") : QT_TRANSLATE_NOOP("core", "extended (O)");
}

DirectSolution direct(double rod, double width, double xAB, double xCD)
{
    DirectSolution solution;
    const double e = xCD - xAB - width; // 0: the crossing; its sign is the form
    const double radicand = 4.0 * rod * rod - e * e;
    if (radicand < -1e-12 * rod * rod)
        return solution;
    solution.platform = {0.5 * (xAB + xCD), 0.5 * std::sqrt(std::max(0.0, radicand))};
    solution.form = e > 0 ? formO : (e < 0 ? formX : 0);
    solution.valid = true;
    return solution;
}

Eigen::Vector2d inverse(double rod, double width, int form, const Eigen::Vector2d &platform)
{
    const double w = std::sqrt(std::max(0.0, rod * rod - platform.y() * platform.y()));
    const double sign = form == formX ? -1.0 : 1.0;
    return {platform.x() - 0.5 * width - sign * w, platform.x() + 0.5 * width + sign * w};
}

} // namespace oxglide

// -- design --------------------------------------------------------------------------------

namespace {
/// The form is a sign: exactly +1 (O) or −1 (X).
Result<double> formRule(const ParameterInfo &, double value)
{
    if (value != 1.0 && value != -1.0) {
        return Failure{FailureKind::InvalidParameter, "mode",
                       text::format(text::translate("core", "mode = %1 is invalid: it must be +1 (O, extended) or -1 "
                                                            "(X, crossed)."),
                                    {text::number(value)})};
    }
    return value;
}
} // namespace

const ParameterTable<OxGlideDesign> &OxGlide::table()
{
    using T = ParameterTable<OxGlideDesign>;
    using D = OxGlideDesign;
    static const T table = [] {
        const Interval positive{0.0, 1e5};
        const Interval coordinate{-1e5, 1e5};
        using G = ParameterGroup;
        const ChangeRules rules{.unknownName = QT_TRANSLATE_NOOP("core", "The O-X glide has no parameter named '%1'.")};
        return T(rules, joinRows<OxGlideDesign>({
            {{"l", "l", QT_TRANSLATE_NOOP("core", "rod length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::rod>()},
            {{"s", "s", QT_TRANSLATE_NOOP("core", "platform width"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::width>()},
            {{"L", "L", QT_TRANSLATE_NOOP("core", "transverse guide length (slider positions 0…L)"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::guideLength>()},
            {{"a", "a", QT_TRANSLATE_NOOP("core", "spacing of the transverse guides"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::spacing>()},
            {{"z_min", "z_min", QT_TRANSLATE_NOOP("core", "start of the longitudinal travel"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real<&D::zMin>()},
            {{"z_max", "z_max", QT_TRANSLATE_NOOP("core", "end of the longitudinal travel"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real<&D::zMax>()},
            {{"mode", QT_TRANSLATE_NOOP("core", "form"), QT_TRANSLATE_NOOP("core", "+1 extended (O), −1 crossed (X)"), units::none, G::Mode, Interval{-1.0, 1.0}, false, false, true, 0, 2, {{"O", 1.0}, {"X", -1.0}}}, T::sign<&D::form>(), &formRule},
        }, {actuatorRows<OxGlideDesign, 0>(ActuatorNames::Linear, [](auto &d) -> auto & { return d.actuators[0]; }), actuatorRows<OxGlideDesign, 1>(ActuatorNames::Linear, [](auto &d) -> auto & { return d.actuators[1]; }), loadRows<OxGlideDesign>(LoadNames::Force, [](auto &d) -> auto & { return d.load; })}));
    }();
    return table;
}

Result<MechanismPtr> OxGlide::create(const OxGlideDesign &d)
{
    if (auto checked = table().checkDomains(d); !checked)
        return checked.failure();
    // the form by this check, not by its row's rule (checkDesign): a design given as a value
    // has its own message
    if (d.form != oxglide::formO && d.form != oxglide::formX)
        return Failure{FailureKind::InvalidParameter, "mode",
                       text::translate("core", "mode must be +1 (O, extended) or -1 (X, crossed).")};
    if (!(d.width < 2.0 * d.rod)) {
        return Failure{FailureKind::InvalidParameter, "s",
                       text::format(text::translate("core", "s = %1 must be less than 2l = %2: a platform that wide keeps "
                                                            "the rods from ever crossing, so there is no X form."),
                                    {mm(d.width), mm(2.0 * d.rod)})};
    }
    if (!(d.guideLength > d.width)) {
        return Failure{FailureKind::InvalidParameter, "L",
                       text::format(text::translate("core", "L = %1 must be more than the platform width s = %2: with "
                                                            "guides that short the extended (O) form has no workspace."),
                                    {mm(d.guideLength), mm(d.width)})};
    }
    if (!(d.zMin < d.zMax)) {
        return Failure{FailureKind::InvalidParameter, "z_min",
                       text::format(text::translate("core", "z_min = %1 must be less than z_max = %2."),
                                    {mm(d.zMin), mm(d.zMax)})};
    }
    OxGlide candidate(d);
    if (!candidate.m_home.inputs.size()) {
        const std::string pattern =
            d.form == oxglide::formX
                ? text::translate("core", "The crossed (X) form has no workspace with L = %1, s = %2 and l = %3.")
                : text::translate("core", "The extended (O) form has no workspace with L = %1, s = %2 and l = %3.");
        return Failure{FailureKind::Unreachable, "L",
                       text::format(pattern, {mm(d.guideLength), mm(d.width), mm(d.rod)})};
    }
    return MechanismPtr(new OxGlide(candidate));
}

OxGlide::OxGlide(const OxGlideDesign &design)
    : m_design(design)
{
    m_bounds = formBounds(design.form);
    // Home: the platform over the middle of the guides, at the height that is farthest from
    // the singularities (rods at 45°) while leaving the most room sideways.
    const double l = design.rod;
    const double x = 0.5 * design.guideLength;
    double best = -1.0;
    // heights from the form's lowest slice up to l: a thin workspace near y = l is sampled too
    const double lowest = heightWhereW(l, 0.5 * (design.guideLength - design.form * design.width));
    constexpr int samples = 400;
    for (int i = 1; i < samples; ++i) {
        const double y = lowest + (l - lowest) * i / samples;
        auto pose = inverse({x, y}, 0.5 * (design.zMin + design.zMax));
        if (!pose)
            continue;
        const double w = std::sqrt(l * l - y * y);
        const double room = std::min({pose->inputs[0], design.guideLength - pose->inputs[0], pose->inputs[1],
                                      design.guideLength - pose->inputs[1]}) / design.guideLength;
        const double score = std::min(std::min(y, w) / l, 4.0 * room);
        if (score > best) {
            best = score;
            m_home = *pose;
        }
    }
}

Eigen::AlignedBox2d OxGlide::formBounds(int form) const
{
    const OxGlideDesign &d = m_design;
    const double l = d.rod, s = d.width, L = d.guideLength;
    Eigen::AlignedBox2d box;
    if (form == oxglide::formO) {
        // the widest slice is at the top (w = 0): x ∈ [s/2, L − s/2]
        box.extend(Eigen::Vector2d(0.5 * s, heightWhereW(l, 0.5 * (L - s))));
        box.extend(Eigen::Vector2d(L - 0.5 * s, l));
    } else {
        // the widest slice is where w = s/2: x ∈ [0, L]
        box.extend(Eigen::Vector2d(0.0, heightWhereW(l, 0.5 * (L + s))));
        box.extend(Eigen::Vector2d(L, l));
    }
    const Eigen::Vector2d pad = Eigen::Vector2d::Constant(0.02 * std::max(L, l));
    return {box.min() - pad, box.max() + pad};
}

Eigen::AlignedBox2d OxGlide::unionBounds() const
{
    return formBounds(oxglide::formX);
}

// -- joint variables -----------------------------------------------------------------------

const std::vector<VariableInfo> &OxGlide::variableInfo() const
{
    static const std::vector<VariableInfo> infos = {
        {"x_AB", "x_AB", QT_TRANSLATE_NOOP("core", "slider pair AB position (actuated)"), units::millimetre, true, 2},
        {"x_CD", "x_CD", QT_TRANSLATE_NOOP("core", "slider pair CD position (actuated)"), units::millimetre, true, 2},
        {"z", "z", QT_TRANSLATE_NOOP("core", "longitudinal position (actuated serial axis)"), units::millimetre, true, 2,
         true},
        {"x", "x", QT_TRANSLATE_NOOP("core", "platform centre T, x"), units::millimetre, false, 2},
        {"y", "y", QT_TRANSLATE_NOOP("core", "platform centre T, y"), units::millimetre, false, 2},
    };
    return infos;
}

Interval OxGlide::variableRange(int variable) const
{
    switch (variable) {
    case variableXAB:
    case variableXCD: return {0.0, m_design.guideLength};
    case variableZ: return {m_design.zMin, m_design.zMax};
    case variableX: return {m_bounds.min().x(), m_bounds.max().x()};
    default: return {std::max(0.0, m_bounds.min().y()), m_design.rod};
    }
}

Eigen::Vector2d OxGlide::crossingInputs(double x) const
{
    return {x - 0.5 * m_design.width, x + 0.5 * m_design.width};
}

// -- kinematics ----------------------------------------------------------------------------

Result<Pose> OxGlide::inverse(const Eigen::Vector2d &platform, double z) const
{
    const OxGlideDesign &d = m_design;
    const double l = d.rod;
    if (platform.y() > l * (1.0 + 1e-12)) {
        return Failure{FailureKind::Unreachable, "y",
                       text::format(text::translate("core", "The platform cannot reach %1: y is more than the rod length "
                                                            "l = %2."),
                                    {point(platform), mm(l)})};
    }
    if (platform.y() < 0.0) {
        return Failure{FailureKind::Unreachable, "y",
                       text::format(text::translate("core", "The platform cannot reach %1: it would pass the rod joints' "
                                                            "plane y = 0, where the rods lie along the guides (a direct "
                                                            "singularity)."),
                                    {point(platform)})};
    }
    const Eigen::Vector2d q = oxglide::inverse(l, d.width, d.form, platform);
    const double tolerance = 1e-9 * std::max(l, d.guideLength);
    const char *names[2] = {"x_AB", "x_CD"};
    for (int i = 0; i < 2; ++i) {
        if (q[i] < -tolerance || q[i] > d.guideLength + tolerance) {
            const std::string pattern =
                d.form == oxglide::formX
                    ? text::translate("core", "The crossed (X) form cannot reach %1: slider pair %2 would have to be at "
                                              "%3 = %4, off its guides (0…%5 mm).")
                    : text::translate("core", "The extended (O) form cannot reach %1: slider pair %2 would have to be at "
                                              "%3 = %4, off its guides (0…%5 mm).");
            const std::string message = text::format(pattern, {point(platform), i == 0 ? "AB" : "CD", names[i], mm(q[i]),
                                                               text::number(d.guideLength, 2)});
            return Failure{FailureKind::OutOfRange, names[i], message};
        }
    }
    Pose pose;
    pose.inputs.resize(3);
    pose.inputs << std::clamp(q[0], 0.0, d.guideLength), std::clamp(q[1], 0.0, d.guideLength), z;
    pose.outputs.resize(2);
    pose.outputs << platform.x(), platform.y();
    pose.mode = d.form;
    return pose;
}

Result<Pose> OxGlide::solveDirect(const Coordinates &inputs, const Pose *near) const
{
    const OxGlideDesign &d = m_design;
    const char *names[3] = {"x_AB", "x_CD", "z"};
    for (int i = 0; i < 3; ++i) {
        const Interval range = variableRange(i);
        if (!std::isfinite(inputs[i]))
            return Failure{FailureKind::OutOfRange, names[i],
                           text::format(text::translate("core", "%1 must be a finite number."), {names[i]})};
        if (!range.contains(inputs[i])) {
            const std::string pattern = i < 2 ? text::translate("core", "%1 = %2 is off the guides (%3…%4 mm).")
                                              : text::translate("core", "%1 = %2 is outside the travel (%3…%4 mm).");
            const std::string message = text::format(pattern, {names[i], text::format(text::translate("core", "%1 mm"), {text::numberOutside(inputs[i], range.min, range.max, 2)}), text::number(range.min, 2),
                                                               text::number(range.max, 2)});
            return Failure{FailureKind::OutOfRange, names[i], message};
        }
    }
    const double xAB = inputs[0], xCD = inputs[1];
    const auto solution = oxglide::direct(d.rod, d.width, xAB, xCD);
    const double e = xCD - xAB - d.width;
    if (!solution.valid) {
        return Failure{FailureKind::Unreachable, "x_CD",
                       text::format(text::translate("core", "The rods cannot reach the platform at x_AB = %1, x_CD = %2: "
                                                            "|x_CD − x_AB − s| = %3 is more than 2l = %4."),
                                    {mm(xAB), mm(xCD), mm(std::abs(e)), mm(2.0 * d.rod)})};
    }
    if (solution.form != 0 && solution.form != d.form && std::abs(e) > 1e-9 * d.rod) {
        // the positions hold the other form than the design's: X (less than s) in an O design, or O
        const std::string pattern =
            solution.form == oxglide::formX
                ? text::translate("core", "x_CD − x_AB = %1 is less than s = %2: these slider positions hold the crossed "
                                          "(X) form, and the mechanism is extended (O). At x_CD − x_AB = s the rods are "
                                          "parallel and the platform can swing (a singularity), so the pairs do not pass "
                                          "it on their own: switch the form to go on.")
                : text::translate("core", "x_CD − x_AB = %1 is more than s = %2: these slider positions hold the extended "
                                          "(O) form, and the mechanism is crossed (X). At x_CD − x_AB = s the rods are "
                                          "parallel and the platform can swing (a singularity), so the pairs do not pass "
                                          "it on their own: switch the form to go on.");
        const std::string message = text::format(pattern, {mm(xCD - xAB), mm(d.width)});
        // the pair that moved is the culprit (x_CD when both did or nothing says)
        const bool abMoved = near && near->inputs.size() == 3 && near->inputs[0] != xAB && near->inputs[1] == xCD;
        return Failure{FailureKind::Singular, abMoved ? "x_AB" : "x_CD", message};
    }
    Pose pose;
    pose.inputs = inputs;
    pose.outputs.resize(2);
    pose.outputs << solution.platform.x(), solution.platform.y();
    pose.mode = d.form;
    return pose;
}

Result<Pose> OxGlide::solveInverse(const Coordinates &outputs, const Pose *near) const
{
    for (int i = 0; i < 2; ++i) {
        if (!std::isfinite(outputs[i])) {
            const std::string name = i == 0 ? "x" : "y";
            return Failure{FailureKind::OutOfRange, name,
                           text::format(text::translate("core", "%1 must be a finite number."), {name})};
        }
    }
    const double z = near && near->inputs.size() == 3 ? near->inputs[2] : m_home.inputs[2];
    return inverse(outputs.head<2>(), z);
}

// -- analysis ------------------------------------------------------------------------------

namespace {
enum Slot {
    SlotXAB, SlotXCD, SlotZ, SlotX, SlotY,
    SlotJq, SlotJx = SlotJq + 4, SlotJ = SlotJx + 4, SlotDetJ = SlotJ + 4, SlotDetJq, SlotDetJx, SlotCond,
    SlotRodAngle, SlotCrossing, SlotMargin,
    SlotCount
};

/// u₁, u₂: the rods' components along the guides (platform joint minus rod joint).
Eigen::Vector2d rodRuns(const OxGlideDesign &d, const Pose &pose)
{
    const double x = pose.outputs[0];
    return {x - 0.5 * d.width - pose.inputs[0], x + 0.5 * d.width - pose.inputs[1]};
}
} // namespace

const ReportLayout &OxGlide::reportLayout() const
{
    static const ReportLayout layout = [] {
        using G = ReportGroup;
        ReportLayout l;
        l.add(G::Pose, "x_AB", "x_AB", QT_TRANSLATE_NOOP("core", "slider pair AB position"), units::millimetre, 2);
        l.add(G::Pose, "x_CD", "x_CD", QT_TRANSLATE_NOOP("core", "slider pair CD position"), units::millimetre, 2);
        l.add(G::Pose, "z", "z", QT_TRANSLATE_NOOP("core", "longitudinal position"), units::millimetre, 2);
        l.add(G::Pose, "x", "x", QT_TRANSLATE_NOOP("core", "platform centre T, x"), units::millimetre, 2);
        l.add(G::Pose, "y", "y", QT_TRANSLATE_NOOP("core", "platform centre T, y"), units::millimetre, 2);
        l.add(G::Jacobian, "Jq", "J_q", QT_TRANSLATE_NOOP("core", "J_q = diag(−2u₁, −2u₂), u_i the rods' runs along the guides"), units::millimetre, 1, 2, 2);
        l.add(G::Jacobian, "Jx", "J_x", QT_TRANSLATE_NOOP("core", "J_x rows (2u_i, 2y)"), units::millimetre, 1, 2, 2);
        l.add(G::Jacobian, "J", "J", QT_TRANSLATE_NOOP("core", "q̇ = J·ẋ of the planar part, J = −J_q⁻¹·J_x"), units::none, 3, 2, 2);
        l.add(G::Jacobian, "det_J", "det J", QT_TRANSLATE_NOOP("core", "determinant of J (0: direct, ∞: inverse singularity)"), units::none, 4);
        l.add(G::Jacobian, "det_Jq", "det J_q", QT_TRANSLATE_NOOP("core", "0 at an inverse singularity"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "det_Jx", "det J_x", QT_TRANSLATE_NOOP("core", "0 at a direct singularity"), units::squareMillimetre, 1);
        l.add(G::Jacobian, "cond", "κ(J)", QT_TRANSLATE_NOOP("core", "condition number of J"), units::none, 3);
        l.add(G::Derived, "rod_angle", "ψ", QT_TRANSLATE_NOOP("core", "angle between the rods and the guides (90°: the O↔X crossing)"), units::angle, 2);
        l.add(G::Derived, "crossing", "x_CD − x_AB − s", QT_TRANSLATE_NOOP("core", "distance from the O↔X crossing (0 there; > 0 O, < 0 X)"), units::millimetre, 2);
        l.add(G::Derived, "margin", "m", QT_TRANSLATE_NOOP("core", "distance from the nearest singularity (0 … 1)"), units::none, 4);
        // exact values at singular poses (mechanism.h: AtSingularity)
        l.atSingularityOfJ("det_Jq");
        return l;
    }();
    return layout;
}

Singularity OxGlide::singularity(const Pose &pose) const
{
    const double l = m_design.rod;
    const double y = pose.outputs[1];
    const double w = std::sqrt(std::max(0.0, l * l - y * y));
    // inverse: a rod perpendicular to its guide (w = 0); direct: the rods parallel (w = 0, the
    // crossing) or along the guides (y = 0)
    const double inverseMargin = w / l;
    const double directMargin = std::min(std::abs(y), w) / l;
    return classifySingularity(inverseMargin, directMargin, singularTolerance);
}

Jacobians OxGlide::jacobians(const Pose &pose) const
{
    const Eigen::Vector2d u = rodRuns(m_design, pose);
    const double y = pose.outputs[1];
    Eigen::Matrix3d jq = Eigen::Matrix3d::Zero();
    jq(0, 0) = -2.0 * u[0];
    jq(1, 1) = -2.0 * u[1];
    jq(2, 2) = 1.0; // the serial axis: z of the platform is the input z
    Eigen::Matrix<double, 3, 2> fx = Eigen::Matrix<double, 3, 2>::Zero();
    fx << 2.0 * u[0], 2.0 * y, 2.0 * u[1], 2.0 * y, 0.0, 0.0;
    Jacobians j;
    j.inputs = jq;
    j.outputs = -fx; // J_q·q̇ = J_x·ẋ in the interface's convention
    Eigen::Matrix<double, 3, 2> full = Eigen::Matrix<double, 3, 2>::Zero();
    full.row(0) << 1.0, y / u[0];
    full.row(1) << 1.0, y / u[1];
    j.full = full;
    return j;
}

Singularity OxGlide::evaluate(const Pose &pose, std::span<double> v) const
{
    const Eigen::Vector2d u = rodRuns(m_design, pose);
    const double y = pose.outputs[1];
    const double l = m_design.rod;
    v[SlotXAB] = pose.inputs[0];
    v[SlotXCD] = pose.inputs[1];
    v[SlotZ] = pose.inputs[2];
    v[SlotX] = pose.outputs[0];
    v[SlotY] = y;
    const double jq1 = -2.0 * u[0], jq2 = -2.0 * u[1];
    const double values[12] = {jq1, 0.0, 0.0, jq2, 2.0 * u[0], 2.0 * y, 2.0 * u[1], 2.0 * y,
                               1.0, y / u[0], 1.0, y / u[1]};
    std::copy(values, values + 12, v.begin() + SlotJq);
    const double detJq = jq1 * jq2, detJx = 4.0 * y * (u[0] - u[1]);
    v[SlotDetJq] = detJq;
    v[SlotDetJx] = detJx;
    v[SlotDetJ] = detJx / detJq;
    const double w = std::sqrt(std::max(0.0, l * l - y * y));
    // J's columns (1, 1) and (y/u₁, y/u₂) = ±(y/w)(1, −1) are orthogonal: κ = max(y/w, w/y)
    v[SlotCond] = (w > 0.0 && y > 0.0) ? std::max(y / w, w / y) : std::numeric_limits<double>::infinity();
    v[SlotRodAngle] = std::atan2(std::abs(y), w);
    v[SlotCrossing] = pose.inputs[1] - pose.inputs[0] - m_design.width;
    const Singularity s = singularity(pose);
    v[SlotMargin] = s.margin;
    settleSingularValues(reportLayout(), v, s.type);
    return s;
}

std::vector<ReportText> OxGlide::reportText(const Pose &) const
{
    return {{ReportGroup::Pose, "mode", oxglide::formName(m_design.form),
             QT_TRANSLATE_NOOP("core", "form of the pose: O extended, X crossed")}};
}

std::vector<ModeAlternative> OxGlide::modeNeighbours() const
{
    std::vector<ModeAlternative> neighbours;
    const int other = -m_design.form;
    const ParameterSet changes = {{"mode", double(other)}};
    if (auto made = withParameters(changes)) {
        const char *label = other == oxglide::formX
                                ? QT_TRANSLATE_NOOP("core", "crossed (X) form (same platform position)")
                                : QT_TRANSLATE_NOOP("core", "extended (O) form (same platform position)");
        neighbours.push_back({label, changes, *made, false, {}});
    }
    return neighbours;
}

// -- drawing -------------------------------------------------------------------------------

Result<Pose> OxGlide::dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const
{
    if (handle == 0) {
        Coordinates outputs(2);
        outputs << target.x(), target.y();
        return solveInverse(outputs, &current);
    }
    if (handle == 1 || handle == 2) {
        Coordinates inputs = current.inputs;
        inputs[handle - 1] = std::clamp(target.x(), 0.0, m_design.guideLength);
        // A drag stops short of the O↔X crossing, as the crossing animation does: on it the
        // platform can swing, and the values there are ∞ or undefined. The document's move
        // then ends at the last pose allowed.
        const double run = 0.5 * (inputs[1] - inputs[0] - m_design.width) * double(m_design.form);
        if (run < oxglide::crossingStopMargin * m_design.rod) {
            return Failure{FailureKind::Singular, handle == 1 ? "x_AB" : "x_CD",
                text::format(text::translate("core", "The drag stops short of the O↔X crossing at x_CD − x_AB = s = "
                                                     "%1 mm, where the rods are parallel and the platform can swing: "
                                                     "switch the form to go on."),
                    {text::number(m_design.width, 2)})};
        }
        return solveDirect(inputs, &current);
    }
    return Failure{FailureKind::UnknownName, {}, text::translate("core", "No handle with that index.")};
}

} // namespace pkm
