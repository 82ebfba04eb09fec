// The parameters of a design of the leg library: the platform, each leg's type, working mode
// and dimensions, with the rules a value must keep (a whole number, a sign), as the Design
// panel, the design files and "pkm … --set NAME=VALUE" name them.
#include "planarparallel.h"

#include "text.h"

#include <cmath>
#include <numbers>
#include <string>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;

/// The leg types and platforms are small integers: exactly 0…3 (0…2).
Result<double> integerRule(const ParameterInfo &info, double value)
{
    if (value != std::round(value)) {
        return Failure{FailureKind::InvalidParameter, info.name,
                       text::format(text::translate("core", "%1 = %2 is invalid: it must be a whole number."),
                                    {info.name, text::number(value)})};
    }
    return value;
}

/// The assembly mode: ±1 (2 DOF) or 1…6 (3 DOF), checked against the platform by create().
Result<double> assemblyRule(const ParameterInfo &info, double value)
{
    if (value == 0.0)
        return Failure{FailureKind::InvalidParameter, info.name,
                       text::format(text::translate("core", "%1 = %2 is invalid: it must be -1 or +1."),
                                    {info.name, text::number(value)})};
    return integerRule(info, value);
}

template <int Leg>
FieldAccess<PlanarParallelDesign> legTypeField()
{
    return {[](const PlanarParallelDesign &d) { return double(int(d.legs[Leg].type)); },
            [](PlanarParallelDesign &d, double v) { d.legs[Leg].type = LegType(int(std::lround(v))); }};
}

FieldAccess<PlanarParallelDesign> assemblyField()
{
    return {[](const PlanarParallelDesign &d) { return double(d.assembly); },
            [](PlanarParallelDesign &d, double v) { d.assembly = int(std::lround(v)); }};
}

FieldAccess<PlanarParallelDesign> platformField()
{
    return {[](const PlanarParallelDesign &d) { return double(int(d.platform)); },
            [](PlanarParallelDesign &d, double v) { d.platform = PlatformType(int(std::lround(v))); }};
}
} // namespace

