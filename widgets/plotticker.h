#pragma once
/// Axis ticks shared by the plots.

#include <qcustomplot.h>

#include <QFontMetrics>

#include <algorithm>
#include <cmath>

namespace pkm {

/// Tick labels with a real minus sign ("−200"), as in the rest of the interface. Given its
/// axis, it also keeps the labels apart: fewer ticks where the axis is short for them (the
/// map's x axis in presentation mode's large text ran "−100−50 0 50 100150200"). Very small
/// or large values share one power of ten, "1,5·10⁻⁴ … 0,5·10⁻⁴ … 0": 'g' format had mixed
/// "0,00015" with "5E−05" along the 3-R̲RR's colour scale.
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
        const double end = std::max(std::abs(range.lower), std::abs(range.upper));
        m_power = m_sharePower && end > 0.0 && std::isfinite(end) && (end < 1e-2 || end >= 1e5)
            ? int(std::floor(std::log10(end)))
            : 0;
        // At least two ticks inside the range: for two, QCustomPlot may take a step as long as
        // the range, and presentation mode's MOMA map had "0" alone under its x axis.
        double step = QCPAxisTicker::getTickStep(range);
        for (int i = 0; i < 4 && step > 0.0 && std::floor(range.upper / step) - std::ceil(range.lower / step) < 1.0; ++i) {
            const double power = std::pow(10.0, std::floor(std::log10(step)));
            const double mantissa = step / power;
            step = (mantissa > 4.99 ? 2.0 : mantissa > 1.99 ? 1.0 : 0.5) * power; // 5 → 2 → 1 → 0.5
        }
        return step;
    }

    QString getTickLabel(double tick, const QLocale &locale, QChar formatChar, int precision) override
    {
        if (m_power == 0)
            return QCPAxisTicker::getTickLabel(tick, locale, formatChar, precision).replace(QLatin1Char('-'), QChar(0x2212));
        const double mantissa = tick / std::pow(10.0, m_power);
        if (std::abs(mantissa) < 1e-9)
            return QStringLiteral("0");
        static const QString superscripts = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
        QString power = m_power < 0 ? QStringLiteral("⁻") : QString();
        for (const QChar digit : QString::number(std::abs(m_power)))
            power += superscripts[digit.digitValue()];
        QString label = locale.toString(mantissa, 'g', std::max(2, precision)) + QStringLiteral("·10") + power;
        return label.replace(QLatin1Char('-'), QChar(0x2212));
    }

    /// Off for a logarithmic scale, whose ticks span decades (ConditionTicker).
    bool m_sharePower = true;

private:
    int m_power = 0; ///< the power of ten the labels share (0: none), set by getTickStep()
    const QCPAxis *m_axis = nullptr;
    int m_most = 5; ///< QCPAxisTicker's own count, where there is room
};

} // namespace pkm
