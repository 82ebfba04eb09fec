#include "sceneprimitives.h"

#include "scenegeometry.h"

#include <QLineF>
#include <QSizeF>
#include <QString>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

// The guides (rails) of sliders and linear axes, and the carriages that ride them. Fills are
// the screen's; CAD gets the rail's edges, axis, end stops and hatching.

namespace pkm {

using namespace detail;

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
    using drawing::Layer;
    const GuideShape &shape = canvas.guides[std::size_t(index)];
    const SceneGuide &guide = canvas.scene.guides[std::size_t(index)];
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    const double begin = -shape.overrun, end = shape.stroke + shape.overrun;
    auto at = [&shape](double along, double across) { return shape.at(along, across); };
    if (!std::isfinite(shape.start.x()) || !std::isfinite(shape.start.y()) || !std::isfinite(shape.stroke)) {
        ++canvas.out.skipped;
        return;
    }

    // Hatching along the outer edge: the engineering mark of a part fixed to the ground.
    const double pitch = 7.0 * px;
    std::vector<QLineF> hatch;
    hatch.reserve(std::size_t(std::max(0.0, (end - begin) / pitch)) + 2);
    for (double x = end; x >= begin + shape.hatch && hatch.size() < 4000; x -= pitch)
        hatch.emplace_back(at(x, shape.half), at(x - shape.hatch, shape.half + shape.hatch));
    canvas.lines(Layer::Guides, pen(style.guideOutline, 1.2 * px), std::move(hatch));

    // The rail: light steel, one thick flat-capped line, its two long edges, a dash-dot axis.
    canvas.band(Layer::Guides, at(begin, 0.0), at(end, 0.0), 2.0 * shape.half, style.guideFill, drawing::Medium::Screen);
    canvas.line(Layer::Guides, pen(style.guideOutline.lighter(150), 1.0 * px, Qt::FlatCap, drawing::Dash::Centre),
        at(begin - shape.stop - 8.0 * px, 0.0), at(end + shape.stop + 8.0 * px, 0.0));
    canvas.lines(Layer::Guides, pen(style.guideOutline, 1.4 * px),
        {QLineF(at(begin, shape.half), at(end, shape.half)), QLineF(at(begin, -shape.half), at(end, -shape.half))});

    // End stops: short blocks across both ends, a little wider than the rail.
    canvas.band(Layer::Guides, at(begin - 0.5 * shape.stop, -shape.stopHalf), at(begin - 0.5 * shape.stop, shape.stopHalf),
        shape.stop, style.guideOutline);
    canvas.band(Layer::Guides, at(end + 0.5 * shape.stop, -shape.stopHalf), at(end + 0.5 * shape.stop, shape.stopHalf),
        shape.stop, style.guideOutline);

    const double outerReach = shape.reach(1.0), innerReach = shape.reach(-1.0);
    canvas.labels.addObstacle(Quad {at(shape.railBegin(), -innerReach), at(shape.railEnd(), -innerReach),
        at(shape.railEnd(), outerReach), at(shape.railBegin(), outerReach)});
    // The rail leaves the joints on it: their names go beside it, not on it.
    for (std::size_t j = 0; j < canvas.points.size() && j < canvas.jointGuide.size(); ++j) {
        if (canvas.jointGuide[j] != index || !canvas.valid(int(j)))
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
    using drawing::Layer;
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    const double l = 0.5 * shape.carriageLength, w = shape.carriageHalfWidth;
    auto at = [&](double along, double across) { return centre + along * shape.u + across * shape.outer; };
    // The block, a lighter band where the rail runs through it, and its outline.
    canvas.band(Layer::Joints, at(-l, 0.0), at(l, 0.0), 2.0 * w, style.carriage, drawing::Medium::Screen);
    canvas.band(Layer::Joints, at(-l + 2.0 * px, 0.0), at(l - 2.0 * px, 0.0), 2.0 * shape.half,
        style.carriage.lighter(118), drawing::Medium::Screen);
    canvas.lines(Layer::Joints, pen(style.carriage.darker(200), 1.4 * px, Qt::SquareCap),
        {QLineF(at(-l, w), at(l, w)), QLineF(at(l, w), at(l, -w)), QLineF(at(l, -w), at(-l, -w)),
            QLineF(at(-l, -w), at(-l, w))});
    canvas.labels.addObstacle(Quad {at(-l, w), at(l, w), at(l, -w), at(-l, -w)});
}

} // namespace pkm
