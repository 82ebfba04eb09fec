#pragma once
/// Label layout of a scene's drawing: while the geometry is laid out, SceneLabels learns what
/// each label must keep off (obstacles) and what leaves each joint (rays); once all of it is
/// known it places the labels (scenelabelplaces.cpp) where they cover nothing or, in a crowded
/// pose, least: never another label, a bar or a pivot before a thin line. An angle's label
/// pushed away from its arc gets a leader to it; a bar's or an angle's name that could only
/// cover another label is left out. The labels go last into the draw list, so no line crosses
/// a label, and every medium shows them where they were placed here. Internal to pkm_drawing.

#include "drawlist.h"
#include "scene.h"
#include "scenestyle.h"

#include <QColor>
#include <QFont>
#include <QFontMetricsF>
#include <QLineF>
#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QString>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

class QPaintDevice;

namespace pkm {

namespace detail {

/// A convex quadrilateral in device units: drawn geometry or a placed label.
using Quad = std::array<QPointF, 4>;

/// The outline of a line from `a` to `b` drawn `2 × halfWidth` wide, caps included.
Quad segmentQuad(const QPointF &a, const QPointF &b, double halfWidth);
/// A `size` box about `centre`, turned as QPainter::rotate(rotationDegrees) turns it.
Quad boxQuad(const QPointF &centre, const QSizeF &size, double rotationDegrees);
/// Separating-axis test of two convex quads.
bool overlap(const Quad &a, const Quad &b);
/// How long a stretch of the line from `a` to `b`, `2 × halfWidth` wide, lies in the
/// rectangle `box`; a point with a width (a pin's ring) as long as it is wide.
double coveredLength(const Quad &box, const QPointF &a, const QPointF &b, double halfWidth);

/// What a label costs that covers another (SceneLabels::collisions()): more than all the
/// lines it could hide.
inline constexpr double coversALabel = 100.0;

/// How much room (style pixels on each side) a label's first-choice place must have to take
/// it back from the place it kept from the frame before: a place freed by a pixel would pull
/// it back and forth.
inline constexpr double keptMargin = 6.0;

/// The application's font at `pixels` device units, so labels match the rest of the UI.
QFont labelFont(double pixels, bool bold);

} // namespace detail

/// Text is collected while the geometry is laid out and added last, so no line crosses a label.
struct SceneLabel {
    QPointF centre;
    double rotationDegrees = 0.0;
    QString text;
    bool joint = false; ///< bold joint name
    QColor colour;
    drawing::Layer layer = drawing::Layer::Text;
    std::string cad; ///< what a CAD drawing writes instead (drawing::Text::cad)
    /// Where a CAD drawing writes it when that is not where the screen shows it: a dimension's
    /// text on its dimension line, which the screen moved off its member with a leader.
    std::optional<std::pair<QPointF, double>> cadPlace;
    /// What it names, device (its joint; else its first, preferred place): a moving drawing
    /// keeps a label where it stood relative to this (SceneLabels::setPrevious()).
    std::optional<QPointF> anchor;
};

/// Labels placed once all geometry is known, so they can avoid it.
struct PendingAngleLabel {
    int vertex = 0;
    double radius = 0.0; ///< device
    double start = 0.0;
    double sweep = 0.0;
    QString text;
};
/// A label that goes at the first free one of some candidate centres (the first when none is).
struct PendingFreeLabel {
    SceneLabel label; ///< its centre is ignored
    std::vector<QPointF> candidates;
};
/// A guide's name: beside the rail, clear of its hatching, upright.
struct PendingGuideLabel {
    QPointF start; ///< the rail's ends on its axis, device
    QPointF end;
    QPointF outer; ///< unit normal to the hatched side
    double outerReach = 0.0; ///< how far the drawing reaches from the axis on the hatched side
    double innerReach = 0.0; ///< and on the other
    QString text;
    QColor colour;
};
struct PendingMemberLabel {
    int from = 0;
    int to = 0;
    QString text;
    QColor colour;
    bool preferReadingUp = true; ///< dimension text: above the member as read
    std::string cad; ///< a dimension's text in a CAD drawing
};

class SceneLabels
{
public:
    /// `points` are the scene's joints in device units; scene, points, mapping and style must
    /// outlive this object. `device` sets the font metrics (a printer's differ from a screen's).
    SceneLabels(const Scene &scene, const std::vector<QPointF> &points, const ViewMapping &mapping,
        const SceneStyle &style, const QPaintDevice *device);

