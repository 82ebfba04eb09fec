#include "scenelayout.h"

#include "scenegeometry.h"
#include "scenelabels.h"
#include "sceneprimitives.h"

#include <QFontMetricsF>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

// The scene is laid out in three parts: this file lays out the paths, members, joints and
// handles, and ghosts; sceneprimitives.cpp and sceneguides.cpp the ground, guides and
// carriages, actuators, dimensions and angles; scenelabels.cpp places all text last, clear of
// the geometry. Drawing order is the list's order: paths under guides under actuators under
// members, then dimensions, handles, pins and labels.

namespace pkm::drawing {

using namespace pkm::detail;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// The joints in device units; a joint that is not shown gets a non-finite point, which every
/// step then leaves out.
std::vector<QPointF> devicePoints(const Scene &scene, const ViewMapping &mapping, double farPointMargin)
{
    const std::vector<bool> shown = std::isfinite(farPointMargin) ? shownJoints(scene, farPointMargin)
                                                                  : std::vector<bool>(scene.joints.size(), true);
    std::vector<QPointF> points;
    points.reserve(scene.joints.size());
    for (std::size_t i = 0; i < scene.joints.size(); ++i)
        points.push_back(shown[i] ? mapping.toDevice(scene.joints[i].position) : QPointF(nan, nan));
    return points;
}

/// Tells the label layout what leaves each joint (members, the motor body, the ground symbol)
/// and keeps labels off the pivots and their handle rings.
void collectRaysAndJoints(const SceneCanvas &canvas)
{
    const Scene &scene = canvas.scene;
    SceneLabels &labels = canvas.labels;
    const double px = canvas.px();
    auto member = [&](int a, int b) {
        if (!canvas.valid(a) || !canvas.valid(b))
            return;
        const QPointF v = canvas.point(b) - canvas.point(a);
        labels.addRay(a, v, length(v));
        labels.addRay(b, -v, length(v));
    };
    for (const SceneBar &bar : scene.bars)
        member(bar.from, bar.to);
    for (const SceneActuator &actuator : scene.actuators) {
        member(actuator.from, actuator.to);
        // The motor body spreads sideways from its joint: keep the joint's name off it.
        if (canvas.valid(actuator.from) && canvas.valid(actuator.to) && actuator.bodyWidth > 0.0) {
            const QPointF across = screenLeft(unit(canvas.point(actuator.to) - canvas.point(actuator.from)));
            const double half = 0.5 * actuator.bodyWidth * canvas.mapping.scale;
            labels.addRay(actuator.from, across, half);
            labels.addRay(actuator.from, -across, half);
        }
    }
    const double ring = (canvas.style.pivotRadius + (canvas.style.showHandles ? 6.0 : 2.0)) * px;
    for (std::size_t i = 0; i < canvas.points.size(); ++i) {
        if (!canvas.valid(int(i)))
            continue;
        if (scene.joints[i].kind == JointKind::Ground)
            labels.addRay(int(i), {0.0, 1.0}, 34.0 * px); // the ground symbol hangs below
        labels.addObstacle(canvas.points[i], canvas.points[i], ring);
    }
}

/// A path is a thin line to the labels (the four-bar's coupler curve ran through B, M and δ):
/// one in chords of about 16 px, each within a pixel of the curve, so that a label across it
/// counts one line, not a dozen.
void keepLabelsOffPath(const SceneCanvas &canvas, const QPolygonF &run)
{
    const double px = canvas.px(), chord = 16.0 * px;
    QPointF from = run.front();
    for (qsizetype i = 1; i < run.size(); ++i) {
        const QPointF d = run[i] - from;
        if (i + 1 < run.size() && d.x() * d.x() + d.y() * d.y() < chord * chord)
            continue;
        canvas.labels.addObstacle(from, run[i], 1.5 * px);
        from = run[i];
    }
}

/// Paths (a coupler curve) lie under the mechanism, thin; a path is broken where a point is
/// undefined rather than bridged. The capability shapes (`shapes`) go over the members instead,
/// since they are centred on the platform point: polygons solid, ellipses dashed.
void layoutPaths(const SceneCanvas &canvas, bool shapes)
{
    const SceneStyle &style = canvas.style;
    for (const ScenePolyline &polyline : canvas.scene.polylines) {
        if ((polyline.kind != PathKind::Path) != shapes)
            continue;
        const bool velocity = polyline.kind == PathKind::VelocityPolygon || polyline.kind == PathKind::VelocityEllipse;
        const bool ellipse = polyline.kind == PathKind::VelocityEllipse || polyline.kind == PathKind::ForceEllipse;
        const Pen pen {!shapes ? style.path : velocity ? style.velocity : style.force,
            (shapes && !ellipse ? 2.0 : 1.6) * canvas.px(), ellipse ? Qt::FlatCap : Qt::RoundCap, ellipse ? Dash::Dashed : Dash::Solid,
            ellipse ? Qt::BevelJoin : Qt::RoundJoin};
        QPolygonF run;
        bool broken = false;
        auto flush = [&] {
            if (run.size() >= 2) {
                canvas.out.add(Polygon {run, polyline.closed && !broken, pen}, Layer::Paths);
                if (!shapes)
                    keepLabelsOffPath(canvas, run);
            }
            run.clear();
        };
        for (const Eigen::Vector3d &p : polyline.points) {
            if (p.head<2>().allFinite()) {
                run << canvas.mapping.toDevice(p);
            } else {
                broken = true;
                flush();
            }
        }
        if (broken)
            ++canvas.out.skipped;
        flush();
    }
}

/// The radius of the pin circle drawn at `joint`.
double pinRadius(const SceneCanvas &canvas, int joint)
{
    const double r = canvas.style.pivotRadius * canvas.px();
    return canvas.scene.joints[std::size_t(joint)].kind == JointKind::Point ? 0.5 * r : r;
}

void layoutBars(const SceneCanvas &canvas)
{
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    for (const SceneBar &bar : canvas.scene.bars) {
        if (!canvas.valid(bar.from) || !canvas.valid(bar.to)) {
            ++canvas.out.skipped;
            continue;
        }
        QColor colour;
        double width = style.barWidth;
        switch (bar.kind) {
        case BarKind::Ground:
            colour = style.ink;
            width = style.groundWidth;
            break;
        case BarKind::Crank:
            colour = style.crank;
            break;
        case BarKind::Coupler:
            colour = style.coupler;
            break;
        case BarKind::Link:
            colour = style.link;
            break;
        case BarKind::Rod:
            colour = style.rod;
            break;
        case BarKind::Platform:
            colour = style.platform;
            break;
        }
        const QPointF a = canvas.point(bar.from), b = canvas.point(bar.to);
        if (bar.kind == BarKind::Ground) {
            // The frame: a line from pivot to pivot.
            canvas.line(Layer::Ground, pen(colour, width * px), a, b);
        } else {
            // Flat caps: the pivot circles cover the ends. CAD's edges start where they leave
            // the pins.
            const double half = 0.5 * width * px;
            auto trim = [&](int joint) {
                const double r = pinRadius(canvas, joint);
                return std::sqrt(std::max(r * r - half * half, 0.0));
            };
            canvas.out.add(Member {a, b, width * px, colour, trim(bar.from), trim(bar.to)}, Layer::Links);
        }
        canvas.labels.addObstacle(a, b, 0.5 * width * px + 1.0 * px);
        if (!bar.label.empty()) {
            const QColor text = bar.kind == BarKind::Ground ? style.ink : colour.darker(120);
            canvas.labels.addMemberLabel({bar.from, bar.to, QString::fromStdString(bar.label), text, false, {}});
        }
    }
    canvas.labels.dropDimensionedActuatorLabels();
}

void layoutJoints(const SceneCanvas &canvas)
{
    const double r = canvas.style.pivotRadius * canvas.px();
    const Pen outline = pen(canvas.style.ink, 2.0 * canvas.px(), Qt::SquareCap);
    const QColor white(Qt::white);
    auto circle = [&](const QPointF &p, double radius, const QColor &fill, Medium medium = Medium::All) {
        canvas.out.add(Circle {p, radius, outline, fill}, Layer::Joints, medium);
    };
    for (std::size_t i = 0; i < canvas.points.size(); ++i) {
        if (!canvas.valid(int(i))) {
            if (std::isfinite(canvas.scene.joints[i].position.x()) && std::isfinite(canvas.scene.joints[i].position.y()))
                continue; // left out on purpose (a far free point)
            ++canvas.out.skipped;
            continue;
        }
        const QPointF p = canvas.points[i];
        switch (canvas.scene.joints[i].kind) {
        case JointKind::Ground:
        case JointKind::Revolute:
            circle(p, r, white);
            break;
        case JointKind::Spherical:
            circle(p, r, white);
            circle(p, 0.35 * r, canvas.style.ink);
            break;
        case JointKind::Slider:
            if (canvas.carriageGuide(int(i))) {
                circle(p, r, white); // the pin on its carriage, drawn with the guide
            } else {
                const QRectF block(p.x() - 1.6 * r, p.y() - r, 3.2 * r, 2.0 * r);
                canvas.out.add(Polygon {QPolygonF(block), true, outline, white}, Layer::Joints);
                circle(p, r, white, Medium::Cad); // the pin links end at
            }
            break;
        case JointKind::Point:
            circle(p, 0.5 * r, canvas.style.ink);
            break;
        }
    }
}

void layoutHandles(const SceneCanvas &canvas, int activeHandle)
{
    const SceneStyle &style = canvas.style;
    if (!style.showHandles)
        return;
    const double px = canvas.px();
    for (std::size_t i = 0; i < canvas.scene.handles.size(); ++i) {
        const int joint = canvas.scene.handles[i].joint;
        if (!canvas.valid(joint))
            continue;
        const QPointF p = canvas.point(joint);
        QColor ring = style.handle;
        if (int(i) == activeHandle) {
            QColor glow = ring;
            glow.setAlpha(55);
            canvas.out.add(Circle {p, (style.pivotRadius + 13.0) * px, Pen {ring, 0.0}, glow}, Layer::Joints,
                Medium::Screen);
            canvas.out.add(Circle {p, (style.pivotRadius + 7.0) * px, pen(ring, 3.0 * px, Qt::SquareCap)},
                Layer::Joints, Medium::Screen);
        } else if (canvas.scene.handles[i].editsDesign()) {
            // an attachment point: a fainter, thinner ring, so the pose handles stand out
            ring.setAlpha(90);
            canvas.out.add(Circle {p, (style.pivotRadius + 4.0) * px, pen(ring, 1.2 * px, Qt::SquareCap)},
                Layer::Joints, Medium::Screen);
        } else {
            ring.setAlpha(150);
            canvas.out.add(Circle {p, (style.pivotRadius + 5.0) * px, pen(ring, 2.0 * px, Qt::SquareCap)},
                Layer::Joints, Medium::Screen);
        }
    }
}

} // namespace

