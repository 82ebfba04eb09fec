#pragma once
/// The names of a 3D model's points ("A", "Z₁", "T") drawn over the rendered model: in the 3D
/// view, in its saved pictures and in `pkm render --view 3d`, by one function, so that all
/// three put the same name at the same place. Each name sits up and to the right of its point
/// on a light knock-out, moved to another corner when it would cover a name already placed;
/// a point behind the camera or outside the picture is not named, nor are the corners of a
/// platform drawn too small for a name at each.

#include "camera3d.h"
#include "scene3d.h"

#include <QFont>

#include <vector>

class QPainter;

namespace pkm {

/// Draws `labels` over a picture that `camera` (its viewport the picture's size, in the
/// painter's units) rendered.
void paintLabels3D(QPainter &painter, const std::vector<Label3D> &labels, const Camera3D &camera, const QFont &font);

/// The font of the names: the given one, bold and a little larger, as the 2D view's joint names.
QFont labelFont3D(const QFont &base);

} // namespace pkm
