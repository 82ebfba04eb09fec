#include "scenepainter.h"

#include "drawlistpainter.h"
#include "quantityformat.h"
#include "scenegeometry.h"
#include "scenelabels.h"
#include "scenelayout.h"

#include <QFont>
#include <QFontMetricsF>
#include <QLocale>
#include <QMarginsF>
#include <QPainter>
#include <QPen>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

// The scene itself is laid out once (scenelayout.h) and rendered by paintDrawList(); this
// file adds what only a view has: ghosts of the other poses, the background and its mm grid,
// the scale bar and messages. The grid is drawn with fillRect, a plain span fill.

namespace pkm {

// -- ScenePainter ------------------------------------------------------------------------

void ScenePainter::paint(QPainter &painter, const Scene &scene, const ViewMapping &mapping, const SceneStyle &style,
    int activeHandle, const QList<Scene> &ghosts, const QRectF &scaleBar, std::vector<std::pair<QString, QPointF>> *labelPlaces)
{
    drawing::LayoutOptions options;
    options.activeHandle = activeHandle;
    for (const Scene &ghost : ghosts) {
        const std::vector<QLineF> lines = drawing::ghostLines(ghost, mapping);
        options.avoid.insert(options.avoid.end(), lines.begin(), lines.end());
    }
    if (!scaleBar.isEmpty())
        options.covered.push_back(scaleBar);
    options.device = painter.device();
    // Labels stay inside what the painter shows (a view's rectangle), where no transform
    // stands between the layout's device units and the painter's window.
    if (painter.worldTransform().isIdentity())
        options.labelRoom = QRectF(painter.window()).adjusted(2.0, 2.0, -2.0, -2.0);
    drawing::LabelPlaces previous;
    if (labelPlaces) {
        previous = std::move(*labelPlaces);
        options.previousLabels = &previous;
        options.placedLabels = labelPlaces;
    }
    drawing::paintDrawList(painter, drawing::layoutScene(scene, mapping, style, options));
}

void ScenePainter::paintGhost(
    QPainter &painter, const Scene &scene, const ViewMapping &mapping, const SceneStyle &style, bool highlighted)
{
    drawing::paintDrawList(painter, drawing::layoutGhost(scene, mapping, style, highlighted));
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

double ScenePainter::scaleBarHeight(const SceneStyle &style, const QPaintDevice *device)
{
    const QFontMetricsF metrics(detail::labelFont(style.fontPixels * style.pixelSize, false),
                                const_cast<QPaintDevice *>(device));
    return (16.0 + 8.0 + 2.0 + 6.0) * style.pixelSize + metrics.height();
}

namespace {
/// Where the scale bar goes in `area`: the bar's ends, the box of its text and the font.
struct ScaleBarGeometry {
    QPointF left, right;
    QRectF textBox;
    QRectF box; ///< the white knockout under all of it
    QString text;
    QFont font;
    double tick = 0.0;
};

ScaleBarGeometry scaleBarGeometry(const QRectF &area, const ViewMapping &mapping, const SceneStyle &style,
    const QPaintDevice *device)
{
    ScaleBarGeometry g;
    const double px = style.pixelSize;
    const double millimetres = ScenePainter::niceStep(90.0 * px, mapping.scale);
    const double barLength = millimetres * mapping.scale;
    g.font = detail::labelFont(style.fontPixels * px, false);
    const QFontMetricsF metrics(g.font, const_cast<QPaintDevice *>(device));
    // "50 mm", "0,5 мм": the locale's number (no group separator, as everywhere) and unit.
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    g.text = locale.toString(millimetres, 'g', 6) + QLatin1Char(' ') + unitText(units::millimetre);
    const double margin = 16.0 * px;
    g.tick = 8.0 * px;
    g.right = QPointF(area.right() - margin, area.bottom() - margin);
    g.left = g.right - QPointF(barLength, 0.0);
    // Centred over the bar; where large text is wider than the bar ("100 mm" at presentation
    // mode's size over a bar of 90 px), ending with the bar, whole, never cut to "100 m".
    const double textWidth = metrics.horizontalAdvance(g.text);
    const double textLeft = textWidth <= barLength ? g.left.x() : g.right.x() - textWidth;
    g.textBox = QRectF(textLeft, g.left.y() - g.tick - metrics.height() - 2.0 * px, g.right.x() - textLeft, metrics.height());
    const double pad = 6.0 * px;
    g.box = QRectF(QPointF(textLeft - pad, g.textBox.top() - pad), QPointF(g.right.x() + pad, g.right.y() + pad));
    return g;
}
} // namespace

QRectF ScenePainter::scaleBarBox(const QRectF &area, const ViewMapping &mapping, const SceneStyle &style,
    const QPaintDevice *device)
{
    if (!(mapping.scale > 0.0) || !std::isfinite(mapping.scale))
        return {};
    return scaleBarGeometry(area, mapping, style, device).box;
}

void ScenePainter::paintScaleBar(
    QPainter &painter, const QRectF &area, const ViewMapping &mapping, const SceneStyle &style)
{
    if (!(mapping.scale > 0.0) || !std::isfinite(mapping.scale))
        return;
    const ScaleBarGeometry g = scaleBarGeometry(area, mapping, style, painter.device());
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    paintKnockout(painter, g.box, style);
    QPen pen(style.ink, 2.0 * style.pixelSize, Qt::SolidLine, Qt::FlatCap);
    painter.setPen(pen);
    painter.drawLine(g.left, g.right);
    painter.drawLine(g.left, g.left - QPointF(0.0, g.tick));
    painter.drawLine(g.right, g.right - QPointF(0.0, g.tick));
    painter.drawLine(0.5 * (g.left + g.right), 0.5 * (g.left + g.right) - QPointF(0.0, 0.5 * g.tick));
    painter.setFont(g.font);
    painter.drawText(g.textBox, Qt::AlignCenter | Qt::TextDontClip, g.text);
    painter.restore();
}

ScenePainter::MessageLayout ScenePainter::messageLayout(const QRectF &area, const QString &message,
    const SceneStyle &style, QPaintDevice *device, const QRectF &drawing, const std::vector<QPointF> &joints)
{
    const double px = style.pixelSize;
    MessageLayout layout;
    layout.font = detail::labelFont(style.fontPixels * px, false);
    const QFontMetricsF metrics(layout.font, device);
    const double margin = 16.0 * px, pad = 8.0 * px;
    // A short message sits in the bottom-left corner beside the scale bar. A long one (a
    // limit's reason, a singular pose) is the one thing the user must read whole: it wraps
    // over the view's width, above the scale bar.
    const double besideScaleBar = area.width() - 2.0 * margin - 2.0 * pad - 200.0 * px;
    const double full = std::max(40.0 * px, area.width() - 2.0 * margin - 2.0 * pad);
    const bool oneLine = metrics.horizontalAdvance(message) <= besideScaleBar;
    const double available = oneLine ? besideScaleBar : full;
    // the scale bar's height (paintScaleBar(): its tick and its label) and a gap
    const double bottom = area.bottom() - margin - (oneLine ? 0.0 : 8.0 * px + metrics.height() + 8.0 * px);
    layout.flags = Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap;
    QRectF text = metrics.boundingRect(QRectF(0, 0, available, 1e6), layout.flags, message);
    if (text.width() > available) { // a word longer than the room: break it anywhere
        layout.flags = Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWrapAnywhere;
        text = metrics.boundingRect(QRectF(0, 0, available, 1e6), layout.flags, message);
    }
    const QSizeF size(std::ceil(text.width()) + 2.0 * pad, std::ceil(text.height()) + 2.0 * pad);
    // never above the view's top: a message taller than the view starts at its top
    layout.box = QRectF(area.left() + margin, std::max(area.top(), bottom - size.height()), size.width(), size.height());
    layout.message = message;
    if (drawing.isValid()) {
        const auto covered = [&drawing](const QRectF &box) {
            const QRectF both = box.intersected(drawing);
            return both.isValid() ? both.width() * both.height() : 0.0;
        };
        // A mechanism low in a short view (a five-bar at a singular pose, its view squeezed by
        // the mode buttons) would lose its lower joints under the box: at the top, where it
        // covers less.
        const QRectF top(layout.box.left(), area.top() + margin, size.width(), size.height());
        if (top.bottom() <= area.bottom() && covered(top) < covered(layout.box))
            layout.box = top;
        // One that fills the view is covered wherever the whole message goes: its headline
        // ("Singular pose (inverse)", "x stops at its upper limit 18.49 mm") alone then goes to
        // the corner where it covers least; the whole message is in the status bar.
        const qsizetype colon = message.indexOf(QStringLiteral(": "));
        if (covered(layout.box) > 0.0 && colon > 0) {
            const QString headline = message.left(colon);
            const auto sized = [&](double width) {
                const QRectF text = metrics.boundingRect(QRectF(0, 0, width, 1e6), layout.flags, headline);
                return QSizeF(std::ceil(text.width()) + 2.0 * pad, std::ceil(text.height()) + 2.0 * pad);
            };
            // A joint under the note hides what it says is singular (the Russian five-bar's A
            // under a headline of four lines beside the scale bar): one costs more than any area.
            const double ring = (style.pivotRadius + 4.0) * px;
            const auto cost = [&](const QRectF &box) {
                const QRectF grown = box.adjusted(-ring, -ring, ring, ring);
                const auto hidden = std::count_if(joints.begin(), joints.end(), [&](const QPointF &p) { return grown.contains(p); });
                return covered(box) + double(hidden) * (drawing.width() * drawing.height() + 1.0);
            };
            const QSizeF beside = sized(std::max(besideScaleBar, 40.0 * px));
            const double upper = area.top() + margin, lower = area.bottom() - margin;
            // beside the scale bar (wrapped to the room there), or in a corner above it or at the
            // top, wrapped to the whole width or to half of it (two lines in a corner may leave
            // a joint free that one line across would cover)
            std::vector<QRectF> boxes {QRectF(QPointF(area.left() + margin, lower - beside.height()), beside)};
            for (const double width : {full, std::max(0.5 * full, 40.0 * px)}) {
                const QSizeF small = sized(width);
                const double left = area.left() + margin, right = area.right() - margin - small.width();
                // the scale bar's height (paintScaleBar(): its tick and its label) and a gap
                const double aboveBar = lower - small.height() - (8.0 * px + metrics.height() + 8.0 * px);
                for (const QPointF &corner : {QPointF(left, upper), QPointF(right, upper), QPointF(left, aboveBar), QPointF(right, aboveBar)})
                    boxes.emplace_back(corner, small);
            }
            QRectF best = layout.box;
            for (const QRectF &box : boxes) {
                if (area.contains(box) && cost(box) < cost(best))
                    best = box;
            }
            if (best != layout.box) {
                layout.box = best;
                layout.message = headline;
            }
        }
    }
    layout.text = layout.box.adjusted(pad, pad, -pad, -pad);
    return layout;
}

QRectF ScenePainter::jointBounds(const Scene &scene, const ViewMapping &mapping, const SceneStyle &style)
{
    QRectF bounds;
    for (const SceneJoint &joint : scene.joints) {
        if (joint.kind == JointKind::Point || !joint.position.allFinite())
            continue; // a point of interest (an instant centre) may lie far out
        const QPointF at = mapping.toDevice(joint.position);
        const QRectF point(at, QSizeF(0.001, 0.001)); // a rect of no size is null: united() skips it
        bounds = bounds.isValid() ? bounds.united(point) : point;
    }
    const double grow = (style.pivotRadius + style.fontPixels) * style.pixelSize;
    return bounds.isValid() ? bounds.adjusted(-grow, -grow, grow, grow) : QRectF();
}

std::vector<QPointF> ScenePainter::jointPoints(const Scene &scene, const ViewMapping &mapping)
{
    std::vector<QPointF> points;
    for (const SceneJoint &joint : scene.joints) {
        if (joint.kind != JointKind::Point && joint.position.allFinite())
            points.push_back(mapping.toDevice(joint.position));
    }
    return points;
}

void ScenePainter::paintMessage(QPainter &painter, const QRectF &area, const QString &message, const SceneStyle &style,
    const QRectF &drawing, const std::vector<QPointF> &joints)
{
    if (message.isEmpty())
        return;
    const double px = style.pixelSize;
    const MessageLayout layout = messageLayout(area, message, style, painter.device(), drawing, joints);

    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(QColor(0xd9, 0xa4, 0x41), 1.2 * px));
    painter.setBrush(QColor(0xff, 0xf6, 0xdc, 240));
    painter.drawRoundedRect(layout.box, 6.0 * px, 6.0 * px);
    painter.setFont(layout.font);
    painter.setPen(style.ink);
    painter.drawText(layout.text, layout.flags, layout.message);
    painter.restore();
}

namespace {

/// Where paintLegend() puts its lines: the frame and each line's text box (width `available`).
struct LegendLayout {
    QRectF frame;
    std::vector<double> heights;
    double available = 0.0;
    double sample = 0.0, gap = 0.0, pad = 0.0;
};

LegendLayout legendLayout(const QRectF &area, const Scene &scene, const QFontMetricsF &metrics, const SceneStyle &style)
{
    LegendLayout l;
    const double px = style.pixelSize;
    const double margin = 16.0 * px;
    l.pad = 8.0 * px;
    l.sample = 34.0 * px;
    l.gap = 8.0 * px;
    // the whole width if need be: a legend line broken in two is harder to read than a drawing
    // partly covered
    l.available = std::max(60.0 * px, area.width() - 2.0 * margin - 2.0 * l.pad - l.sample - l.gap);
    const int flags = Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap;
    double width = 0.0, height = 0.0;
    for (const SceneLegendEntry &entry : scene.legend) {
        const QRectF box = metrics.boundingRect(QRectF(0, 0, l.available, 1e6), flags, QString::fromStdString(entry.text));
        l.heights.push_back(box.height());
        width = std::max(width, box.width());
        height += box.height() + (l.heights.size() > 1 ? 4.0 * px : 0.0);
    }
    l.frame = QRectF(area.left() + margin, area.top() + margin, l.sample + l.gap + std::ceil(width) + 2.0 * l.pad,
                     std::ceil(height) + 2.0 * l.pad);
    return l;
}

} // namespace

double ScenePainter::legendHeight(const QRectF &area, const Scene &scene, const SceneStyle &style, QPaintDevice *device)
{
    if (scene.legend.empty())
        return 0.0;
    const QFont font = detail::labelFont(style.fontPixels * style.pixelSize, false);
    const QFontMetricsF metrics(font, device);
    const LegendLayout l = legendLayout(area, scene, metrics, style);
    return l.frame.bottom() - area.top();
}

void ScenePainter::paintPicture(QPainter &painter, const QRectF &area, const Scene &scene, const ViewMapping &mapping,
    const SceneStyle &style, std::vector<std::pair<QString, QPointF>> *labelPlaces)
{
    painter.save();
    painter.setClipRect(area, Qt::IntersectClip);
    paintBackground(painter, area, mapping, style);
    paint(painter, scene, mapping, style, -1, {}, {}, labelPlaces);
    paintScaleBar(painter, area, mapping, style);
    paintLegend(painter, area, scene, style);
    painter.restore();
}

void ScenePainter::paintLegend(QPainter &painter, const QRectF &area, const Scene &scene, const SceneStyle &style)
{
    if (scene.legend.empty())
        return;
    const double px = style.pixelSize;
    const QFont font = detail::labelFont(style.fontPixels * px, false);
    const QFontMetricsF metrics(font, painter.device());
    const LegendLayout l = legendLayout(area, scene, metrics, style);
    const int flags = Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    paintKnockout(painter, l.frame, style);
    painter.setFont(font);
    double y = l.frame.top() + l.pad;
    for (std::size_t i = 0; i < scene.legend.size(); ++i) {
        const SceneLegendEntry &entry = scene.legend[i];
        const bool velocity = entry.kind == PathKind::VelocityPolygon || entry.kind == PathKind::VelocityEllipse;
        const QColor colour = entry.kind == PathKind::Path ? style.path : velocity ? style.velocity : style.force;
        const double middle = y + 0.5 * metrics.height();
        const double x = l.frame.left() + l.pad;
        painter.setPen(QPen(colour, 2.0 * px, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(QPointF(x, middle), QPointF(x + 0.45 * l.sample, middle));
        painter.setPen(QPen(colour, 1.6 * px, Qt::DashLine, Qt::RoundCap));
        painter.drawLine(QPointF(x + 0.6 * l.sample, middle), QPointF(x + l.sample, middle));
        painter.setPen(style.ink);
        painter.drawText(QRectF(x + l.sample + l.gap, y, l.available, l.heights[i] + 1.0), flags,
                         QString::fromStdString(entry.text));
        y += l.heights[i] + 4.0 * px;
    }
    painter.restore();
}

} // namespace pkm
