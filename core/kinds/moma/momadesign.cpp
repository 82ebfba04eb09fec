// MOMA's design (docs/mathematics.md, section 2): its parameters with their rules, the
// creation of a mechanism from them, and the warnings about a design that works but may
// disappoint (guides that cross inside their strokes).

#include "moma.h"
#include "momainternal.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

using moma::cross;
using moma::legName;

// -- design --------------------------------------------------------------------------------

namespace {
/// The one-side constraint is a switch: exactly 0 or 1.
Result<double> switchRule(const ParameterInfo &, double value)
{
    if (value != 0.0 && value != 1.0) {
        return Failure{FailureKind::InvalidParameter, "one_side",
                       text::format(text::translate("core", "one_side = %1 is invalid: it must be 0 (off) or 1 (on)."),
                                    {text::number(value)})};
    }
    return value;
}

/// α_i and γ_i given together both turn guide i.
template <int Leg>
Failure guideClash(double, double)
{
    const std::string alpha = "alpha" + legName(Leg), gamma = "gamma" + legName(Leg);
    return Failure{FailureKind::InvalidParameter, gamma,
                   text::format(text::translate("core", "%1 and %2 both turn guide %3: give one of them."),
                                {alpha, gamma, legName(Leg)})};
}

/// γ_i = α_i − 270°, read in [−180°, 180°] and written as α_i = 270° + γ_i brought into
/// [0°, 360°), so that every γ of its domain gives a valid α.
template <int Leg>
FieldAccess<MomaDesign> guideTurn()
{
    // γ = α − 270° cancels the leading digits of α: in radians, α₁ = 265° gave γ₁ =
    // −4.99999999999999° in every report. Worked in degrees and rounded to the 12 decimals
    // to which α (below 1000°, 15 significant digits) is known, γ reads as it was typed.
    return {[](const MomaDesign &d) {
                const double gamma = std::remainder(units::angle.toDisplay(d.alpha[Leg]) - 270.0, 360.0);
                return units::angle.fromDisplay(std::round(gamma * 1e12) / 1e12);
            },
            [](MomaDesign &d, double gamma) {
                const double alpha = std::fmod(270.0 + units::angle.toDisplay(gamma), 360.0);
                d.alpha[Leg] = units::angle.fromDisplay(alpha < 0 ? alpha + 360.0 : alpha);
            }};
}
} // namespace

