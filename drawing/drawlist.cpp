#include "drawlist.h"

#include "scenegeometry.h"

#include <QRectF>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace pkm::drawing {

using namespace pkm::detail;

std::array<QPointF, 4> arrowCorners(const QPointF &tip, const QPointF &direction, const ArrowShape &head)
{
    const QPointF u = unit(direction), n = screenLeft(u);
    const double l = head.length, w = 0.5 * head.width;
    return {tip, tip - l * u + w * n, tip - 0.8 * l * u, tip - l * u - w * n};
}

std::pair<QPointF, QPointF> arcArrow(const Arc &arc)
{
    const double end = arc.start + arc.sweep;
    const double turn = arc.sweep > 0.0 ? 1.0 : -1.0;
    const QPointF tip = arc.centre + arc.radius * deviceDirection(end);
    const QPointF back = arc.centre + arc.radius * deviceDirection(end - turn * arc.head.length / arc.radius);
    return {tip, tip - back};
}

namespace {

/// A box that can hold a single point: QRectF::united() drops a rectangle of no size, so the
/// corners of a text without a knock-out box (reach 0) would not count.
struct Extent {
    double left = std::numeric_limits<double>::infinity(), top = left;
    double right = -std::numeric_limits<double>::infinity(), bottom = right;
};

/// Grows `box` by the points and the half width `reach` around them.
void extend(Extent &box, const QPointF &p, double reach = 0.0)
{
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        return;
    box.left = std::min(box.left, p.x() - reach);
    box.top = std::min(box.top, p.y() - reach);
    box.right = std::max(box.right, p.x() + reach);
    box.bottom = std::max(box.bottom, p.y() + reach);
}

} // namespace

QRectF bounds(const DrawList &list, bool cad)
{
    Extent box;
    for (const Primitive &item : list.items) {
        if (cad ? !shownInCad(item.medium) : !shownOnScreen(item.medium))
            continue;
        std::visit(
            [&box](const auto &shape) {
                using T = std::decay_t<decltype(shape)>;
                if constexpr (std::is_same_v<T, Lines>) {
                    for (const QLineF &line : shape.lines) {
                        extend(box, line.p1(), 0.5 * shape.pen.width);
                        extend(box, line.p2(), 0.5 * shape.pen.width);
                    }
                } else if constexpr (std::is_same_v<T, Band> || std::is_same_v<T, Member>) {
                    extend(box, shape.a, 0.5 * shape.width);
                    extend(box, shape.b, 0.5 * shape.width);
                } else if constexpr (std::is_same_v<T, Polygon>) {
                    for (const QPointF &p : shape.points)
                        extend(box, p, 0.5 * shape.pen.width);
                } else if constexpr (std::is_same_v<T, Circle>) {
                    extend(box, shape.centre, shape.radius + 0.5 * shape.pen.width);
                } else if constexpr (std::is_same_v<T, Arc>) {
                    // the arc's points every few degrees: close enough for a frame around it
                    const int steps = std::max(2, int(std::abs(shape.sweep) / (5.0 * degree)) + 1);
                    for (int k = 0; k <= steps; ++k)
                        extend(box, shape.centre + shape.radius * deviceDirection(shape.start + shape.sweep * k / steps),
                            0.5 * shape.pen.width);
                } else if constexpr (std::is_same_v<T, DimensionLine>) {
                    const QPointF u = unit(shape.to - shape.from);
                    const double tail = shape.arrowsInside ? 0.0 : shape.tail;
                    extend(box, shape.from - tail * u, 0.5 * shape.head.width);
                    extend(box, shape.to + tail * u, 0.5 * shape.head.width);
                } else if constexpr (std::is_same_v<T, Text>) {
                    const QPointF u = deviceDirection(-shape.rotationDegrees * degree) * (0.5 * shape.box.width());
                    const QPointF v = screenLeft(unit(u)) * (0.5 * shape.box.height());
                    for (const QPointF &corner : {shape.centre - u - v, shape.centre + u - v, shape.centre + u + v,
                             shape.centre - u + v})
                        extend(box, corner);
                }
            },
            item.shape);
    }
    return box.left <= box.right ? QRectF(QPointF(box.left, box.top), QPointF(box.right, box.bottom)) : QRectF();
}

} // namespace pkm::drawing
