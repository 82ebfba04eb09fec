#include "canvas3d.h"

#include "renderer3d.h"

#include <QCoreApplication>
#include <QExposeEvent>
#include <QOpenGLContext>
#include <QWidget>

namespace pkm {

Canvas3D::Canvas3D(QWidget *input)
    : m_input(input)
{
    setSurfaceType(QSurface::OpenGLSurface);
    setFormat(Renderer3D::surfaceFormat());
    // The view takes the focus on a click (LinkageView3D::mousePressEvent): keys then reach it
    // and the window's shortcuts as for any widget.
    setFlag(Qt::WindowDoesNotAcceptFocus);
    m_frame.setSingleShot(true);
    m_frame.setInterval(0);
    connect(&m_frame, &QTimer::timeout, this, [this] {
        if (isExposed())
            emit frameDue();
    });
}

Canvas3D::~Canvas3D() = default;

bool Canvas3D::makeCurrent()
{
    if (!handle())
        return false;
    if (!m_context) {
        auto context = std::make_unique<QOpenGLContext>();
        context->setFormat(format());
        if (!context->create())
            return false;
        m_context = std::move(context);
    }
    return m_context->makeCurrent(this);
}

void Canvas3D::doneCurrent()
{
    if (m_context)
        m_context->doneCurrent();
}

void Canvas3D::swapBuffers()
{
    if (m_context)
        m_context->swapBuffers(this);
}

void Canvas3D::requestFrame()
{
    if (!m_frame.isActive())
        m_frame.start();
}

bool Canvas3D::event(QEvent *event)
{
    switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::MouseMove:
    case QEvent::Wheel:
        // QApplication takes it from here: to the view, and on to its parents if ignored.
        if (m_input)
            QCoreApplication::sendEvent(m_input, event);
        return true;
    default:
        return QWindow::event(event);
    }
}

void Canvas3D::exposeEvent(QExposeEvent *)
{
    // Shown, uncovered or resized: the window must be drawn now, not later.
    if (isExposed()) {
        m_frame.stop();
        emit frameDue();
    }
}

} // namespace pkm
