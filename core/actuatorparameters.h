#pragma once
/// The actuator of one actuated joint as design parameters (the names of capability.h): four
/// rows of a kind's ParameterTable, made here once for every kind instead of being written out
/// per kind. A design keeps its actuators as ActuatorSpec values; a design file of an older
/// version, which has none of these names, loads with the kind's defaults.

#include "capability.h"
#include "parametertable.h"

#include <array>
#include <type_traits>
#include <vector>

namespace pkm {

/// One actuator's limits, core units: N or N·m, mm/s or rad/s, mm or rad, N/mm or N·m/rad.
struct ActuatorSpec {
    double forceMax = 0.0;
    double speedMax = 0.0;
    double step = 0.0;
    double stiffness = 0.0;
};

/// Plausible actuators where the documents give none (assumed, not measured; presets say so):
/// a NEMA 17 stepper with a 5:1 planetary gearbox (2 N·m, 180 °/s, 1.8°/5 per full step,
/// about 1000 N·m/rad at the output shaft) and a small lead-screw slide (200 N, 50 mm/s,
/// 0.01 mm per step, about 10 N/µm with its nut and bearings).
inline constexpr ActuatorSpec assumedRotary{2.0, std::numbers::pi, 0.36 * units::degree, 1000.0};
inline constexpr ActuatorSpec assumedLinear{200.0, 50.0, 0.01, 10000.0};

enum class ActuatorNames {
    Linear, ///< force_max{i} N, speed_max{i} mm/s, step{i} mm, stiffness{i} N/mm
    Rotary, ///< the same names in N·m, °/s, °, N·m/rad
    /// torque_max{i}, rate_max{i}, angle_step{i}, torsion{i}: a rotary actuator whose
    /// parameters must not share names (and units) with the linear ones of the same leg.
    RotaryOwn,
};

namespace actuatorlabels {
// literal per index, so that the translation tools see every label
inline constexpr std::array<const char *, 3> force = {QT_TRANSLATE_NOOP("core", "actuator 1: maximum force"),
    QT_TRANSLATE_NOOP("core", "actuator 2: maximum force"), QT_TRANSLATE_NOOP("core", "actuator 3: maximum force")};
inline constexpr std::array<const char *, 3> speed = {QT_TRANSLATE_NOOP("core", "actuator 1: maximum speed"),
    QT_TRANSLATE_NOOP("core", "actuator 2: maximum speed"), QT_TRANSLATE_NOOP("core", "actuator 3: maximum speed")};
inline constexpr std::array<const char *, 3> step = {QT_TRANSLATE_NOOP("core", "actuator 1: step (resolution)"),
    QT_TRANSLATE_NOOP("core", "actuator 2: step (resolution)"), QT_TRANSLATE_NOOP("core", "actuator 3: step (resolution)")};
inline constexpr std::array<const char *, 3> stiffness = {QT_TRANSLATE_NOOP("core", "actuator 1: axial stiffness"),
    QT_TRANSLATE_NOOP("core", "actuator 2: axial stiffness"), QT_TRANSLATE_NOOP("core", "actuator 3: axial stiffness")};
inline constexpr std::array<const char *, 3> torque = {QT_TRANSLATE_NOOP("core", "actuator 1: maximum torque"),
    QT_TRANSLATE_NOOP("core", "actuator 2: maximum torque"), QT_TRANSLATE_NOOP("core", "actuator 3: maximum torque")};
inline constexpr std::array<const char *, 3> rate = {QT_TRANSLATE_NOOP("core", "actuator 1: maximum angular speed"),
    QT_TRANSLATE_NOOP("core", "actuator 2: maximum angular speed"),
    QT_TRANSLATE_NOOP("core", "actuator 3: maximum angular speed")};
inline constexpr std::array<const char *, 3> angleStep = {QT_TRANSLATE_NOOP("core", "actuator 1: angular step (resolution)"),
    QT_TRANSLATE_NOOP("core", "actuator 2: angular step (resolution)"),
    QT_TRANSLATE_NOOP("core", "actuator 3: angular step (resolution)")};
inline constexpr std::array<const char *, 3> torsion = {QT_TRANSLATE_NOOP("core", "actuator 1: torsional stiffness"),
    QT_TRANSLATE_NOOP("core", "actuator 2: torsional stiffness"),
    QT_TRANSLATE_NOOP("core", "actuator 3: torsional stiffness")};
inline constexpr std::array<const char *, 3> digits = {"₁", "₂", "₃"};
} // namespace actuatorlabels

/// The four rows of actuator I (0-based) of a design, whose spec `Locate` finds: a lambda
/// without captures, [](auto &d) -> auto & { return d.actuators[0]; }.
template <class Design, int I, class Locate>
std::vector<ParameterRow<Design>> actuatorRows(ActuatorNames names, Locate)
{
    static_assert(std::is_empty_v<Locate>, "a locator captures nothing");
    static_assert(I >= 0 && I < 3);
    using T = ParameterTable<Design>;
    using G = ParameterGroup;
    namespace L = actuatorlabels;
    const Interval positive{0.0, 1e9};
    const std::string i = std::to_string(I + 1), sub = L::digits[I];
    const bool rotary = names != ActuatorNames::Linear, own = names == ActuatorNames::RotaryOwn;
    const auto force = T::real([](auto &d) -> auto & { return Locate{}(d).forceMax; });
    const auto speed = T::real([](auto &d) -> auto & { return Locate{}(d).speedMax; });
    const auto step = T::real([](auto &d) -> auto & { return Locate{}(d).step; });
    const auto stiffness = T::real([](auto &d) -> auto & { return Locate{}(d).stiffness; });
    return {
        {{(own ? "torque_max" : "force_max") + i, (rotary ? "T_max" : "F_max") + sub, rotary ? L::torque[I] : L::force[I],
          rotary ? units::newtonMetre : units::newton, G::Actuator, positive, true, false, true, rotary ? 3 : 1,
          rotary ? 0.1 : 5.0},
         force},
        {{(own ? "rate_max" : "speed_max") + i, (rotary ? "ω_max" : "v_max") + sub, rotary ? L::rate[I] : L::speed[I],
          rotary ? units::degreePerSecond : units::millimetrePerSecond, G::Actuator, positive, true, false, true, 1, 5.0},
         speed},
        {{(own ? "angle_step" : "step") + i, (rotary ? "Δθ" : "Δq") + sub, rotary ? L::angleStep[I] : L::step[I],
          rotary ? units::angle : units::millimetre, G::Actuator, positive, true, false, true, 4, rotary ? 0.01 : 0.001},
         step},
        {{(own ? "torsion" : "stiffness") + i, "k" + sub, rotary ? L::torsion[I] : L::stiffness[I],
          rotary ? units::newtonMetrePerRadian : units::newtonPerMillimetre, G::Actuator, positive, true, false, true, 0,
          100.0},
         stiffness},
    };
}

/// A load on the platform (or the output link) whose static deflection the capability group
/// reports (capability.h): a force at the platform point and a moment, or a torque on an
/// output that is an angle. Zero by default: no load, no deflection.
struct LoadSpec {
    double x = 0.0;      ///< N
    double y = 0.0;      ///< N
    double moment = 0.0; ///< N·m (a torque on an angular output)
};

enum class LoadNames {
    Torque, ///< load_torque: an output that is an angle
    Force,  ///< load_x, load_y: a platform point
    ForceAndMoment, ///< load_x, load_y, load_moment: a platform that turns
};

/// The rows of the load that `Locate` finds ([](auto &d) -> auto & { return d.load; }).
template <class Design, class Locate>
std::vector<ParameterRow<Design>> loadRows(LoadNames names, Locate)
{
    static_assert(std::is_empty_v<Locate>, "a locator captures nothing");
    using T = ParameterTable<Design>;
    using G = ParameterGroup;
    const Interval any{-1e9, 1e9};
    const auto x = T::real([](auto &d) -> auto & { return Locate{}(d).x; });
    const auto y = T::real([](auto &d) -> auto & { return Locate{}(d).y; });
    const auto moment = T::real([](auto &d) -> auto & { return Locate{}(d).moment; });
    if (names == LoadNames::Torque)
        return {{{"load_torque", "T_L", QT_TRANSLATE_NOOP("core", "load: torque on the output link"), units::newtonMetre,
                  G::Actuator, any, false, false, true, 2, 1.0},
                 moment}};
    std::vector<ParameterRow<Design>> rows = {
        {{"load_x", "F_Lx", QT_TRANSLATE_NOOP("core", "load: force on the platform, x"), units::newton, G::Actuator, any,
          false, false, true, 1, 5.0},
         x},
        {{"load_y", "F_Ly", QT_TRANSLATE_NOOP("core", "load: force on the platform, y"), units::newton, G::Actuator, any,
          false, false, true, 1, 5.0},
         y},
    };
    if (names == LoadNames::ForceAndMoment)
        rows.push_back({{"load_moment", "M_L", QT_TRANSLATE_NOOP("core", "load: moment on the platform"), units::newtonMetre,
                         G::Actuator, any, false, false, true, 2, 0.5},
                        moment});
    return rows;
}

/// `rows` followed by `more`: a kind's own rows, then its actuators'.
template <class Design>
std::vector<ParameterRow<Design>> joinRows(std::vector<ParameterRow<Design>> rows,
                                           std::initializer_list<std::vector<ParameterRow<Design>>> more)
{
    for (const auto &part : more)
        rows.insert(rows.end(), part.begin(), part.end());
    return rows;
}

} // namespace pkm