    /// Where labels may stand (device); empty: anywhere. A place past it is never free.
    void setRoom(const QRectF &room) { m_room = room; }
    /// Where the labels stood in the frame before relative to what they name, by text (null:
    /// nowhere): of the places as good as the best, each label takes the one nearest its last.
    void setPrevious(const std::vector<std::pair<QString, QPointF>> *previous) { m_previous = previous; }
    /// The placed labels' centres relative to what they name, by text, for the next frame's
    /// setPrevious().
    std::vector<std::pair<QString, QPointF>> places() const;

    // -- while the geometry is laid out ---------------------------------------------------
    /// Something leaves `joint` towards `towards` (device) for `reach` device units: joint
    /// names go into the widest gap between such rays.
    void addRay(int joint, const QPointF &towards, double reach);
    /// A drawn line from `a` to `b`, `2 × halfWidth` wide, that no label may cover.
    void addObstacle(const QPointF &a, const QPointF &b, double halfWidth, bool faint = false);
    void addObstacle(const detail::Quad &quad);
    void addMemberLabel(const PendingMemberLabel &label);
    void addAngleLabel(const PendingAngleLabel &label);
    void addGuideLabel(const PendingGuideLabel &label);
    /// Placed first of all, before the other pending labels.
    void addFreeLabel(const PendingFreeLabel &label);
    /// A label whose place is fixed (a dimension's text on its line); it becomes an obstacle.
    void place(const SceneLabel &label);
    /// Drops the pending labels of actuators whose joints a dimension already names.
    void dropDimensionedActuatorLabels();
    /// How far the farthest-reaching thing drawn so far leaves `joint` along the unit device
    /// `direction` (0: nothing does).
    double memberReach(int joint, const QPointF &direction) const;

    /// The size of a label's knock-out box.
    QSizeF textSize(const QString &text, bool joint = false) const;

    // -- once all geometry is known -------------------------------------------------------
    /// Places the pending labels, most constrained first.
    void placeAll();
    /// Adds the placed labels to `list`, each on an opaque knock-out box.
    void addTo(drawing::DrawList &list) const;

private:
    /// A direction leaving a joint (device, unit): joint names go into the widest gap between them.
    struct Ray {
        QPointF direction;
        double reach = 0.0;
    };

