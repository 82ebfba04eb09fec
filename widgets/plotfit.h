#pragma once
/// Fitting a plot's ranges to its axis rect, shared by the plots with equal scales.

#include <qcustomplot.h>

#include <cmath>

namespace pkm {

/// Sets the ranges found for the axis rect of the last layout (from QCustomPlot::afterLayout).
/// The ticks were laid out for the old ranges, and the new tick labels may want other margins,
/// so a change lays out once more — a few times at most, should two layouts keep trading a
/// pixel; `refits` counts them and is reset once the ranges hold. The top and right axes follow.
inline void applyFittedRanges(QCustomPlot *plot, const QCPRange &x, const QCPRange &y, int &refits)
{
    const double tolerance = 1e-6 * x.size();
    const auto differs = [tolerance](const QCPRange &a, const QCPRange &b) {
        return std::abs(a.lower - b.lower) > tolerance || std::abs(a.upper - b.upper) > tolerance;
    };
    if (!differs(plot->xAxis->range(), x) && !differs(plot->yAxis->range(), y)) {
        refits = 0;
        return;
    }
    for (QCPAxis *axis : {plot->xAxis, plot->xAxis2})
        axis->setRange(x);
    for (QCPAxis *axis : {plot->yAxis, plot->yAxis2})
        axis->setRange(y);
    if (++refits <= 3)
        plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace pkm
