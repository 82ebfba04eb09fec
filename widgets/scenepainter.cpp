#include "scenepainter.h"

#include "quantityformat.h"
#include "scenegeometry.h"
#include "scenelabels.h"
#include "sceneprimitives.h"

#include <QFont>
#include <QFontMetricsF>
#include <QLocale>
#include <QPainter>
#include <QPen>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <vector>

// Performance note: Qt's raster engine strokes flat- or square-capped lines through a fast
// path, while round caps, filled rotated shapes and gradients (blended on a thread pool in
// Qt 6) cost ten times more. So bars, the motor, the screw and rotated label boxes are all
// thick flat-capped lines computed in device coordinates, and the grid is drawn with fillRect.
//
// The scene is drawn in three layers: this file draws the members (bars, joints, handles),
// ghosts, and the background, grid and scale bar; sceneprimitives.cpp the ground, guides and
// carriages, actuators, dimensions and angles; scenelabels.cpp places and draws all text
// last, clear of the geometry.

namespace pkm {

namespace {

using namespace detail;

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
        if (scene.joints[i].kind == JointKind::Ground)
            labels.addRay(int(i), {0.0, 1.0}, 34.0 * px); // the ground symbol hangs below
        labels.addObstacle(canvas.points[i], canvas.points[i], ring);
    }
}

void drawBars(const SceneCanvas &canvas)
{
    const SceneStyle &style = canvas.style;
    const double px = canvas.px();
    for (const SceneBar &bar : canvas.scene.bars) {
        if (!canvas.valid(bar.from) || !canvas.valid(bar.to))
            continue;
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
        // Flat caps: the pivot circles cover the ends.
        canvas.stroke(colour, width * px);
        canvas.painter.drawLine(canvas.point(bar.from), canvas.point(bar.to));
        canvas.labels.addObstacle(canvas.point(bar.from), canvas.point(bar.to), 0.5 * width * px + 1.0 * px);
        if (!bar.label.empty()) {
            const QColor text = bar.kind == BarKind::Ground ? style.ink : colour.darker(120);
            canvas.labels.addMemberLabel({bar.from, bar.to, QString::fromStdString(bar.label), text, false});
        }
    }
    canvas.labels.dropDimensionedActuatorLabels();
}

void drawJoints(const SceneCanvas &canvas)
{
    QPainter &painter = canvas.painter;
    const double r = canvas.style.pivotRadius * canvas.px();
    painter.setPen(QPen(canvas.style.ink, 2.0 * canvas.px()));
    for (std::size_t i = 0; i < canvas.points.size(); ++i) {
        const QPointF p = canvas.points[i];
        switch (canvas.scene.joints[i].kind) {
        case JointKind::Ground:
        case JointKind::Revolute:
            painter.setBrush(Qt::white);
            painter.drawEllipse(p, r, r);
            break;
        case JointKind::Spherical:
            painter.setBrush(Qt::white);
            painter.drawEllipse(p, r, r);
            painter.setBrush(canvas.style.ink);
            painter.drawEllipse(p, 0.35 * r, 0.35 * r);
            painter.setBrush(Qt::white);
            break;
        case JointKind::Slider:
            painter.setBrush(Qt::white);
            if (canvas.carriageGuide(int(i)))
                painter.drawEllipse(p, r, r); // the pin on its carriage, drawn with the guide
            else
                painter.drawRect(QRectF(p.x() - 1.6 * r, p.y() - r, 3.2 * r, 2.0 * r));
            break;
        case JointKind::Point:
            painter.setBrush(canvas.style.ink);
            painter.drawEllipse(p, 0.5 * r, 0.5 * r);
            break;
        }
    }
}

void drawHandles(const SceneCanvas &canvas, int activeHandle)
{
    const SceneStyle &style = canvas.style;
    if (!style.showHandles)
        return;
    QPainter &painter = canvas.painter;
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
            painter.setPen(Qt::NoPen);
            painter.setBrush(glow);
            const double halo = (style.pivotRadius + 13.0) * px;
            painter.drawEllipse(p, halo, halo);
            painter.setPen(QPen(ring, 3.0 * px));
            painter.setBrush(Qt::NoBrush);
            const double radius = (style.pivotRadius + 7.0) * px;
            painter.drawEllipse(p, radius, radius);
        } else {
            ring.setAlpha(150);
            painter.setPen(QPen(ring, 2.0 * px));
            painter.setBrush(Qt::NoBrush);
            const double radius = (style.pivotRadius + 5.0) * px;
            painter.drawEllipse(p, radius, radius);
        }
    }
}

} // namespace