    /// A joint that is shown: an index at a finite point.
    bool valid(int joint) const
    {
        return joint >= 0 && joint < int(m_points.size()) && std::isfinite(point(joint).x())
            && std::isfinite(point(joint).y());
    }
    const QPointF &point(int joint) const { return m_points[std::size_t(joint)]; }
    /// How much `box` would cover: 100 for each label and
    /// `perLine` × (½ + the area hidden / 80 px²) for each line; the sum stops once it reaches
    /// `enough`.
    double collisions(const detail::Quad &box, double enough, double perLine = 1.0) const;
    /// Whether `box` lies on an angle label's leader.
    bool onALeader(const detail::Quad &box) const;
    /// Whether `box` covers nothing at all (quicker than collisions()).
    /// Nothing under `box`; `faint`: the faint lines (ghosts) count too.
    bool isFree(const detail::Quad &box, bool faint = false) const;
    /// The number of thin lines (hatching, extension and dimension lines) and outlines `box`
    /// covers; 100 or more when it covers a label, a pivot or a bar.
    double thinLinesOnly(const detail::Quad &box) const;
    /// Places `label` at the first free candidate centre or, when none is free, at the one
    /// that covers least, unless that covers `leaveOutAt` or more (collisions()); true when it
    /// is free. Of the first `near` candidates, the one that covers fewest thin lines
    /// (thinLinesOnly(), fewer than `nearEnough`) is taken rather than a later free one.
    /// `leaderFor` gives the leader a label at a candidate would need to what it names (none
    /// where it is next to it): a free place whose leader crosses a bar, a pivot or a label
    /// is passed over while another free one is left, and the leader is drawn with the label.
    /// What a leader may cross: the lines that end at the joint it names (`from` = `to`), or
    /// the bar it names (from `from` to `to`); a dimension's leader may cross bars too, as a
    /// callout on a drawing does.
    struct Leader {
        QLineF line;
        QPointF from, to;
        bool acrossBars = false;
        bool nearerAnother = false; ///< the name is nearer another joint: taken only when no other is free
    };
    using LeaderFor = std::function<std::optional<Leader>(std::size_t candidate)>;
    bool placeFirstFree(SceneLabel label, const std::vector<QPointF> &candidates,
        double leaveOutAt = std::numeric_limits<double>::infinity(), std::size_t near = 0, double nearEnough = 0.0,
        const LeaderFor &leaderFor = {});
    /// A leader from `anchor` to the edge of a `size` box about `centre`; none when the box is
    /// within `slack` of the anchor.
    static std::optional<QLineF> leaderToBox(const QPointF &anchor, const QPointF &centre, const QSizeF &size, double slack);
    /// Whether `leader` crosses nothing that matters: no label, no outline and no bar or pivot
    /// (thin lines may cross it), apart from what it names.
    bool leaderIsClear(const Leader &leader) const;
    double memberHalfWidth(int from, int to, double fraction) const;
    void placeMemberLabels(bool dimensions);
    /// The middle of the joints shown (device).
    QPointF shownCentroid() const;
    /// The side of its bar a bar's name tries first (±1 along screenLeft() of from→to): outward.
    double barNameSide(const PendingMemberLabel &pending, const QPointF &centroid) const;
    /// A member label's centre `extra` beyond its place beside the member at `fraction` along
    /// it, on the side of unit `normal`; `extent`: the label's half extent along `normal`.
    QPointF memberLabelCentre(const PendingMemberLabel &pending, double fraction, const QPointF &normal, double extent,
        double extra) const;
    /// Fills m_barNamePlaces.
    void reserveBarNames();
    /// A dimension's text along its member (`beside`: the candidate centres there) or, where
    /// that covers a bar, upright away from it with a leader.
    void placeDimensionText(const PendingMemberLabel &pending, const SceneLabel &label, const std::vector<QPointF> &beside);
    /// Whether a bar other than the member from `from` to `to` passes nearer `centre`.
    bool nearerAnotherBar(const QPointF &centre, int from, int to) const;
    void placeAngleLabels();
    /// Whether a label of `size` at `centre` lies nearer another named joint than `vertex`, the
    /// joint whose angle it states: there it reads as that joint's (θ₁ under E).
    bool nearerAnotherJoint(const QPointF &centre, const QSizeF &size, int vertex) const;
    /// A line from the arc of `pending` to the edge of its label (`size`) at `centre`; none
    /// when the label is next to the arc.
    std::optional<QLineF> leaderTo(const PendingAngleLabel &pending, const QPointF &centre, const QSizeF &size) const;
    void placeGuideLabels();
    void placeJointLabels();
    /// The angular gaps (width, middle) between what leaves `joint`, widest first.
    std::vector<std::pair<double, double>> gapsAround(std::size_t joint) const;
    /// The directions a joint's name is tried in first: in the gap between what leaves the
    /// joint that faces outward of the linkage, the most outward first; none in its middle.
    std::vector<double> outwardNameAngles(std::size_t joint) const;
    /// The middle of the named joints that are shown (device), and how many they are.
    QPointF namedMiddle(int *count) const;
    /// The centre of a joint's name of `size` in direction `angle`, `extra` beyond the ring.
    QPointF jointNameCentre(std::size_t joint, const QSizeF &size, double angle, double extra) const;
    /// Where a ground pivot's name goes as a drawing puts it: beside its symbol on the side
    /// away from the linkage, under it, beside it on the other side.
    std::array<QPointF, 3> groundNamePlaces(std::size_t joint, const QSizeF &size) const;
    /// Fills m_reserved.
    void reserveJointNames();
    /// Fills m_jointNames: each shown joint's name as drawn. Joints drawn on one spot share one
    /// name ("Oₚ = P₁"); the corners of a platform of three or more named corners drawn too
    /// small for a name beside each (a 3-leg platform with the whole range of motion in sight)
    /// are left out.
    void settleJointNames();
    /// Whether joint `joint` has a name to place (settleJointNames()).
    bool named(std::size_t joint) const { return joint < m_jointNames.size() && !m_jointNames[joint].isEmpty(); }
    /// Where a label of `text` that names what is now at `anchor` stood in the frame before
    /// (setPrevious()), moved with it; none if it was not drawn.
    std::optional<QPointF> lastPlace(const QString &text, const QPointF &anchor) const;