const ParameterTable<MomaDesign> &Moma::table()
{
    using T = ParameterTable<MomaDesign>;
    using D = MomaDesign;
    static const T table = [] {
        const Interval coordinate{-1e5, 1e5};
        const Interval positive{0.0, 1e5};
        const Interval turn{-360.0 * units::degree, 360.0 * units::degree};
        const Interval halfTurn{-180.0 * units::degree, 180.0 * units::degree};
        const Interval sign{-1.0, 1.0};
        using G = ParameterGroup;
        // every given value against its own domain first, so that a bad γ is named as γ, not
        // as the α it would make
        // the modes by name in files and on screen ("β₁ = ahead, σ = right"), as other kinds'
        // modes: p_i = B_i + β_i·√… (7–9) puts the platform's foot on guide i behind the slider
        // for β_i = +1 and ahead of it for −1; σ = +1 puts the platform left of Z₁→Z₂
        const std::vector<std::pair<std::string, double>> ends = {{QT_TRANSLATE_NOOP("core", "behind"), 1.0},
                                                                  {QT_TRANSLATE_NOOP("core", "ahead"), -1.0}};
        const std::vector<std::pair<std::string, double>> sides = {{QT_TRANSLATE_NOOP("core", "left"), 1.0},
                                                                   {QT_TRANSLATE_NOOP("core", "right"), -1.0}};
        const ChangeRules rules{.unknownName = QT_TRANSLATE_NOOP("core", "MOMA has no parameter named '%1'."),
                                .order = CheckOrder::DomainsFirst};
        return T(rules, joinRows<MomaDesign>({
            {{"R1x", "x_R1", QT_TRANSLATE_NOOP("core", "guide 1 reference point, x"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.reference[0].x(); })},
            {{"R1y", "y_R1", QT_TRANSLATE_NOOP("core", "guide 1 reference point, y"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.reference[0].y(); })},
            {{"R2x", "x_R2", QT_TRANSLATE_NOOP("core", "guide 2 reference point, x"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.reference[1].x(); })},
            {{"R2y", "y_R2", QT_TRANSLATE_NOOP("core", "guide 2 reference point, y"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.reference[1].y(); })},
            {{"alpha1", "α₁", QT_TRANSLATE_NOOP("core", "direction of guide 1"), units::angle, G::Geometry, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.alpha[0]; })},
            {{"alpha2", "α₂", QT_TRANSLATE_NOOP("core", "direction of guide 2"), units::angle, G::Geometry, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.alpha[1]; })},
            {{"gamma1", "γ₁", QT_TRANSLATE_NOOP("core", "turn of guide 1 from the vertical (α₁ = 270° + γ₁)"), units::angle, G::Geometry, halfTurn, false, false, false, 2, 1}, guideTurn<0>(), nullptr, "alpha1", &guideClash<0>},
            {{"gamma2", "γ₂", QT_TRANSLATE_NOOP("core", "turn of guide 2 from the vertical (α₂ = 270° + γ₂)"), units::angle, G::Geometry, halfTurn, false, false, false, 2, 1}, guideTurn<1>(), nullptr, "alpha2", &guideClash<1>},
            {{"l1", "l₁", QT_TRANSLATE_NOOP("core", "length of link S₁"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.length[0]; })},
            {{"l2", "l₂", QT_TRANSLATE_NOOP("core", "length of link S₂"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.length[1]; })},
            {{"p_min", "p_min", QT_TRANSLATE_NOOP("core", "start of the stroke"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real<&D::strokeMin>()},
            {{"p_max", "p_max", QT_TRANSLATE_NOOP("core", "end of the stroke"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real<&D::strokeMax>()},
            {{"branch1", "β₁", QT_TRANSLATE_NOOP("core", "working mode of leg 1: sign in p₁ = B₁ ± √…"), units::none, G::Mode, sign, false, false, true, 0, 2, ends, {}, QT_TRANSLATE_NOOP("core", "working mode of leg 1: the platform behind slider Z₁ along guide 1 or ahead of it"), true}, T::sign([](auto &d) -> auto & { return d.branch[0]; }), &signRule},
            {{"branch2", "β₂", QT_TRANSLATE_NOOP("core", "working mode of leg 2: sign in p₂ = B₂ ± √…"), units::none, G::Mode, sign, false, false, true, 0, 2, ends, {}, QT_TRANSLATE_NOOP("core", "working mode of leg 2: the platform behind slider Z₂ along guide 2 or ahead of it"), true}, T::sign([](auto &d) -> auto & { return d.branch[1]; }), &signRule},
            {{"assembly", "σ", QT_TRANSLATE_NOOP("core", "assembly mode: +1 platform left of Z₁→Z₂"), units::none, G::Mode, sign, false, false, true, 0, 2, sides, {}, QT_TRANSLATE_NOOP("core", "assembly mode: the platform left or right of Z₁→Z₂"), true}, T::sign<&D::assembly>(), &signRule},
            {{"one_side", QT_TRANSLATE_NOOP("core", "one side"), QT_TRANSLATE_NOOP("core", "links kept on the inner side of the guides (1: on)"), units::none, G::Mode, Interval{0.0, 1.0}, false, false, true, 0, 1}, T::flag<&D::oneSide>(), &switchRule},
            {{"guide_width", "w_g", QT_TRANSLATE_NOOP("core", "drawn width of a guide"), units::millimetre, G::Drawing, positive, true, false, true, 1, 1}, T::real<&D::guideWidth>()},
        }, {actuatorRows<MomaDesign, 0>(ActuatorNames::Linear, [](auto &d) -> auto & { return d.actuators[0]; }), actuatorRows<MomaDesign, 1>(ActuatorNames::Linear, [](auto &d) -> auto & { return d.actuators[1]; }), loadRows<MomaDesign>(LoadNames::Force, [](auto &d) -> auto & { return d.load; })}));
    }();
    return table;
}

Result<MechanismPtr> Moma::create(const MomaDesign &design)
{
    if (auto checked = table().checkDomains(design); !checked)
        return checked.failure();
    if (auto modes = table().checkRules(design); !modes)
        return modes.failure();
    if (!(design.strokeMin < design.strokeMax)) {
        return Failure{FailureKind::InvalidParameter, "p_min",
                       text::format(text::translate("core", "p_min = %1 mm must be less than p_max = %2 mm."),
                                    {text::number(design.strokeMin), text::number(design.strokeMax)})};
    }
    // Two guides on one line whose strokes overlap let the slider joints coincide.
    const Eigen::Vector2d a1 = moma::direction(design.alpha[0]), a2 = moma::direction(design.alpha[1]);
    const Eigen::Vector2d r = design.reference[1] - design.reference[0];
    const double scale = std::max({1.0, design.length[0], design.length[1], r.norm()});
    if (std::abs(cross(a1, a2)) < 1e-9 && std::abs(cross(a1, r)) < 1e-9 * scale) {
        auto along = [&](int leg, double p) { return a1.dot(moma::sliderJoint(design, leg, p) - design.reference[0]); };
        const double lo1 = std::min(along(0, design.strokeMin), along(0, design.strokeMax));
        const double hi1 = std::max(along(0, design.strokeMin), along(0, design.strokeMax));
        const double lo2 = std::min(along(1, design.strokeMin), along(1, design.strokeMax));
        const double hi2 = std::max(along(1, design.strokeMin), along(1, design.strokeMax));
        if (lo1 <= hi2 && lo2 <= hi1) {
            return Failure{FailureKind::InvalidParameter, "R2x",
                           text::translate("core", "The guides lie on one line and their strokes overlap: the slider "
                                                   "joints Z₁ and Z₂ could coincide. Move R₂ or turn a guide.")};
        }
    }
    Moma candidate(design);
    if (!candidate.m_home.inputs.size()) {
        return Failure{FailureKind::Unreachable, "l1",
                       text::format(text::translate("core", "This configuration has no workspace: with l₁ = %1 mm, "
                                                            "l₂ = %2 mm and strokes [%3, %4] mm the links cannot meet "
                                                            "in the chosen working and assembly modes."),
                                    {text::number(design.length[0]), text::number(design.length[1]),
                                     text::number(design.strokeMin), text::number(design.strokeMax)})};
    }
    return MechanismPtr(new Moma(candidate));
}

std::vector<std::string> Moma::designWarnings() const
{
    std::vector<std::string> warnings;
    const Eigen::Vector2d a1 = moma::direction(m_design.alpha[0]), a2 = moma::direction(m_design.alpha[1]);
    // Crossing guides: the sliders can collide where the strokes cross.
    const Eigen::Vector2d r = m_design.reference[1] - m_design.reference[0];
    const double det = cross(a1, -a2);
    if (std::abs(det) > 1e-9) {
        const double p1 = cross(r, -a2) / det, p2 = cross(a1, r) / det;
        if (p1 >= m_design.strokeMin && p1 <= m_design.strokeMax && p2 >= m_design.strokeMin && p2 <= m_design.strokeMax)
            warnings.push_back(text::translate("core", "The guides cross inside their strokes: the sliders can collide there."));
    }
    return warnings;
}

} // namespace pkm