// -- ViewMapping -------------------------------------------------------------------------

ViewMapping ViewMapping::fit(const Eigen::AlignedBox3d &extent, const QRectF &target, double margin)
{
    ViewMapping mapping;
    if (extent.isEmpty() || target.isEmpty()) {
        mapping.origin = target.center();
        return mapping;
    }
    const double width = std::max(extent.sizes().x(), 1e-9), height = std::max(extent.sizes().y(), 1e-9);
    const double availableWidth = std::max(target.width() - 2.0 * margin, 1.0);
    const double availableHeight = std::max(target.height() - 2.0 * margin, 1.0);
    mapping.scale = std::min(availableWidth / width, availableHeight / height);
    const Eigen::Vector3d centre = extent.center();
    mapping.origin = target.center() - QPointF(mapping.scale * centre.x(), -mapping.scale * centre.y());
    return mapping;
}

// -- ScenePainter ------------------------------------------------------------------------

void ScenePainter::paint(
    QPainter &painter, const Scene &scene, const ViewMapping &mapping, const SceneStyle &style, int activeHandle)
{
    if (!(mapping.scale > 0.0) || !std::isfinite(mapping.scale))
        return;
    std::vector<QPointF> points; // joint positions, device
    points.reserve(scene.joints.size());
    for (const SceneJoint &joint : scene.joints)
        points.push_back(mapping.toDevice(joint.position));
    const std::vector<int> jointGuide = jointsOnGuides(scene);
    const std::vector<GuideShape> guides = guideShapes(scene, points, jointGuide, mapping, style);
    SceneLabels labels(scene, points, mapping, style, painter.device());
    const SceneCanvas canvas {painter, scene, mapping, style, points, labels, guides, jointGuide};

    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    collectRaysAndJoints(canvas);
    // paths (a coupler curve) lie under the mechanism, thin
    for (const ScenePolyline &polyline : scene.polylines) {
        QPolygonF line;
        for (const Eigen::Vector3d &p : polyline.points) {
            if (p.allFinite())
                line << mapping.toDevice(p);
        }
        if (line.size() < 2)
            continue;
        painter.setPen(QPen(style.path, 1.6 * style.pixelSize, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.setBrush(Qt::NoBrush);
        if (polyline.closed)
            painter.drawPolygon(line);
        else
            painter.drawPolyline(line);
    }
    for (std::size_t g = 0; g < guides.size(); ++g)
        drawGuide(canvas, int(g));
    for (const SceneActuator &actuator : scene.actuators)
        drawActuator(canvas, actuator);
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (scene.joints[i].kind == JointKind::Ground)
            drawGround(canvas, points[i]);
        else if (const GuideShape *guide = canvas.carriageGuide(int(i)))
            drawCarriage(canvas, *guide, points[i]);
    }
    drawBars(canvas);
    for (const SceneDimension &dimension : scene.dimensions)
        drawDimension(canvas, dimension);
    for (const SceneAngle &angle : scene.angles)
        drawAngle(canvas, angle);
    drawHandles(canvas, activeHandle);
    drawJoints(canvas);
    labels.placeAll();
    labels.draw(painter);
    painter.restore();
}

void ScenePainter::paintGhost(
    QPainter &painter, const Scene &scene, const ViewMapping &mapping, const SceneStyle &style, bool highlighted)
{
    if (!(mapping.scale > 0.0) || !std::isfinite(mapping.scale))
        return;
    std::vector<QPointF> points;
    points.reserve(scene.joints.size());
    for (const SceneJoint &joint : scene.joints)
        points.push_back(mapping.toDevice(joint.position));
    auto valid = [&points](int joint) { return joint >= 0 && joint < int(points.size()); };
    const std::vector<int> jointGuide = jointsOnGuides(scene);
    const std::vector<GuideShape> guides = guideShapes(scene, points, jointGuide, mapping, style);
    const double px = style.pixelSize;
    const QColor colour = highlighted ? style.handle : style.ghost;

    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setOpacity(highlighted ? std::min(1.0, 2.0 * style.ghostOpacity) : style.ghostOpacity);
    // Members (the ground is the real scene's): dashed, a little thinner than the real ones.
    const double width = (highlighted ? 0.8 : 0.65) * style.barWidth * px;
    QPen dashed(colour, width, Qt::CustomDashLine, Qt::FlatCap);
    dashed.setDashPattern({2.4, 1.2}); // in pen widths
    painter.setPen(dashed);
    for (const SceneBar &bar : scene.bars) {
        if (bar.kind != BarKind::Ground && valid(bar.from) && valid(bar.to))
            painter.drawLine(points[std::size_t(bar.from)], points[std::size_t(bar.to)]);
    }
    for (const SceneActuator &actuator : scene.actuators) {
        if (valid(actuator.from) && valid(actuator.to))
            painter.drawLine(points[std::size_t(actuator.from)], points[std::size_t(actuator.to)]);
    }
    // Joints: hollow pivots; sliders on a guide as their carriage's outline.
    const double r = 0.85 * style.pivotRadius * px;
    painter.setPen(QPen(colour, 2.0 * px));
    painter.setBrush(style.background);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const QPointF p = points[i];
        switch (scene.joints[i].kind) {
        case JointKind::Ground:
        case JointKind::Point:
            break; // fixed: the real scene shows them
        case JointKind::Slider: {
            const int guide = jointGuide[i];
            if (guide >= 0) {
                const GuideShape &shape = guides[std::size_t(guide)];
                const QPointF l = 0.5 * shape.carriageLength * shape.u, w = shape.carriageHalfWidth * shape.outer;
                painter.setBrush(Qt::NoBrush);
                painter.drawPolygon(QPolygonF({p - l - w, p + l - w, p + l + w, p - l + w}));
                painter.setBrush(style.background);
            } else {
                painter.drawRect(QRectF(p.x() - 1.6 * r, p.y() - r, 3.2 * r, 2.0 * r));
            }
            painter.drawEllipse(p, r, r);
            break;
        }
        case JointKind::Revolute:
        case JointKind::Spherical:
            painter.drawEllipse(p, r, r);
            break;
        }
    }
    painter.restore();
}

