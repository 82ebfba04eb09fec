#include "scenepainter.h"

#include "drawlist.h"
#include "scenelayout.h"

#include <QFontMetricsF>
#include <QMarginsF>

#include <algorithm>
#include <limits>

// How a view frames a scene: the extent at the largest scale that fits (ViewMapping::fit), and
// Fit, which also leaves room for the labels, which keep their size in pixels whatever the
// scale (ScenePainter::fitWithLabels).

namespace pkm {

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

// -- Fit with the labels in sight ---------------------------------------------------------

ViewMapping ScenePainter::fitWithLabels(const Scene &scene, const Eigen::AlignedBox3d &extent, const QRectF &room,
    const QRectF &labelRoom, double margin, const SceneStyle &style)
{
    const double gap = 4.0 * style.pixelSize;
    const QRectF inner = labelRoom.adjusted(gap, gap, -gap, -gap);
    // How far the labels of the drawing at `mapping` reach past the inner room on each side.
    const auto overhangs = [&](const ViewMapping &mapping) {
        double left = 0.0, top = 0.0, right = 0.0, bottom = 0.0;
        for (const drawing::Primitive &item : drawing::layoutScene(scene, mapping, style).items) {
            const auto *text = std::get_if<drawing::Text>(&item.shape);
            if (!text || !drawing::shownOnScreen(item.medium))
                continue;
            drawing::Text sized = *text; // its own size where it has no knock-out box
            if (sized.box.isEmpty()) {
                const QFontMetricsF metrics(sized.font);
                sized.box = QSizeF(metrics.horizontalAdvance(sized.text), metrics.height());
            }
            drawing::DrawList one;
            one.add(sized, item.layer, item.medium);
            const QRectF box = drawing::bounds(one, false);
            // a label more than its own size past the edge is a far point's (an instant centre
            // that Fit leaves out); nearer, it is the drawing's, cut or pushed out by the edge
            const QRectF near = labelRoom.adjusted(-box.width(), -2.0 * box.height(), box.width(), 2.0 * box.height());
            if (!box.intersects(near) || inner.contains(box))
                continue;
            left = std::max(left, inner.left() - box.left());
            top = std::max(top, inner.top() - box.top());
            right = std::max(right, box.right() - inner.right());
            bottom = std::max(bottom, box.bottom() - inner.bottom());
        }
        return QMarginsF(left, top, right, bottom);
    };
    const auto total = [](const QMarginsF &m) { return m.left() + m.top() + m.right() + m.bottom(); };
    // Less room on the side a label overhangs, a few times: the fit centres the drawing, so
    // where the other side limits the scale, less room moves it by only half the overhang.
    QRectF fitted = room;
    ViewMapping mapping = ViewMapping::fit(extent, fitted, margin);
    ViewMapping best = mapping;
    // The labels may take half of the scale at most: a short view (a status message of
    // two lines in presentation mode) gave large-text labels up to 60 % of the room, and the
    // five-bar shrank to 60 px under a 500 mm bar. Past that a label is cut or left out.
    const double leastScale = 0.5 * mapping.scale;
    double leastOverhang = std::numeric_limits<double>::infinity();
    int stuck = 0; // passes in a row that cut no less
    for (int pass = 0; pass < 8 && stuck < 2; ++pass) {
        const QMarginsF over = overhangs(mapping);
        stuck = total(over) < leastOverhang - 0.5 ? 0 : stuck + 1;
        if (total(over) < leastOverhang) {
            leastOverhang = total(over);
            best = mapping;
        }
        const QRectF less = fitted.marginsRemoved(over);
        // at most 60 % less room: a label wider than the view is cut whatever the scale
        if (total(over) < 0.5 || less.width() < 0.4 * room.width() || less.height() < 0.4 * room.height())
            break;
        fitted = less;
        mapping = ViewMapping::fit(extent, fitted, margin);
        if (mapping.scale < leastScale)
            break;
    }
    // A label may jump to another side at another scale (a joint's name in a crowded pose), so
    // that taking room from one side after another never ends: then less and less of the whole
    // room, moved away from the side a label overhangs, and of the scales tried the one that
    // cuts least.
    // Three tries in a row that cut no less end it: a label wider than the view, or a view
    // not laid out yet, is cut at any scale, and each try is a layout (a start-up paid 20 ms).
    int fruitless = 0;
    for (double factor = 0.95; leastOverhang >= 0.5 && factor > 0.45 && fruitless < 3; factor -= 0.05) {
        const double before = leastOverhang;
        const QSizeF size = room.size() * factor;
        QRectF smaller(room.center() - QPointF(0.5 * size.width(), 0.5 * size.height()), size);
        for (int move = 0; move < 2 && leastOverhang >= 0.5; ++move) {
            mapping = ViewMapping::fit(extent, smaller, margin);
            if (mapping.scale < leastScale)
                break;
            const QMarginsF over = overhangs(mapping);
            if (total(over) < leastOverhang) {
                leastOverhang = total(over);
                best = mapping;
            }
            const QPointF by(std::clamp(over.left() - over.right(), room.left() - smaller.left(), room.right() - smaller.right()),
                std::clamp(over.top() - over.bottom(), room.top() - smaller.top(), room.bottom() - smaller.bottom()));
            smaller.translate(by);
        }
        fruitless = leastOverhang < before - 0.5 ? 0 : fruitless + 1;
    }
    return best;
}

} // namespace pkm
