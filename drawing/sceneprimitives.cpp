#include "sceneprimitives.h"

#include "dimensiontext.h"
#include "scenegeometry.h"

#include <QLineF>
#include <QPolygonF>
#include <QSizeF>
#include <QString>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

// The ground symbol, the linear actuator, dimensions and angles. Shading is the screen's
// alone; the outlines, axes and measurable dimension lines are every medium's.

namespace pkm {

using namespace detail;
using drawing::Layer;
using drawing::Medium;

void drawGround(const SceneCanvas &canvas, const QPointF &pivot)
{
    // The engineering ground symbol: a support triangle under the pivot, a base line and
    // short hatch strokes below it.
    const double px = canvas.px();
    const double w = 26.0 * px, h = 15.0 * px, hatch = 7.0 * px, pitch = 6.0 * px;
    drawing::Pen outline = pen(canvas.style.ink, 1.6 * px);
    outline.join = Qt::MiterJoin;
    const QPointF p = pivot;
    canvas.out.add(drawing::Polygon {QPolygonF({p, p + QPointF(-0.5 * w, h), p + QPointF(0.5 * w, h)}), true, outline,
                       QColor(0xe4, 0xe8, 0xee)},
        Layer::Ground);
    const double left = p.x() - 0.5 * w - 6.0 * px, right = p.x() + 0.5 * w + 6.0 * px, y = p.y() + h;
    std::vector<QLineF> strokes {QLineF(left, y, right, y)};
    for (double x = right; x > left + hatch * 0.5 && strokes.size() < 17; x -= pitch)
        strokes.emplace_back(x, y, x - hatch, y + hatch);
    canvas.lines(Layer::Ground, outline, std::move(strokes));
    canvas.labels.addObstacle(boxQuad(QPointF(p.x(), y + 0.5 * (hatch - h)), QSizeF(right - left, h + hatch), 0.0));
}

void drawActuator(const SceneCanvas &canvas, const SceneActuator &actuator)
{
    if (!canvas.valid(actuator.from) || !canvas.valid(actuator.to)) {
        ++canvas.out.skipped;
        return;
    }
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
        canvas.band(Layer::Actuators, at(body, 0.0), q, screwWidth, style.screw, Medium::Screen);
        if (screwWidth >= 6.0 * px) {
            const double pitch = std::max(4.0 * px, 0.5 * screwWidth);
            std::vector<QLineF> thread;
            thread.reserve(std::size_t((distance - body) / pitch) + 1);
            for (double x = body + pitch; x < distance - 0.5 * pitch; x += pitch)
                thread.emplace_back(at(x, half), at(x - 0.4 * screwWidth, -half));
            canvas.lines(Layer::Actuators, pen(style.screwShade, 0.8 * px), std::move(thread), Medium::Screen);
        }
        if (screwWidth >= 4.0 * px) {
            canvas.line(Layer::Actuators, pen(style.screw.lighter(130), std::max(1.0 * px, 0.18 * screwWidth)),
                at(body, 0.22 * screwWidth), at(distance, 0.22 * screwWidth), Medium::Screen);
        }
        canvas.lines(Layer::Actuators, pen(style.screwShade.darker(125), 0.8 * px),
            {QLineF(at(body, half), at(distance, half)), QLineF(at(body, -half), at(distance, -half))});
        canvas.labels.addObstacle(at(body, 0.0), q, half + 1.0 * px);
    }
    if (body > 0.0) {
        // Motor body, a highlight along its upper edge, and a lighter end cap with the
        // bearing boss where the screw leaves it (both absent when clipped).
        const double half = 0.5 * bodyWidth;
        canvas.band(Layer::Actuators, p, at(body, 0.0), bodyWidth, style.motorBody, Medium::Screen);
        canvas.line(Layer::Actuators, pen(style.motorBody.lighter(140), 0.16 * bodyWidth), at(0.0, 0.36 * bodyWidth),
            at(body, 0.36 * bodyWidth), Medium::Screen);
        if (body >= bodyLength) {
            const double cap = std::min(0.16 * body, std::max(3.0 * px, 0.12 * body));
            canvas.band(Layer::Actuators, at(body - cap, 0.0), at(body, 0.0), bodyWidth, style.motorCap, Medium::Screen);
            const double boss = std::min(0.55 * bodyWidth, std::max(screwWidth * 2.2, 6.0 * px));
            const double bossLength = std::min(2.5 * px + 0.04 * body, distance - body);
            canvas.band(Layer::Actuators, at(body, 0.0), at(body + bossLength, 0.0), boss, style.motorCap.lighter(115),
                Medium::Screen);
            canvas.lines(Layer::Actuators, pen(outline, 1.0 * px),
                {QLineF(at(body, 0.5 * boss), at(body + bossLength, 0.5 * boss)),
                    QLineF(at(body + bossLength, 0.5 * boss), at(body + bossLength, -0.5 * boss)),
                    QLineF(at(body + bossLength, -0.5 * boss), at(body, -0.5 * boss)),
                    QLineF(at(body - cap, half), at(body - cap, -half))});
        }
        canvas.lines(Layer::Actuators, pen(outline, 1.2 * px, Qt::SquareCap),
            {QLineF(at(0.0, half), at(body, half)), QLineF(at(body, half), at(body, -half)),
                QLineF(at(body, -half), at(0.0, -half)), QLineF(at(0.0, -half), at(0.0, half))});
        canvas.labels.addObstacle(Quad {at(0.0, half), at(body, half), at(body, -half), at(0.0, -half)});
    }
    // The axis from joint to joint, which the screen shows by the body and the screw.
    canvas.line(Layer::Actuators, pen(outline, 1.0 * px, Qt::FlatCap, drawing::Dash::Centre), p, q, Medium::Cad);
    if (!actuator.label.empty())
        canvas.labels.addMemberLabel(
            {actuator.from, actuator.to, QString::fromStdString(actuator.label), style.ink, false, {}});
}

