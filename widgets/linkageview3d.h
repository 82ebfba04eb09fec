#pragma once
/// The 3D view: a thin widget around Renderer3D and Camera3D. It shows one Scene3D, orbits,
/// pans and zooms, and renders pictures of any size. Like the 2D view it never changes the
/// pose: its owner calls setScene() whenever the pose or the design changes.
///
/// Without OpenGL 3.3 (the offscreen platform, a remote session, an old driver) it does not
/// crash and does not go blank: it shows why, and isGlAvailable() is false. The OpenGL surface
/// (canvas3d.h) is a child made only once a 3.3 core context is known to work.
///
/// Mouse: left drag orbits; right, middle or Shift+left drag pans; the wheel zooms towards the
/// cursor; a double click fits. Keys: F (or Home) fits, 1 front, 3 side, 7 top, 5 switches
/// between perspective and orthographic.

#include "camera3d.h"
#include "renderer3d.h"
#include "scene3d.h"

#include <QImage>
#include <QPoint>
#include <QString>
#include <QTimer>
#include <QWidget>

class QLabel;
class QToolButton;

namespace pkm {

class Canvas3D;

class LinkageView3D : public QWidget
{
    Q_OBJECT

public:
    using Projection = Camera3D::Projection;
    using StandardView = Camera3D::StandardView;

    explicit LinkageView3D(QWidget *parent = nullptr);
    ~LinkageView3D() override;

    /// Tessellates the scene and schedules a repaint. The first scene is fitted; later ones keep
    /// the camera, so the model moves smoothly while the user drags a slider.
    void setScene(const Scene3D &scene);
    const Scene3D &scene() const { return m_scene; }

    const Camera3D &camera() const { return m_camera; }
    /// Takes a camera as it is (its viewport follows the widget; its clip bounds the scene).
    void setCamera(const Camera3D &camera);
    Projection projection() const { return m_camera.projection(); }

    /// False when OpenGL 3.3 could not be started; glStatus() then says why.
    bool isGlAvailable() const { return !m_glFailed; }
    /// The OpenGL in use ("OpenGL 4.5 (…), llvmpipe"), or why the view is unavailable.
    QString glStatus() const;

    /// The current scene and camera rendered into an image of `size` pixels (multisampled),
    /// for "Save picture…" and exports; works before the view is first shown. A null image,
    /// with imageError(), when it cannot be rendered.
    QImage renderImage(const QSize &size);
    QString imageError() const { return m_imageError; }

    /// The names of the model's points over it, in the view and its pictures (on by default).
    void setLabelsShown(bool shown);
    bool labelsShown() const;

    /// Whether the view has its OpenGL surface (false when OpenGL is unavailable) and whether
    /// that surface has made its context (it does when first shown).
    bool hasGlSurface() const { return m_canvas != nullptr; }
    bool hasGlContext() const;
    /// Draws a frame now, as the view would show it, and returns it (a null image when the
    /// view is not on screen): what a test compares.
    QImage grabFrame();
    /// Draws the frame asked for, if one is, and waits until OpenGL has finished it: what a
    /// benchmark times.
    void finishFrame();

    int frameCount() const { return m_frameCount; }
    /// The samples per pixel of the last frame: 4, or 1 for a frame drawn in motion by a
    /// renderer on the CPU (it is drawn again with 4 once the motion rests).
    int lastFrameSamples() const { return m_lastFrameSamples; }
    /// CPU time of the last frame, ms (GL work may finish later).
    double lastFrameMilliseconds() const { return m_lastFrameMilliseconds; }

    QSize sizeHint() const override { return {800, 600}; }
    QSize minimumSizeHint() const override { return {200, 150}; }

public slots:
    /// Frames the whole model (its extent over the range of motion), keeping the direction.
    void fit();
    /// Looks from a standard direction and fits.
    void setStandardView(pkm::Camera3D::StandardView view);
    void setProjection(pkm::Camera3D::Projection projection);

signals:
    void projectionChanged(pkm::Camera3D::Projection projection);
    void cameraChanged();

protected:
    void resizeEvent(QResizeEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    enum class Drag { None, Orbit, Pan };

    /// Makes the canvas's context current, setting the renderer up in it the first time.
    bool makeCurrent();
    /// Draws the frame into the canvas's back buffer (swapped by the caller).
    void paintGl();
    /// Draws the frame and shows it.
    void drawFrame();
    void cleanupGl();
    void requestFrame();
    /// Shows why (one sentence) instead of the picture.
    void setUnavailable(const Renderer3D::Message &reason);
    /// The headline and the reason, in the current language.
    QString unavailableText(QChar separator) const;
    void syncViewport();
    void cameraMoved();
    /// On the view and on its canvas, a native window with a cursor of its own.
    void setDragCursor(Qt::CursorShape shape);
    void unsetDragCursor();

    Renderer3D m_renderer;
    Camera3D m_camera;
    Scene3D m_scene;
    bool m_hasScene = false;
    bool m_userMoved = false; ///< orbited, panned or zoomed since the last fit
    bool m_glFailed = false;
    Renderer3D::Message m_unavailableReason;
    QString m_imageError;
    Canvas3D *m_canvas = nullptr;
    QWidget *m_container = nullptr; ///< the canvas as a child widget filling the view
    QLabel *m_unavailableLabel = nullptr;
    bool m_labelsShown = true;

    Drag m_drag = Drag::None;
    QPoint m_lastPosition;

    int m_frameCount = 0;
    double m_lastFrameMilliseconds = 0.0;
    int m_lastFrameSamples = 0;
    QTimer m_refine;           ///< the motion rests: the still frame with every sample
    bool m_refining = false;
};

/// The 3D view under a row of large text buttons a classroom can read on a projector: Fit, the
/// standard views, Perspective, and Save picture….
class View3DPanel : public QWidget
{
    Q_OBJECT

public:
    explicit View3DPanel(QWidget *parent = nullptr);

    LinkageView3D *view() const { return m_view; }
    void setScene(const Scene3D &scene) { m_view->setScene(scene); }

    /// Writes the view at twice its size as a PNG to `path`, atomically (QSaveFile). False,
    /// with `error`, when it cannot be rendered or written.
    bool savePicture(const QString &path, QString *error = nullptr);
    /// The same at `size` pixels (any size from 16 to 8000 per side).
    bool savePicture(const QString &path, const QSize &size, QString *error = nullptr);

public slots:
    /// Asks for a PNG file name and saves the picture; a failure is shown in a message box.
    void savePictureAs();

protected:
    void changeEvent(QEvent *event) override;

private:
    /// The buttons' texts and tooltips in the current language.
    void retranslate();

    LinkageView3D *m_view = nullptr;
    QToolButton *m_fitButton = nullptr;
    QToolButton *m_frontButton = nullptr;
    QToolButton *m_topButton = nullptr;
    QToolButton *m_sideButton = nullptr;
    QToolButton *m_isometricButton = nullptr;
    QToolButton *m_saveButton = nullptr;
    QToolButton *m_perspectiveButton = nullptr;
    QToolButton *m_labelsButton = nullptr;
    QString m_lastDirectory;
};

} // namespace pkm
