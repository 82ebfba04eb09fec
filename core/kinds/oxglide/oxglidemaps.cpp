// The O-X glide's workspace: the exact area of either form's workspace in closed form, the
// inner loop of its maps and the singular curves drawn over them (docs/mathematics.md,
// section 3).

#include "oxglide.h"
#include "oxglideinternal.h"

#include "capabilitycell.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

namespace {
/// ∫ √(l² − y²) dy
double halfDiscArea(double l, double y)
{
    const double t = std::clamp(y / l, -1.0, 1.0);
    return 0.5 * (y * std::sqrt(std::max(0.0, l * l - y * y)) + l * l * std::asin(t));
}
} // namespace

namespace oxglide {

double exactArea(const OxGlideDesign &d, int form)
{
    const double l = d.rod, s = d.width, L = d.guideLength;
    auto integralW = [&](double from, double to) { return halfDiscArea(l, to) - halfDiscArea(l, from); };
    if (form == formO) {
        // slice width L − s − 2w, positive above y₀
        const double y0 = heightWhereW(l, 0.5 * (L - s));
        return (L - s) * (l - y0) - 2.0 * integralW(y0, l);
    }
    // slice width L − 2|w − s/2|: below y_h (w ≥ s/2) it is L + s − 2w, positive above y₁;
    // above y_h it is L − s + 2w
    const double yh = heightWhereW(l, 0.5 * s);
    const double y1 = std::min(yh, heightWhereW(l, 0.5 * (L + s)));
    return (L + s) * (yh - y1) - 2.0 * integralW(y1, yh) + (L - s) * (l - yh) + 2.0 * integralW(yh, l);
}

} // namespace oxglide

// -- maps ----------------------------------------------------------------------------------

namespace {

/// The reachable x of a row whose rods run w along the guides: both slider pairs on [0, L].
struct Slice {
    double lo, hi;
};
Slice sliceOf(const OxGlideDesign &d, double w)
{
    const double sign = d.form == oxglide::formX ? -1.0 : 1.0;
    return {std::max(0.5 * d.width + sign * w, -0.5 * d.width - sign * w),
            std::min(d.guideLength + 0.5 * d.width + sign * w, d.guideLength - 0.5 * d.width - sign * w)};
}

/// A row of the map at height y: every reachable cell has the same value and margin, since the
/// Jacobians depend on y alone; NaN outside the slice and wherever y is out of (0, l].
template <class ValueAt>
void fillRow(const OxGlideDesign &d, double y, double x0, double dx, std::span<float> values, std::span<float> margins,
             ValueAt &&valueAt)
{
    const double l = d.rod;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    if (!(y > 0.0) || y > l) {
        std::fill(values.begin(), values.end(), nan);
        std::fill(margins.begin(), margins.end(), nan);
        return;
    }
    const double w = std::sqrt(l * l - y * y);
    const Slice slice = sliceOf(d, w);
    const float value = valueAt(w);
    const float margin = static_cast<float>(std::min(y, w) / l);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double x = x0 + static_cast<double>(i) * dx;
        const bool inside = x >= slice.lo && x <= slice.hi;
        values[i] = inside ? value : nan;
        if (!margins.empty())
            margins[i] = inside ? margin : nan;
    }
}

} // namespace

void OxGlide::fillMapRow(MapQuantity quantity, double y, double x0, double dx, std::span<float> values,
                         std::span<float> margins) const
{
    const double sign = m_design.form == oxglide::formX ? -1.0 : 1.0;
    fillRow(m_design, y, x0, dx, values, margins, [&](double w) {
        return static_cast<float>(quantity == MapQuantity::Determinant
                                      ? -sign * 2.0 * y / std::max(w, 1e-300)
                                      : (w > 0.0 ? std::max(y / w, w / y) : std::numeric_limits<double>::infinity()));
    });
}

void OxGlide::fillCapabilityRow(const capability::CellLimits &limits, double y, double x0, double dx,
                                std::span<float> values, std::span<float> margins) const
{
    const double l = m_design.rod;
    fillRow(m_design, y, x0, dx, values, margins, [&](double w) {
        // the rods' runs along the guides are ±w in either form (the Jacobians of jacobians()):
        // J_q = diag(−2u_i), J_x rows (2u_i, 2y) of length 2l
        return capability::cellValue(capability::cell2(limits, 2.0 * w, -2.0 * w, 2.0 * w, 2.0 * y, -2.0 * w, 2.0 * y,
                                                       2.0 * l, 2.0 * l, w / l < singularTolerance,
                                                       std::min(y, w) / l < singularTolerance));
    });
}

std::vector<SingularCurve> OxGlide::singularCurves() const
{
    const OxGlideDesign &d = m_design;
    std::vector<SingularCurve> curves;
    // y = l: rods perpendicular to the guides (inverse) and parallel to each other (direct):
    // the O↔X crossing, the top edge of both workspaces
    const Eigen::Vector2d from(0.5 * d.width, d.rod), to(d.guideLength - 0.5 * d.width, d.rod);
    curves.push_back({SingularCurve::Type::Inverse, QT_TRANSLATE_NOOP("core", "rods ⟂ guides: the O↔X crossing"), {from, to}});
    curves.push_back({SingularCurve::Type::Direct, QT_TRANSLATE_NOOP("core", "rods parallel: the platform can swing"), {from, to}});
    // y = 0: the rods along the guides, where the workspace reaches down that far
    const auto [lo, hi] = sliceOf(d, d.rod);
    if (lo < hi)
        curves.push_back({SingularCurve::Type::Direct, QT_TRANSLATE_NOOP("core", "rods along the guides"), {{lo, 0.0}, {hi, 0.0}}});
    return curves;
}

std::vector<ExactArea> OxGlide::exactAreas() const
{
    return {
        {"area", "A", QT_TRANSLATE_NOOP("Sheet", "area of this form's workspace (exact)"),
         oxglide::exactArea(m_design, m_design.form)},
        {"area_O", "A_O", QT_TRANSLATE_NOOP("Sheet", "area of the extended (O) form (exact)"),
         oxglide::exactArea(m_design, oxglide::formO)},
        {"area_X", "A_X", QT_TRANSLATE_NOOP("Sheet", "area of the crossed (X) form (exact)"),
         oxglide::exactArea(m_design, oxglide::formX)},
    };
}

} // namespace pkm