namespace {

/// The distance in mm between two joints of the scene, as a dimension states it.
double sceneDistance(const Scene &scene, int from, int to)
{
    return (scene.joints[std::size_t(to)].position.head<2>() - scene.joints[std::size_t(from)].position.head<2>())
        .norm();
}

} // namespace

void drawDimension(const SceneCanvas &canvas, const SceneDimension &dimension)
{
    if (!canvas.valid(dimension.from) || !canvas.valid(dimension.to)) {
        ++canvas.out.skipped;
        return;
    }
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    const QColor colour = style.dimension;
    const drawing::ArrowShape head {style.arrowLength * px, style.arrowWidth * px};
    const double arrow = head.length;
    const QPointF p = canvas.point(dimension.from), q = canvas.point(dimension.to);
    const double span = length(q - p);
    if (span < 1e-6)
        return;
    const QPointF u = (q - p) / span;
    const QString text = QString::fromStdString(dimension.text);
    // A CAD drawing states the measured distance, whatever the scene's text rounds it to.
    const std::string cad = drawing::dimensionText(dimension.text, sceneDistance(canvas.scene, dimension.from, dimension.to));
    const drawing::Pen line = pen(colour, 1.2 * px);
    const double offset = std::abs(dimension.offset) * canvas.mapping.scale;
    if (offset < 1.0 * px) {
        // Along the member itself: the screen writes only the text, beside it (placed with
        // the labels); CAD also gets the dimension line on the member's axis, pin to pin.
        if (!text.isEmpty())
            canvas.labels.addMemberLabel({dimension.from, dimension.to, text, colour, true, cad});
        canvas.out.add(drawing::DimensionLine {p, q, true, 0.0, 0.0, line, head}, Layer::Dimensions, Medium::Cad);
        return;
    }
    // Positive offset: to the left of from→to in the scene, which stays the left on screen.
    const QPointF side = screenLeft(u) * (dimension.offset > 0 ? 1.0 : -1.0);
    const QPointF d1 = p + offset * side, d2 = q + offset * side;
    const double overshoot = 7.0 * px;
    // Extension lines start clear of the pivot, and of the rail and carriage of a joint on a
    // guide the dimension runs along.
    auto gapAt = [&](int joint) {
        double gap = (style.pivotRadius + 4.0) * px;
        const int guide = std::size_t(joint) < canvas.jointGuide.size() ? canvas.jointGuide[std::size_t(joint)] : -1;
        if (guide >= 0 && guide < int(canvas.guides.size())) {
            const GuideShape &shape = canvas.guides[std::size_t(guide)];
            if (std::abs(dot(side, shape.u)) < 0.5) {
                gap = std::max(gap, shape.reach(dot(side, shape.outer)) + 3.0 * px);
                if (canvas.carriageGuide(joint))
                    gap = std::max(gap, shape.carriageHalfWidth + 3.0 * px);
            }
        }
        return gap;
    };
    const double gapFrom = gapAt(dimension.from), gapTo = gapAt(dimension.to);

    std::vector<QLineF> extensions;
    if (offset > gapFrom) {
        extensions.emplace_back(p + gapFrom * side, d1 + overshoot * side);
        canvas.labels.addObstacle(p + gapFrom * side, d1 + overshoot * side, 1.0 * px);
    }
    if (offset > gapTo) {
        extensions.emplace_back(q + gapTo * side, d2 + overshoot * side);
        canvas.labels.addObstacle(q + gapTo * side, d2 + overshoot * side, 1.0 * px);
    }
    if (!extensions.empty())
        canvas.lines(Layer::Dimensions, line, std::move(extensions));
    canvas.labels.addRay(dimension.from, side, offset + overshoot);
    canvas.labels.addRay(dimension.to, side, offset + overshoot);
    // The text centred on the line (the knock-out hides the line under it; CAD leaves a gap)
    // with the arrows inside when both fit; when only the text fits, the arrows point in from
    // outside; when the text does not fit either, it goes beside the line or past one of its ends.
    const QSizeF size = text.isEmpty() ? QSizeF() : canvas.labels.textSize(text);
    const double textLength = text.isEmpty() ? 0.0 : size.width(); // padding included
    const bool arrowsInside = span > textLength + 2.0 * arrow + 6.0 * px;
    const bool textInside = !text.isEmpty() && span >= textLength;
    canvas.out.add(
        drawing::DimensionLine {d1, d2, arrowsInside, 2.0 * arrow, textInside ? textLength : 0.0, line, head},
        Layer::Dimensions);
    if (arrowsInside)
        canvas.labels.addObstacle(d1, d2, 0.5 * head.width);
    else
        canvas.labels.addObstacle(d1 - 2.0 * arrow * u, d2 + 2.0 * arrow * u, 0.5 * head.width);
    if (text.isEmpty())
        return;
    const double rotation = readableRotation(u);
    const QPointF middle = 0.5 * (d1 + d2);
    if (textInside) {
        canvas.labels.place({middle, rotation, text, false, colour, Layer::Dimensions, cad, {}, {}});
        return;
    }
    const double beside = 0.5 * size.height() + 3.0 * px;
    const double past = 2.0 * arrow + 4.0 * px + 0.5 * size.width();
    canvas.labels.addFreeLabel({{{}, rotation, text, false, colour, Layer::Dimensions, cad, {}, {}},
        {middle + beside * side, d2 + past * u, d1 - past * u, middle - beside * side,
            middle + (beside + 12.0 * px) * side}});
}

