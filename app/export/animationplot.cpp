// The plot beside an animation's mechanism, drawn with QPainter: white, a closed frame, nice
// ticks, the curve in the design's blue and the pose's cursor in red, as the window's plots
// (plotstyle.h) — so that a video of a lesson looks like the lesson.

#include "export/animationplot.h"

#include "plotstyle.h"
#include "quantityformat.h"
#include "report/texttable.h"
#include "text.h"

#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

namespace {

/// "θ (°)", or the symbol alone for a quantity without a unit.
QString axisName(const std::string &symbol, const Unit &unit)
{
    const QString name = toQString(text::label(symbol));
    return unit.symbol.empty() ? name : QStringLiteral("%1 (%2)").arg(name, toQString(text::label(unit.symbol)));
}

/// The value range shown: every finite value, unless a few of them run off towards a singular
/// pose (J grows without bound near one): then the 2nd to 98th percentiles, so the curve's
/// shape stays readable and the runaway part leaves the frame.
std::pair<double, double> valueRange(const std::vector<QPointF> &curve)
{
    std::vector<double> values;
    for (const QPointF &point : curve) {
        if (std::isfinite(point.y()))
            values.push_back(point.y());
    }
    if (values.empty())
        return {0.0, 1.0};
    std::sort(values.begin(), values.end());
    double lo = values.front(), hi = values.back();
    const auto at = [&](double fraction) { return values[std::size_t(fraction * double(values.size() - 1))]; };
    const double inner = at(0.98) - at(0.02);
    if (values.size() >= 20 && inner > 0.0 && hi - lo > 10.0 * inner) {
        lo = at(0.02);
        hi = at(0.98);
    }
    const double span = hi - lo;
    const double pad = span > 0.0 ? 0.06 * span : std::max(1e-9, 0.05 * std::abs(lo)) + (lo == 0.0 ? 1.0 : 0.0);
    return {lo - pad, hi + pad};
}

/// A step of 1, 2 or 5 times a power of ten giving about `count` ticks over `span`. (The ticks
/// start at ceil(min / step − 1e-9): a range end such as −59.99999999999999°, −60° converted
/// to radians and back, keeps its tick.)
double niceStep(double span, int count)
{
    const double raw = span / std::max(1, count);
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double factor : {1.0, 2.0, 5.0}) {
        if (factor * power >= raw)
            return factor * power;
    }
    return 10.0 * power;
}

/// A tick label with a real minus sign, as the window's plots (plotticker.h).
QString tickText(double value, double step)
{
    const int decimals = std::clamp(int(-std::floor(std::log10(step) + 1e-9)), 0, 9);
    const double shown = std::abs(value) < step * 1e-6 ? 0.0 : value;
    return QString::fromStdString(text::number(shown, decimals)).replace(QLatin1Char('-'), QChar(0x2212));
}

QFont sized(double pixels, bool bold = false)
{
    QFont font;
    font.setPixelSize(std::max(6, int(std::lround(pixels))));
    font.setBold(bold);
    return font;
}

QString readout(const AnimationPlot &plot, double value)
{
    const ReportEntry &entry = plot.entry;
    QString shown;
    if (std::isinf(value))
        shown = QStringLiteral("∞");
    else if (!std::isfinite(value))
        shown = QCoreApplication::translate("pkm::AnimationPlot", "— (undefined at this singular pose)");
    else
        shown = formatQuantity(value, entry.unit, entry.decimals);
    return QStringLiteral("%1 = %2").arg(toQString(text::label(entry.symbol)), shown);
}

} // namespace

std::vector<const ReportEntry *> animationPlotQuantities(const Mechanism &mechanism, int variable)
{
    std::vector<const ReportEntry *> entries;
    const auto &variables = mechanism.variableInfo();
    const std::string swept = variable >= 0 && variable < int(variables.size()) ? variables[variable].name : "";
    for (const ReportEntry &entry : mechanism.reportLayout().entries) {
        if (entry.rows * entry.cols == 1 && entry.name != swept)
            entries.push_back(&entry);
    }
    return entries;
}

