#pragma once
/// The leg-built versions of two built-in presets, in core units, for the tests of the
/// planar parallel kind (tst_planarparallel, tst_planarcurves): one list for both, so that
/// they compare the same designs with the five-bar and MOMA 3a.

#include "mechanism.h"
#include "units.h"

#include <numbers>

namespace pkm::test::legdesigns {

/// resources/presets/pp-5r.pkm.json in core units.
inline ParameterSet fiveR()
{
    constexpr double pi = std::numbers::pi;
    return {{"platform", 0}, {"leg1_type", 0}, {"leg2_type", 0}, {"A1x", 0}, {"A1y", 0}, {"A2x", 100}, {"A2y", 0},
            {"r1", 80}, {"r2", 80}, {"l1", 120}, {"l2", 120}, {"theta1_min", -pi}, {"theta1_max", pi}, {"theta2_min", -pi},
            {"theta2_max", pi}, {"working1", 1}, {"working2", -1}, {"assembly", 1}};
}

/// resources/presets/pp-2prr-moma3a.pkm.json in core units.
inline ParameterSet moma3a()
{
    constexpr double deg = units::degree;
    return {{"platform", 0}, {"leg1_type", 1}, {"leg2_type", 1}, {"A1x", -100}, {"A1y", 0}, {"A2x", 100}, {"A2y", 0},
            {"l1", 195}, {"l2", 195}, {"alpha1", 265 * deg}, {"alpha2", 275 * deg}, {"q1_min", 0}, {"q1_max", 200},
            {"q2_min", 0}, {"q2_max", 200}, {"working1", -1}, {"working2", -1}, {"assembly", -1}};
}

} // namespace pkm::test::legdesigns
