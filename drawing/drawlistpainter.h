#pragma once
/// Renders a DrawList onto any QPainter — a widget, a QImage, a QSvgGenerator, a QPdfWriter:
/// the screen's medium. It draws what the list holds and decides nothing about where.

#include "drawlist.h"

class QPainter;

namespace pkm::drawing {

/// Draws the primitives the screen shows (Medium::All and Medium::Screen), in order.
void paintDrawList(QPainter &painter, const DrawList &list);

} // namespace pkm::drawing
