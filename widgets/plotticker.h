#pragma once
/// Axis ticks shared by the plots.

#include <qcustomplot.h>

namespace pkm {

/// Tick labels with a real minus sign ("−200"), as in the rest of the interface.
class MinusTicker : public QCPAxisTicker
{
protected:
    QString getTickLabel(double tick, const QLocale &locale, QChar formatChar, int precision) override
    {
        return QCPAxisTicker::getTickLabel(tick, locale, formatChar, precision).replace(QLatin1Char('-'), QChar(0x2212));
    }
};

} // namespace pkm
