#pragma once
/// Fonts of the plots: a base font at a size in points, for the classroom projector, times the
/// text size the user chose (textscale.h).

#include "textscale.h"

#include <QFont>

namespace pkm {

inline QFont fontOf(const QFont &base, double points, bool bold = false)
{
    QFont font(base);
    font.setPointSizeF(points * textscale::factor());
    font.setBold(bold);
    return font;
}

} // namespace pkm
