// The sheet PDF's plots, drawn as vectors: the axes with their ticks and grid, the curves in
// their styles, the bands and the legend.

#include "export/sheetpdfinternal.h"

#include "scenepainter.h"
#include "export/sheet.h"
#include "export/sheetparts.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QMarginsF>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QPicture>

#include <algorithm>
#include <array>
#include <cmath>

namespace pkm::sheet {

namespace detail {

QPen PdfSheet::seriesPen(PlotSeries::Style style, int familyIndex) const
{
    static const std::array<QColor, 5> family {QColor(0x7f, 0x95, 0xb5), QColor(0xc9, 0x8a, 0x4e),
        QColor(0x6f, 0xa8, 0x7e), QColor(0xa3, 0x86, 0xc4), QColor(0xb8, 0x6a, 0x6a)};
    QPen pen;
    switch (style) {
    case PlotSeries::Style::Design:
        pen = QPen(accent, mm(0.5));
        break;
    case PlotSeries::Style::Extension:
        pen = QPen(accent, mm(0.25), Qt::DashLine);
        break;
    case PlotSeries::Style::Family:
        pen = QPen(family[std::size_t(familyIndex) % family.size()], mm(0.25));
        break;
    }
    pen.setCapStyle(Qt::FlatCap);
    pen.setJoinStyle(Qt::RoundJoin);
    return pen;
}

QColor PdfSheet::bandColour(PlotBand::Kind kind)
{
    return kind == PlotBand::Kind::Recommended ? QColor(0xdf, 0xf1, 0xe3) : QColor(0xfb, 0xe4, 0xd6);
}

std::vector<PdfSheet::LegendEntry> PdfSheet::legendEntries(const Plot &plot) const
{
    std::vector<LegendEntry> entries;
    if (plot.series.size() > 1) {
        int familyIndex = 0;
        for (const PlotSeries &series : plot.series) {
            const int index = series.style == PlotSeries::Style::Family ? familyIndex++ : 0;
            entries.push_back({seriesPen(series.style, index), {}, series.name});
        }
    }
    for (const PlotBand &band : plot.bands) {
        const bool seen = std::any_of(
            entries.begin(), entries.end(), [&](const LegendEntry &entry) { return entry.name == band.name; });
        if (!seen)
            entries.push_back({QPen(Qt::NoPen), bandColour(band.kind), band.name});
    }
    return entries;
}

double PdfSheet::legend(const Plot &plot, QPointF origin, double width)
{
    const std::vector<LegendEntry> entries = legendEntries(plot);
    if (entries.empty())
        return 0.0;
    const QFont f = font(6.5);
    const double lineHeight = metrics(f).height();
    const double swatch = mm(5.0), gap = mm(1.0), spacing = mm(3.5);
    double x = 0.0, y = 0.0;
    for (const LegendEntry &entry : entries) {
        const double textWidth = metrics(f).horizontalAdvance(entry.name) + mm(0.5);
        const double w = swatch + gap + textWidth;
        if (x > 0.0 && x + w > width) {
            x = 0.0;
            y += lineHeight;
        }
        if (m_painter) {
            const double middle = origin.y() + y + lineHeight / 2.0;
            if (entry.pen.style() == Qt::NoPen) {
                m_painter->fillRect(QRectF(origin.x() + x, middle - lineHeight * 0.3, swatch, lineHeight * 0.6), entry.fill);
            } else {
                m_painter->setPen(entry.pen);
                m_painter->drawLine(QPointF(origin.x() + x, middle), QPointF(origin.x() + x + swatch, middle));
            }
        }
        text(QRectF(origin.x() + x + swatch + gap, origin.y() + y, textWidth, lineHeight), f, grey,
            Qt::AlignLeft | Qt::AlignVCenter, entry.name);
        x += w + spacing;
    }
    return y + lineHeight + mm(0.8);
}

double PdfSheet::legendHeight(const Plot &plot, double width)
{
    QPainter *painter = m_painter;
    m_painter = nullptr; // measure only
    const double height = legend(plot, QPointF(), width);
    m_painter = painter;
    return height;
}

double PdfSheet::tickStep(double span, int count, bool degrees)
{
    if (!(span > 0.0))
        return 1.0;
    if (degrees && span >= 20.0) {
        for (double step : {5.0, 10.0, 15.0, 30.0, 45.0, 90.0, 180.0}) {
            if (span / step <= count)
                return step;
        }
    }
    const double raw = span / count;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
        if (m * power >= raw)
            return m * power;
    }
    return 10.0 * power;
}

QString PdfSheet::tickText(double value, double step)
{
    const int decimals = std::clamp(int(std::ceil(-std::log10(step) + 1e-9)), 0, 6)
        + (std::abs(std::round(step / std::pow(10.0, std::floor(std::log10(step)))) - 2.5) < 1e-9 ? 1 : 0);
    return detail::numberText(std::abs(value) < step * 1e-9 ? 0.0 : value, std::max(0, decimals)); // locale
}

void PdfSheet::paintAxes(const QRectF &plotArea, double x0, double x1, double y0, double y1, bool xDegrees, bool yDegrees,
    bool grid)
{
    const QFont tickFont = font(6.5);
    const auto mx = [&](double x) { return plotArea.left() + (x - x0) / (x1 - x0) * plotArea.width(); };
    const auto my = [&](double y) { return plotArea.bottom() - (y - y0) / (y1 - y0) * plotArea.height(); };
    const double xStep = tickStep(x1 - x0, 6, xDegrees), yStep = tickStep(y1 - y0, 5, yDegrees);
    const double th = metrics(tickFont).height();
    for (double x = std::ceil(x0 / xStep - 1e-9) * xStep; x <= x1 + 1e-9 * xStep; x += xStep) {
        if (grid)
            line(QPointF(mx(x), plotArea.top()), QPointF(mx(x), plotArea.bottom()), QColor(0xe2, 0xe6, 0xec), 0.12);
        line(QPointF(mx(x), plotArea.bottom()), QPointF(mx(x), plotArea.bottom() + mm(0.8)), ink, 0.15);
        text(QRectF(mx(x) - mm(8.0), plotArea.bottom() + mm(1.0), mm(16.0), th), tickFont, ink,
            Qt::AlignHCenter | Qt::AlignTop, tickText(x, xStep));
    }
    for (double y = std::ceil(y0 / yStep - 1e-9) * yStep; y <= y1 + 1e-9 * yStep; y += yStep) {
        if (grid)
            line(QPointF(plotArea.left(), my(y)), QPointF(plotArea.right(), my(y)), QColor(0xe2, 0xe6, 0xec), 0.12);
        line(QPointF(plotArea.left() - mm(0.8), my(y)), QPointF(plotArea.left(), my(y)), ink, 0.15);
        text(QRectF(plotArea.left() - mm(13.0), my(y) - th / 2.0, mm(12.0), th), tickFont, ink,
            Qt::AlignRight | Qt::AlignVCenter, tickText(y, yStep));
    }
    if (m_painter) {
        m_painter->setPen(QPen(ink, mm(0.2)));
        m_painter->setBrush(Qt::NoBrush);
        m_painter->drawRect(plotArea);
    }
}

void PdfSheet::paintPlot(const Plot &plot, const QRectF &area)
{
    const QFont labelFont = font(7.0);
    const double labelHeight = metrics(labelFont).height();
    const double legendSpace = legendHeight(plot, area.width() - mm(2.0));
    const QRectF plotArea(area.left() + mm(15.5), area.top() + mm(1.0), area.width() - mm(17.0),
        area.height() - mm(1.0) - mm(4.0) - labelHeight - legendSpace);
    const bool xDegrees = plot.xLabel.contains(QStringLiteral("°"));
    const bool yDegrees = plot.yLabel.contains(QStringLiteral("(°)"));
    const double x0 = plot.xMin, x1 = plot.xMax > plot.xMin ? plot.xMax : plot.xMin + 1.0;
    const double y0 = plot.yMin, y1 = plot.yMax > plot.yMin ? plot.yMax : plot.yMin + 1.0;
    const auto mx = [&](double x) { return plotArea.left() + (x - x0) / (x1 - x0) * plotArea.width(); };
    const auto my = [&](double y) { return plotArea.bottom() - (y - y0) / (y1 - y0) * plotArea.height(); };

    if (m_painter) {
        for (const PlotBand &band : plot.bands) {
            const double a = std::clamp(mx(band.from), plotArea.left(), plotArea.right());
            const double b = std::clamp(mx(band.to), plotArea.left(), plotArea.right());
            m_painter->fillRect(QRectF(a, plotArea.top(), b - a, plotArea.height()), bandColour(band.kind));
        }
    }
    paintAxes(plotArea, x0, x1, y0, y1, xDegrees, yDegrees, true);
    text(QRectF(plotArea.left(), plotArea.bottom() + mm(4.0), plotArea.width(), labelHeight), labelFont, ink,
        Qt::AlignHCenter | Qt::AlignTop, plot.xLabel);
    if (m_painter) {
        m_painter->save();
        m_painter->translate(area.left() + labelHeight * 0.1, plotArea.center().y());
        m_painter->rotate(-90.0);
        text(QRectF(-plotArea.height() / 2.0, 0.0, plotArea.height(), labelHeight), labelFont, ink,
            Qt::AlignHCenter | Qt::AlignTop, plot.yLabel);
        m_painter->restore();
    }
    if (m_painter) {
        m_painter->save();
        m_painter->setClipRect(plotArea);
        m_painter->setRenderHint(QPainter::Antialiasing, true);
        int familyIndex = 0;
        for (const PlotSeries &series : plot.series) {
            const QPen pen
                = seriesPen(series.style, series.style == PlotSeries::Style::Family ? familyIndex++ : 0);
            m_painter->setPen(pen);
            m_painter->setBrush(Qt::NoBrush);
            QPainterPath path;
            bool open = false;
            for (const auto &[x, y] : series.points) {
                if (!std::isfinite(x) || !std::isfinite(y)) {
                    open = false;
                    continue;
                }
                const QPointF p(mx(x), my(std::clamp(y, y0 - (y1 - y0), y1 + (y1 - y0))));
                if (open)
                    path.lineTo(p);
                else
                    path.moveTo(p);
                open = true;
            }
            m_painter->drawPath(path);
        }
        for (const auto &[level, name] : plot.levels) {
            m_painter->setPen(QPen(failColour, mm(0.3), Qt::DashLine));
            m_painter->drawLine(QPointF(plotArea.left(), my(level)), QPointF(plotArea.right(), my(level)));
            text(QRectF(plotArea.left() + mm(1.0), my(level) - labelHeight - mm(0.3), plotArea.width() - mm(2.0),
                     labelHeight),
                font(6.3), failColour, Qt::AlignRight | Qt::AlignBottom, name);
        }
        if (plot.cursor && *plot.cursor >= x0 && *plot.cursor <= x1) {
            m_painter->setPen(QPen(QColor(0x9c, 0x1f, 0x6e), mm(0.25), Qt::DotLine));
            m_painter->drawLine(QPointF(mx(*plot.cursor), plotArea.top()), QPointF(mx(*plot.cursor), plotArea.bottom()));
            text(QRectF(mx(*plot.cursor) + mm(0.8), plotArea.top() + mm(0.5), mm(25.0), labelHeight), font(6.0),
                QColor(0x9c, 0x1f, 0x6e), Qt::AlignLeft | Qt::AlignTop, QCoreApplication::translate("Sheet", "this pose"));
        }
        m_painter->restore();
    }
    if (legendSpace > 0.0)
        legend(plot, QPointF(area.left() + mm(2.0), area.bottom() - legendSpace), area.width() - mm(2.0));
}

} // namespace detail

} // namespace pkm::sheet
