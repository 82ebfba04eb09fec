#pragma once
/// Axis ticks shared by the plots.

#include <qcustomplot.h>

#include <QFontMetrics>

#include <algorithm>
#include <cmath>

namespace pkm {

/// Tick labels with a real minus sign ("−200"), as in the rest of the interface. Given its
/// axis, it also keeps the labels apart: fewer ticks where the axis is short for them (the
/// map's x axis in presentation mode's large text ran "−100−50 0 50 100150200").
class MinusTicker : public QCPAxisTicker
{
public:
    explicit MinusTicker(const QCPAxis *axis = nullptr)
        : m_axis(axis)
    {
    }

protected:
    double getTickStep(const QCPRange &range) override
    {
        if (m_axis && m_axis->axisRect()) {
            const QFontMetrics metrics(m_axis->tickLabelFont());
            const bool horizontal = m_axis->orientation() == Qt::Horizontal;
            const int length = horizontal ? m_axis->axisRect()->width() : m_axis->axisRect()->height();
            // the longer end's label, "−100", and a gap of a quarter of it
            const double end = std::max(std::abs(range.lower), std::abs(range.upper));
            const int label = horizontal ? metrics.horizontalAdvance(QStringLiteral("−") + QString::number(end, 'g', 3))
                                         : metrics.height();
            setTickCount(std::clamp(length / std::max(1, label * 5 / 4), 2, m_most));
        }
        return QCPAxisTicker::getTickStep(range);
    }

    QString getTickLabel(double tick, const QLocale &locale, QChar formatChar, int precision) override
    {
        return QCPAxisTicker::getTickLabel(tick, locale, formatChar, precision).replace(QLatin1Char('-'), QChar(0x2212));
    }

private:
    const QCPAxis *m_axis = nullptr;
    int m_most = 5; ///< QCPAxisTicker's own count, where there is room
};

} // namespace pkm