DrawList layoutScene(const Scene &scene, const ViewMapping &mapping, const SceneStyle &style, const LayoutOptions &options)
{
    DrawList list;
    if (!(mapping.scale > 0.0) || !std::isfinite(mapping.scale))
        return list;
    const std::vector<QPointF> points = devicePoints(scene, mapping, options.farPointMargin);
    const std::vector<int> jointGuide = jointsOnGuides(scene);
    const std::vector<GuideShape> guides = guideShapes(scene, points, jointGuide, mapping, style);
    SceneLabels labels(scene, points, mapping, style, options.device);
    labels.setRoom(options.labelRoom);
    labels.setPrevious(options.previousLabels);
    for (const QLineF &line : options.avoid) // a thin line: covered where nothing else is free
        labels.addObstacle(line.p1(), line.p2(), 1.5 * style.pixelSize, true);
    for (const QRectF &box : options.covered)
        labels.addObstacle(boxQuad(box.center(), box.size(), 0.0));
    const SceneCanvas canvas {list, scene, mapping, style, points, labels, guides, jointGuide};
    list.items.reserve(8 * (scene.joints.size() + scene.bars.size()) + 16);

    collectRaysAndJoints(canvas);
    layoutPaths(canvas, false);
    for (std::size_t g = 0; g < guides.size(); ++g)
        drawGuide(canvas, int(g));
    for (const SceneActuator &actuator : scene.actuators)
        drawActuator(canvas, actuator);
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!canvas.valid(int(i)))
            continue;
        if (scene.joints[i].kind == JointKind::Ground)
            drawGround(canvas, points[i]);
        else if (const GuideShape *guide = canvas.carriageGuide(int(i)))
            drawCarriage(canvas, *guide, points[i]);
    }
    layoutBars(canvas);
    layoutPaths(canvas, true);
    for (const SceneDimension &dimension : scene.dimensions)
        drawDimension(canvas, dimension);
    for (const SceneAngle &angle : scene.angles)
        drawAngle(canvas, angle);
    layoutHandles(canvas, options.activeHandle);
    layoutJoints(canvas);
    labels.placeAll();
    labels.addTo(list);
    if (options.placedLabels)
        *options.placedLabels = labels.places();
    return list;
}