Result<AnimationPlot> animationPlot(const Mechanism &mechanism, const Pose &start, const AnimationSettings &settings,
                                    const std::string &quantity)
{
    const auto quantities = animationPlotQuantities(mechanism, settings.variable);
    const auto found = std::find_if(quantities.begin(), quantities.end(),
                                    [&](const ReportEntry *entry) { return entry->name == quantity; });
    if (found == quantities.end() || settings.variable < 0
        || settings.variable >= int(mechanism.variableInfo().size())) {
        std::string names;
        for (std::size_t i = 0; i < quantities.size() && i < 12; ++i)
            names.append(i ? ", " : "").append(quantities[i]->name);
        if (quantities.size() > 12)
            names.append(" …");
        return Failure{FailureKind::UnknownName, "plot",
                       text::format(QCoreApplication::translate("pkm::AnimationPlot",
                                                                "'%1' is not a quantity the %2 can plot; it has %3")
                                        .toStdString(),
                                    {text::printable(quantity, 40), mechanism.kind(), names})};
    }
    AnimationPlot plot;
    plot.variable = settings.variable;
    plot.entry = **found;
    const VariableInfo &input = mechanism.variableInfo()[settings.variable];
    plot.xLabel = axisName(input.symbol, input.unit);
    plot.yLabel = axisName(plot.entry.symbol, plot.entry.unit);
    // The labels' names only, without what follows them ("(0: direct, ∞: inverse singularity)",
    // ", from +x counter-clockwise"): the whole descriptions took three lines over a plot of
    // half a frame, and the axes give the symbols and units.
    const auto name = [](const std::string &label) {
        QString text = coreLabel(label);
        for (const QString &end : {QStringLiteral(" ("), QStringLiteral(", ")}) {
            if (const qsizetype at = text.indexOf(end); at > 0)
                text.truncate(at);
        }
        return text;
    };
    plot.title = QCoreApplication::translate("pkm::AnimationPlot", "%1 against %2")
                     .arg(name(plot.entry.label), name(input.label));
    if (!plot.title.isEmpty())
        plot.title[0] = plot.title[0].toUpper(); // a title, where the labels are set for a sentence
    const double from = std::min(settings.from, settings.to), to = std::max(settings.from, settings.to);
    plot.xMin = input.unit.toDisplay(from);
    plot.xMax = input.unit.toDisplay(to);
    if (plot.xMax <= plot.xMin)
        plot.xMax = plot.xMin + 1.0;

    // Solved from the animation's start along its path, one sample from the last.
    std::vector<double> buffer(std::size_t(mechanism.reportLayout().size));
    Pose near = start;
    const double gap = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i < animationPlotSamples; ++i) {
        const double value = settings.from + (settings.to - settings.from) * i / (animationPlotSamples - 1);
        double y = gap;
        if (auto solved = mechanism.solveWith(near, settings.variable, value)) {
            near = *solved;
            mechanism.evaluate(near, buffer);
            const double v = buffer[std::size_t(plot.entry.offset)];
            if (std::isfinite(v))
                y = plot.entry.unit.toDisplay(v);
        }
        plot.curve.emplace_back(input.unit.toDisplay(value), y);
    }
    std::tie(plot.yMin, plot.yMax) = valueRange(plot.curve);
    return plot;
}

QString animationPlotReadout(const AnimationPlot &plot, const Mechanism &mechanism, const Pose &pose)
{
    std::vector<double> buffer(std::size_t(mechanism.reportLayout().size));
    mechanism.evaluate(pose, buffer);
    return readout(plot, buffer[std::size_t(plot.entry.offset)]);
}

