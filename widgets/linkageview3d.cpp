#include "linkageview3d.h"

#include "canvas3d.h"
#include "labels3d.h"

#include <QElapsedTimer>
#include <QEvent>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLPaintDevice>
#include <QFontInfo>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace pkm {

LinkageView3D::LinkageView3D(QWidget *parent)
    : QWidget(parent)
{
    setFocusPolicy(Qt::WheelFocus);
    m_refine.setSingleShot(true);
    m_refine.setInterval(150);
    connect(&m_refine, &QTimer::timeout, this, [this] {
        m_refining = true;
        if (m_canvas)
            m_canvas->requestFrame();
    });

    m_unavailableLabel = new QLabel(this);
    m_unavailableLabel->setWordWrap(true);
    m_unavailableLabel->setAlignment(Qt::AlignCenter);
    m_unavailableLabel->setMargin(24);
    m_unavailableLabel->setAutoFillBackground(true);
    QPalette palette = m_unavailableLabel->palette();
    palette.setColor(QPalette::Window, Renderer3D::backgroundColour());
    palette.setColor(QPalette::WindowText, QColor(0x1c, 0x20, 0x26));
    m_unavailableLabel->setPalette(palette);
    QFont font = m_unavailableLabel->font();
    font.setPointSizeF(font.pointSizeF() * 1.25);
    m_unavailableLabel->setFont(font);
    m_unavailableLabel->hide();

    // Known before the first paint, so that a view that can never draw says so at once and
    // never makes a native OpenGL window that cannot work.
    static const Renderer3D::Message problem = Renderer3D::probeOpenGLMessage(); // once per process: it makes a context

    if (problem.isEmpty()) {
        m_canvas = new Canvas3D(this);
        connect(m_canvas, &Canvas3D::frameDue, this, &LinkageView3D::drawFrame);
        m_container = QWidget::createWindowContainer(m_canvas, this); // owns the canvas
        m_container->setFocusPolicy(Qt::NoFocus);
    } else {
        setUnavailable(problem);
    }
}

LinkageView3D::~LinkageView3D()
{
    cleanupGl();
    // The canvas and its context go now, while this object is whole: its frames reach
    // drawFrame(), which a view being destroyed must not run.
    QWidget *container = m_container;
    m_container = nullptr;
    m_canvas = nullptr;
    delete container;
}

bool LinkageView3D::hasGlContext() const
{
    return m_canvas && m_canvas->hasContext();
}

void LinkageView3D::setUnavailable(const Renderer3D::Message &reason)
{
    m_glFailed = true;
    m_unavailableReason = reason;
    m_unavailableLabel->setText(unavailableText(QLatin1Char('\n')));
    m_unavailableLabel->setGeometry(rect());
    m_unavailableLabel->show();
    m_unavailableLabel->raise();
    if (m_container)
        m_container->hide();
}

QString LinkageView3D::unavailableText(QChar separator) const
{
    return tr("3D view unavailable: OpenGL 3.3 could not be started.") + separator + m_unavailableReason.text();
}

QString LinkageView3D::glStatus() const
{
    return m_glFailed ? unavailableText(QLatin1Char(' ')) : m_renderer.glDescription();
}

void LinkageView3D::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_glFailed)
        m_unavailableLabel->setText(unavailableText(QLatin1Char('\n')));
    if (event->type() == QEvent::FontChange)
        requestFrame(); // the names follow the text size
    QWidget::changeEvent(event);
}

void LinkageView3D::requestFrame()
{
    if (m_canvas)
        m_canvas->requestFrame();
}

void LinkageView3D::setLabelsShown(bool shown)
{
    m_labelsShown = shown;
    requestFrame();
}

bool LinkageView3D::labelsShown() const
{
    return m_labelsShown;
}

void LinkageView3D::cleanupGl()
{
    if (!m_canvas || !m_renderer.isInitialized() || !m_canvas->makeCurrent())
        return;
    m_renderer.cleanup();
    m_canvas->doneCurrent();
}

bool LinkageView3D::makeCurrent()
{
    // a canvas never shown has no native window yet: nothing failed, there is nothing to draw on
    if (!m_canvas || m_glFailed || !m_canvas->handle())
        return false;
    if (!m_canvas->makeCurrent()) {
        setUnavailable({QT_TRANSLATE_NOOP("pkm::Renderer3D", "No OpenGL context is current."), {}});
        return false;
    }
    if (!m_renderer.isInitialized() && !m_renderer.initialize()) {
        setUnavailable(m_renderer.errorMessage());
        return false;
    }
    return true;
}

