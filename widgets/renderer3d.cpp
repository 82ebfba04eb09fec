#include "renderer3d.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>
#include <QOpenGLVersionFunctionsFactory>

#include <algorithm>
#include <cstddef>

namespace pkm {

namespace {

// Solids: lit in linear light (the vertex colours are sRGB), written back as sRGB.
const char *const solidVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 colour;
uniform mat4 view;
uniform mat4 projection;
out vec3 eyePosition;
out vec3 eyeNormal;
out vec4 baseColour;
void main()
{
    vec4 p = view * vec4(position, 1.0);
    eyePosition = p.xyz;
    eyeNormal = mat3(view) * normal; // the view is rigid
    baseColour = colour;
    gl_Position = projection * p;
}
)";

const char *const solidFragmentShader = R"(#version 330 core
in vec3 eyePosition;
in vec3 eyeNormal;
in vec4 baseColour;
uniform bool orthographic;
out vec4 fragmentColour;
void main()
{
    vec3 n = normalize(eyeNormal);
    if (!gl_FrontFacing)
        n = -n;
    vec3 v = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-eyePosition);
    vec3 albedo = pow(baseColour.rgb, vec3(2.2));
    float shine = baseColour.a;
    // A headlight a little above and left of the eye, a weak fill from the lower right, and
    // more ambient light from above than from below.
    const vec3 key = normalize(vec3(-0.35, 0.55, 1.0));
    const vec3 fill = normalize(vec3(0.7, -0.3, 0.45));
    float ambient = 0.24 + 0.06 * n.y;
    float diffuse = 0.72 * max(dot(n, key), 0.0) + 0.2 * max(dot(n, fill), 0.0);
    vec3 h = normalize(key + v);
    float specular = 0.5 * shine * pow(max(dot(n, h), 0.0), mix(20.0, 90.0, shine));
    // Darker where the surface turns away from the eye: outlines between parts.
    float rim = mix(0.62, 1.0, smoothstep(0.0, 0.45, max(dot(n, v), 0.0)));
    vec3 colour = (albedo * (ambient + diffuse) + vec3(specular)) * rim;
    fragmentColour = vec4(pow(clamp(colour, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
)";

// Grid lines: unlit, fading out towards the edges of the grid.
const char *const lineVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
uniform mat4 view;
uniform mat4 projection;
out vec4 lineColour;
out vec2 planePosition;
void main()
{
    lineColour = colour;
    planePosition = position.xz;
    gl_Position = projection * view * vec4(position, 1.0);
}
)";

const char *const lineFragmentShader = R"(#version 330 core
in vec4 lineColour;
in vec2 planePosition;
uniform vec4 gridRectangle; // x0, z0, x1, z1
uniform float fadeWidth;
out vec4 fragmentColour;
void main()
{
    vec2 inside = min(planePosition - gridRectangle.xy, gridRectangle.zw - planePosition);
    float edge = min(inside.x, inside.y);
    fragmentColour = vec4(lineColour.rgb, lineColour.a * smoothstep(0.0, fadeWidth, edge));
}
)";

} // namespace

Renderer3D::Renderer3D()
{
    m_grid = groundGrid(Eigen::AlignedBox3d());
}

Renderer3D::~Renderer3D() = default;

QSurfaceFormat Renderer3D::surfaceFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    // None on the surface: render() draws its own samples where they are cheap or wanted.
    format.setSamples(0);
    return format;
}

QColor Renderer3D::backgroundColour()
{
    return {0xfb, 0xfc, 0xfe};
}

bool Renderer3D::contextIsCurrent() const
{
    return m_gl && m_context && QOpenGLContext::currentContext() == m_context;
}

