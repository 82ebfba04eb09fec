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
#include <utility>

// Everything here is drawn as flat- or square-capped lines in device coordinates, for the
// raster engine's fast path (see the performance note in scenepainter.cpp).

namespace pkm {

using namespace detail;

void SceneCanvas::stroke(const QColor &colour, double width, Qt::PenCapStyle cap) const
{
    painter.setPen(QPen(colour, width, Qt::SolidLine, cap));
}

const GuideShape *SceneCanvas::carriageGuide(int joint) const
{
    if (!valid(joint) || std::size_t(joint) >= jointGuide.size() || scene.joints[std::size_t(joint)].kind != JointKind::Slider)
        return nullptr;
    const int guide = jointGuide[std::size_t(joint)];
    return guide >= 0 && guide < int(guides.size()) ? &guides[std::size_t(guide)] : nullptr;
}

// -- guides ------------------------------------------------------------------------------

namespace {
/// A carriage's length per rail width; the rail runs half a carriage past each stroke end.
constexpr double carriagePerWidth = 1.8;
} // namespace

std::vector<int> jointsOnGuides(const Scene &scene)
{
    std::vector<int> result(scene.joints.size(), -1);
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        const SceneJoint &joint = scene.joints[j];
        if (joint.kind != JointKind::Slider && joint.kind != JointKind::Point)
            continue;
        const Eigen::Vector2d p = joint.position.head<2>();
        double best = 1e300;
        for (std::size_t g = 0; g < scene.guides.size(); ++g) {
            const SceneGuide &guide = scene.guides[g];
            const Eigen::Vector2d a = guide.start.head<2>(), b = guide.end.head<2>();
            const double span = (b - a).norm();
            if (!std::isfinite(span) || !std::isfinite(p.x()) || !std::isfinite(p.y()))
                continue;
            const double width = std::max(guide.width, 0.0);
            const Eigen::Vector2d u = span > 1e-12 ? Eigen::Vector2d((b - a) / span) : Eigen::Vector2d(1.0, 0.0);
            const double along = u.dot(p - a);
            const double across = std::abs(u.x() * (p - a).y() - u.y() * (p - a).x());
            const double tolerance = std::max({0.25 * width, 1e-6 * span, 1e-9});
            const double overrun = 0.5 * carriagePerWidth * width + tolerance;
            if (across <= tolerance && along >= -overrun && along <= span + overrun && across < best) {
                best = across;
                result[j] = int(g);
            }
        }
    }
    return result;
}

std::vector<GuideShape> guideShapes(const Scene &scene, const std::vector<QPointF> &points,
    const std::vector<int> &jointGuide, const ViewMapping &mapping, const SceneStyle &style)
{
    const double px = style.pixelSize;
    std::vector<GuideShape> shapes;
    shapes.reserve(scene.guides.size());
    for (std::size_t g = 0; g < scene.guides.size(); ++g) {
        const SceneGuide &guide = scene.guides[g];
        GuideShape shape;
        shape.start = mapping.toDevice(guide.start);
        const QPointF end = mapping.toDevice(guide.end);
        shape.stroke = length(end - shape.start);
        if (!std::isfinite(shape.stroke))
            shape.stroke = 0.0;
        if (shape.stroke > 1e-9)
            shape.u = (end - shape.start) / shape.stroke;
        // Geometry scales with the zoom; the minimums keep a zoomed-out rail a rail.
        const double width = std::max(guide.width, 0.0) * mapping.scale;
        shape.half = std::max(0.5 * width, 3.0 * px);
        shape.carriageLength = std::max(carriagePerWidth * 2.0 * shape.half, (2.0 * style.pivotRadius + 10.0) * px);
        shape.carriageHalfWidth = std::max({1.3 * shape.half, shape.half + 3.0 * px, (style.pivotRadius + 4.0) * px});
        shape.overrun = 0.5 * shape.carriageLength;
        shape.stop = std::clamp(0.3 * shape.half, 3.0 * px, 8.0 * px);
        shape.stopHalf = shape.half + std::clamp(0.35 * shape.half, 3.0 * px, 8.0 * px);
        shape.hatch = std::clamp(0.4 * shape.half, 6.0 * px, 9.0 * px);

        // Hatch (ground) on the side away from the members that leave the guide's joints, or,
        // with none, away from the rest of the mechanism.
        const QPointF left = screenLeft(shape.u), middle = shape.at(0.5 * shape.stroke, 0.0);
        auto finite = [](const QPointF &p) { return std::isfinite(p.x()) && std::isfinite(p.y()); };
        auto onGuide = [&](int joint) {
            return joint >= 0 && std::size_t(joint) < jointGuide.size() && jointGuide[std::size_t(joint)] == int(g);
        };
        double towards = 0.0;
        for (const SceneBar &bar : scene.bars) {
            const int n = int(points.size());
            if (bar.kind == BarKind::Ground || bar.from < 0 || bar.to < 0 || bar.from >= n || bar.to >= n
                || onGuide(bar.from) == onGuide(bar.to))
                continue;
            const QPointF on = points[std::size_t(onGuide(bar.from) ? bar.from : bar.to)];
            const QPointF off = points[std::size_t(onGuide(bar.from) ? bar.to : bar.from)];
            if (finite(on) && finite(off))
                towards += dot(off - on, left);
        }
        if (std::abs(towards) <= 1e-6) {
            QPointF sum;
            int count = 0;
            for (std::size_t j = 0; j < points.size(); ++j) {
                if (!onGuide(int(j)) && finite(points[j])) {
                    sum += points[j];
                    ++count;
                }
            }
            towards = count > 0 ? dot(sum / double(count) - middle, left) : 0.0;
        }
        if (std::abs(towards) > 1e-6)
            shape.outer = towards > 0.0 ? -left : left;
        else
            shape.outer = left.y() >= 0.0 ? left : -left; // nothing else: hatch below, as ground reads
        shapes.push_back(shape);
    }
    return shapes;
}

