#include "linkageview.h"

#include "quantityformat.h"

#include <QApplication>
#include <QCursor>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QResizeEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace pkm {

namespace {
double distanceToSegment(const QPointF &p, const QPointF &a, const QPointF &b)
{
    const QPointF ab = b - a, ap = p - a;
    const double squared = ab.x() * ab.x() + ab.y() * ab.y();
    const double t = squared > 0.0 ? std::clamp((ap.x() * ab.x() + ap.y() * ab.y()) / squared, 0.0, 1.0) : 0.0;
    const QPointF offset = ap - t * ab;
    return std::hypot(offset.x(), offset.y());
}
} // namespace

LinkageView::LinkageView(QWidget *parent)
    : QWidget(parent)
{
    setMouseTracking(true); // hover feedback over handles
    setFocusPolicy(Qt::WheelFocus);
    setAttribute(Qt::WA_OpaquePaintEvent); // the background is painted in full
    setMinimumSize(minimumSizeHint());
}

void LinkageView::setScene(const Scene &scene)
{
    m_scene = scene;
    if (!m_hasScene) {
        m_hasScene = true;
        fitToView();
    } else {
        followMechanism();
    }
    if (m_hoverHandle >= int(m_scene.handles.size()))
        setHoverHandle(-1);
    update();
}

void LinkageView::setMessage(const QString &message)
{
    if (message == m_message)
        return;
    m_message = message;
    update();
}

void LinkageView::setGhostScenes(const QList<Scene> &ghosts, const QStringList &labels)
{
    m_ghosts = ghosts;
    m_ghostLabels = labels;
    m_pressGhost = -1;
    setHoverGhost(-1);
    // The first ghosts are fitted like the first scene, unless the user has moved the view
    // or is dragging: later ones keep the mapping so the drawing does not jump.
    if (!m_ghostsFitted && !m_ghosts.isEmpty() && m_hasScene) {
        m_ghostsFitted = true;
        if (!m_userMoved && m_dragHandle < 0 && !m_panning)
            fitToView();
    }
    if (underMouse() && m_dragHandle < 0 && !m_panning)
        updateHover(mapFromGlobal(QCursor::pos()));
    update();
}

int LinkageView::ghostAt(const QPointF &position) const
{
    if (m_ghosts.isEmpty() || handleAt(position) >= 0)
        return -1;
    int best = -1;
    double bestDistance = hitRadius;
    for (int i = 0; i < int(m_ghosts.size()); ++i) {
        const Scene &ghost = m_ghosts[i];
        std::vector<QPointF> points;
        points.reserve(ghost.joints.size());
        for (const SceneJoint &joint : ghost.joints)
            points.push_back(m_mapping.toDevice(joint.position));
        auto valid = [&points](int joint) { return joint >= 0 && joint < int(points.size()); };
        double nearest = 1e300;
        // What a ghost draws: its moving members and joints (not the ground it shares).
        for (const SceneBar &bar : ghost.bars) {
            if (bar.kind != BarKind::Ground && valid(bar.from) && valid(bar.to))
                nearest = std::min(nearest,
                    distanceToSegment(position, points[std::size_t(bar.from)], points[std::size_t(bar.to)]));
        }
        for (const SceneActuator &actuator : ghost.actuators) {
            if (valid(actuator.from) && valid(actuator.to))
                nearest = std::min(nearest,
                    distanceToSegment(position, points[std::size_t(actuator.from)], points[std::size_t(actuator.to)]));
        }
        for (std::size_t j = 0; j < points.size(); ++j) {
            const JointKind kind = ghost.joints[j].kind;
            if (kind != JointKind::Ground && kind != JointKind::Point)
                nearest = std::min(nearest, std::hypot(points[j].x() - position.x(), points[j].y() - position.y()));
        }
        if (nearest <= bestDistance) {
            best = i;
            bestDistance = nearest;
        }
    }
    return best;
}

QString LinkageView::shownMessage() const
{
    if (m_hoverGhost >= 0 && m_dragHandle < 0)
        return tr("Click to switch to: %1").arg(m_hoverGhost < m_ghostLabels.size() ? m_ghostLabels[m_hoverGhost] : tr("this pose"));
    return m_message;
}

void LinkageView::setSceneStyle(const SceneStyle &style)
{
    m_style = style;
    update();
}

QPointF LinkageView::handlePosition(int handle) const
{
    if (handle < 0 || handle >= int(m_scene.handles.size()))
        return {};
    const int joint = m_scene.handles[std::size_t(handle)].joint;
    if (joint < 0 || joint >= int(m_scene.joints.size()))
        return {};
    return m_mapping.toDevice(m_scene.joints[std::size_t(joint)].position);
}