double ScenePainter::niceStep(double minimumDevice, double scale)
{
    if (!(scale > 0.0) || !(minimumDevice > 0.0))
        return 1.0;
    const double minimumMm = minimumDevice / scale;
    double decade = std::pow(10.0, std::floor(std::log10(minimumMm)));
    for (;;) {
        for (double mantissa : {1.0, 2.0, 5.0}) {
            // The tolerance keeps 5 × 1 mm from rounding up to 10 mm.
            if (mantissa * decade >= minimumMm * (1.0 - 1e-9))
                return mantissa * decade;
        }
        decade *= 10.0;
    }
}

void ScenePainter::paintBackground(QPainter &painter, const QRectF &area, const ViewMapping &mapping,
    const SceneStyle &style, double minimumGridPixels)
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, false); // crisp one-pixel grid lines
    painter.fillRect(area, style.background);
    if (mapping.scale > 0.0 && std::isfinite(mapping.scale)) {
        const double step = niceStep(minimumGridPixels * style.pixelSize, mapping.scale);
        const double major = niceStep(5.0 * step * mapping.scale, mapping.scale);
        const long long ratio = std::max(1LL, std::llround(major / step));
        const Eigen::Vector2d topLeft = mapping.toScene(area.topLeft());
        const Eigen::Vector2d bottomRight = mapping.toScene(area.bottomRight());
        const long long i0 = std::llround(std::ceil(topLeft.x() / step)),
                        i1 = std::llround(std::floor(bottomRight.x() / step));
        const long long j0 = std::llround(std::ceil(bottomRight.y() / step)),
                        j1 = std::llround(std::floor(topLeft.y() / step));
        if (i1 - i0 < 4000 && j1 - j0 < 4000) {
            // One-unit rectangles rather than lines: fillRect is a plain span fill, about five
            // times faster than stroking full-length lines.
            const double w = std::max(1.0, std::round(style.pixelSize));
            for (long long i = i0; i <= i1; ++i) {
                const double x = std::floor(mapping.toDevice(Eigen::Vector2d(double(i) * step, 0.0)).x());
                painter.fillRect(
                    QRectF(x, area.top(), w, area.height()), i % ratio == 0 ? style.gridMajor : style.gridMinor);
            }
            for (long long j = j0; j <= j1; ++j) {
                const double y = std::floor(mapping.toDevice(Eigen::Vector2d(0.0, double(j) * step)).y());
                painter.fillRect(
                    QRectF(area.left(), y, area.width(), w), j % ratio == 0 ? style.gridMajor : style.gridMinor);
            }
        }
    }
    painter.restore();
}

