#pragma once
/// Draws a pkm::Scene3D with OpenGL 3.3 core into whatever framebuffer is bound: Blinn–Phong
/// shading with a headlight and a fill light, a darker rim where surfaces turn away (so parts
/// stay apart), a subtle ground grid under the model, on the 2D view's light background.
///
/// Holds no widget and no context (Avogadro's `rendering` beside its thin GLWidget): the
/// owner makes its context current around initialize(), render(), renderImage() and cleanup(),
/// and the renderer makes no GL call unless the context it was initialised in is current.
/// setScene() only tessellates (CPU); the upload happens in the next render().

#include "camera3d.h"
#include "mesh3d.h"
#include "scene3d.h"

#include <QColor>
#include <QOpenGLFramebufferObject>
#include <QCoreApplication>
#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>
#include <QSurfaceFormat>

#include <memory>

class QOpenGLContext;
class QOpenGLFunctions_3_3_Core;
class QOpenGLShaderProgram;

namespace pkm {

class Renderer3D
{
    Q_DECLARE_TR_FUNCTIONS(pkm::Renderer3D)

public:
    Renderer3D();
    /// Releases nothing in GL (there may be no context): call cleanup() before, current.
    ~Renderer3D();
    Renderer3D(const Renderer3D &) = delete;
    Renderer3D &operator=(const Renderer3D &) = delete;

    /// The format the renderer wants: OpenGL 3.3 core, 24-bit depth, 4× multisampling.
    static QSurfaceFormat surfaceFormat();
    /// SceneStyle::background, the 2D view's.
    static QColor backgroundColour();

    /// A sentence kept as its English source and its arguments, so that it can be said again
    /// after a change of language (the 3D view's "unavailable" text follows one).
    struct Message {
        const char *source = nullptr; ///< marked QT_TRANSLATE_NOOP("pkm::Renderer3D", …)
        QStringList arguments; ///< for %1, %2, …
        bool isEmpty() const { return source == nullptr; }
        /// In the current language, the arguments filled in.
        QString text() const;
    };

    /// With a context current: resolves the 3.3 core functions, compiles the shaders and
    /// creates the buffers. False, with errorString(), when any of it fails.
    bool initialize();
    bool isInitialized() const { return m_gl != nullptr; }
    /// Why initialize() or renderImage() failed, in one sentence.
    QString errorString() const { return m_error.text(); }
    Message errorMessage() const { return m_error; }
    /// "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe" once initialised.
    QString glDescription() const { return m_description.text(); }

    /// Tessellates the scene and its ground grid now; they are uploaded by the next render().
    void setScene(const Scene3D &scene);
    const Mesh3D &mesh() const { return m_mesh; }
    const GroundGrid &grid() const { return m_grid; }
    /// What fitting frames: the extent and the solids.
    Eigen::AlignedBox3d modelBounds() const { return m_modelBounds; }
    /// The model's vertices in the pose shown (what Fit frames; the grid is not in it); the
    /// corners of modelBounds() while there is no solid.
    std::vector<Eigen::Vector3d> modelPoints() const;
    /// What must never be clipped: the model and the grid.
    Eigen::AlignedBox3d drawnBounds() const;

    /// Draws into the bound framebuffer: `viewport` in logical pixels (the camera's), the GL
    /// viewport in device pixels (× devicePixelRatio). With `samples` > 1 it draws into a
    /// multisampled framebuffer of its own (kept for the next frame of that size) and resolves
    /// it into the bound one: the view's surface has no samples, so that a renderer on the CPU
    /// can draw moving frames without them (LinkageView3D). Nothing without the context current.
    void render(const Camera3D &camera, const QSize &viewport, qreal devicePixelRatio, int samples = 0);
    /// Whether the driver renders on the CPU (Mesa's llvmpipe, softpipe or swrast), where each
    /// sample of each pixel costs processor time. Known once initialised.
    bool isSoftware() const { return m_software; }
    /// Renders the camera's view into a multisampled framebuffer of `size` pixels (the camera's
    /// viewport set to it), resolves it and reads it back; the previously bound framebuffer is
    /// bound again. A null image, with errorString(), on failure. Needs the context current.
    QImage renderImage(const Camera3D &camera, const QSize &size);

    /// Renders a scene without a window, in a context and an offscreen surface of its own made
    /// and destroyed here (GUI thread only): for exports from the command line or before the
    /// view was ever shown. A null image, with `error`, when OpenGL 3.3 cannot be started.
    static QImage renderOffscreen(
        const Scene3D &scene, const Camera3D &camera, const QSize &size, QString *error = nullptr);
    /// Why an OpenGL 3.3 core context cannot be had here, or an empty string when it can.
    /// Creates and destroys a throwaway context.
    static QString probeOpenGL() { return probeOpenGLMessage().text(); }
    /// The same, to be said again in another language; empty when a context can be had.
    static Message probeOpenGLMessage();

    /// Deletes the GL objects; call with the context of initialize() current. Safe to repeat.
    void cleanup();

private:
    bool contextIsCurrent() const;
    bool buildPrograms();
    void upload();
    void draw(const Camera3D &camera, const QSize &viewport, const QSize &pixels);

    QOpenGLContext *m_context = nullptr;
    QOpenGLFunctions_3_3_Core *m_gl = nullptr;
    std::unique_ptr<QOpenGLShaderProgram> m_solidProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_lineProgram;
    unsigned int m_solidArray = 0, m_solidVertices = 0, m_solidIndices = 0;
    unsigned int m_lineArray = 0, m_lineVertices = 0;
    int m_uploadedIndices = 0;
    int m_uploadedLines = 0;
    bool m_dirty = true;
    bool m_software = false;
    std::unique_ptr<QOpenGLFramebufferObject> m_multisampled; ///< render()'s, at its last size
    Message m_error;
    Message m_description;

    Mesh3D m_mesh;
    GroundGrid m_grid;
    Eigen::AlignedBox3d m_modelBounds;
};

} // namespace pkm
