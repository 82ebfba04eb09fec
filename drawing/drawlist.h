#pragma once
/// The drawing of a scene as placed, styled primitives: what the 2D view, the PNG/SVG/PDF
/// pictures, the GIF frames, the sheet's drawing and the DXF file all show. layoutScene()
/// (scenelayout.h) makes the list once — every size worked out, every label placed — and each
/// medium only renders it: paintDrawList() onto a QPainter, the DXF writer as CAD entities.
///
/// Coordinates are device units (y down) of the ViewMapping the list was laid out with; the
/// DXF writer maps them back to millimetres with the same mapping.
///
/// Some primitives belong to one medium only. Fills, shading and highlights make the screen's
/// picture but are not geometry a CAD program can use; a CAD drawing needs the centre lines and
/// measurable dimension lines that the screen shows through the members themselves.

#include <QColor>
#include <QFont>
#include <QLineF>
#include <QPointF>
#include <QPolygonF>
#include <QSizeF>
#include <QString>

#include <array>
#include <string>
#include <variant>
#include <vector>

namespace pkm::drawing {

/// What a primitive shows; the DXF file has one layer for each.
enum class Layer : unsigned char { Ground, Links, Actuators, Guides, Joints, Dimensions, Text, Paths };

/// Which media show a primitive.
enum class Medium : unsigned char {
    All,
    Screen, ///< fills, shading, highlights, handle rings, text knock-outs
    Cad, ///< centre lines, a dimension line along a member
};

/// Line patterns; each medium has its own way of drawing them (Qt dash patterns in pen widths,
/// DXF line types).
enum class Dash : unsigned char {
    Solid,
    Dashed, ///< reference lines: the legs of an angle that no member shows
    Centre, ///< dash-dot axes of guides and actuators
    Ghost, ///< the members of another assembly mode's pose
};

struct Pen {
    QColor colour;
    double width = 1.0; ///< device units
    Qt::PenCapStyle cap = Qt::FlatCap;
    Dash dash = Dash::Solid;
    Qt::PenJoinStyle join = Qt::BevelJoin;
};

/// Straight lines drawn with one pen (hatching, edges, extension lines).
struct Lines {
    std::vector<QLineF> lines;
    Pen pen;
};

/// A filled rectangle from `a` to `b`, `width` across: a rail, an end stop, a motor body. The
/// screen draws it as one thick flat-capped line; CAD gets its outline.
struct Band {
    QPointF a, b;
    double width = 0.0;
    QColor colour;
};

/// A link from joint to joint, drawn `width` wide. CAD gets its centre line, which is exactly
/// as long as the link, and its two edges outside the pins: they start `trimA` from `a` and
/// end `trimB` before `b`.
struct Member {
    QPointF a, b;
    double width = 0.0;
    QColor colour;
    double trimA = 0.0;
    double trimB = 0.0;
};

/// A polyline or polygon; `fill` with alpha 0 is not filled, a pen of width 0 not stroked.
struct Polygon {
    QPolygonF points;
    bool closed = false;
    Pen pen;
    QColor fill = QColor(0, 0, 0, 0);
};

/// A circle (a pin, a handle ring); fill and pen as for Polygon.
struct Circle {
    QPointF centre;
    double radius = 0.0;
    Pen pen;
    QColor fill = QColor(0, 0, 0, 0);
};

/// The arrowhead every dimension and angle arc ends in.
struct ArrowShape {
    double length = 0.0; ///< device units
    double width = 0.0;
};

/// An arc about `centre` from scene angle `start` (rad, counter-clockwise from +x, y up) over
/// `sweep`, with an arrowhead at its end when `arrow`. Its sweep is the angle it marks: the
/// screen stops the stroke under the arrowhead, CAD keeps the whole arc.
struct Arc {
    QPointF centre;
    double radius = 0.0;
    double start = 0.0;
    double sweep = 0.0;
    Pen pen;
    bool arrow = false;
    ArrowShape head;
};

/// A dimension line whose arrow tips are `from` and `to`, so that the distance between the
/// tips is the dimension. `arrowsInside`: the arrows point out from between the tips;
/// otherwise they point in from tails `tail` long beyond them. `gap` (a length along the
/// line, centred) is left open for the text placed on the line.
struct DimensionLine {
    QPointF from, to;
    bool arrowsInside = true;
    double tail = 0.0;
    double gap = 0.0;
    Pen pen;
    ArrowShape head;
};

/// A text centred on `centre`, turned by `rotationDegrees` (as QPainter::rotate turns it,
/// clockwise on screen), on an opaque knock-out box of `box` in `knockout`. `cad`, when not
/// empty, is what a CAD drawing writes instead (a dimension's measured length, "a = 170.00").
struct Text {
    QPointF centre;
    double rotationDegrees = 0.0;
    QString text;
    QFont font;
    QColor colour;
    QSizeF box;
    QColor knockout;
    std::string cad;
};

using Shape = std::variant<Lines, Band, Member, Polygon, Circle, Arc, DimensionLine, Text>;

struct Primitive {
    Shape shape;
    Layer layer = Layer::Links;
    Medium medium = Medium::All;
};

/// A scene's drawing, in drawing order (later primitives on top).
struct DrawList {
    std::vector<Primitive> items;
    /// Elements of the scene left out because a coordinate is not finite.
    int skipped = 0;

    void add(Shape shape, Layer layer, Medium medium = Medium::All)
    {
        items.push_back({std::move(shape), layer, medium});
    }
};

/// Which media draw primitives of `medium`.
inline bool shownOnScreen(Medium medium)
{
    return medium != Medium::Cad;
}
inline bool shownInCad(Medium medium)
{
    return medium != Medium::Screen;
}

/// An arrowhead's corners: its tip, one barb, the notch between the barbs, the other barb.
std::array<QPointF, 4> arrowCorners(const QPointF &tip, const QPointF &direction, const ArrowShape &head);
/// Where an arc's arrowhead sits (its tip, on the arc's end) and where it points: along the
/// chord of the arc's last arrow length, so that the head lies on the arc.
std::pair<QPointF, QPointF> arcArrow(const Arc &arc);
/// The box holding what `list` shows on the screen (`cad` false) or in CAD (true); texts by
/// their knock-out boxes. Empty when nothing is shown.
QRectF bounds(const DrawList &list, bool cad);

} // namespace pkm::drawing