namespace {
/// A ghost's members as drawn: its links and actuators, not its ground (the real scene's).
std::vector<QLineF> ghostMembers(const Scene &scene, const std::vector<QPointF> &points)
{
    auto valid = [&points](int joint) {
        return joint >= 0 && joint < int(points.size()) && std::isfinite(points[std::size_t(joint)].x())
            && std::isfinite(points[std::size_t(joint)].y());
    };
    std::vector<QLineF> members;
    for (const SceneBar &bar : scene.bars) {
        if (bar.kind != BarKind::Ground && valid(bar.from) && valid(bar.to))
            members.emplace_back(points[std::size_t(bar.from)], points[std::size_t(bar.to)]);
    }
    for (const SceneActuator &actuator : scene.actuators) {
        if (valid(actuator.from) && valid(actuator.to))
            members.emplace_back(points[std::size_t(actuator.from)], points[std::size_t(actuator.to)]);
    }
    return members;
}
} // namespace

std::vector<QLineF> ghostLines(const Scene &scene, const ViewMapping &mapping)
{
    if (!(mapping.scale > 0.0) || !std::isfinite(mapping.scale))
        return {};
    return ghostMembers(scene, devicePoints(scene, mapping, std::numeric_limits<double>::infinity()));
}

DrawList layoutGhost(const Scene &scene, const ViewMapping &mapping, const SceneStyle &style, bool highlighted)
{
    DrawList list;
    if (!(mapping.scale > 0.0) || !std::isfinite(mapping.scale))
        return list;
    const std::vector<QPointF> points = devicePoints(scene, mapping, std::numeric_limits<double>::infinity());
    auto valid = [&points](int joint) {
        return joint >= 0 && joint < int(points.size()) && std::isfinite(points[std::size_t(joint)].x())
            && std::isfinite(points[std::size_t(joint)].y());
    };
    const std::vector<int> jointGuide = jointsOnGuides(scene);
    const std::vector<GuideShape> guides = guideShapes(scene, points, jointGuide, mapping, style);
    const double px = style.pixelSize;
    // Faded: every colour at the ghost's opacity.
    const double opacity = highlighted ? std::min(1.0, 2.0 * style.ghostOpacity) : style.ghostOpacity;
    auto faded = [opacity](QColor colour) {
        colour.setAlphaF(float(colour.alphaF() * opacity));
        return colour;
    };
    const QColor colour = faded(highlighted ? style.handle : style.ghost);

    // Members (the ground is the real scene's): dashed, a little thinner than the real ones.
    const std::vector<QLineF> members = ghostMembers(scene, points);
    const double width = (highlighted ? 0.8 : 0.65) * style.barWidth * px;
    list.add(Lines {std::move(members), Pen {colour, width, Qt::FlatCap, Dash::Ghost}}, Layer::Links, Medium::Screen);

    // Joints: hollow pivots; sliders on a guide as their carriage's outline.
    const double r = 0.85 * style.pivotRadius * px;
    const Pen outline = pen(colour, 2.0 * px, Qt::SquareCap);
    const QColor background = faded(style.background);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const QPointF p = points[i];
        if (!valid(int(i)))
            continue;
        switch (scene.joints[i].kind) {
        case JointKind::Ground:
        case JointKind::Point:
            break; // fixed: the real scene shows them
        case JointKind::Slider: {
            const int guide = jointGuide[i];
            if (guide >= 0) {
                const GuideShape &shape = guides[std::size_t(guide)];
                const QPointF l = 0.5 * shape.carriageLength * shape.u, w = shape.carriageHalfWidth * shape.outer;
                list.add(Polygon {QPolygonF({p - l - w, p + l - w, p + l + w, p - l + w}), true, outline},
                    Layer::Joints, Medium::Screen);
            } else {
                list.add(Polygon {QPolygonF(QRectF(p.x() - 1.6 * r, p.y() - r, 3.2 * r, 2.0 * r)), true, outline,
                             background},
                    Layer::Joints, Medium::Screen);
            }
            list.add(Circle {p, r, outline, background}, Layer::Joints, Medium::Screen);
            break;
        }
        case JointKind::Revolute:
        case JointKind::Spherical:
            list.add(Circle {p, r, outline, background}, Layer::Joints, Medium::Screen);
            break;
        }
    }
    return list;
}

void addCaption(DrawList &list, const QString &caption, const SceneStyle &style, const QPaintDevice *device)
{
    const QRectF box = bounds(list, true);
    if (caption.isEmpty() || box.isNull())
        return;
    const QFont font = labelFont(style.fontPixels * style.pixelSize, false);
    const QFontMetricsF metrics(font, device);
    const QSizeF size(metrics.horizontalAdvance(caption) + 8.0 * style.pixelSize, metrics.height() + 2.0 * style.pixelSize);
    // Under the drawing, one text line clear of it.
    const QPointF centre(box.left() + 0.5 * size.width(), box.bottom() + metrics.height() + 0.5 * size.height());
    list.add(Text {centre, 0.0, caption, font, style.ink, size, style.background, {}}, Layer::Text);
}

} // namespace pkm::drawing
