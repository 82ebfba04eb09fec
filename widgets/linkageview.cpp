#include "linkageview.h"

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
constexpr double fitMargin = 24.0; ///< style px between the extent and the widget's edge
constexpr double minimumScale = 1e-3; ///< px per mm: a 100 m mechanism still fits a screen
constexpr double maximumScale = 1e3; ///< px per mm: a micrometre is a millimetre on screen
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
        if (distance <= bestDistance) {
            best = i;
            bestDistance = distance;
        }
    }
    return best;
}

// -- export ------------------------------------------------------------------------------

ViewMapping LinkageView::fittedMapping(const Scene &scene, const QRectF &target, const SceneStyle &style)
{
    return ViewMapping::fit(scene.extent, target, fitMargin * style.pixelSize);
}

void LinkageView::renderScene(QPainter &painter, const QRectF &target, const Scene &scene, const SceneStyle &style)
{
    SceneStyle exported = style;
    exported.showHandles = false; // rings are an affordance of the screen, not of a drawing
    const ViewMapping mapping = fittedMapping(scene, target, exported);
    painter.save();
    painter.setClipRect(target, Qt::IntersectClip);
    ScenePainter::paintBackground(painter, target, mapping, exported);
    ScenePainter::paint(painter, scene, mapping, exported);
    ScenePainter::paintScaleBar(painter, target, mapping, exported);
    painter.restore();
}

void LinkageView::renderTo(QPainter &painter, const QRectF &target) const
{
    renderScene(painter, target, m_scene, m_style);
}

// -- view --------------------------------------------------------------------------------

void LinkageView::fitToView()
{
    m_mapping = fittedMapping(m_scene, QRectF(rect()), m_style);
    m_userMoved = false;
    update();
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

void LinkageView::paintEvent(QPaintEvent *)
{
    QElapsedTimer timer;
    timer.start();
    QPainter painter(this);
    const QRectF area(rect());
    ScenePainter::paintBackground(painter, area, m_mapping, m_style);
    if (m_hasScene)
        ScenePainter::paint(painter, m_scene, m_mapping, m_style, activeHandle());
    ScenePainter::paintScaleBar(painter, area, m_mapping, m_style);
    ScenePainter::paintMessage(painter, area, m_message, m_style);
    painter.end();
    ++m_paintCount;
    m_lastPaintMilliseconds = double(timer.nsecsElapsed()) * 1e-6;
}

void LinkageView::resizeEvent(QResizeEvent *event)
{
    if (!m_userMoved) {
        fitToView();
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
    setHoverHandle(handleAt(position));
    QWidget::mouseMoveEvent(event);
}

void LinkageView::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_dragHandle >= 0 && event->button() == Qt::LeftButton) {
        m_dragHandle = -1;
        setHoverHandle(handleAt(event->position()));
        updateCursor();
        update();
        emit dragFinished();
        event->accept();
        return;
    }
    if (m_panning && !(event->buttons() & (Qt::LeftButton | Qt::MiddleButton | Qt::RightButton))) {
        m_panning = false;
        setHoverHandle(handleAt(event->position()));
        updateCursor();
        event->accept();
        return;
    }
    QWidget::mouseReleaseEvent(event);
}

void LinkageView::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && handleAt(event->position()) < 0) {
        m_panning = false;
        fitToView();
        updateCursor();
        event->accept();
        return;
    }
    // On a handle a double-click is a press like any other.
    mousePressEvent(event);
}

void LinkageView::leaveEvent(QEvent *event)
{
    if (m_dragHandle < 0)
        setHoverHandle(-1);
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

void LinkageView::setHoverHandle(int handle)
{
    if (handle == m_hoverHandle)
        return;
    m_hoverHandle = handle;
    setToolTip(handle >= 0 ? QString::fromStdString(m_scene.handles[std::size_t(handle)].hint) : QString());
    updateCursor();
    update();
}

void LinkageView::updateCursor()
{
    if (m_dragHandle >= 0 || m_panning)
        setCursor(Qt::ClosedHandCursor);
    else if (m_hoverHandle >= 0)
        setCursor(Qt::OpenHandCursor);
    else
        unsetCursor();
}

} // namespace pkm