QImage animationPlotImage(const AnimationPlot &plot, const Mechanism &mechanism, const Pose &pose, QSize size)
{
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing, true);
    const double h = size.height(), w = size.width();
    const double unit = std::min(h / 720.0, w / 560.0); // the 720-pixel frame's sizes, scaled
    const double margin = 20.0 * unit, tick = 6.0 * unit;
    const QFont titleFont = sized(22.0 * unit, true), labelFont = sized(19.0 * unit), tickFont = sized(16.0 * unit);
    const QFontMetricsF titleMetrics(titleFont, &image), labelMetrics(labelFont, &image),
        tickMetrics(tickFont, &image);

    // The title, wrapped; the read-out of the pose's value under it.
    const QRectF titleBox(margin, margin, w - 2.0 * margin, h / 3.0);
    const QRectF titleUsed = titleMetrics.boundingRect(titleBox, Qt::AlignHCenter | Qt::TextWordWrap, plot.title);
    painter.setPen(QColor::fromRgb(plotstyle::axisRgb));
    painter.setFont(titleFont);
    painter.drawText(titleBox, Qt::AlignHCenter | Qt::TextWordWrap, plot.title);

    std::vector<double> buffer(std::size_t(mechanism.reportLayout().size));
    mechanism.evaluate(pose, buffer);
    const double raw = buffer[std::size_t(plot.entry.offset)];
    const double value = std::isfinite(raw) ? plot.entry.unit.toDisplay(raw) : raw;
    const double x = mechanism.variableInfo()[plot.variable].unit.toDisplay(mechanism.variableValue(pose, plot.variable));
    const QString valueText = readout(plot, raw); // as animationPlotReadout()
    const QRectF readoutBox(margin, titleUsed.bottom() + 0.4 * labelMetrics.height(), w - 2.0 * margin,
                            labelMetrics.height());
    painter.setFont(labelFont);
    painter.setPen(QColor::fromRgb(plotstyle::cursorRgb));
    painter.drawText(readoutBox, Qt::AlignHCenter,
                     labelMetrics.elidedText(valueText, Qt::ElideRight, readoutBox.width()));

    // Ticks first: the left margin takes the widest label.
    const double xStep = niceStep(plot.xMax - plot.xMin, int(std::max(2.0, w / (80.0 * unit))));
    const double yStep = niceStep(plot.yMax - plot.yMin, int(std::max(3.0, h / (90.0 * unit))));
    std::vector<std::pair<double, QString>> xTicks, yTicks;
    for (double t = std::ceil(plot.xMin / xStep - 1e-9) * xStep; t <= plot.xMax + 1e-9 * xStep; t += xStep)
        xTicks.emplace_back(t, tickText(t, xStep));
    double widest = 0.0;
    for (double t = std::ceil(plot.yMin / yStep - 1e-9) * yStep; t <= plot.yMax + 1e-9 * yStep; t += yStep) {
        yTicks.emplace_back(t, tickText(t, yStep));
        widest = std::max(widest, tickMetrics.horizontalAdvance(yTicks.back().second));
    }
    const QRectF axes(QPointF(margin + labelMetrics.height() + 0.5 * margin + widest + tick + 4.0 * unit,
                              readoutBox.bottom() + 0.8 * margin),
                      QPointF(w - 1.5 * margin,
                              h - margin - labelMetrics.height() - 0.3 * margin - tickMetrics.height() - tick));
    if (axes.width() < 20.0 || axes.height() < 20.0)
        return image; // too small for axes: the title and read-out alone
    const auto px = [&](double v) { return axes.left() + (v - plot.xMin) / (plot.xMax - plot.xMin) * axes.width(); };
    const auto py = [&](double v) { return axes.bottom() - (v - plot.yMin) / (plot.yMax - plot.yMin) * axes.height(); };

    // Grid, ticks and their labels.
    painter.setFont(tickFont);
    for (const auto &[t, label] : xTicks) {
        painter.setPen(QPen(QColor::fromRgb(plotstyle::gridRgb), unit));
        painter.drawLine(QPointF(px(t), axes.top()), QPointF(px(t), axes.bottom()));
        painter.setPen(QPen(QColor::fromRgb(plotstyle::axisRgb), unit));
        painter.drawLine(QPointF(px(t), axes.bottom()), QPointF(px(t), axes.bottom() + tick));
        const double width = tickMetrics.horizontalAdvance(label);
        painter.drawText(QPointF(px(t) - width / 2.0, axes.bottom() + tick + tickMetrics.ascent()), label);
    }
    for (const auto &[t, label] : yTicks) {
        painter.setPen(QPen(QColor::fromRgb(plotstyle::gridRgb), unit));
        painter.drawLine(QPointF(axes.left(), py(t)), QPointF(axes.right(), py(t)));
        painter.setPen(QPen(QColor::fromRgb(plotstyle::axisRgb), unit));
        painter.drawLine(QPointF(axes.left() - tick, py(t)), QPointF(axes.left(), py(t)));
        const double width = tickMetrics.horizontalAdvance(label);
        painter.drawText(QPointF(axes.left() - tick - 3.0 * unit - width,
                                 py(t) + (tickMetrics.ascent() - tickMetrics.descent()) / 2.0),
                         label);
    }
    painter.setPen(QPen(QColor::fromRgb(plotstyle::axisRgb), 1.2 * unit));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(axes);

    // Axis names: x centred under the tick labels, y turned up the left edge.
    painter.setFont(labelFont);
    painter.drawText(QRectF(axes.left(), h - margin - labelMetrics.height(), axes.width(), labelMetrics.height()),
                     Qt::AlignHCenter, labelMetrics.elidedText(plot.xLabel, Qt::ElideRight, axes.width()));
    painter.save();
    painter.translate(margin, axes.center().y());
    painter.rotate(-90.0);
    painter.drawText(QRectF(-axes.height() / 2.0, 0.0, axes.height(), labelMetrics.height()), Qt::AlignHCenter,
                     labelMetrics.elidedText(plot.yLabel, Qt::ElideRight, axes.height()));
    painter.restore();

    // The curve, broken at gaps, clipped to the axes (a runaway part near a singular pose).
    painter.save();
    painter.setClipRect(axes.adjusted(-1.0, -1.0, 1.0, 1.0));
    QPainterPath path;
    bool drawing = false;
    for (const QPointF &point : plot.curve) {
        if (!std::isfinite(point.y())) {
            drawing = false;
            continue;
        }
        const QPointF at(px(point.x()), py(std::clamp(point.y(), plot.yMin - 10.0 * (plot.yMax - plot.yMin),
                                                      plot.yMax + 10.0 * (plot.yMax - plot.yMin))));
        drawing ? path.lineTo(at) : path.moveTo(at);
        drawing = true;
    }
    painter.setPen(QPen(QColor::fromRgb(plotstyle::designRgb), 2.5 * unit, Qt::SolidLine, Qt::RoundCap,
                        Qt::RoundJoin));
    painter.drawPath(path);

    // The cursor: a line at the pose's x, a ring on the curve where the value is finite.
    const QColor cursor = QColor::fromRgb(plotstyle::cursorRgb);
    if (std::isfinite(x)) {
        painter.setPen(QPen(cursor, 1.2 * unit, Qt::DashLine));
        painter.drawLine(QPointF(px(x), axes.top()), QPointF(px(x), axes.bottom()));
        if (std::isfinite(value) && value >= plot.yMin && value <= plot.yMax) {
            painter.setPen(QPen(cursor, 2.0 * unit));
            painter.setBrush(Qt::white);
            painter.drawEllipse(QPointF(px(x), py(value)), 6.0 * unit, 6.0 * unit);
        }
    }
    painter.restore();
    return image;
}

} // namespace pkm