int LinkageView::handleAt(const QPointF &position) const
{
    int best = -1;
    double bestDistance = hitRadius;
    for (int i = 0; i < int(m_scene.handles.size()); ++i) {
        const int joint = m_scene.handles[std::size_t(i)].joint;
        if (joint < 0 || joint >= int(m_scene.joints.size()))
            continue;
        const QPointF offset = handlePosition(i) - position;
        const double distance = std::hypot(offset.x(), offset.y());
        // On one spot a pose handle wins over an attachment point (a platform point at the
        // platform's reference): moving the mechanism is what a drag there usually means.
        const bool editsDesign = m_scene.handles[std::size_t(i)].editsDesign();
        if (editsDesign ? distance < bestDistance : distance <= bestDistance) {
            best = i;
            bestDistance = distance;
        }
    }
    return best;
}

void LinkageView::paintEvent(QPaintEvent *)
{
    QElapsedTimer timer;
    timer.start();
    if (m_fitPending && !m_userMoved)
        fit(); // visible now, at its size
    QPainter painter(this);
    const QRectF area(rect());
    ScenePainter::paintBackground(painter, area, m_mapping, m_style);
    // Ghosts under the real scene, the hovered one over the others.
    SceneStyle faint = m_style;
    faint.ghostOpacity *= ghostShare();
    for (int i = 0; i < int(m_ghosts.size()); ++i) {
        if (i != m_hoverGhost)
            ScenePainter::paintGhost(painter, m_ghosts[i], m_mapping, faint, false);
    }
    if (m_hoverGhost >= 0 && m_hoverGhost < int(m_ghosts.size()))
        ScenePainter::paintGhost(painter, m_ghosts[m_hoverGhost], m_mapping, m_style, true);
    if (m_hasScene)
        ScenePainter::paint(painter, m_scene, m_mapping, m_style, activeHandle(), m_ghosts,
                            ScenePainter::scaleBarBox(area, m_mapping, m_style, this), &m_labelPlaces);
    ScenePainter::paintScaleBar(painter, area, m_mapping, m_style);
    if (m_hasScene)
        ScenePainter::paintLegend(painter, area, m_scene, m_style);
    const double legend = m_hasScene ? ScenePainter::legendHeight(area, m_scene, m_style, this) : 0.0;
    ScenePainter::paintMessage(painter, area.adjusted(0.0, legend, 0.0, 0.0), shownMessage(), m_style, // below the legend
                               m_hasScene ? ScenePainter::jointBounds(m_scene, m_mapping, m_style) : QRectF(),
                               m_hasScene ? ScenePainter::jointPoints(m_scene, m_mapping) : std::vector<QPointF>());
    painter.end();
    ++m_paintCount;
    m_lastPaintMilliseconds = double(timer.nsecsElapsed()) * 1e-6;
}

void LinkageView::resizeEvent(QResizeEvent *event)
{
    if (!m_userMoved) {
        fit();
    } else if (event->oldSize().isValid()) {
        // Keep what the user zoomed into at the centre.
        const QSizeF delta = QSizeF(event->size() - event->oldSize()) / 2.0;
        m_mapping.origin += QPointF(delta.width(), delta.height());
    }
    QWidget::resizeEvent(event);
}

void LinkageView::wheelEvent(QWheelEvent *event)
{
    // 120 units per notch; touchpads send fractions of it.
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    zoomAbout(event->position(), std::pow(zoomStep, notches));
    event->accept();
}

// -- mouse -------------------------------------------------------------------------------

void LinkageView::mousePressEvent(QMouseEvent *event)
{
    const QPointF position = event->position();
    if (event->button() == Qt::LeftButton && m_dragHandle < 0 && !m_panning) {
        const int handle = handleAt(position);
        if (handle >= 0) {
            m_dragHandle = handle;
            updateCursor();
            update();
            emit dragStarted(handle);
            event->accept();
            return;
        }
    }
    if (m_dragHandle < 0 && !m_panning
        && (event->button() == Qt::LeftButton || event->button() == Qt::MiddleButton
            || event->button() == Qt::RightButton)) {
        // On a ghost a press may be a click: it pans only once the pointer moves off.
        m_pressGhost = event->button() == Qt::LeftButton ? ghostAt(position) : -1;
        m_pressPosition = position;
        m_panning = true;
        m_lastPanPosition = position;
        updateCursor();
        event->accept();
        return;
    }
    QWidget::mousePressEvent(event);
}

