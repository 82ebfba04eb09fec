// The four-bar's plotted curves (docs/mathematics.md, section 4): δ, ω₃, ε₃ and γ over the
// input range and δ over the crank-length sweep, sampled in closed form, with the axis ranges
// fitted to them.

#include "kinds/fourbar/fourbarplots.h"
#include "kinds/fourbar/fourbarplotsinternal.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace pkm {

namespace {
using fourbarplots::angleStep;
using fourbarplots::nan;
using fourbarplots::setDegreeStep;

constexpr double pi = std::numbers::pi;
constexpr int alphaSamples = 360; ///< α samples over the input range (1° for a full turn)
constexpr int sweepSamples = 300; ///< AB samples of the sweep

/// The value range of `values` (NaN skipped), robust against the blow-up of a rate at a dead
/// point: the 15 %…85 % spread widened by half of itself each side (a sine's whole swing),
/// never past the data, then padded by 8 %. `fallback` when nothing is finite.
QCPRange robustRange(const QVector<QCPGraphData> &data, QCPRange fallback)
{
    std::vector<double> values;
    values.reserve(std::size_t(data.size()));
    for (const QCPGraphData &d : data)
        if (std::isfinite(d.value))
            values.push_back(d.value);
    if (values.empty())
        return fallback;
    std::sort(values.begin(), values.end());
    auto quantile = [&](double q) { return values[std::size_t(std::lround(q * double(values.size() - 1)))]; };
    const double q15 = quantile(0.15), q85 = quantile(0.85);
    const double spread = q85 - q15;
    double lo = std::max(values.front(), q15 - 0.5 * spread);
    double hi = std::min(values.back(), q85 + 0.5 * spread);
    if (hi - lo < 1e-9 * std::max(1.0, std::abs(hi))) {
        const double half = std::max(1.0, std::abs(hi) * 0.1);
        return {lo - half, hi + half};
    }
    const double pad = 0.08 * (hi - lo);
    return {lo - pad, hi + pad};
}

/// The data's [min, max], padded by 8 % (NaN skipped).
QCPRange paddedRange(const QVector<QCPGraphData> &data, QCPRange fallback)
{
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const QCPGraphData &d : data) {
        if (std::isfinite(d.value)) {
            lo = std::min(lo, d.value);
            hi = std::max(hi, d.value);
        }
    }
    if (!(lo <= hi))
        return fallback;
    const double pad = std::max(0.08 * (hi - lo), 1.0);
    return {lo - pad, hi + pad};
}

/// δ of the rocker joint C, in (−π, π]: C = D + CD·(−cos δ, sin δ).
double deltaOf(const FourBarDesign &design, const Eigen::Vector2d &c)
{
    return pi - std::atan2(c.y(), c.x() - design.ground);
}

double nearestTurn(double angle, double reference)
{
    return angle + 2.0 * pi * std::round((reference - angle) / (2.0 * pi));
}
} // namespace

double FourBarPlots::largestCrank(const FourBarDesign &design, double alpha)
{
    // |BD|² = AB² + AD² − 2·AB·AD·cos α = (BC + CD)²: the positive root in AB
    const double reach = design.coupler + design.rocker;
    const double sinPart = design.ground * std::sin(alpha);
    const double discriminant = reach * reach - sinPart * sinPart;
    if (discriminant < 0.0)
        return nan;
    const double root = design.ground * std::cos(alpha) + std::sqrt(discriminant);
    return root > 0.0 ? root : nan;
}


double FourBarPlots::valueAt(int index, double alpha, double delta) const
{
    switch (index) {
    case DeltaPlot:
        return delta / units::degree;
    case Omega3Plot:
        return fourbar::motion(m_design, alpha, delta, m_design.omega1).omega3;
    case Epsilon3Plot:
        return fourbar::motion(m_design, alpha, delta, m_design.omega1).epsilon3;
    case GammaPlot:
        return fourbar::angles(m_design, alpha, delta).gamma / units::degree;
    default:
        return nan;
    }
}