bool Renderer3D::initialize()
{
    cleanup();
    m_error = {};
    QOpenGLContext *context = QOpenGLContext::currentContext();
    if (!context) {
        m_error = {QT_TRANSLATE_NOOP("pkm::Renderer3D", "No OpenGL context is current."), {}};
        return false;
    }
    const QSurfaceFormat format = context->format();
    if (context->isOpenGLES() || format.version() < qMakePair(3, 3)) {
        m_error = {QT_TRANSLATE_NOOP("pkm::Renderer3D", "The driver offers OpenGL %1%2.%3; the 3D view needs OpenGL 3.3."),
            {context->isOpenGLES() ? QStringLiteral("ES ") : QString(), QString::number(format.majorVersion()),
                QString::number(format.minorVersion())}};
        return false;
    }
    auto *gl = QOpenGLVersionFunctionsFactory::get<QOpenGLFunctions_3_3_Core>(context);
    if (!gl || !gl->initializeOpenGLFunctions()) {
        m_error = {QT_TRANSLATE_NOOP("pkm::Renderer3D", "The OpenGL 3.3 core functions could not be resolved."), {}};
        return false;
    }
    m_gl = gl;
    m_context = context;
    if (!buildPrograms()) {
        cleanup();
        return false;
    }

    m_gl->glGenVertexArrays(1, &m_solidArray);
    m_gl->glGenBuffers(1, &m_solidVertices);
    m_gl->glGenBuffers(1, &m_solidIndices);
    m_gl->glBindVertexArray(m_solidArray);
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_solidVertices);
    m_gl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_solidIndices);
    const auto stride = GLsizei(sizeof(MeshVertex));
    m_gl->glEnableVertexAttribArray(0);
    m_gl->glVertexAttribPointer(
        0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void *>(offsetof(MeshVertex, position)));
    m_gl->glEnableVertexAttribArray(1);
    m_gl->glVertexAttribPointer(
        1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void *>(offsetof(MeshVertex, normal)));
    m_gl->glEnableVertexAttribArray(2);
    m_gl->glVertexAttribPointer(
        2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void *>(offsetof(MeshVertex, colour)));

    m_gl->glGenVertexArrays(1, &m_lineArray);
    m_gl->glGenBuffers(1, &m_lineVertices);
    m_gl->glBindVertexArray(m_lineArray);
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_lineVertices);
    const auto lineStride = GLsizei(sizeof(LineVertex));
    m_gl->glEnableVertexAttribArray(0);
    m_gl->glVertexAttribPointer(
        0, 3, GL_FLOAT, GL_FALSE, lineStride, reinterpret_cast<void *>(offsetof(LineVertex, position)));
    m_gl->glEnableVertexAttribArray(1);
    m_gl->glVertexAttribPointer(
        1, 4, GL_FLOAT, GL_FALSE, lineStride, reinterpret_cast<void *>(offsetof(LineVertex, colour)));
    m_gl->glBindVertexArray(0);
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, 0);

    m_description = {QT_TRANSLATE_NOOP("pkm::Renderer3D", "OpenGL %1.%2 (%3), %4"),
        {QString::number(format.majorVersion()), QString::number(format.minorVersion()),
            QString::fromLatin1(reinterpret_cast<const char *>(m_gl->glGetString(GL_VERSION))),
            QString::fromLatin1(reinterpret_cast<const char *>(m_gl->glGetString(GL_RENDERER)))}};
    const QString renderer = QString::fromLatin1(reinterpret_cast<const char *>(m_gl->glGetString(GL_RENDERER)));
    m_software = renderer.contains(QLatin1String("llvmpipe")) || renderer.contains(QLatin1String("softpipe"))
        || renderer.contains(QLatin1String("swrast"));
    m_dirty = true;
    return true;
}

bool Renderer3D::buildPrograms()
{
    auto build = [this](std::unique_ptr<QOpenGLShaderProgram> &program, const char *vertex, const char *fragment) {
        program = std::make_unique<QOpenGLShaderProgram>();
        if (program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex)
            && program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment) && program->link())
            return true;
        m_error = {QT_TRANSLATE_NOOP("pkm::Renderer3D", "The 3D view's shaders could not be built: %1"), {program->log().trimmed()}};
        return false;
    };
    return build(m_solidProgram, solidVertexShader, solidFragmentShader)
        && build(m_lineProgram, lineVertexShader, lineFragmentShader);
}