void LinkageView3D::drawFrame()
{
    if (!m_canvas || !m_canvas->isExposed() || !makeCurrent())
        return;
    paintGl();
    m_canvas->swapBuffers();
}

QImage LinkageView3D::grabFrame()
{
    if (!m_canvas || !m_canvas->isExposed() || !makeCurrent())
        return {};
    m_canvas->cancelFrame(); // this one is the latest
    paintGl();
    const QSize pixels = m_canvas->size() * m_canvas->devicePixelRatio();
    QImage frame(pixels, QImage::Format_RGBA8888);
    QOpenGLFunctions *gl = QOpenGLContext::currentContext()->functions();
    gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl->glReadPixels(0, 0, pixels.width(), pixels.height(), GL_RGBA, GL_UNSIGNED_BYTE, frame.bits());
    m_canvas->swapBuffers();
    return frame.mirrored().convertToFormat(QImage::Format_RGB32);
}

void LinkageView3D::finishFrame()
{
    if (m_canvas && m_canvas->framePending()) {
        m_canvas->cancelFrame();
        drawFrame();
    }
    if (makeCurrent())
        QOpenGLContext::currentContext()->functions()->glFinish();
}

void LinkageView3D::paintGl()
{
    if (!m_renderer.isInitialized())
        return; // the label says why
    QElapsedTimer timer;
    timer.start();
    syncViewport();
    // A GPU draws 4 samples a pixel at no cost that matters. A renderer on the CPU (Mesa's
    // llvmpipe, what a machine without a graphics driver has) pays for each: 4 took a slider
    // move with the 3D view from 25 to 35 ms. It draws frames in motion with one sample and
    // the frame the motion rests on with 4, a moment later.
    const bool refine = m_refining;
    m_refining = false;
    m_lastFrameSamples = !m_renderer.isSoftware() || refine ? 4 : 1;
    m_renderer.render(m_camera, m_canvas->size(), m_canvas->devicePixelRatio(), m_lastFrameSamples);
    if (m_lastFrameSamples == 1)
        m_refine.start();
    if (m_labelsShown && !m_scene.labels.empty()) {
        // The names over the model, by QPainter on OpenGL: Renderer3D sets every state it
        // draws with, so what the painter leaves behind does not reach the next frame.
        QOpenGLPaintDevice device(m_canvas->size() * m_canvas->devicePixelRatio());
        device.setDevicePixelRatio(m_canvas->devicePixelRatio());
        QPainter painter(&device);
        Camera3D view = m_camera;
        view.setViewport(m_canvas->width(), m_canvas->height());
        paintLabels3D(painter, m_scene.labels, view, font());
    }
    ++m_frameCount;
    m_lastFrameMilliseconds = double(timer.nsecsElapsed()) / 1e6;
}

void LinkageView3D::syncViewport()
{
    m_camera.setViewport(width(), height());
}

void LinkageView3D::setScene(const Scene3D &scene)
{
    m_scene = scene;
    m_renderer.setScene(scene); // CPU only: fine without a context
    m_camera.setClipBounds(m_renderer.drawnBounds());
    if (!m_hasScene) {
        m_hasScene = true;
        fit();
        return;
    }
    requestFrame();
}

void LinkageView3D::setCamera(const Camera3D &camera)
{
    const Projection before = m_camera.projection();
    m_camera = camera;
    syncViewport();
    if (m_hasScene)
        m_camera.setClipBounds(m_renderer.drawnBounds());
    m_userMoved = true;
    requestFrame();
    emit cameraChanged();
    if (camera.projection() != before)
        emit projectionChanged(camera.projection());
}

void LinkageView3D::fit()
{
    syncViewport();
    m_camera.fitPoints(m_renderer.modelPoints()); // the model as posed, tightly
    m_camera.setClipBounds(m_renderer.drawnBounds());
    m_userMoved = false;
    requestFrame();
    emit cameraChanged();
}

void LinkageView3D::setStandardView(Camera3D::StandardView view)
{
    m_camera.setStandardView(view);
    fit();
}

void LinkageView3D::setProjection(Camera3D::Projection projection)
{
    if (projection == m_camera.projection())
        return;
    m_camera.setProjection(projection);
    // A fitted view is fitted again: the two projections need different distances.
    if (!m_userMoved && m_hasScene)
        fit();
    requestFrame();
    emit projectionChanged(projection);
}

