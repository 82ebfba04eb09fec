#include "linkageview.h"

// How the view frames the scene: Fit, the widening that keeps a moving mechanism in sight,
// zoom, and the mappings the screen and the pictures share.

#include <QPainter>

#include <algorithm>

namespace pkm {

namespace {
constexpr double fitMargin = 24.0; ///< style px between the extent and the widget's edge
constexpr double minimumScale = 1e-3; ///< px per mm: a 100 m mechanism still fits a screen
constexpr double maximumScale = 1e3; ///< px per mm: a micrometre is a millimetre on screen
} // namespace

// -- export ------------------------------------------------------------------------------

QRectF LinkageView::belowLegend(const QRectF &area, const Scene &scene, const SceneStyle &style)
{
    // the fit's own margin already keeps the top free in part
    const double legend = ScenePainter::legendHeight(area, scene, style, nullptr) - fitMargin * style.pixelSize;
    QRectF below = area;
    if (legend > 0.0)
        below.setTop(area.top() + std::min(legend, 0.4 * area.height()));
    return below;
}

ViewMapping LinkageView::fittedMapping(const Scene &scene, const QRectF &target, const SceneStyle &style)
{
    return ViewMapping::fit(scene.extent, belowLegend(target, scene, style), fitMargin * style.pixelSize);
}

ViewMapping LinkageView::screenMapping(
    const Scene &scene, const Eigen::AlignedBox3d &extent, const QRectF &area, const SceneStyle &style)
{
    // above the scale bar (the fit's margin covers part of it), and with every label whole
    QRectF room = belowLegend(area, scene, style), labelRoom = room;
    const double bar = std::min(ScenePainter::scaleBarHeight(style, nullptr), 0.25 * room.height());
    room.setBottom(room.bottom() - std::max(0.0, bar - fitMargin * style.pixelSize));
    labelRoom.setBottom(labelRoom.bottom() - bar);
    return ScenePainter::fitWithLabels(scene, extent, room, labelRoom, fitMargin * style.pixelSize, style);
}

void LinkageView::renderScene(QPainter &painter, const QRectF &target, const Scene &scene, const SceneStyle &style)
{
    SceneStyle exported = style;
    exported.showHandles = false; // rings are an affordance of the screen, not of a drawing
    ScenePainter::paintPicture(painter, target, scene, fittedMapping(scene, target, exported), exported);
}

void LinkageView::renderTo(QPainter &painter, const QRectF &target) const
{
    renderScene(painter, target, m_scene, m_style);
}

// -- view --------------------------------------------------------------------------------

Eigen::AlignedBox3d LinkageView::withGhostJoints(Eigen::AlignedBox3d box) const
{
    // The ghosts' joints where they are now, so they can be clicked — not their points of
    // interest: a ghost four-bar's instant centre lies wherever AB and DC meet, far out when
    // they are nearly parallel, and left the linkage small in a corner.
    if (box.isEmpty())
        return box;
    for (const Scene &ghost : m_ghosts) {
        for (const SceneJoint &joint : ghost.joints) {
            if (joint.kind != JointKind::Point && joint.position.allFinite())
                box.extend(joint.position);
        }
    }
    return box;
}

bool LinkageView::fitsPose() const
{
    // Worth it only where the range of motion is well beyond the pose: a 3-R̲RR's reach is
    // about its own size, and the pose's margin would make its fit smaller, not larger.
    const Eigen::AlignedBox3d &pose = m_scene.poseExtent, &whole = m_scene.extent;
    if (pose.isEmpty() || whole.isEmpty())
        return !pose.isEmpty();
    return pose.sizes().head<2>().prod() < 0.5 * whole.sizes().head<2>().prod();
}

Eigen::AlignedBox3d LinkageView::inSightBox() const
{
    return fitsPose() ? m_scene.poseExtent : m_scene.extent;
}

void LinkageView::fitToView()
{
    // The pose where the scene gives one (a mechanism whose range of motion dwarfs it), else
    // the whole range of motion.
    m_fitBox = withGhostJoints(inSightBox());
    m_userMoved = false;
    fit();
}

void LinkageView::fit()
{
    // A hidden view (the window being built, its docks resized one after another at start-up)
    // gets the plain fit; the fit that keeps every label whole runs once it is painted.
    m_fitPending = !isVisible();
    m_mapping = m_fitPending ? ViewMapping::fit(m_fitBox, QRectF(rect()), fitMargin * m_style.pixelSize)
                             : screenMapping(m_scene, m_fitBox, QRectF(rect()), m_style);
    update();
}

void LinkageView::followMechanism()
{
    // Only a view fitted to a pose widens, and not under the user's hand: a zoom or pan is
    // theirs, and a drag would see its handle jump away from the pointer.
    if (!m_hasScene || m_userMoved || m_fitPending || m_dragHandle >= 0 || m_panning || m_fitBox.isEmpty())
        return;
    Eigen::AlignedBox3d whole = withGhostJoints(m_scene.extent);
    whole.extend(inSightBox());
    if (whole.isEmpty() || m_fitBox.contains(whole))
        return;
    const QRectF drawn = ScenePainter::jointBounds(m_scene, m_mapping, m_style);
    const QRectF sight = QRectF(rect()); // jointBounds() takes in the pivots and a label's height
    if (drawn.isEmpty() || sight.contains(drawn))
        return;
    // A quarter more than the poses seen so far, in a few steps at most: once the box nears
    // the range of motion, the whole of it, after which the view no longer moves. The poses
    // are the mechanism's own, as the first fit's: with the other modes' ghosts, whose elbows
    // stand out far, the five-bar's first step took the whole range of its cranks' circles.
    Eigen::AlignedBox3d box = m_fitBox;
    box.extend(inSightBox());
    const Eigen::Vector3d half = 0.625 * box.sizes();
    box = Eigen::AlignedBox3d(box.center() - half, box.center() + half).intersection(whole);
    const Eigen::Vector3d share = box.sizes().cwiseQuotient(whole.sizes().cwiseMax(1e-9));
    m_fitBox = share.head<2>().minCoeff() > 0.75 ? whole : box;
    fit();
}

void LinkageView::keepInSight()
{
    // After a design edit: refit only when the mechanism leaves the view or shrinks to a small
    // part of it — a fixed scale while stepping a dimension shows it growing or shrinking. Not
    // under a drag (an attachment point's), whose handle would jump away from the pointer.
    const Eigen::AlignedBox3d extent = inSightBox();
    if (extent.isEmpty() || m_dragHandle >= 0)
        return;
    const QRectF box = QRectF(m_mapping.toDevice(Eigen::Vector2d(extent.min().head<2>())),
                              m_mapping.toDevice(Eigen::Vector2d(extent.max().head<2>())))
                           .normalized();
    const QRectF area = QRectF(rect());
    // A pose's box has a margin for moves: what must stay in sight is the mechanism itself.
    const bool outside = !area.contains(fitsPose() ? ScenePainter::jointBounds(m_scene, m_mapping, m_style) : box);
    const bool tiny = box.width() < 0.3 * area.width() && box.height() < 0.3 * area.height();
    if (outside || tiny)
        fitToView();
}

void LinkageView::zoomIn()
{
    zoomAbout(QRectF(rect()).center(), zoomStep);
}

void LinkageView::zoomOut()
{
    zoomAbout(QRectF(rect()).center(), 1.0 / zoomStep);
}

void LinkageView::zoomAbout(const QPointF &anchor, double factor)
{
    const double scale = std::clamp(m_mapping.scale * factor, minimumScale, maximumScale);
    if (scale == m_mapping.scale)
        return;
    const Eigen::Vector2d fixed = m_mapping.toScene(anchor);
    m_mapping.scale = scale;
    m_mapping.origin = anchor - QPointF(scale * fixed.x(), -scale * fixed.y());
    m_userMoved = true;
    update();
}

} // namespace pkm