void Renderer3D::setScene(const Scene3D &scene)
{
    m_mesh = Mesh3D::fromScene(scene);
    m_modelBounds = pkm::modelBounds(scene);
    m_grid = groundGrid(m_modelBounds);
    m_dirty = true;
}

std::vector<Eigen::Vector3d> Renderer3D::modelPoints() const
{
    std::vector<Eigen::Vector3d> points;
    points.reserve(m_mesh.vertices().size());
    for (const MeshVertex &vertex : m_mesh.vertices())
        points.emplace_back(vertex.position[0], vertex.position[1], vertex.position[2]);
    if (points.empty() && !m_modelBounds.isEmpty()) { // no solid yet: the corners of its extent
        for (int corner = 0; corner < 8; ++corner)
            points.push_back(m_modelBounds.corner(Eigen::AlignedBox3d::CornerType(corner)));
    }
    return points;
}

Eigen::AlignedBox3d Renderer3D::drawnBounds() const
{
    Eigen::AlignedBox3d box = m_modelBounds;
    box.extend(m_grid.bounds);
    return box;
}

void Renderer3D::upload()
{
    // Orphaning with glBufferData each time: the driver never waits for the last frame.
    m_gl->glBindVertexArray(m_solidArray);
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_solidVertices);
    m_gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m_mesh.vertices().size() * sizeof(MeshVertex)),
        m_mesh.vertices().data(), GL_DYNAMIC_DRAW);
    m_gl->glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m_mesh.indices().size() * sizeof(std::uint32_t)),
        m_mesh.indices().data(), GL_DYNAMIC_DRAW);
    m_gl->glBindVertexArray(m_lineArray);
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_lineVertices);
    m_gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m_grid.vertices.size() * sizeof(LineVertex)), m_grid.vertices.data(),
        GL_DYNAMIC_DRAW);
    m_gl->glBindVertexArray(0);
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, 0);
    m_uploadedIndices = int(m_mesh.indices().size());
    m_uploadedLines = int(m_grid.vertices.size());
    m_dirty = false;
}

void Renderer3D::render(const Camera3D &camera, const QSize &viewport, qreal devicePixelRatio, int samples)
{
    if (!contextIsCurrent() || viewport.isEmpty())
        return;
    if (m_dirty)
        upload();
    const QSize pixels = viewport * devicePixelRatio;
    if (samples <= 1) {
        draw(camera, viewport, pixels);
        return;
    }
    GLint target = 0, maximumSamples = 0;
    m_gl->glGetIntegerv(GL_FRAMEBUFFER_BINDING, &target);
    m_gl->glGetIntegerv(GL_MAX_SAMPLES, &maximumSamples);
    samples = std::min(samples, int(maximumSamples));
    if (!m_multisampled || m_multisampled->size() != pixels || m_multisampled->format().samples() != samples) {
        QOpenGLFramebufferObjectFormat format;
        format.setAttachment(QOpenGLFramebufferObject::Depth);
        format.setSamples(samples);
        format.setInternalTextureFormat(GL_RGBA8);
        m_multisampled = std::make_unique<QOpenGLFramebufferObject>(pixels, format);
    }
    if (!m_multisampled->isValid() || !m_multisampled->bind()) {
        m_multisampled.reset(); // no samples, then: the frame still shows
        m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
        draw(camera, viewport, pixels);
        return;
    }
    draw(camera, viewport, pixels);
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_multisampled->handle());
    m_gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(target));
    m_gl->glBlitFramebuffer(0, 0, pixels.width(), pixels.height(), 0, 0, pixels.width(), pixels.height(),
        GL_COLOR_BUFFER_BIT, GL_NEAREST);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
}

