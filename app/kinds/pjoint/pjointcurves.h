#pragma once
/// The curves behind PJointPlots (the П-joint document's figs. 8–17), without a widget:
/// what each plot shows, its samples over θ, its axis ranges and the clipping to them. Pure
/// functions of the design, so the tests check them without drawing anything.
///
/// Units: θ in degrees (the plots' θ axis); every value in its quantity's display unit.

#include "kinds/pjoint/pjoint.h"

#include <QString>

#include <array>
#include <vector>

namespace pkm::pjointcurves {

/// The tab a quantity is drawn on; it also decides the plotted θ range (thetaRange()).
enum class Tab { Geometry, Jacobian, Actuator };

/// What one plot shows: a closed form of (design, θ in rad) in the display unit.
struct Quantity {
    const char *name; ///< PJointPlots::plotName()
    const char *symbol; ///< UTF-8, as printed
    Tab tab;
    int familySize; ///< how many of familyK are drawn with it
    bool singularAtEnds; ///< grows without bound at θ → ±90° (J → 0, (7))
    Unit unit;
    double (*value)(const PJointDesign &, double theta);
};

inline constexpr int quantityCount = 8;
/// In the order of PJointPlots::PlotIndex: d, φ, μ, J, J⁻¹, Δθ, θ̇, T.
extern const std::array<Quantity, quantityCount> quantities;

/// Fig. 10: below this μ the actuator pushes almost along the crank, so J = a·sin μ (and with it
/// the output torque per newton) is nearly zero. Not the four-bar's usual 40°: with this μ (at
/// A, between diagonal and crank) μ ≤ arcsin k, ≤ 30° for every preferred k ≤ 0.5. The document
/// accepts θ within −75…75°, where μ ≥ 3.4° (k = 0.3) … 5.0° (k = 0.5).
inline constexpr double weakTransmission = 5.0; ///< °

/// Fig. 8's family; figs. 9–10 use its first three (k ≤ 0.5, the preferred designs).
inline constexpr std::array<double, 5> familyK {0.3, 0.4, 0.5, 1.0, 1.5};

inline constexpr int sampleCount = 401; ///< odd, so θ = 0 is a sample of every symmetric range
inline constexpr double headroom = 0.08; ///< of the value span, above and below the curves
/// J⁻¹, Δθ and θ̇ grow without bound at θ → ±90°: their value range comes from |θ| ≤ 80° only,
/// and beyond that the curves are cut at the axis edge (clip()).
inline constexpr double singularGuard = 80.0; ///< °
inline constexpr double jacobianSpan = 75.0; ///< °, figs. 11–12 are drawn over −75…75°

struct Point {
    double theta; ///< °
    double value; ///< display unit
};
using Curve = std::vector<Point>;

/// A closed interval; empty when !(lower <= upper).
struct Range {
    double lower;
    double upper;
};

/// Everything one plot draws.
struct Plot {
    Range theta {}; ///< the θ axis, °
    Range value {}; ///< the value axis
    Curve design; ///< this design over its θ range (within the axis): graph(0)
    Curve extension; ///< this design over the whole θ axis; empty on the Actuator tab
    bool extensionBeyond = false; ///< the extension shows more than `design` does
    std::vector<Curve> family; ///< familySize curves, k = familyK[j] at the design's a
};

/// Whether quantity q draws this design beyond its θ range (figs. 8–12 do).
inline bool hasExtension(const Quantity &q)
{
    return q.tab != Tab::Actuator;
}

/// The θ axis: −90…90° (figs. 8–10), −75…75° or the design's range if wider (figs. 11–12), the
/// design's range (figs. 15–17). Never narrower than 1°, also for a degenerate or NaN range.
Range thetaRange(Tab tab, const PJointDesign &design);

/// sampleCount samples of q over [from, to] °, equally spaced; non-finite values are left out.
Curve sample(const PJointDesign &design, const Quantity &q, double from, double to);

/// |θ| up to which a singular quantity's samples count towards its value range: singularGuard,
/// or further out for a design working entirely beyond it (θ 85…89°).
double guardOf(const PJointDesign &design);

/// The value axis for the curves: their extent over |θ| ≤ guard (over all θ if no sample is
/// that close), plus headroom; never below 0 when no value is negative.
Range valueRange(const std::vector<const Curve *> &curves, double guard);

/// The part of a curve inside [lower, upper], ending exactly at the edge where it leaves it.
Curve clip(const Curve &curve, double lower, double upper);

/// Plot `index` (PJointPlots::PlotIndex) of the design, every curve clipped to the value axis.
Plot compute(const PJointDesign &design, int index);

/// Quantity `index`'s symbol ("μ") and display unit ("°"), as printed.
QString symbolOf(int index);
QString unitOf(int index);
/// "d = 183.1 mm", "μ = 21.8°": three or four significant digits, at least one decimal; "∞"
/// for a value that is not finite.
QString valueText(int index, double value);

/// Tick step of an angle axis (φ, μ) spanning `span` °: at most 8 intervals.
double angleStep(double span);

/// θ tick step, °: every 15° where the labels have room (~64 px a step at 11 pt), else 30°,
/// 45° or 90° in a narrower plot (at least ~44 px a step), so that the labels never overlap.
/// `labelPixels` is the width of a label such as "−60°" (~34 px at 11 pt): presentation mode's
/// larger text needs wider steps, or fig. 8 read "−90°−60°−30°".
double thetaStep(double span, int pixels, double labelPixels = 34.0);

} // namespace pkm::pjointcurves
