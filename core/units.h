#pragma once
/// Units. Inside core/ lengths are millimetres, angles radians, forces newtons, torques
/// newton-metres, times seconds. A Unit says how a core value is shown to a person (UI, CLI):
/// display = core × scale. Only angle-bearing units have a scale other than 1.

#include "text.h"

#include <numbers>
#include <string_view>

namespace pkm {

struct Unit {
    std::string_view symbol; ///< display symbol, UTF-8 ("mm", "°", "N·m"); empty: dimensionless
    double scale = 1.0;      ///< display value = core value × scale

    double toDisplay(double coreValue) const { return coreValue * scale; }
    double fromDisplay(double displayValue) const { return displayValue / scale; }
};

namespace units {
inline constexpr double degree = std::numbers::pi / 180.0; ///< radians per degree

inline constexpr Unit none{"", 1.0};
inline constexpr Unit millimetre{QT_TRANSLATE_NOOP("core", "mm"), 1.0};
inline constexpr Unit squareMillimetre{QT_TRANSLATE_NOOP("core", "mm²"), 1.0};
inline constexpr Unit angle{"°", 180.0 / std::numbers::pi};             ///< core: rad
inline constexpr Unit newton{QT_TRANSLATE_NOOP("core", "N"), 1.0};
inline constexpr Unit newtonMetre{QT_TRANSLATE_NOOP("core", "N·m"), 1.0};
inline constexpr Unit millimetrePerSecond{QT_TRANSLATE_NOOP("core", "mm/s"), 1.0};
inline constexpr Unit radianPerSecond{QT_TRANSLATE_NOOP("core", "rad/s"), 1.0};
inline constexpr Unit millimetrePerRadian{QT_TRANSLATE_NOOP("core", "mm/rad"), 1.0};
inline constexpr Unit millimetrePerRadian2{QT_TRANSLATE_NOOP("core", "mm/rad²"), 1.0};
inline constexpr Unit squareMillimetrePerRadian{QT_TRANSLATE_NOOP("core", "mm²/rad"), 1.0};
inline constexpr Unit radianPerMillimetre{QT_TRANSLATE_NOOP("core", "rad/mm"), 1.0};
inline constexpr Unit millimetrePerRevolution{QT_TRANSLATE_NOOP("core", "mm/rev"), 1.0};
inline constexpr Unit millimetrePerStep{QT_TRANSLATE_NOOP("core", "mm/step"), 1.0};
inline constexpr Unit anglePerStep{QT_TRANSLATE_NOOP("core", "°/step"), 180.0 / std::numbers::pi}; ///< core: rad/step
inline constexpr Unit newtonMetrePerRadian{QT_TRANSLATE_NOOP("core", "N·m/rad"), 1.0};

/// A product of powers of millimetres and radians, mm^length · rad^angle, such as the
/// determinants of a leg-built mechanism's Jacobians, whose units follow its leg types. Only
/// the powers those determinants take are listed, each a translatable symbol; others are
/// shown bare (none).
struct PowerUnit {
    int length;
    int angle;
    Unit unit;
};
inline constexpr PowerUnit powerUnits[] = {
    {-2, 2, {QT_TRANSLATE_NOOP("core", "rad²/mm²"), 1.0}},
    {-1, 1, radianPerMillimetre},
    {0, 0, none},
    {1, -1, millimetrePerRadian},
    {2, 0, squareMillimetre},
    {3, 0, {QT_TRANSLATE_NOOP("core", "mm³"), 1.0}},
    {4, 0, {QT_TRANSLATE_NOOP("core", "mm⁴"), 1.0}},
    {2, -1, squareMillimetrePerRadian},
    {3, -1, {QT_TRANSLATE_NOOP("core", "mm³/rad"), 1.0}},
    {4, -1, {QT_TRANSLATE_NOOP("core", "mm⁴/rad"), 1.0}},
    {5, -1, {QT_TRANSLATE_NOOP("core", "mm⁵/rad"), 1.0}},
    {4, -2, {QT_TRANSLATE_NOOP("core", "mm⁴/rad²"), 1.0}},
    {5, -2, {QT_TRANSLATE_NOOP("core", "mm⁵/rad²"), 1.0}},
    {6, -2, {QT_TRANSLATE_NOOP("core", "mm⁶/rad²"), 1.0}},
    {6, -3, {QT_TRANSLATE_NOOP("core", "mm⁶/rad³"), 1.0}},
    {7, -3, {QT_TRANSLATE_NOOP("core", "mm⁷/rad³"), 1.0}},
};
constexpr Unit power(int length, int angle)
{
    for (const PowerUnit &p : powerUnits) {
        if (p.length == length && p.angle == angle)
            return p.unit;
    }
    return none;
}
} // namespace units

} // namespace pkm