void drawAngle(const SceneCanvas &canvas, const SceneAngle &angle)
{
    if (!canvas.valid(angle.vertex) || !std::isfinite(angle.start) || !std::isfinite(angle.sweep)) {
        ++canvas.out.skipped;
        return;
    }
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    const QColor colour = style.angle;
    const double minimumRadius = 22.0 * px;
    const drawing::Pen dashed = pen(colour, 1.2 * px, Qt::FlatCap, drawing::Dash::Dashed);
    const QPointF v = canvas.point(angle.vertex);
    double r = std::max((std::isfinite(angle.radius) ? angle.radius : 0.0) * canvas.mapping.scale, minimumRadius);
    const double end = angle.start + angle.sweep;
    // Too small an arc to see is left to CAD, whose drawing states every angle it labels.
    const bool drawArc = std::abs(angle.sweep) >= 0.5 * degree;

    // An angle between a guide and another line at a joint on the guide (γ at R): an arc that
    // ends on the rail's axis hides under the rail unless the other leg is clear of it there.
    // Then take a radius at which it is, or, for a small angle, one beyond the rail's end.
    const int guide = std::size_t(angle.vertex) < canvas.jointGuide.size() ? canvas.jointGuide[std::size_t(angle.vertex)] : -1;
    if (drawArc && guide >= 0 && guide < int(canvas.guides.size()) && std::abs(angle.sweep) < 0.5 * pi) {
        const GuideShape &shape = canvas.guides[std::size_t(guide)];
        const double t = dot(v - shape.start, shape.u);
        for (const auto &[legAngle, otherAngle] : {std::pair {angle.start, end}, std::pair {end, angle.start}}) {
            const double along = dot(deviceDirection(legAngle), shape.u);
            if (std::abs(along) < std::cos(1.0 * degree))
                continue;
            const double railLeft = along > 0.0 ? shape.railEnd() - t : t - shape.railBegin();
            const double side = dot(deviceDirection(otherAngle), shape.outer);
            const double clear = (shape.reach(side) + 12.0 * px) / std::sin(std::abs(angle.sweep));
            if (r < clear) // zoomed out, the clearance is mostly pixels: do not go far past the end
                r = clear <= 0.5 * railLeft ? clear : std::max(railLeft + 16.0 * px, std::min(clear, 1.3 * railLeft));
            break;
        }
    }

    // Dashed reference lines for the legs that no member shows (θ's vertical, say), or for
    // the part beyond a member shorter than the arc's radius.
    for (double legAngle : {angle.start, end}) {
        const QPointF leg = deviceDirection(legAngle);
        if (legAngle == end && !drawArc)
            continue;
        const double shown = canvas.labels.memberReach(angle.vertex, leg);
        if (shown > 20.0 * px && shown >= r + 8.0 * px)
            continue;
        const double start = shown > 20.0 * px ? shown : (style.pivotRadius + 3.0) * px;
        const QPointF from = v + start * leg, to = v + (r + 16.0 * px) * leg;
        canvas.line(Layer::Dimensions, dashed, from, to);
        canvas.labels.addRay(angle.vertex, leg, r + 16.0 * px);
        canvas.labels.addObstacle(from, to, 1.0 * px);
    }

    const drawing::ArrowShape head {style.arrowLength * px, style.arrowWidth * px};
    if (drawArc) {
        const bool withArrow = r * std::abs(angle.sweep) > 1.6 * head.length;
        canvas.out.add(drawing::Arc {v, r, angle.start, angle.sweep, pen(colour, 2.0 * px), withArrow, head},
            Layer::Dimensions);
        const int chords = std::clamp(int(std::abs(angle.sweep) / (15.0 * degree)) + 1, 1, 24);
        for (int i = 0; i < chords; ++i) {
            canvas.labels.addObstacle(v + r * deviceDirection(angle.start + angle.sweep * i / chords),
                v + r * deviceDirection(angle.start + angle.sweep * (i + 1) / chords), 2.0 * px);
        }
    } else if (std::abs(angle.sweep) > 1e-9) {
        canvas.out.add(drawing::Arc {v, r, angle.start, angle.sweep, pen(colour, 2.0 * px), false, head},
            Layer::Dimensions, Medium::Cad);
    }
    if (!angle.label.empty())
        canvas.labels.addAngleLabel({angle.vertex, r, angle.start, angle.sweep, QString::fromStdString(angle.label)});
}

} // namespace pkm
