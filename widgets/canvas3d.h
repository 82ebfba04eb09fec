#pragma once
/// The 3D view's OpenGL surface: a native window inside the view (QWidget::
/// createWindowContainer), with an OpenGL context of its own.
///
/// Why not a QOpenGLWidget: a top-level window that holds one is composited by OpenGL as a
/// whole. Every frame uploads the window's other widgets as a texture, draws the whole window
/// and swaps it — at 1920×1080 on Mesa's software renderer (a classroom PC without a graphics
/// driver) that took 20 of a slider move's 24 ms, against 4 ms for the model itself. A window
/// of its own swaps only the view, and the widgets around it repaint as they do without 3D.
///
/// The window takes no keyboard focus and hands every mouse event to the widget it lies in,
/// so the view handles input as any widget does. Frames asked for while the event loop is busy
/// are drawn once, when it next runs.

#include <QPointer>
#include <QTimer>
#include <QWindow>

#include <memory>

class QOpenGLContext;

namespace pkm {

class Canvas3D : public QWindow
{
    Q_OBJECT

public:
    /// Mouse events go to `input` (with the same coordinates: the window fills it).
    explicit Canvas3D(QWidget *input);
    ~Canvas3D() override;

    /// Makes the context current on this window, creating the context the first time. False
    /// when the window is not created yet or the context cannot be made or made current.
    bool makeCurrent();
    void doneCurrent();
    bool hasContext() const { return bool(m_context); }
    void swapBuffers();

    /// A frame is wanted: frameDue() follows once the event loop runs, however many requests
    /// come before it.
    void requestFrame();
    /// Drops the frame asked for (one was drawn another way).
    void cancelFrame() { m_frame.stop(); }
    bool framePending() const { return m_frame.isActive(); }

signals:
    /// Draw now: the window is exposed (a frame is asked for, or it was shown or resized).
    void frameDue();

protected:
    bool event(QEvent *event) override;
    void exposeEvent(QExposeEvent *event) override;

private:
    QPointer<QWidget> m_input;
    std::unique_ptr<QOpenGLContext> m_context;
    QTimer m_frame;
};

} // namespace pkm
