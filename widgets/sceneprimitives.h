#pragma once
/// The engineering-drawing primitives ScenePainter draws a scene with: the ground symbol, the
/// linear actuator (motor body and lead screw), dimension lines and angle arcs with their
/// arrowheads. Each one tells the canvas's label layout what it covers, and queues its text
/// to be placed once all geometry is known. Internal to pkm_widgets.

#include "scene.h"
#include "scenelabels.h"
#include "scenepainter.h"

#include <QColor>
#include <QPointF>

#include <vector>

class QPainter;

namespace pkm {

/// What every drawing step needs: the painter, the scene with its joints in device units, the
/// mapping and style, and the label layout that learns what the labels must keep off.
struct SceneCanvas {
    QPainter &painter;
    const Scene &scene;
    const ViewMapping &mapping;
    const SceneStyle &style;
    const std::vector<QPointF> &points; ///< joint positions, device
    SceneLabels &labels;

    double px() const { return style.pixelSize; } ///< device units per style pixel
    bool valid(int joint) const { return joint >= 0 && joint < int(points.size()); }
    const QPointF &point(int joint) const { return points[std::size_t(joint)]; }
    void stroke(const QColor &colour, double width, Qt::PenCapStyle cap = Qt::FlatCap) const;
};

/// The ground symbol under the pivot at device point `pivot`.
void drawGround(const SceneCanvas &canvas, const QPointF &pivot);
/// Motor body at `actuator.from`, lead screw on to `actuator.to`.
void drawActuator(const SceneCanvas &canvas, const SceneActuator &actuator);
/// A dimension line with extension lines, arrowheads and its text on the line; a dimension
/// without offset only queues its text beside the member.
void drawDimension(const SceneCanvas &canvas, const SceneDimension &dimension);
/// An angle arc with an arrowhead at its end, and dashed legs where no member shows them.
void drawAngle(const SceneCanvas &canvas, const SceneAngle &angle);
/// A filled arrowhead with its tip at `tip`, pointing along `direction` (device).
void drawArrow(const SceneCanvas &canvas, const QPointF &tip, const QPointF &direction, const QColor &colour);

} // namespace pkm