void LinkageView::mouseMoveEvent(QMouseEvent *event)
{
    const QPointF position = event->position();
    if (m_dragHandle >= 0) {
        emit handleDragged(m_dragHandle, m_mapping.toScene(position));
        event->accept();
        return;
    }
    if (m_panning) {
        if (m_pressGhost >= 0) {
            const QPointF moved = position - m_pressPosition;
            if (std::hypot(moved.x(), moved.y()) < QApplication::startDragDistance()) {
                event->accept();
                return;
            }
            m_pressGhost = -1; // a drag after all: pan from the press
        }
        const QPointF delta = position - m_lastPanPosition;
        m_lastPanPosition = position;
        if (!delta.isNull()) {
            m_mapping.origin += delta;
            m_userMoved = true;
            update();
        }
        event->accept();
        return;
    }
    updateHover(position);
    QWidget::mouseMoveEvent(event);
}

void LinkageView::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_dragHandle >= 0 && event->button() == Qt::LeftButton) {
        m_dragHandle = -1;
        updateHover(event->position());
        updateCursor();
        keepInSight(); // an attachment point's drag may have taken the mechanism out of sight
        followMechanism(); // a pose's drag too
        update();
        emit dragFinished();
        event->accept();
        return;
    }
    const int clicked = event->button() == Qt::LeftButton ? m_pressGhost : -1;
    if (event->button() == Qt::LeftButton)
        m_pressGhost = -1;
    if (m_panning && !(event->buttons() & (Qt::LeftButton | Qt::MiddleButton | Qt::RightButton))) {
        m_panning = false;
        updateHover(event->position());
        updateCursor();
        event->accept();
        if (clicked >= 0 && clicked < int(m_ghosts.size()))
            emit ghostClicked(clicked);
        return;
    }
    QWidget::mouseReleaseEvent(event);
}

void LinkageView::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && handleAt(event->position()) < 0 && ghostAt(event->position()) < 0) {
        m_panning = false;
        fitToView();
        updateCursor();
        event->accept();
        return;
    }
    // On a handle or a ghost a double-click is a press like any other.
    mousePressEvent(event);
}

void LinkageView::leaveEvent(QEvent *event)
{
    if (m_dragHandle < 0) {
        setHoverHandle(-1);
        setHoverGhost(-1);
    }
    QWidget::leaveEvent(event);
}

void LinkageView::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoomIn();
        break;
    case Qt::Key_Minus:
        zoomOut();
        break;
    case Qt::Key_0:
    case Qt::Key_Home:
        fitToView();
        break;
    default:
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

void LinkageView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        // The hovered handle's hint, "Click to switch to: …" and the scale bar's unit; the
        // scene's own texts come with the next setScene() from the owner.
        updateToolTip();
        update();
    }
    QWidget::changeEvent(event);
}

void LinkageView::updateHover(const QPointF &position)
{
    const int handle = handleAt(position);
    setHoverHandle(handle);
    setHoverGhost(handle < 0 ? ghostAt(position) : -1);
}

void LinkageView::setHoverHandle(int handle)
{
    if (handle == m_hoverHandle)
        return;
    m_hoverHandle = handle;
    updateToolTip();
    updateCursor();
    update();
}

void LinkageView::highlightGhost(int index)
{
    setHoverGhost(index >= 0 && index < int(m_ghosts.size()) ? index : -1);
}

double LinkageView::ghostShare() const
{
    // two ghosts at full strength (a five-bar's modes), five at about half, and fainter still
    // while one of them is hovered
    const double crowd = m_ghosts.size() > 2 ? std::sqrt(2.0 / double(m_ghosts.size())) * 0.8 : 1.0;
    return m_hoverGhost >= 0 ? 0.6 * crowd : crowd;
}

void LinkageView::setHoverGhost(int ghost)
{
    if (ghost == m_hoverGhost)
        return;
    m_hoverGhost = ghost;
    updateToolTip();
    updateCursor();
    update();
}

void LinkageView::updateToolTip()
{
    if (m_hoverHandle >= 0 && m_hoverHandle < int(m_scene.handles.size()))
        setToolTip(coreLabel(m_scene.handles[std::size_t(m_hoverHandle)].hint));
    else if (m_hoverGhost >= 0)
        setToolTip(shownMessage());
    else
        setToolTip(QString());
}

void LinkageView::updateCursor()
{
    if (m_dragHandle >= 0 || m_panning)
        setCursor(Qt::ClosedHandCursor);
    else if (m_hoverHandle >= 0 && m_hoverHandle < int(m_scene.handles.size()))
        setCursor(m_scene.handles[std::size_t(m_hoverHandle)].editsDesign() ? Qt::SizeAllCursor : Qt::OpenHandCursor);
    else if (m_hoverGhost >= 0)
        setCursor(Qt::PointingHandCursor);
    else
        unsetCursor();
}

} // namespace pkm
