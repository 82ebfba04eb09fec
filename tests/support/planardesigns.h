#pragma once
/// The leg-built versions of two built-in presets, in core units, for the tests of the
/// planar parallel kind (tst_planarparallel, tst_planarcurves): one list for both, so that
/// they compare the same designs with the five-bar and MOMA 3a.

#include "mechanism.h"
#include "units.h"

#include <cmath>
#include <numbers>
#include <string>

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

/// resources/presets/pp-5r-pjoint.pkm.json in core units: the 5R driven by two П-joints.
inline ParameterSet fiveRPjoint()
{
    constexpr double deg = units::degree;
    return {{"platform", 0}, {"leg1_type", 3}, {"leg2_type", 3}, {"A1x", 0}, {"A1y", 0}, {"A2x", 200}, {"A2y", 0},
            {"l1", 200}, {"l2", 200}, {"alpha1", 30 * deg}, {"alpha2", -30 * deg}, {"a1", 170}, {"a2", 170},
            {"k1", 0.4}, {"k2", 0.4}, {"q1_min", 116.5}, {"q1_max", 231}, {"q2_min", 116.5}, {"q2_max", 231},
            {"working1", 1}, {"working2", -1}, {"assembly", 1}};
}

/// The 5R with its second crank replaced by a slider on a vertical guide (R̲RR + P̲RR).
inline ParameterSet crankAndSlider()
{
    ParameterSet mixed = fiveR();
    mixed["leg2_type"] = 1;
    mixed["alpha2"] = 90 * units::degree;
    mixed["q2_min"] = -100;
    mixed["q2_max"] = 250;
    return mixed;
}

/// The 5R with its first crank replaced by a strut (RP̲R + R̲RR).
inline ParameterSet strutAndCrank()
{
    ParameterSet strut = fiveR();
    strut["leg1_type"] = 2;
    strut["q1_min"] = 20;
    strut["q1_max"] = 250;
    return strut;
}

/// resources/presets/pp-3rpr.pkm.json in core units: the 3-RPR of Innocenti and
/// Parenti-Castelli.
inline ParameterSet threeRpr()
{
    const double d1 = 17.04, d2 = 16.54, d3 = 20.84;
    const double bx = (d3 * d3 - d2 * d2 + d1 * d1) / (2 * d1), by = std::sqrt(d3 * d3 - bx * bx);
    return {{"platform", 2}, {"leg1_type", 2}, {"leg2_type", 2}, {"leg3_type", 2}, {"A1x", 0}, {"A1y", 0},
            {"A2x", 15.91}, {"A2y", 0}, {"A3x", 0}, {"A3y", 10}, {"B1x", 0}, {"B1y", 0}, {"B2x", d1}, {"B2y", 0},
            {"B3x", bx}, {"B3y", by}, {"q1_min", 5}, {"q1_max", 30}, {"q2_min", 5}, {"q2_max", 30}, {"q3_min", 5},
            {"q3_max", 30}, {"assembly", 1}};
}

/// A 3-PRR with a free platform: three sliders at 120° and unequal actuators, in core units.
inline ParameterSet threePrr()
{
    ParameterSet p = {{"platform", 2}, {"assembly", 1}};
    const double A[3][2] = {{-173.205081, -100}, {173.205081, -100}, {0, 200}};
    const double B[3][2] = {{-34.641016, -20}, {34.641016, -20}, {0, 40}};
    const double alpha[3] = {0, 120, -120};
    for (int i = 0; i < 3; ++i) {
        const std::string n = std::to_string(i + 1);
        p["leg" + n + "_type"] = 1;
        p["A" + n + "x"] = A[i][0];
        p["A" + n + "y"] = A[i][1];
        p["B" + n + "x"] = B[i][0];
        p["B" + n + "y"] = B[i][1];
        p["l" + n] = 150;
        p["alpha" + n] = alpha[i] * units::degree;
        p["q" + n + "_min"] = 0;
        p["q" + n + "_max"] = 346.41;
        p["working" + n] = 1;
        p["force_max" + n] = 100.0 + 50.0 * i; // unequal actuators
        p["speed_max" + n] = 40.0 + 10.0 * i;
    }
    return p;
}

} // namespace pkm::test::legdesigns