void FourBarPlots::recomputeCurves()
{
    const Interval range = m_mechanism->variableRange(FourBar::variableAlpha);
    const double from = range.min / units::degree, to = range.max / units::degree;
    std::array<QVector<QCPGraphData>, PlotCount> data;
    double previousDelta = nan;
    for (int i = 0; i <= alphaSamples; ++i) {
        const double key = from + (to - from) * i / alphaSamples; // exact whole degrees for a full turn
        const double alpha = key * units::degree;
        Coordinates inputs(1);
        inputs << alpha;
        const auto solved = m_mechanism->solveDirect(inputs);
        const double delta = solved ? solved->outputs[0] : nan;
        // an output that turns fully wraps at 360°: break the line there rather than cross the plot
        if (std::isfinite(delta) && std::isfinite(previousDelta) && std::abs(delta - previousDelta) > pi)
            data[DeltaPlot].append(QCPGraphData((key + (from + (to - from) * (i - 1) / alphaSamples)) / 2, nan));
        previousDelta = delta;
        for (int plot = DeltaPlot; plot <= GammaPlot; ++plot) {
            double value = std::isfinite(delta) ? valueAt(plot, alpha, delta) : nan;
            if (!std::isfinite(value))
                value = nan; // a dead point: a gap, never an infinite axis
            data[std::size_t(plot)].append(QCPGraphData(key, value));
        }
    }
    for (int plot = DeltaPlot; plot <= GammaPlot; ++plot) {
        Panel &p = m_panels[plot];
        const double slack = 1e-9 * std::max(1.0, to - from); // the end ticks stay on the axis
        p.plot->xAxis->setRange(from - slack, to + slack);
        QCPRange values;
        switch (plot) {
        case DeltaPlot:
            values = paddedRange(data[std::size_t(plot)], QCPRange(0, 180));
            break;
        case GammaPlot:
            values = m_design.branch == fourbar::crossed ? QCPRange(-180, 0) : QCPRange(0, 180);
            break;
        default:
            values = robustRange(data[std::size_t(plot)], QCPRange(-1, 1));
            break;
        }
        p.plot->yAxis->setRange(values);
        // a rate near a dead point (~1e48 at it) leaves the plot steeply: drawn clipped to a few
        // heights beyond the axis, so the line stays numerically sane
        for (QCPGraphData &point : data[std::size_t(plot)])
            point.value
                = std::clamp(point.value, values.lower - 4.0 * values.size(), values.upper + 4.0 * values.size());
        if (plot == DeltaPlot || plot == GammaPlot)
            setDegreeStep(p.plot->yAxis, plot == GammaPlot ? 30.0 : angleStep(values.size(), 7));
        p.curve->data()->set(data[std::size_t(plot)], true);
        const double width = std::max(200, p.plot->axisRect()->width());
        setDegreeStep(p.plot->xAxis, angleStep(to - from, std::max(3.0, width / 60.0)));
    }
    // γ: the poor bands on the branch's side, |γ| < 40° and |γ| > 140°
    const double sign = m_design.branch == fourbar::crossed ? -1.0 : 1.0;
    const double poor = FourBar::poorTransmission;
    const std::array<std::pair<double, double>, 2> bands = {std::pair {0.0, poor}, std::pair {180.0 - poor, 180.0}};
    for (std::size_t b = 0; b < bands.size(); ++b) {
        m_poorBands[b]->topLeft->setCoords(0.0, sign * (sign > 0 ? bands[b].second : bands[b].first));
        m_poorBands[b]->bottomRight->setCoords(1.0, sign * (sign > 0 ? bands[b].first : bands[b].second));
    }
}

void FourBarPlots::recomputeSweep()
{
    Panel &p = m_panels[SweepPlot];
    const double alpha = m_pose.inputs[0];
    const double delta = m_pose.outputs[0];
    m_sweepAlpha = alpha;
    m_largestCrank = largestCrank(m_design, alpha);
    const double top = std::isfinite(m_largestCrank) ? m_largestCrank : 2.0 * m_design.crank;
    const double from = 0.01 * top, to = 1.15 * top;
    // samples, plus the exact largest crank and the current one (the curve passes the pose)
    std::vector<double> lengths;
    lengths.reserve(sweepSamples + 3);
    for (int i = 0; i <= sweepSamples; ++i)
        lengths.push_back(from + (to - from) * i / sweepSamples);
    if (std::isfinite(m_largestCrank))
        lengths.push_back(m_largestCrank);
    lengths.push_back(m_design.crank);
    std::sort(lengths.begin(), lengths.end());

    QVector<QCPGraphData> data;
    data.reserve(qsizetype(lengths.size()));
    double previous = nan, atCurrent = nan;
    FourBarDesign d = m_design;
    for (const double length : lengths) {
        d.crank = length;
        const fourbar::Position position = fourbar::position(d, alpha);
        double value = nan;
        if (position.valid) {
            const double raw = deltaOf(d, position.C);
            value = std::isfinite(previous) ? nearestTurn(raw, previous) : raw;
            previous = value;
        }
        if (length == m_design.crank)
            atCurrent = value;
        data.append(QCPGraphData(length, value));
    }
    // the same turn as the pose's δ
    const double shift = std::isfinite(atCurrent) ? nearestTurn(atCurrent, delta) - atCurrent : 0.0;
    for (QCPGraphData &point : data)
        point.value = (point.value + shift) / units::degree;
    p.curve->data()->set(data, true);
    p.plot->xAxis->setRange(0.0, to);
    const QCPRange values = paddedRange(data, QCPRange(0, 180));
    p.plot->yAxis->setRange(values);
    setDegreeStep(p.plot->yAxis, angleStep(values.size(), 7));
    QVector<QCPGraphData> line;
    if (std::isfinite(m_largestCrank))
        line = {QCPGraphData(m_largestCrank, values.lower - values.size()),
            QCPGraphData(m_largestCrank, values.upper + values.size())};
    m_largestCrankLine->data()->set(line, true);
}

} // namespace pkm
