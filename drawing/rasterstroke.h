#pragma once
// Wide outlines on a raster device, drawn the cheap way. Qt's raster engine strokes a wide
// antialiased path into one outline and fills it, at a cost that grows with the path's bounding
// box, and round caps and joins add Bézier arcs to it: the velocity polygon of a MOMA drag
// (a closed hexagon some 1500 px round, 2 px wide) took 0.25 ms and its dashed ellipse
// 0.37 ms, most of what View ▸ Velocity and Force Shapes added to a repaint. Drawn as
// flat-capped segments, each its own small path, with the round joins and caps as dots and
// bevel and miter joins as small polygons, the same outlines take 0.03–0.06 ms and look the
// same (tst_rasterstroke compares the pixels).
#include "drawlist.h"

#include <QPainter>
#include <QPolygonF>
#include <QVector>

namespace pkm::drawing {

/// A dash pattern's on and off lengths, in pen widths (empty: solid), as QPen takes it.
QVector<qreal> dashPattern(Dash dash);

/// Whether strokeOnRaster() draws with `pen` on `painter`: a raster engine, antialiasing, a
/// wide opaque pen (a translucent one would darken where the pieces overlap; a pen of 1 px or
/// less takes Qt's own cosmetic path, which is fast already).
bool strokesOnRaster(const QPainter &painter, const Pen &pen);

/// Strokes the polyline `points` (closed: back to the first) with `pen` as QPainter::drawPolyline()
/// or drawPolygon() would, piece by piece. Call only where strokesOnRaster() holds.
void strokeOnRaster(QPainter &painter, const QPolygonF &points, bool closed, const Pen &pen);

} // namespace pkm::drawing
