#include "kinds/pjoint/pjointcurves.h"

#include "quantityformat.h"

#include <QLocale>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

namespace pkm::pjointcurves {

const std::array<Quantity, quantityCount> quantities {{
    {"d", "d", Tab::Geometry, 5, false, units::millimetre, pjoint::diagonal}, // (2)
    {"phi", "φ", Tab::Geometry, 3, false, units::angle,
        [](const PJointDesign &p, double t) { return units::angle.toDisplay(pjoint::passiveAngle(p, t)); }},
    {"mu", "μ", Tab::Geometry, 3, false, units::angle,
        [](const PJointDesign &p, double t) { return units::angle.toDisplay(pjoint::transmissionAngle(p, t)); }},
    {"J", "J", Tab::Jacobian, 0, false, units::millimetrePerRadian, pjoint::jacobian}, // (7)
    {"J_inv", "J⁻¹", Tab::Jacobian, 0, true, units::radianPerMillimetre,
        [](const PJointDesign &p, double t) { return 1.0 / pjoint::jacobian(p, t); }}, // (8)
    {"resolution", "Δθ", Tab::Actuator, 0, true, units::anglePerStep,
        [](const PJointDesign &p, double t) { return units::anglePerStep.toDisplay(p.step / pjoint::jacobian(p, t)); }},
    {"speed", "θ̇", Tab::Actuator, 0, true, units::radianPerSecond,
        [](const PJointDesign &p, double t) { return p.speedMax / pjoint::jacobian(p, t); }},
    {"torque", "T", Tab::Actuator, 0, false, units::newtonMetre,
        [](const PJointDesign &p, double t) { return pjoint::outputTorque(p, t, p.forceMax); }}, // (13)
}};

Range thetaRange(Tab tab, const PJointDesign &design)
{
    // Figs. 8–10 show the whole −90…90°, figs. 11–12 at least the document's −75…75°, figs.
    // 15–17 the design's range only: what the actuator can actually reach.
    double from = design.thetaMin / units::degree, to = design.thetaMax / units::degree;
    if (tab == Tab::Geometry) {
        from = -90.0;
        to = 90.0;
    } else if (tab == Tab::Jacobian) {
        from = std::min(-jacobianSpan, from);
        to = std::max(jacobianSpan, to);
    }
    // θ_min/° is −60.00000000000001, not −60: snap, or the end ticks fall off the axis.
    from = std::round(from * 1e9) / 1e9;
    to = std::round(to * 1e9) / 1e9;
    if (!(to - from >= 0.5)) { // a degenerate (or NaN) range still gets a readable axis
        const double middle = std::isfinite(from + to) ? 0.5 * (from + to) : 0.0;
        from = middle - 0.5;
        to = middle + 0.5;
    }
    return {from, to};
}

Curve sample(const PJointDesign &design, const Quantity &q, double from, double to)
{
    Curve curve;
    curve.reserve(sampleCount);
    for (int i = 0; i < sampleCount; ++i) {
        const double theta = from + (to - from) * i / (sampleCount - 1); // °
        const double value = q.value(design, theta * units::degree);
        if (std::isfinite(value)) // the range may touch a singularity; never hand QCP a NaN
            curve.push_back({theta, value});
    }
    return curve;
}

double guardOf(const PJointDesign &design)
{
    // A design working entirely beyond the guard keeps at least half of its own curve in view.
    const double from = design.thetaMin / units::degree, to = design.thetaMax / units::degree;
    const double innerEnd = from > 0.0 ? from : to < 0.0 ? -to : 0.0;
    if (innerEnd > singularGuard)
        return 0.5 * (innerEnd + std::max(std::abs(from), std::abs(to)));
    return singularGuard;
}

Range valueRange(const std::vector<const Curve *> &curves, double guard)
{
    auto extent = [&](double limit) {
        Range r {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
        for (const Curve *curve : curves)
            for (const Point &point : *curve)
                if (std::abs(point.theta) <= limit) {
                    r.lower = std::min(r.lower, point.value);
                    r.upper = std::max(r.upper, point.value);
                }
        return r;
    };
    auto empty = [](const Range &r) { return !(r.lower <= r.upper); };
    Range values = extent(guard); // near-singular samples do not count…
    if (empty(values)) // …unless nothing else is there (a design range beyond the guard)
        values = extent(std::numeric_limits<double>::infinity());
    if (empty(values))
        values = {0.0, 1.0};
    double span = values.upper - values.lower;
    if (span <= 0.0)
        span = std::max(0.1 * std::abs(values.upper), 1e-9);
    Range axis {values.lower - headroom * span, values.upper + headroom * span};
    if (values.lower >= 0.0 && axis.lower < 0.0) // a positive quantity: do not invent negative values
        axis.lower = 0.0;
    return axis;
}

Curve clip(const Curve &curve, double lower, double upper)
{
    // Done here rather than by the axis rect: QSvgGenerator writes no clip path (docs/architecture.md).
    Curve out;
    out.reserve(curve.size());
    auto inside = [&](const Point &p) { return p.value >= lower && p.value <= upper; };
    for (size_t i = 0; i < curve.size(); ++i) {
        const Point &p = curve[i];
        if (i > 0 && inside(p) != inside(curve[i - 1])) {
            const Point &q = curve[i - 1];
            const Point &outside = inside(p) ? q : p;
            const double edge = outside.value > upper ? upper : lower;
            const double s = (edge - q.value) / (p.value - q.value);
            out.push_back({q.theta + s * (p.theta - q.theta), edge});
        }
        if (inside(p))
            out.push_back(p);
    }
    return out;
}

Plot compute(const PJointDesign &design, int index)
{
    const Quantity &q = quantities[size_t(index)];
    const double designFrom = design.thetaMin / units::degree, designTo = design.thetaMax / units::degree;
    Plot result;
    result.theta = thetaRange(q.tab, design);
    const auto [from, to] = result.theta;

    result.design = sample(design, q, std::max(from, designFrom), std::min(to, designTo));
    std::vector<Curve *> curves {&result.design};
    if (hasExtension(q)) {
        result.extension = sample(design, q, from, to);
        result.extensionBeyond = from < designFrom || to > designTo; // else it hides under graph(0)
        curves.push_back(&result.extension);
    }
    result.family.reserve(size_t(q.familySize)); // no reallocation: `curves` points into it
    for (int j = 0; j < q.familySize; ++j) {
        PJointDesign member = design; // fig. 8: the family at the same a
        member.b = familyK[size_t(j)] * member.a;
        curves.push_back(&result.family.emplace_back(sample(member, q, from, to)));
    }

    const double guard = q.singularAtEnds ? guardOf(design) : std::numeric_limits<double>::infinity();
    result.value = valueRange({curves.begin(), curves.end()}, guard);
    for (Curve *curve : curves)
        *curve = clip(*curve, result.value.lower, result.value.upper);
    return result;
}

QString symbolOf(int index)
{
    return QString::fromUtf8(quantities[size_t(index)].symbol);
}

QString unitOf(int index)
{
    return unitText(quantities[size_t(index)].unit);
}

QString valueText(int index, double value)
{
    QString number = QStringLiteral("∞");
    if (std::isfinite(value)) {
        const int magnitude = value == 0.0 ? 0 : int(std::floor(std::log10(std::abs(value))));
        number = QLocale().toString(value, 'f', std::clamp(2 - magnitude, 1, 8));
    }
    const QString unit = unitOf(index);
    const QString gap = unit == QStringLiteral("°") ? QString() : QStringLiteral(" "); // "21.8°", "183.1 mm"
    return spelledDots(symbolOf(index)) + QStringLiteral(" = ") + number + gap + unit; // "dθ/dt = ∞ rad/s"
}

double angleStep(double span)
{
    for (double step : {1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0})
        if (span / step <= 8.0)
            return step;
    return 90.0;
}

double thetaStep(double span, int pixels, double labelPixels)
{
    if (span <= 40.0)
        return 5.0;
    // 15° steps with room to spare (64 px for a 34 px label), others with 10 px between labels
    if (pixels * 15.0 / span >= labelPixels * 64.0 / 34.0)
        return 15.0;
    for (const double step : {30.0, 45.0})
        if (pixels * step / span >= labelPixels + 10.0)
            return step;
    return 90.0;
}

} // namespace pkm::pjointcurves
