#include "drawlistpainter.h"
#include "rasterstroke.h"

#include "scenegeometry.h"

#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <QRectF>

#include <type_traits>

// Performance: Qt's raster engine strokes flat- or square-capped lines through a fast path,
// while round caps, filled rotated shapes and gradients cost ten times more. So bands and
// rotated knock-out boxes are thick flat-capped lines, and lines sharing a pen go to the
// painter in one call.

namespace pkm::drawing {

using namespace pkm::detail;

namespace {

QPen qtPen(const Pen &pen)
{
    QPen result(pen.colour, pen.width, Qt::SolidLine, pen.cap, pen.join);
    if (const QVector<qreal> pattern = dashPattern(pen.dash); !pattern.isEmpty())
        result.setDashPattern(pattern); // in pen widths
    return result;
}

void setStroke(QPainter &painter, const Pen &pen)
{
    if (pen.width > 0.0)
        painter.setPen(qtPen(pen));
    else
        painter.setPen(Qt::NoPen);
}

void setFill(QPainter &painter, const QColor &fill)
{
    if (fill.alpha() > 0)
        painter.setBrush(fill);
    else
        painter.setBrush(Qt::NoBrush);
}

void band(QPainter &painter, const QPointF &a, const QPointF &b, double width, const QColor &colour)
{
    painter.setPen(QPen(colour, width, Qt::SolidLine, Qt::FlatCap));
    painter.drawLine(a, b);
}

void arrow(QPainter &painter, const QPointF &tip, const QPointF &direction, const ArrowShape &head, const QColor &colour)
{
    const std::array<QPointF, 4> corners = arrowCorners(tip, direction, head);
    painter.setPen(Qt::NoPen);
    painter.setBrush(colour);
    painter.drawPolygon(corners.data(), int(corners.size()));
}

void paintArc(QPainter &painter, const Arc &arc)
{
    const double r = arc.radius;
    const QRectF box(arc.centre.x() - r, arc.centre.y() - r, 2.0 * r, 2.0 * r);
    const double turn = arc.sweep > 0.0 ? 1.0 : -1.0;
    // Stop the line under the arrowhead so its tip stays sharp.
    const double sweep = arc.arrow ? arc.sweep - turn * (0.7 * arc.head.length / r) : arc.sweep;
    QPainterPath path;
    path.arcMoveTo(box, arc.start / degree);
    path.arcTo(box, arc.start / degree, sweep / degree);
    setStroke(painter, arc.pen);
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(path);
    if (arc.arrow) {
        const auto [tip, direction] = arcArrow(arc);
        arrow(painter, tip, direction, arc.head, arc.pen.colour);
    }
}

void paintDimension(QPainter &painter, const DimensionLine &dimension)
{
    // The gap is left to the text's knock-out box, which hides the line under it.
    const QPointF u = unit(dimension.to - dimension.from);
    const double arrowLength = dimension.head.length;
    setStroke(painter, dimension.pen);
    if (dimension.arrowsInside) {
        painter.drawLine(dimension.from + 0.5 * arrowLength * u, dimension.to - 0.5 * arrowLength * u);
        arrow(painter, dimension.from, -u, dimension.head, dimension.pen.colour);
        arrow(painter, dimension.to, u, dimension.head, dimension.pen.colour);
    } else {
        painter.drawLine(dimension.from - dimension.tail * u, dimension.to + dimension.tail * u);
        arrow(painter, dimension.from, u, dimension.head, dimension.pen.colour);
        arrow(painter, dimension.to, -u, dimension.head, dimension.pen.colour);
    }
}

void paintText(QPainter &painter, const Text &text)
{
    // An opaque knock-out box in the background colour hides the lines under the text; unlike
    // a translucent or rounded one it is a plain span fill.
    const QRectF box(-0.5 * text.box.width(), -0.5 * text.box.height(), text.box.width(), text.box.height());
    if (text.rotationDegrees == 0.0) {
        painter.fillRect(box.translated(text.centre), text.knockout);
    } else {
        const QPointF u = deviceDirection(-text.rotationDegrees * degree);
        band(painter, text.centre - 0.5 * text.box.width() * u, text.centre + 0.5 * text.box.width() * u,
            text.box.height(), text.knockout);
    }
    painter.save();
    painter.translate(text.centre);
    if (text.rotationDegrees != 0.0)
        painter.rotate(text.rotationDegrees);
    painter.setFont(text.font);
    painter.setPen(text.colour);
    painter.drawText(box, Qt::AlignCenter, text.text);
    painter.restore();
}

} // namespace

void paintDrawList(QPainter &painter, const DrawList &list)
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    for (const Primitive &item : list.items) {
        if (!shownOnScreen(item.medium))
            continue;
        std::visit(
            [&painter](const auto &shape) {
                using T = std::decay_t<decltype(shape)>;
                if constexpr (std::is_same_v<T, Lines>) {
                    if (strokesOnRaster(painter, shape.pen)) {
                        for (const QLineF &line : shape.lines)
                            strokeOnRaster(painter, QPolygonF{line.p1(), line.p2()}, false, shape.pen);
                        return;
                    }
                    setStroke(painter, shape.pen);
                    painter.drawLines(shape.lines.data(), int(shape.lines.size()));
                } else if constexpr (std::is_same_v<T, Band> || std::is_same_v<T, Member>) {
                    band(painter, shape.a, shape.b, shape.width, shape.colour);
                } else if constexpr (std::is_same_v<T, Polygon>) {
                    if (strokesOnRaster(painter, shape.pen)) {
                        if (shape.fill.alpha() > 0 && shape.closed) {
                            painter.setPen(Qt::NoPen);
                            painter.setBrush(shape.fill);
                            painter.drawPolygon(shape.points);
                        }
                        strokeOnRaster(painter, shape.points, shape.closed, shape.pen);
                        return;
                    }
                    setStroke(painter, shape.pen);
                    setFill(painter, shape.fill);
                    if (shape.closed)
                        painter.drawPolygon(shape.points);
                    else
                        painter.drawPolyline(shape.points);
                } else if constexpr (std::is_same_v<T, Circle>) {
                    setStroke(painter, shape.pen);
                    setFill(painter, shape.fill);
                    painter.drawEllipse(shape.centre, shape.radius, shape.radius);
                } else if constexpr (std::is_same_v<T, Arc>) {
                    paintArc(painter, shape);
                } else if constexpr (std::is_same_v<T, DimensionLine>) {
                    paintDimension(painter, shape);
                } else if constexpr (std::is_same_v<T, Text>) {
                    paintText(painter, shape);
                }
            },
            item.shape);
    }
    painter.restore();
}

} // namespace pkm::drawing
