// Helpers that the four-bar's plots share: the panels and their cursor (fourbarplots.cpp) and the
// curves (fourbarcurves.cpp) both mark missing samples with NaN and step the degree ticks.
#pragma once

#include <qcustomplot.h>

#include <limits>

namespace pkm::fourbarplots {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

inline void setDegreeStep(QCPAxis *axis, double step)
{
    qSharedPointerCast<QCPAxisTickerFixed>(axis->ticker())->setTickStep(step);
}

/// A tick step (°) giving at most `maxTicks` intervals over `span`.
inline double angleStep(double span, double maxTicks)
{
    for (double step : {1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0, 60.0})
        if (span / step <= maxTicks)
            return step;
    return 90.0;
}

} // namespace pkm::fourbarplots