    const Scene &m_scene;
    const std::vector<QPointF> &m_points; ///< joint positions, device
    const ViewMapping &m_mapping;
    const SceneStyle &m_style;
    const double m_px;
    QFont m_font;
    QFont m_jointFont;
    QFontMetricsF m_metrics;
    QFontMetricsF m_jointMetrics;
    std::vector<std::vector<Ray>> m_rays; ///< per joint: what leaves it
    /// Something drawn that labels should not cover: a line (its ends and half width known) or
    /// an outline.
    struct Obstacle {
        detail::Quad quad;
        QPointF a, b;
        double halfWidth = 0.0;
        bool line = false;
        /// A line drawn faintly under the scene (another mode's ghost): of a label's nearest
        /// places the first clear of these too is taken; else they count for nothing, so that
        /// a name is never moved far or left out for them (the 3-RP̲R's q₁ and q₃ vanished
        /// among five ghosts when they counted as thin lines).
        bool faint = false;
        /// An angle label's leader (faint too): a bar's name beside it reads as what the
        /// leader points to, so among its nearest places it takes one clear of the leader,
        /// even one that covers a thin line.
        bool leader = false;
    };
    std::vector<Obstacle> m_obstacles;
    std::vector<detail::Quad> m_labelBoxes; ///< the labels placed so far
    /// the joints' names' first places, kept free while the other labels are placed
    std::vector<detail::Quad> m_reserved;
    /// the bars' names' first places, which an angle label's leader keeps off where it can
    std::vector<detail::Quad> m_barNamePlaces;
    std::vector<QString> m_jointNames; ///< per joint: its name as drawn, empty if none (settleJointNames())
    std::vector<QPointF> m_crowdedCorners; ///< the corners of a platform whose corners are unnamed
    QRectF m_crowdedPlatform; ///< and their bounds
    QRectF m_room; ///< where labels may stand; empty: anywhere
    const std::vector<std::pair<QString, QPointF>> *m_previous = nullptr; ///< the frame before
    /// Whether `box` lies past the room's edge.
    bool outside(const detail::Quad &box) const
    {
        return !m_room.isEmpty()
            && std::any_of(box.begin(), box.end(), [this](const QPointF &corner) { return !m_room.contains(corner); });
    }
    std::vector<QLineF> m_leaders; ///< from angle labels placed away to their arcs
    /// from joint and bar names placed away to their joint or bar, in the name's colour; on
    /// screen only where the CAD text stays on its member
    struct NameLeader {
        QLineF line;
        QColor colour;
        bool screenOnly = false;
    };
    std::vector<NameLeader> m_nameLeaders;
    std::vector<PendingMemberLabel> m_memberLabels;
    std::vector<PendingAngleLabel> m_angleLabels;
    std::vector<PendingGuideLabel> m_guideLabels;
    std::vector<PendingFreeLabel> m_freeLabels;
    std::vector<SceneLabel> m_labels;
};

} // namespace pkm