void Renderer3D::draw(const Camera3D &camera, const QSize &viewport, const QSize &pixels)
{
    m_gl->glViewport(0, 0, pixels.width(), pixels.height());
    // What a QPainter on the same context (the view's names) may have left set.
    m_gl->glDisable(GL_SCISSOR_TEST);
    m_gl->glDisable(GL_STENCIL_TEST);
    m_gl->glDisable(GL_BLEND);
    m_gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const QColor background = backgroundColour();
    m_gl->glClearColor(float(background.redF()), float(background.greenF()), float(background.blueF()), 1.0f);
    m_gl->glDepthMask(GL_TRUE);
    m_gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    m_gl->glEnable(GL_DEPTH_TEST);
    m_gl->glDepthFunc(GL_LEQUAL);
    m_gl->glEnable(GL_CULL_FACE);
    m_gl->glCullFace(GL_BACK);
    m_gl->glFrontFace(GL_CCW);
    m_gl->glEnable(GL_MULTISAMPLE);

    Camera3D view = camera;
    view.setViewport(viewport.width(), viewport.height());
    const Eigen::Matrix4f viewMatrix = view.viewMatrix().cast<float>();
    const Eigen::Matrix4f projection = view.projectionMatrix().cast<float>();
    auto setMatrices = [&](QOpenGLShaderProgram &program) {
        // Eigen is column-major, as GL expects.
        m_gl->glUniformMatrix4fv(program.uniformLocation("view"), 1, GL_FALSE, viewMatrix.data());
        m_gl->glUniformMatrix4fv(program.uniformLocation("projection"), 1, GL_FALSE, projection.data());
    };

    if (m_uploadedIndices > 0) {
        m_solidProgram->bind();
        setMatrices(*m_solidProgram);
        m_solidProgram->setUniformValue(
            "orthographic", GLint(camera.projection() == Camera3D::Projection::Orthographic));
        m_gl->glBindVertexArray(m_solidArray);
        m_gl->glDrawElements(GL_TRIANGLES, m_uploadedIndices, GL_UNSIGNED_INT, nullptr);
        m_solidProgram->release();
    }
    if (m_uploadedLines > 0) {
        // After the solids, without writing depth: the model hides the grid, never the reverse.
        m_lineProgram->bind();
        setMatrices(*m_lineProgram);
        const Eigen::AlignedBox3d &r = m_grid.bounds;
        m_lineProgram->setUniformValue(
            "gridRectangle", float(r.min().x()), float(r.min().z()), float(r.max().x()), float(r.max().z()));
        m_lineProgram->setUniformValue("fadeWidth", float(0.2 * std::max(r.sizes().x(), r.sizes().z())));
        m_gl->glEnable(GL_BLEND);
        m_gl->glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        m_gl->glDepthMask(GL_FALSE);
        m_gl->glBindVertexArray(m_lineArray);
        m_gl->glDrawArrays(GL_LINES, 0, m_uploadedLines);
        m_gl->glDepthMask(GL_TRUE);
        m_gl->glDisable(GL_BLEND);
        m_lineProgram->release();
    }
    m_gl->glBindVertexArray(0);
    m_gl->glDisable(GL_CULL_FACE);
    m_gl->glDisable(GL_DEPTH_TEST);
}

QImage Renderer3D::renderImage(const Camera3D &camera, const QSize &size)
{
    if (!contextIsCurrent()) {
        m_error = {QT_TRANSLATE_NOOP("pkm::Renderer3D", "No OpenGL context is current."), {}};
        return {};
    }
    GLint maximumSize = 0, maximumSamples = 0, previous = 0;
    m_gl->glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maximumSize);
    m_gl->glGetIntegerv(GL_MAX_SAMPLES, &maximumSamples);
    if (size.isEmpty() || size.width() > maximumSize || size.height() > maximumSize) {
        m_error = {QT_TRANSLATE_NOOP("pkm::Renderer3D", "A picture of %1 × %2 pixels is not possible: the largest is %3 × %3."),
            {QString::number(size.width()), QString::number(size.height()), QString::number(maximumSize)}};
        return {};
    }
    m_gl->glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);

    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::Depth);
    format.setSamples(std::min(4, int(maximumSamples)));
    format.setInternalTextureFormat(GL_RGBA8);
    QOpenGLFramebufferObject multisampled(size, format);
    QOpenGLFramebufferObject resolved(size, QOpenGLFramebufferObject::NoAttachment, GL_TEXTURE_2D, GL_RGBA8);
    QImage image;
    if (multisampled.isValid() && resolved.isValid() && multisampled.bind()) {
        Camera3D view = camera;
        view.setViewport(size.width(), size.height());
        render(view, size, 1.0);
        QOpenGLFramebufferObject::blitFramebuffer(&resolved, &multisampled);
        image = resolved.toImage(true).convertToFormat(QImage::Format_RGB32);
    }
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    if (image.isNull())
        m_error = {QT_TRANSLATE_NOOP("pkm::Renderer3D", "The OpenGL driver could not make a framebuffer of %1 × %2 pixels."),
            {QString::number(size.width()), QString::number(size.height())}};
    return image;
}

