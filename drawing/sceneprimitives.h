#pragma once
/// The engineering-drawing elements a scene's drawing is laid out with: the ground symbol, the
/// linear actuator (motor body and lead screw), guides (rails) with their slider carriages,
/// dimension lines and angle arcs. Each adds its primitives to the draw list, tells the label
/// layout what it covers, and queues its text to be placed once all geometry is known.
/// Guides and carriages are in sceneguides.cpp, the rest in sceneprimitives.cpp.
/// Internal to pkm_drawing.

#include "drawlist.h"
#include "scene.h"
#include "scenelabels.h"
#include "scenestyle.h"

#include <QColor>
#include <QLineF>
#include <QPointF>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pkm {

/// A guide (rail) in device units, worked out once per paint. The rail runs past each end of
/// the stroke by half a carriage, so a carriage at the end of its stroke meets the end stop.
struct GuideShape {
    QPointF start; ///< stroke start (SceneGuide::start), device
    QPointF u {1.0, 0.0}; ///< unit direction start → end, device
    QPointF outer {0.0, 1.0}; ///< unit normal to the hatched side, away from the mechanism
    double stroke = 0.0; ///< stroke length, device
    double half = 0.0; ///< half the rail's width
    double overrun = 0.0; ///< rail past each end of the stroke
    double stop = 0.0; ///< thickness of an end stop, along the rail
    double stopHalf = 0.0; ///< half the end stop's extent across the rail
    double hatch = 0.0; ///< length of the hatch strokes beyond the rail's outer edge
    double carriageLength = 0.0;
    double carriageHalfWidth = 0.0;

    /// A point `along` the rail from the stroke start and `across` towards the outer side.
    QPointF at(double along, double across) const { return start + along * u + across * outer; }
    /// The rail's ends, end stops included, along the axis from the stroke start.
    double railBegin() const { return -overrun - stop; }
    double railEnd() const { return stroke + overrun + stop; }
    /// How far from the axis on side `side` (+1 outer, −1 inner) the guide's drawing reaches.
    double reach(double side) const { return side > 0.0 ? std::max(half + hatch, stopHalf) : stopHalf; }
};

/// Per joint: the guide a slider or point joint lies on (within a quarter of the rail's width
/// of its axis, and no farther past the stroke than the rail runs), or −1. Scene units, so
/// the answer does not depend on the zoom.
std::vector<int> jointsOnGuides(const Scene &scene);
/// The guides of `scene` in device units (`points`: its joints, device; `jointGuide` from
/// jointsOnGuides()). The hatching goes on the side away from the members leaving the
/// guide's joints (with none, away from the other joints).
std::vector<GuideShape> guideShapes(const Scene &scene, const std::vector<QPointF> &points,
    const std::vector<int> &jointGuide, const ViewMapping &mapping, const SceneStyle &style);

/// What every layout step needs: the draw list it adds to, the scene with its joints in device
/// units, the mapping and style, and the label layout that learns what the labels must keep off.
struct SceneCanvas {
    drawing::DrawList &out;
    const Scene &scene;
    const ViewMapping &mapping;
    const SceneStyle &style;
    const std::vector<QPointF> &points; ///< joint positions, device; not finite: not shown
    SceneLabels &labels;
    const std::vector<GuideShape> &guides; ///< scene.guides in device units
    const std::vector<int> &jointGuide; ///< per joint: the guide it lies on, or −1

    double px() const { return style.pixelSize; } ///< device units per style pixel
    /// A joint that is shown: an index into the scene at a finite position.
    bool valid(int joint) const
    {
        return joint >= 0 && joint < int(points.size()) && std::isfinite(point(joint).x())
            && std::isfinite(point(joint).y());
    }
    const QPointF &point(int joint) const { return points[std::size_t(joint)]; }
    /// The guide slider joint `joint` rides on, or null.
    const GuideShape *carriageGuide(int joint) const;

    void lines(drawing::Layer layer, const drawing::Pen &pen, std::vector<QLineF> lines,
        drawing::Medium medium = drawing::Medium::All) const
    {
        out.add(drawing::Lines {std::move(lines), pen}, layer, medium);
    }
    void line(drawing::Layer layer, const drawing::Pen &pen, const QPointF &a, const QPointF &b,
        drawing::Medium medium = drawing::Medium::All) const
    {
        lines(layer, pen, {QLineF(a, b)}, medium);
    }
    void band(drawing::Layer layer, const QPointF &a, const QPointF &b, double width, const QColor &colour,
        drawing::Medium medium = drawing::Medium::All) const
    {
        out.add(drawing::Band {a, b, width, colour}, layer, medium);
    }
};

/// A pen of `width` device units.
inline drawing::Pen pen(const QColor &colour, double width, Qt::PenCapStyle cap = Qt::FlatCap,
    drawing::Dash dash = drawing::Dash::Solid)
{
    return {colour, width, cap, dash};
}

/// The ground symbol under the pivot at device point `pivot`.
void drawGround(const SceneCanvas &canvas, const QPointF &pivot);
/// Guide `guide` of the scene, a ground-fixed rail: light steel fill, outline, end stops,
/// hatching on its outer side and a dash-dot axis; queues its label beside it.
void drawGuide(const SceneCanvas &canvas, int guide);
/// The carriage block of a slider on `shape`, centred at device point `centre`, along the rail.
void drawCarriage(const SceneCanvas &canvas, const GuideShape &shape, const QPointF &centre);
/// Motor body at `actuator.from`, lead screw on to `actuator.to`.
void drawActuator(const SceneCanvas &canvas, const SceneActuator &actuator);
/// A dimension line with extension lines, arrowheads and its text on the line; a dimension
/// without offset only queues its text beside the member.
void drawDimension(const SceneCanvas &canvas, const SceneDimension &dimension);
/// An angle arc with an arrowhead at its end, and dashed legs where no member shows them.
void drawAngle(const SceneCanvas &canvas, const SceneAngle &angle);

} // namespace pkm
