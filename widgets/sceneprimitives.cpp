#include "sceneprimitives.h"

#include "scenegeometry.h"

#include <QLineF>
#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <QPolygonF>
#include <QRectF>
#include <QSizeF>
#include <QString>

#include <algorithm>
#include <array>
#include <cmath>

// Everything here is drawn as flat- or square-capped lines in device coordinates, for the
// raster engine's fast path (see the performance note in scenepainter.cpp).

namespace pkm {

using namespace detail;

void SceneCanvas::stroke(const QColor &colour, double width, Qt::PenCapStyle cap) const
{
    painter.setPen(QPen(colour, width, Qt::SolidLine, cap));
}

void drawGround(const SceneCanvas &canvas, const QPointF &pivot)
{
    // The engineering ground symbol: a support triangle under the pivot, a base line and
    // short hatch strokes below it.
    const double px = canvas.px();
    const double w = 26.0 * px, h = 15.0 * px, hatch = 7.0 * px, pitch = 6.0 * px;
    QPen pen(canvas.style.ink, 1.6 * px);
    pen.setCapStyle(Qt::FlatCap);
    pen.setJoinStyle(Qt::MiterJoin);
    const QPointF p = pivot;
    canvas.painter.setPen(pen);
    canvas.painter.setBrush(QColor(0xe4, 0xe8, 0xee));
    canvas.painter.drawPolygon(QPolygonF({p, p + QPointF(-0.5 * w, h), p + QPointF(0.5 * w, h)}));
    const double left = p.x() - 0.5 * w - 6.0 * px, right = p.x() + 0.5 * w + 6.0 * px, y = p.y() + h;
    std::array<QLineF, 17> strokes;
    strokes[0] = QLineF(left, y, right, y);
    std::size_t n = 1;
    for (double x = right; x > left + hatch * 0.5 && n < strokes.size(); x -= pitch)
        strokes[n++] = QLineF(x, y, x - hatch, y + hatch);
    canvas.painter.drawLines(strokes.data(), int(n));
    canvas.labels.addObstacle(boxQuad(QPointF(p.x(), y + 0.5 * (hatch - h)), QSizeF(right - left, h + hatch), 0.0));
}

void drawActuator(const SceneCanvas &canvas, const SceneActuator &actuator)
{
    if (!canvas.valid(actuator.from) || !canvas.valid(actuator.to))
        return;
    QPainter &painter = canvas.painter;
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    const QPointF p = canvas.point(actuator.from), q = canvas.point(actuator.to);
    const double distance = length(q - p);
    if (distance < 1e-6)
        return; // no direction to draw along
    const QPointF u = (q - p) / distance;
    // Across, towards the top of the screen: where the light falls on the highlights.
    const QPointF n = u.x() >= 0.0 ? screenLeft(u) : -screenLeft(u);
    // A point `along` from `from` towards `to` and `across` to one side, device units.
    auto at = [&](double along, double across) { return p + along * u + across * n; };

    const double scale = canvas.mapping.scale;
    const double bodyLength = std::max(0.0, actuator.bodyLength * scale);
    const double bodyWidth = std::max(actuator.bodyWidth * scale, 6.0 * px);
    const double body = std::min(bodyLength, distance); // clipped when the pose is shorter
    const double screwWidth = std::max(actuator.rodDiameter * scale, style.minimumScrewWidth * px);
    const QColor outline = style.motorBody.darker(160);

    if (body < distance) {
        // Screw: metallic, with a specular line and slanted thread strokes.
        const double half = 0.5 * screwWidth;
        canvas.stroke(style.screw, screwWidth);
        painter.drawLine(at(body, 0.0), q);
        if (screwWidth >= 6.0 * px) {
            const double pitch = std::max(4.0 * px, 0.5 * screwWidth);
            std::vector<QLineF> thread;
            thread.reserve(std::size_t((distance - body) / pitch) + 1);
            for (double x = body + pitch; x < distance - 0.5 * pitch; x += pitch)
                thread.emplace_back(at(x, half), at(x - 0.4 * screwWidth, -half));
            canvas.stroke(style.screwShade, 0.8 * px);
            painter.drawLines(thread.data(), int(thread.size()));
        }
        if (screwWidth >= 4.0 * px) {
            canvas.stroke(style.screw.lighter(130), std::max(1.0 * px, 0.18 * screwWidth));
            painter.drawLine(at(body, 0.22 * screwWidth), at(distance, 0.22 * screwWidth));
        }
        const std::array<QLineF, 2> edges {
            QLineF(at(body, half), at(distance, half)), QLineF(at(body, -half), at(distance, -half))};
        canvas.stroke(style.screwShade.darker(125), 0.8 * px);
        painter.drawLines(edges.data(), int(edges.size()));
        canvas.labels.addObstacle(at(body, 0.0), q, half + 1.0 * px);
    }
    if (body > 0.0) {
        // Motor body, a highlight along its upper edge, and a lighter end cap with the
        // bearing boss where the screw leaves it (both absent when clipped).
        const double half = 0.5 * bodyWidth;
        canvas.stroke(style.motorBody, bodyWidth);
        painter.drawLine(p, at(body, 0.0));
        canvas.stroke(style.motorBody.lighter(140), 0.16 * bodyWidth);
        painter.drawLine(at(0.0, 0.36 * bodyWidth), at(body, 0.36 * bodyWidth));
        if (body >= bodyLength) {
            const double cap = std::min(0.16 * body, std::max(3.0 * px, 0.12 * body));
            canvas.stroke(style.motorCap, bodyWidth);
            painter.drawLine(at(body - cap, 0.0), at(body, 0.0));
            const double boss = std::min(0.55 * bodyWidth, std::max(screwWidth * 2.2, 6.0 * px));
            const double bossLength = std::min(2.5 * px + 0.04 * body, distance - body);
            canvas.stroke(style.motorCap.lighter(115), boss);
            painter.drawLine(at(body, 0.0), at(body + bossLength, 0.0));
            const std::array<QLineF, 4> bossEdges {QLineF(at(body, 0.5 * boss), at(body + bossLength, 0.5 * boss)),
                QLineF(at(body + bossLength, 0.5 * boss), at(body + bossLength, -0.5 * boss)),
                QLineF(at(body + bossLength, -0.5 * boss), at(body, -0.5 * boss)),
                QLineF(at(body - cap, half), at(body - cap, -half))};
            canvas.stroke(outline, 1.0 * px);
            painter.drawLines(bossEdges.data(), int(bossEdges.size()));
        }
        const std::array<QLineF, 4> edges {QLineF(at(0.0, half), at(body, half)),
            QLineF(at(body, half), at(body, -half)), QLineF(at(body, -half), at(0.0, -half)),
            QLineF(at(0.0, -half), at(0.0, half))};
        canvas.stroke(outline, 1.2 * px, Qt::SquareCap);
        painter.drawLines(edges.data(), int(edges.size()));
        canvas.labels.addObstacle(Quad {at(0.0, half), at(body, half), at(body, -half), at(0.0, -half)});
    }
    if (!actuator.label.empty())
        canvas.labels.addMemberLabel(
            {actuator.from, actuator.to, QString::fromStdString(actuator.label), style.ink, false});
}

void drawArrow(const SceneCanvas &canvas, const QPointF &tip, const QPointF &direction, const QColor &colour)
{
    const QPointF u = unit(direction), n = screenLeft(u);
    const double l = canvas.style.arrowLength * canvas.px(), w = 0.5 * canvas.style.arrowWidth * canvas.px();
    const QPolygonF head({tip, tip - l * u + w * n, tip - 0.8 * l * u, tip - l * u - w * n});
    canvas.painter.setPen(Qt::NoPen);
    canvas.painter.setBrush(colour);
    canvas.painter.drawPolygon(head);
}

void drawDimension(const SceneCanvas &canvas, const SceneDimension &dimension)
{
    if (!canvas.valid(dimension.from) || !canvas.valid(dimension.to))
        return;
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    const QColor colour = style.dimension;
    const double arrow = style.arrowLength * px;
    const QPointF p = canvas.point(dimension.from), q = canvas.point(dimension.to);
    const double span = length(q - p);
    if (span < 1e-6)
        return;
    const QPointF u = (q - p) / span;
    const QString text = QString::fromStdString(dimension.text);
    const double offset = std::abs(dimension.offset) * canvas.mapping.scale;
    if (offset < 1.0 * px) {
        // Along the member itself: only the text, beside it (placed with the labels).
        if (!text.isEmpty())
            canvas.labels.addMemberLabel({dimension.from, dimension.to, text, colour, true});
        return;
    }
    // Positive offset: to the left of from→to in the scene, which stays the left on screen.
    const QPointF side = screenLeft(u) * (dimension.offset > 0 ? 1.0 : -1.0);
    const QPointF d1 = p + offset * side, d2 = q + offset * side;
    const double gap = (style.pivotRadius + 4.0) * px, overshoot = 7.0 * px;

    canvas.stroke(colour, 1.2 * px);
    if (offset > gap) {
        const std::array<QLineF, 2> extensions {
            QLineF(p + gap * side, d1 + overshoot * side), QLineF(q + gap * side, d2 + overshoot * side)};
        canvas.painter.drawLines(extensions.data(), int(extensions.size()));
        canvas.labels.addObstacle(p + gap * side, d1 + overshoot * side, 1.0 * px);
        canvas.labels.addObstacle(q + gap * side, d2 + overshoot * side, 1.0 * px);
    }
    canvas.labels.addRay(dimension.from, side, offset + overshoot);
    canvas.labels.addRay(dimension.to, side, offset + overshoot);
    if (span > 2.0 * arrow + 6.0 * px) {
        canvas.painter.drawLine(d1 + 0.5 * arrow * u, d2 - 0.5 * arrow * u);
        drawArrow(canvas, d1, -u, colour);
        drawArrow(canvas, d2, u, colour);
        canvas.labels.addObstacle(d1, d2, 0.5 * style.arrowWidth * px);
    } else {
        // Too short for arrows inside: point at the extension lines from outside.
        canvas.painter.drawLine(d1 - 2.0 * arrow * u, d2 + 2.0 * arrow * u);
        drawArrow(canvas, d1, u, colour);
        drawArrow(canvas, d2, -u, colour);
        canvas.labels.addObstacle(d1 - 2.0 * arrow * u, d2 + 2.0 * arrow * u, 0.5 * style.arrowWidth * px);
    }
    // Centred on the dimension line, whose segment under the text the knock-out hides.
    if (!text.isEmpty())
        canvas.labels.place({0.5 * (d1 + d2), readableRotation(u), text, false, colour});
}

void drawAngle(const SceneCanvas &canvas, const SceneAngle &angle)
{
    if (!canvas.valid(angle.vertex))
        return;
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    const QColor colour = style.angle;
    const double minimumRadius = 22.0 * px;
    QPen dashed(colour, 1.2 * px, Qt::CustomDashLine, Qt::FlatCap);
    dashed.setDashPattern({6.0, 4.0});
    const QPointF v = canvas.point(angle.vertex);
    const double r = std::max(angle.radius * canvas.mapping.scale, minimumRadius);
    const double end = angle.start + angle.sweep;
    const double turn = angle.sweep > 0.0 ? 1.0 : -1.0;
    const bool drawArc = std::abs(angle.sweep) >= 0.5 * degree;

    // Dashed reference lines for the legs that no member shows (θ's vertical, say).
    for (double legAngle : {angle.start, end}) {
        const QPointF leg = deviceDirection(legAngle);
        if (canvas.labels.alongMember(angle.vertex, leg) || (legAngle == end && !drawArc))
            continue;
        const QPointF from = v + (style.pivotRadius + 3.0) * px * leg, to = v + (r + 16.0 * px) * leg;
        canvas.painter.setPen(dashed);
        canvas.painter.drawLine(from, to);
        canvas.labels.addRay(angle.vertex, leg, r + 16.0 * px);
        canvas.labels.addObstacle(from, to, 1.0 * px);
    }

    if (drawArc) {
        const QRectF box(v.x() - r, v.y() - r, 2.0 * r, 2.0 * r);
        const double arrow = style.arrowLength * px;
        const bool withArrow = r * std::abs(angle.sweep) > 1.6 * arrow;
        // Stop the line under the arrowhead so its tip stays sharp.
        const double trimmed = withArrow ? angle.sweep - turn * (0.7 * arrow / r) : angle.sweep;
        QPainterPath path;
        path.arcMoveTo(box, angle.start / degree);
        path.arcTo(box, angle.start / degree, trimmed / degree);
        canvas.stroke(colour, 2.0 * px);
        canvas.painter.setBrush(Qt::NoBrush);
        canvas.painter.drawPath(path);
        if (withArrow) {
            // Aim along the chord of the last arrow length so the head sits on the arc.
            const QPointF tip = v + r * deviceDirection(end);
            const QPointF back = v + r * deviceDirection(end - turn * arrow / r);
            drawArrow(canvas, tip, tip - back, colour);
        }
        const int chords = std::clamp(int(std::abs(angle.sweep) / (15.0 * degree)) + 1, 1, 24);
        for (int i = 0; i < chords; ++i) {
            canvas.labels.addObstacle(v + r * deviceDirection(angle.start + angle.sweep * i / chords),
                v + r * deviceDirection(angle.start + angle.sweep * (i + 1) / chords), 2.0 * px);
        }
    }
    if (!angle.label.empty())
        canvas.labels.addAngleLabel({angle.vertex, r, angle.start, angle.sweep, QString::fromStdString(angle.label)});
}

} // namespace pkm