Renderer3D::Message Renderer3D::probeOpenGLMessage()
{
    QOpenGLContext context;
    context.setFormat(surfaceFormat());
    if (!context.create())
        return {QT_TRANSLATE_NOOP("pkm::Renderer3D", "No OpenGL context could be created on the “%1” display platform."),
            {QGuiApplication::platformName()}};
    const QSurfaceFormat format = context.format();
    if (context.isOpenGLES() || format.version() < qMakePair(3, 3))
        return {QT_TRANSLATE_NOOP("pkm::Renderer3D", "The driver offers OpenGL %1%2.%3 only."),
            {context.isOpenGLES() ? QStringLiteral("ES ") : QString(), QString::number(format.majorVersion()),
                QString::number(format.minorVersion())}};
    return {};
}

QString Renderer3D::Message::text() const
{
    if (!source)
        return {};
    const QString pattern = QCoreApplication::translate("pkm::Renderer3D", source);
    // In one pass, as QString::arg(a, b, …) does: an argument holding "%2" stays as it is.
    QString result;
    result.reserve(pattern.size());
    for (qsizetype i = 0; i < pattern.size(); ++i) {
        if (pattern[i] == QLatin1Char('%') && i + 1 < pattern.size()) {
            const int n = pattern[i + 1].digitValue();
            if (n >= 1 && n <= arguments.size()) {
                result += arguments[n - 1];
                ++i;
                continue;
            }
        }
        result += pattern[i];
    }
    return result;
}

QImage Renderer3D::renderOffscreen(const Scene3D &scene, const Camera3D &camera, const QSize &size, QString *error)
{
    auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return QImage();
    };
    QOpenGLContext context;
    context.setFormat(surfaceFormat());
    if (!context.create())
        return fail(tr("No OpenGL context could be created on the “%1” display platform.")
                        .arg(QGuiApplication::platformName()));
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    if (!surface.isValid() || !context.makeCurrent(&surface))
        return fail(tr("The OpenGL context could not be made current on an offscreen surface."));
    Renderer3D renderer;
    QImage image;
    if (renderer.initialize()) {
        renderer.setScene(scene);
        Camera3D view = camera;
        Eigen::AlignedBox3d bounds = camera.clipBounds();
        view.setClipBounds(bounds.extend(renderer.drawnBounds()));
        image = renderer.renderImage(view, size);
    }
    const QString message = renderer.errorString();
    renderer.cleanup();
    context.doneCurrent();
    return image.isNull() ? fail(message) : image;
}

void Renderer3D::cleanup()
{
    if (contextIsCurrent()) {
        const GLuint arrays[] = {m_solidArray, m_lineArray};
        const GLuint buffers[] = {m_solidVertices, m_solidIndices, m_lineVertices};
        m_gl->glDeleteVertexArrays(2, arrays);
        m_gl->glDeleteBuffers(3, buffers);
    }
    // Safe without the context: Qt defers deleting the programs until it is current or gone.
    m_solidProgram.reset();
    m_lineProgram.reset();
    m_multisampled.reset(); // as the programs: Qt deletes its GL object when it can
    m_solidArray = m_lineArray = m_solidVertices = m_solidIndices = m_lineVertices = 0;
    m_uploadedIndices = m_uploadedLines = 0;
    m_gl = nullptr;
    m_context = nullptr;
    m_dirty = true;
}

} // namespace pkm