void drawGuide(const SceneCanvas &canvas, int index)
{
    const GuideShape &shape = canvas.guides[std::size_t(index)];
    const SceneGuide &guide = canvas.scene.guides[std::size_t(index)];
    QPainter &painter = canvas.painter;
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    const double begin = -shape.overrun, end = shape.stroke + shape.overrun;
    auto at = [&shape](double along, double across) { return shape.at(along, across); };

    // Hatching along the outer edge: the engineering mark of a part fixed to the ground.
    const double pitch = 7.0 * px;
    std::vector<QLineF> hatch;
    hatch.reserve(std::size_t(std::max(0.0, (end - begin) / pitch)) + 2);
    for (double x = end; x >= begin + shape.hatch && hatch.size() < 4000; x -= pitch)
        hatch.emplace_back(at(x, shape.half), at(x - shape.hatch, shape.half + shape.hatch));
    canvas.stroke(style.guideOutline, 1.2 * px);
    painter.drawLines(hatch.data(), int(hatch.size()));

    // The rail: light steel, one thick flat-capped line, its two long edges, a dash-dot axis.
    canvas.stroke(style.guideFill, 2.0 * shape.half);
    painter.drawLine(at(begin, 0.0), at(end, 0.0));
    QPen axis(style.guideOutline.lighter(150), 1.0 * px, Qt::CustomDashLine, Qt::FlatCap);
    axis.setDashPattern({14.0, 3.0, 2.0, 3.0});
    painter.setPen(axis);
    painter.drawLine(at(begin - shape.stop - 8.0 * px, 0.0), at(end + shape.stop + 8.0 * px, 0.0));
    const std::array<QLineF, 2> edges {
        QLineF(at(begin, shape.half), at(end, shape.half)), QLineF(at(begin, -shape.half), at(end, -shape.half))};
    canvas.stroke(style.guideOutline, 1.4 * px);
    painter.drawLines(edges.data(), int(edges.size()));

    // End stops: short blocks across both ends, a little wider than the rail.
    canvas.stroke(style.guideOutline, shape.stop);
    const std::array<QLineF, 2> stops {QLineF(at(begin - 0.5 * shape.stop, -shape.stopHalf),
                                           at(begin - 0.5 * shape.stop, shape.stopHalf)),
        QLineF(at(end + 0.5 * shape.stop, -shape.stopHalf), at(end + 0.5 * shape.stop, shape.stopHalf))};
    painter.drawLines(stops.data(), int(stops.size()));

    const double outerReach = shape.reach(1.0), innerReach = shape.reach(-1.0);
    canvas.labels.addObstacle(Quad {at(shape.railBegin(), -innerReach), at(shape.railEnd(), -innerReach),
        at(shape.railEnd(), outerReach), at(shape.railBegin(), outerReach)});
    // The rail leaves the joints on it: their names go beside it, not on it.
    for (std::size_t j = 0; j < canvas.points.size() && j < canvas.jointGuide.size(); ++j) {
        if (canvas.jointGuide[j] != index)
            continue;
        const double t = dot(canvas.points[j] - shape.start, shape.u);
        canvas.labels.addRay(int(j), shape.u, shape.railEnd() - t);
        canvas.labels.addRay(int(j), -shape.u, t - shape.railBegin());
        canvas.labels.addRay(int(j), shape.outer, outerReach);
        canvas.labels.addRay(int(j), -shape.outer, innerReach);
    }
    if (!guide.label.empty()) {
        canvas.labels.addGuideLabel({at(shape.railBegin(), 0.0), at(shape.railEnd(), 0.0), shape.outer, outerReach,
            innerReach, QString::fromStdString(guide.label), style.guideOutline.darker(115)});
    }
}