QImage LinkageView3D::renderImage(const QSize &size)
{
    m_imageError.clear();
    if (size.isEmpty()) {
        m_imageError = tr("A picture needs a size of at least one pixel.");
        return {};
    }
    syncViewport();
    QImage image;
    if (hasGlContext() && m_renderer.isInitialized() && makeCurrent()) {
        image = m_renderer.renderImage(m_camera, size);
        if (image.isNull())
            m_imageError = m_renderer.errorString();
        m_canvas->doneCurrent();
    } else if (m_glFailed) {
        m_imageError = glStatus();
        return {};
    } else {
        image = Renderer3D::renderOffscreen(m_scene, m_camera, size, &m_imageError); // never shown: a context of its own
    }
    if (!image.isNull() && labelsShown()) {
        // The names as the view shows them, enlarged with the picture (it is drawn at `size`).
        Camera3D view = m_camera;
        view.setViewport(size.width(), size.height());
        QFont font = this->font();
        font.setPixelSize(int(std::lround(QFontInfo(font).pixelSize() * double(size.height()) / std::max(1, height()))));
        QPainter painter(&image);
        paintLabels3D(painter, m_scene.labels, view, font);
    }
    return image;
}

void LinkageView3D::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    m_unavailableLabel->setGeometry(rect());
    if (m_container)
        m_container->setGeometry(rect());
    syncViewport();
    if (m_hasScene && !m_userMoved)
        fit();
}

void LinkageView3D::cameraMoved()
{
    m_userMoved = true;
    requestFrame();
    emit cameraChanged();
}

void LinkageView3D::mousePressEvent(QMouseEvent *event)
{
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    if (event->button() == Qt::LeftButton)
        m_drag = shift ? Drag::Pan : Drag::Orbit;
    else if (event->button() == Qt::RightButton || event->button() == Qt::MiddleButton)
        m_drag = Drag::Pan;
    else
        return QWidget::mousePressEvent(event);
    m_lastPosition = event->position().toPoint();
    setFocus(Qt::MouseFocusReason); // the canvas under the mouse takes no focus itself
    setDragCursor(m_drag == Drag::Orbit ? Qt::SizeAllCursor : Qt::ClosedHandCursor);
    event->accept();
}

void LinkageView3D::setDragCursor(Qt::CursorShape shape)
{
    setCursor(shape);
    if (m_canvas)
        m_canvas->setCursor(shape);
}

void LinkageView3D::unsetDragCursor()
{
    unsetCursor();
    if (m_canvas)
        m_canvas->unsetCursor();
}

void LinkageView3D::mouseMoveEvent(QMouseEvent *event)
{
    if (m_drag == Drag::None)
        return QWidget::mouseMoveEvent(event);
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastPosition;
    m_lastPosition = position;
    syncViewport();
    if (m_drag == Drag::Orbit)
        m_camera.orbit(delta.x(), delta.y());
    else
        m_camera.pan(delta.x(), delta.y(), height());
    cameraMoved();
    event->accept();
}

void LinkageView3D::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_drag == Drag::None)
        return QWidget::mouseReleaseEvent(event);
    if (!(event->buttons() & (Qt::LeftButton | Qt::RightButton | Qt::MiddleButton))) {
        m_drag = Drag::None;
        unsetDragCursor();
    }
    event->accept();
}

void LinkageView3D::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return QWidget::mouseDoubleClickEvent(event);
    m_drag = Drag::None;
    unsetDragCursor();
    fit();
    event->accept();
}

void LinkageView3D::wheelEvent(QWheelEvent *event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0.0)
        return QWidget::wheelEvent(event);
    syncViewport();
    const QPointF cursor = event->position();
    m_camera.zoom(steps, Eigen::Vector2d(cursor.x(), cursor.y()));
    cameraMoved();
    event->accept();
}

void LinkageView3D::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_F:
    case Qt::Key_Home:
        fit();
        break;
    case Qt::Key_1:
        setStandardView(StandardView::Front);
        break;
    case Qt::Key_3:
        setStandardView(StandardView::Side);
        break;
    case Qt::Key_7:
        setStandardView(StandardView::Top);
        break;
    case Qt::Key_5:
        setProjection(projection() == Projection::Perspective ? Projection::Orthographic : Projection::Perspective);
        break;
    default:
        return QWidget::keyPressEvent(event);
    }
    event->accept();
}

} // namespace pkm