void ScenePainter::paintKnockout(QPainter &painter, const QRectF &box, const SceneStyle &style)
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    QColor knockout = style.background;
    knockout.setAlpha(215);
    painter.setPen(Qt::NoPen);
    painter.setBrush(knockout);
    painter.drawRoundedRect(box, 4.0 * style.pixelSize, 4.0 * style.pixelSize);
    painter.restore();
}

void ScenePainter::paintScaleBar(
    QPainter &painter, const QRectF &area, const ViewMapping &mapping, const SceneStyle &style)
{
    if (!(mapping.scale > 0.0) || !std::isfinite(mapping.scale))
        return;
    const double px = style.pixelSize;
    const double millimetres = niceStep(90.0 * px, mapping.scale);
    const double barLength = millimetres * mapping.scale;
    const QFont font = detail::labelFont(style.fontPixels * px, false);
    const QFontMetricsF metrics(font, painter.device());
    // "50 mm", "0,5 мм": the locale's number (no group separator, as everywhere) and unit.
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    const QString text = locale.toString(millimetres, 'g', 6) + QLatin1Char(' ') + unitText(units::millimetre);
    const double margin = 16.0 * px, tick = 8.0 * px;
    const QPointF right(area.right() - margin, area.bottom() - margin);
    const QPointF left = right - QPointF(barLength, 0.0);
    const QRectF textBox(left.x(), left.y() - tick - metrics.height() - 2.0 * px, barLength, metrics.height());

    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    const double pad = 6.0 * px;
    paintKnockout(painter, QRectF(QPointF(left.x() - pad, textBox.top() - pad), QPointF(right.x() + pad, right.y() + pad)),
                  style);
    QPen pen(style.ink, 2.0 * px, Qt::SolidLine, Qt::FlatCap);
    painter.setPen(pen);
    painter.drawLine(left, right);
    painter.drawLine(left, left - QPointF(0.0, tick));
    painter.drawLine(right, right - QPointF(0.0, tick));
    painter.drawLine(0.5 * (left + right), 0.5 * (left + right) - QPointF(0.0, 0.5 * tick));
    painter.setFont(font);
    painter.drawText(textBox, Qt::AlignCenter, text);
    painter.restore();
}

void ScenePainter::paintMessage(QPainter &painter, const QRectF &area, const QString &message, const SceneStyle &style)
{
    if (message.isEmpty())
        return;
    const double px = style.pixelSize;
    const QFont font = detail::labelFont(style.fontPixels * px, false);
    const QFontMetricsF metrics(font, painter.device());
    const double margin = 16.0 * px, pad = 8.0 * px;
    // Leave the bottom-right corner to the scale bar.
    const double available = std::max(40.0 * px, area.width() - 2.0 * margin - 2.0 * pad - 200.0 * px);
    const QString shown = metrics.elidedText(message, Qt::ElideRight, available);
    const QSizeF size(metrics.horizontalAdvance(shown) + 2.0 * pad, metrics.height() + 2.0 * pad);
    const QRectF box(area.left() + margin, area.bottom() - margin - size.height(), size.width(), size.height());

    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(QColor(0xd9, 0xa4, 0x41), 1.2 * px));
    painter.setBrush(QColor(0xff, 0xf6, 0xdc, 240));
    painter.drawRoundedRect(box, 6.0 * px, 6.0 * px);
    painter.setFont(font);
    painter.setPen(style.ink);
    painter.drawText(box, Qt::AlignCenter, shown);
    painter.restore();
}

} // namespace pkm