void drawCarriage(const SceneCanvas &canvas, const GuideShape &shape, const QPointF &centre)
{
    QPainter &painter = canvas.painter;
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    const double l = 0.5 * shape.carriageLength, w = shape.carriageHalfWidth;
    auto at = [&](double along, double across) { return centre + along * shape.u + across * shape.outer; };
    // The block, a lighter band where the rail runs through it, and its outline.
    canvas.stroke(style.carriage, 2.0 * w);
    painter.drawLine(at(-l, 0.0), at(l, 0.0));
    canvas.stroke(style.carriage.lighter(118), 2.0 * shape.half);
    painter.drawLine(at(-l + 2.0 * px, 0.0), at(l - 2.0 * px, 0.0));
    const std::array<QLineF, 4> outline {QLineF(at(-l, w), at(l, w)), QLineF(at(l, w), at(l, -w)),
        QLineF(at(l, -w), at(-l, -w)), QLineF(at(-l, -w), at(-l, w))};
    canvas.stroke(style.carriage.darker(200), 1.4 * px, Qt::SquareCap);
    painter.drawLines(outline.data(), int(outline.size()));
    canvas.labels.addObstacle(Quad {at(-l, w), at(l, w), at(l, -w), at(-l, -w)});
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

    canvas.stroke(colour, 1.2 * px);
    if (offset > gapFrom) {
        canvas.painter.drawLine(p + gapFrom * side, d1 + overshoot * side);
        canvas.labels.addObstacle(p + gapFrom * side, d1 + overshoot * side, 1.0 * px);
    }
    if (offset > gapTo) {
        canvas.painter.drawLine(q + gapTo * side, d2 + overshoot * side);
        canvas.labels.addObstacle(q + gapTo * side, d2 + overshoot * side, 1.0 * px);
    }
    canvas.labels.addRay(dimension.from, side, offset + overshoot);
    canvas.labels.addRay(dimension.to, side, offset + overshoot);
    // The text centred on the line (the knock-out hides the line under it) with the arrows
    // inside when both fit; when only the text fits, the arrows point in from outside; when
    // the text does not fit either, it goes beside the line or past one of its ends.
    const QSizeF size = text.isEmpty() ? QSizeF() : canvas.labels.textSize(text);
    const double textLength = text.isEmpty() ? 0.0 : size.width(); // padding included
    const bool arrowsInside = span > textLength + 2.0 * arrow + 6.0 * px;
    const bool textInside = span >= textLength;
    if (arrowsInside) {
        canvas.painter.drawLine(d1 + 0.5 * arrow * u, d2 - 0.5 * arrow * u);
        drawArrow(canvas, d1, -u, colour);
        drawArrow(canvas, d2, u, colour);
        canvas.labels.addObstacle(d1, d2, 0.5 * style.arrowWidth * px);
    } else {
        canvas.painter.drawLine(d1 - 2.0 * arrow * u, d2 + 2.0 * arrow * u);
        drawArrow(canvas, d1, u, colour);
        drawArrow(canvas, d2, -u, colour);
        canvas.labels.addObstacle(d1 - 2.0 * arrow * u, d2 + 2.0 * arrow * u, 0.5 * style.arrowWidth * px);
    }
    if (text.isEmpty())
        return;
    const double rotation = readableRotation(u);
    const QPointF middle = 0.5 * (d1 + d2);
    if (textInside) {
        canvas.labels.place({middle, rotation, text, false, colour});
        return;
    }
    const double beside = 0.5 * size.height() + 3.0 * px;
    const double past = 2.0 * arrow + 4.0 * px + 0.5 * size.width();
    canvas.labels.addFreeLabel({{{}, rotation, text, false, colour},
        {middle + beside * side, d2 + past * u, d1 - past * u, middle - beside * side,
            middle + (beside + 12.0 * px) * side}});
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
    double r = std::max(angle.radius * canvas.mapping.scale, minimumRadius);
    const double end = angle.start + angle.sweep;
    const double turn = angle.sweep > 0.0 ? 1.0 : -1.0;
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