const ParameterTable<PlanarParallelDesign> &PlanarParallel::table()
{
    using T = ParameterTable<PlanarParallelDesign>;
    static const T table = [] {
        const Interval coordinate{-1e5, 1e5};
        const Interval positive{0.0, 1e5};
        const Interval turn{-360.0 * units::degree, 360.0 * units::degree};
        const Interval sign{-1.0, 1.0};
        const Interval legType{0.0, 3.0};
        using G = ParameterGroup;
        // the leg types and the platform in files by name, as numeric codes in the table
        const std::vector<std::pair<std::string, double>> legTypeChoices
            = {{"RRR", 0.0}, {"PRR", 1.0}, {"RPR", 2.0}, {"PiRR", 3.0}};
        const std::vector<std::string> platformLabels = {QT_TRANSLATE_NOOP("core", "point"),
            QT_TRANSLATE_NOOP("core", "constant orientation"), QT_TRANSLATE_NOOP("core", "free body")};
        const std::vector<std::string> legTypeLabels = {"R̲RR", "P̲RR", "RP̲R", "П̲RR"};
        const std::vector<std::pair<std::string, double>> sideChoices = {{"left", 1.0}, {"right", -1.0}};
        const ChangeRules rules{.unknownName = QT_TRANSLATE_NOOP("core", "The planar parallel mechanism has no parameter named '%1'."),
                                .order = CheckOrder::DomainsFirst};
        return T(rules, joinRows<PlanarParallelDesign>({
            {{"platform", "τ_P", QT_TRANSLATE_NOOP("core", "platform: 0 a point (2 DOF), 1 constant orientation (2 DOF), 2 free (3 DOF)"), units::none, G::Mode, Interval{0.0, 2.0}, false, false, true, 0, 1, {{"point", 0.0}, {"translating", 1.0}, {"free", 2.0}}, platformLabels, QT_TRANSLATE_NOOP("core", "platform: 2 DOF as a point or with constant orientation, 3 as a free body")}, platformField(), &integerRule},
            {{"leg1_type", "τ₁", QT_TRANSLATE_NOOP("core", "leg 1: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)"), units::none, G::Mode, legType, false, false, true, 0, 1, legTypeChoices, legTypeLabels, QT_TRANSLATE_NOOP("core", "leg 1: type (the actuated joint underlined)")}, legTypeField<0>(), &integerRule},
            {{"A1x", "x_A₁", QT_TRANSLATE_NOOP("core", "leg 1: base point A₁, x"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].base.x(); })},
            {{"A1y", "y_A₁", QT_TRANSLATE_NOOP("core", "leg 1: base point A₁, y"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].base.y(); })},
            {{"B1x", "x_B₁", QT_TRANSLATE_NOOP("core", "leg 1: platform point B₁ in the platform frame, x"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].platform.x(); })},
            {{"B1y", "y_B₁", QT_TRANSLATE_NOOP("core", "leg 1: platform point B₁ in the platform frame, y"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].platform.y(); })},
            {{"r1", "r₁", QT_TRANSLATE_NOOP("core", "leg 1: crank length (R̲RR)"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].crank; })},
            {{"l1", "l₁", QT_TRANSLATE_NOOP("core", "leg 1: distal link length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].link; })},
            {{"alpha1", "α₁", QT_TRANSLATE_NOOP("core", "leg 1: direction of the guide (P̲RR) or of the П-joint base (П̲RR)"), units::angle, G::Geometry, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].alpha; })},
            {{"a1", "a₁", QT_TRANSLATE_NOOP("core", "leg 1: П-joint crank (lever) length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].lever; })},
            {{"k1", "k₁", QT_TRANSLATE_NOOP("core", "leg 1: П-joint ratio k = b/a"), units::none, G::Geometry, positive, true, false, true, 3, 0.05}, T::real([](auto &d) -> auto & { return d.legs[0].ratio; })},
            {{"q1_min", "q₁_min", QT_TRANSLATE_NOOP("core", "leg 1: lower limit of the input (P̲RR, RP̲R, П̲RR)"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].range.min; })},
            {{"q1_max", "q₁_max", QT_TRANSLATE_NOOP("core", "leg 1: upper limit of the input (P̲RR, RP̲R, П̲RR)"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].range.max; })},
            {{"theta1_min", "θ₁_min", QT_TRANSLATE_NOOP("core", "leg 1: lower limit of the crank angle (R̲RR)"), units::angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].crankRange.min; })},
            {{"theta1_max", "θ₁_max", QT_TRANSLATE_NOOP("core", "leg 1: upper limit of the crank angle (R̲RR)"), units::angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[0].crankRange.max; })},
            {{"working1", "w₁", QT_TRANSLATE_NOOP("core", "leg 1: working mode (+1 elbow left of A₁→P₁; P̲RR: sign in q = B ± √…)"), units::none, G::Mode, sign, false, false, true, 0, 2, sideChoices, {}, QT_TRANSLATE_NOOP("core", "leg 1: working mode, the elbow left or right of A₁→P₁ (P̲RR: left, the root q = B + √…)")}, T::sign([](auto &d) -> auto & { return d.legs[0].working; }), &signRule},
            {{"leg2_type", "τ₂", QT_TRANSLATE_NOOP("core", "leg 2: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)"), units::none, G::Mode, legType, false, false, true, 0, 1, legTypeChoices, legTypeLabels, QT_TRANSLATE_NOOP("core", "leg 2: type (the actuated joint underlined)")}, legTypeField<1>(), &integerRule},
            {{"A2x", "x_A₂", QT_TRANSLATE_NOOP("core", "leg 2: base point A₂, x"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].base.x(); })},
            {{"A2y", "y_A₂", QT_TRANSLATE_NOOP("core", "leg 2: base point A₂, y"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].base.y(); })},
            {{"B2x", "x_B₂", QT_TRANSLATE_NOOP("core", "leg 2: platform point B₂ in the platform frame, x"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].platform.x(); })},
            {{"B2y", "y_B₂", QT_TRANSLATE_NOOP("core", "leg 2: platform point B₂ in the platform frame, y"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].platform.y(); })},
            {{"r2", "r₂", QT_TRANSLATE_NOOP("core", "leg 2: crank length (R̲RR)"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].crank; })},
            {{"l2", "l₂", QT_TRANSLATE_NOOP("core", "leg 2: distal link length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].link; })},
            {{"alpha2", "α₂", QT_TRANSLATE_NOOP("core", "leg 2: direction of the guide (P̲RR) or of the П-joint base (П̲RR)"), units::angle, G::Geometry, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].alpha; })},
            {{"a2", "a₂", QT_TRANSLATE_NOOP("core", "leg 2: П-joint crank (lever) length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].lever; })},
            {{"k2", "k₂", QT_TRANSLATE_NOOP("core", "leg 2: П-joint ratio k = b/a"), units::none, G::Geometry, positive, true, false, true, 3, 0.05}, T::real([](auto &d) -> auto & { return d.legs[1].ratio; })},
            {{"q2_min", "q₂_min", QT_TRANSLATE_NOOP("core", "leg 2: lower limit of the input (P̲RR, RP̲R, П̲RR)"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].range.min; })},
            {{"q2_max", "q₂_max", QT_TRANSLATE_NOOP("core", "leg 2: upper limit of the input (P̲RR, RP̲R, П̲RR)"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].range.max; })},
            {{"theta2_min", "θ₂_min", QT_TRANSLATE_NOOP("core", "leg 2: lower limit of the crank angle (R̲RR)"), units::angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].crankRange.min; })},
            {{"theta2_max", "θ₂_max", QT_TRANSLATE_NOOP("core", "leg 2: upper limit of the crank angle (R̲RR)"), units::angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[1].crankRange.max; })},
            {{"working2", "w₂", QT_TRANSLATE_NOOP("core", "leg 2: working mode (+1 elbow left of A₂→P₂; P̲RR: sign in q = B ± √…)"), units::none, G::Mode, sign, false, false, true, 0, 2, sideChoices, {}, QT_TRANSLATE_NOOP("core", "leg 2: working mode, the elbow left or right of A₂→P₂ (P̲RR: left, the root q = B + √…)")}, T::sign([](auto &d) -> auto & { return d.legs[1].working; }), &signRule},
            {{"leg3_type", "τ₃", QT_TRANSLATE_NOOP("core", "leg 3: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)"), units::none, G::Mode, legType, false, false, true, 0, 1, legTypeChoices, legTypeLabels, QT_TRANSLATE_NOOP("core", "leg 3: type (the actuated joint underlined)")}, legTypeField<2>(), &integerRule},
            {{"A3x", "x_A₃", QT_TRANSLATE_NOOP("core", "leg 3: base point A₃, x"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].base.x(); })},
            {{"A3y", "y_A₃", QT_TRANSLATE_NOOP("core", "leg 3: base point A₃, y"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].base.y(); })},
            {{"B3x", "x_B₃", QT_TRANSLATE_NOOP("core", "leg 3: platform point B₃ in the platform frame, x"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].platform.x(); })},
            {{"B3y", "y_B₃", QT_TRANSLATE_NOOP("core", "leg 3: platform point B₃ in the platform frame, y"), units::millimetre, G::Geometry, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].platform.y(); })},
            {{"r3", "r₃", QT_TRANSLATE_NOOP("core", "leg 3: crank length (R̲RR)"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].crank; })},
            {{"l3", "l₃", QT_TRANSLATE_NOOP("core", "leg 3: distal link length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].link; })},
            {{"alpha3", "α₃", QT_TRANSLATE_NOOP("core", "leg 3: direction of the guide (P̲RR) or of the П-joint base (П̲RR)"), units::angle, G::Geometry, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].alpha; })},
            {{"a3", "a₃", QT_TRANSLATE_NOOP("core", "leg 3: П-joint crank (lever) length"), units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].lever; })},
            {{"k3", "k₃", QT_TRANSLATE_NOOP("core", "leg 3: П-joint ratio k = b/a"), units::none, G::Geometry, positive, true, false, true, 3, 0.05}, T::real([](auto &d) -> auto & { return d.legs[2].ratio; })},
            {{"q3_min", "q₃_min", QT_TRANSLATE_NOOP("core", "leg 3: lower limit of the input (P̲RR, RP̲R, П̲RR)"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].range.min; })},
            {{"q3_max", "q₃_max", QT_TRANSLATE_NOOP("core", "leg 3: upper limit of the input (P̲RR, RP̲R, П̲RR)"), units::millimetre, G::Range, coordinate, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].range.max; })},
            {{"theta3_min", "θ₃_min", QT_TRANSLATE_NOOP("core", "leg 3: lower limit of the crank angle (R̲RR)"), units::angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].crankRange.min; })},
            {{"theta3_max", "θ₃_max", QT_TRANSLATE_NOOP("core", "leg 3: upper limit of the crank angle (R̲RR)"), units::angle, G::Range, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.legs[2].crankRange.max; })},
            {{"working3", "w₃", QT_TRANSLATE_NOOP("core", "leg 3: working mode (+1 elbow left of A₃→P₃; P̲RR: sign in q = B ± √…)"), units::none, G::Mode, sign, false, false, true, 0, 2, sideChoices, {}, QT_TRANSLATE_NOOP("core", "leg 3: working mode, the elbow left or right of A₃→P₃ (P̲RR: left, the root q = B + √…)")}, T::sign([](auto &d) -> auto & { return d.legs[2].working; }), &signRule},
            {{"assembly", "σ", QT_TRANSLATE_NOOP("core", "assembly mode: 2 DOF +1 platform left of C₁→C₂, −1 right; 3 DOF the n-th solution in order of φ"), units::none, G::Mode, Interval{-1.0, 6.0}, false, false, true, 0, 1}, assemblyField(), &assemblyRule},
            {{"phi_map", "φ_m", QT_TRANSLATE_NOOP("core", "platform angle φ of the workspace map (3 DOF)"), units::angle, G::Drawing, turn, false, false, true, 2, 1}, T::real([](auto &d) -> auto & { return d.mapPhi; })},
        }, {actuatorRows<PlanarParallelDesign, 0>(ActuatorNames::Linear, [](auto &d) -> auto & { return d.linearActuators[0]; }), actuatorRows<PlanarParallelDesign, 0>(ActuatorNames::RotaryOwn, [](auto &d) -> auto & { return d.rotaryActuators[0]; }), actuatorRows<PlanarParallelDesign, 1>(ActuatorNames::Linear, [](auto &d) -> auto & { return d.linearActuators[1]; }), actuatorRows<PlanarParallelDesign, 1>(ActuatorNames::RotaryOwn, [](auto &d) -> auto & { return d.rotaryActuators[1]; }), actuatorRows<PlanarParallelDesign, 2>(ActuatorNames::Linear, [](auto &d) -> auto & { return d.linearActuators[2]; }), actuatorRows<PlanarParallelDesign, 2>(ActuatorNames::RotaryOwn, [](auto &d) -> auto & { return d.rotaryActuators[2]; }), loadRows<PlanarParallelDesign>(LoadNames::ForceAndMoment, [](auto &d) -> auto & { return d.load; })}));
    }();
    return table;
}

} // namespace pkm
