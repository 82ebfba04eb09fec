#include "rasterstroke.h"

#include <QPaintEngine>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pkm::drawing {

namespace {

double length(const QPointF &v)
{
    return std::hypot(v.x(), v.y());
}

double cross(const QPointF &a, const QPointF &b)
{
    return a.x() * b.y() - a.y() * b.x();
}

/// One dash, or the whole line: its points, and whether it closes on itself (no caps).
struct Run {
    QPolygonF points;
    bool loop = false;
};

/// The runs of `points` that `pattern` (in device units; empty: solid) draws, as QPainter's
/// dash stroker lays them: from the first point, on across a closed polygon's last side.
std::vector<Run> runsOf(const QPolygonF &points, bool closed, const QVector<qreal> &pattern)
{
    if (pattern.isEmpty())
        return {Run{points, closed}};
    std::vector<Run> runs;
    QPolygonF current;
    int dash = 0;
    double left = pattern[0]; // of the current dash or gap
    const int sides = closed ? int(points.size()) : int(points.size()) - 1;
    for (int k = 0; k < sides; ++k) {
        const QPointF a = points[k], b = points[(k + 1) % points.size()];
        const double side = length(b - a);
        double at = 0.0;
        while (at < side) {
            const double step = std::min(left, side - at);
            const bool on = dash % 2 == 0;
            if (on) {
                if (current.isEmpty())
                    current << a + (b - a) * (at / side);
                current << a + (b - a) * ((at + step) / side);
            }
            at += step;
            left -= step;
            if (left <= 1e-9) {
                if (on && current.size() >= 2)
                    runs.push_back({current, false});
                current.clear();
                dash = (dash + 1) % int(pattern.size());
                left = pattern[dash];
            }
        }
    }
    if (current.size() >= 2)
        runs.push_back({current, false});
    return runs;
}

/// Whether the sides a→v and v→b turn so little that a join would add less than a fifth of a
/// pixel: a traced curve (an ellipse of 96 sides) then needs no join at all.
bool nearlyStraight(const QPointF &a, const QPointF &v, const QPointF &b, double half)
{
    // a side of no length (a dash that ends on a corner) has no direction: nothing to join
    if (!(length(v - a) > 1e-9) || !(length(b - v) > 1e-9))
        return true;
    const QPointF d1 = (v - a) / length(v - a), d2 = (b - v) / length(b - v);
    return d1.x() * d2.x() + d1.y() * d2.y() > 0.0 && half * std::abs(cross(d1, d2)) < 0.2;
}

/// The polygon that joins side a→v to side v→b on the outside of the turn (bevel or miter),
/// or nothing where the sides go straight on.
QPolygonF joinPolygon(const QPointF &a, const QPointF &v, const QPointF &b, double half, Qt::PenJoinStyle join)
{
    const QPointF d1 = (v - a) / length(v - a), d2 = (b - v) / length(b - v);
    const double turn = cross(d1, d2);
    // NaN-safe: a polygon with a NaN corner sends Qt's rasterizer into an endless loop
    if (!(std::abs(turn) >= 1e-9))
        return {};
    // the outside of a left turn is on the right
    const double side = turn > 0.0 ? -1.0 : 1.0;
    const QPointF n1(-d1.y() * side, d1.x() * side), n2(-d2.y() * side, d2.x() * side);
    QPolygonF join_{v, v + half * n1};
    const double along = 1.0 + n1.x() * n2.x() + n1.y() * n2.y();
    // QPen's miter limit: twice the pen width, beyond which Qt bevels
    if (join == Qt::MiterJoin && along > 1e-9 && half * std::sqrt(2.0 / along) <= 2.0 * (2.0 * half))
        join_ << v + half * (n1 + n2) / along;
    join_ << v + half * n2;
    return join_;
}

} // namespace

QVector<qreal> dashPattern(Dash dash)
{
    switch (dash) {
    case Dash::Solid:
        return {};
    case Dash::Dashed:
        return {6.0, 4.0};
    case Dash::Centre:
        return {14.0, 3.0, 2.0, 3.0};
    case Dash::Ghost:
        return {2.4, 1.2};
    }
    return {};
}

bool strokesOnRaster(const QPainter &painter, const Pen &pen)
{
    const QPaintEngine *engine = painter.paintEngine();
    return engine && engine->type() == QPaintEngine::Raster && painter.testRenderHint(QPainter::Antialiasing)
        && pen.width > 1.0 && pen.colour.alpha() == 255;
}

void strokeOnRaster(QPainter &painter, const QPolygonF &input, bool closed, const Pen &pen)
{
    // the distinct points: a side of length 0 has no direction to join or cap
    QPolygonF points;
    for (const QPointF &p : input) {
        if (points.isEmpty() || length(p - points.constLast()) > 1e-9)
            points << p;
    }
    if (closed && points.size() > 2 && length(points.constFirst() - points.constLast()) <= 1e-9)
        points.removeLast();
    const double half = 0.5 * pen.width;
    if (points.size() < 2) {
        // a dot, or nothing, as Qt draws a line of no length: let Qt draw it
        painter.setPen(QPen(pen.colour, pen.width, Qt::SolidLine, pen.cap, pen.join));
        painter.drawPolyline(input);
        return;
    }
    QVector<qreal> pattern = dashPattern(pen.dash);
    for (qreal &dash : pattern)
        dash *= pen.width;
    const std::vector<Run> runs = runsOf(points, closed && points.size() > 2, pattern);

    std::vector<QPointF> dots;
    std::vector<QPolygonF> joins;
    painter.setPen(QPen(pen.colour, pen.width, Qt::SolidLine, Qt::FlatCap));
    for (const Run &run : runs) {
        const QPolygonF &p = run.points;
        const int n = int(p.size());
        for (int k = 0; k < (run.loop ? n : n - 1); ++k) {
            QPointF a = p[k], b = p[(k + 1) % n];
            if (!run.loop && pen.cap == Qt::SquareCap && length(b - a) > 1e-9) {
                // a square cap reaches half the width past the end
                const QPointF u = (b - a) / length(b - a);
                if (k == 0)
                    a -= half * u;
                if (k == n - 2)
                    b += half * u;
            }
            painter.drawLine(a, b);
        }
        for (int k = run.loop ? 0 : 1; k < (run.loop ? n : n - 1); ++k) {
            const QPointF &before = p[(k + n - 1) % n], &v = p[k], &after = p[(k + 1) % n];
            if (nearlyStraight(before, v, after, half))
                continue;
            if (pen.join == Qt::RoundJoin)
                dots.push_back(v);
            else if (QPolygonF j = joinPolygon(before, v, after, half, pen.join); !j.isEmpty())
                joins.push_back(std::move(j));
        }
        if (!run.loop && pen.cap == Qt::RoundCap) {
            dots.push_back(p.constFirst());
            dots.push_back(p.constLast());
        }
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(pen.colour);
    for (const QPointF &dot : dots)
        painter.drawEllipse(dot, half, half);
    for (const QPolygonF &join : joins)
        painter.drawPolygon(join);
    painter.setBrush(Qt::NoBrush);
}

} // namespace pkm::drawing
