#include "linkageview3d.h"

#include "flowlayout.h"

#include <QElapsedTimer>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFrame>
#include <QKeyEvent>
#include <QLabel>
#include <QInputDialog>
#include <QMessageBox>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLWidget>
#include <QSaveFile>
#include <QStandardPaths>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWheelEvent>

namespace pkm {

/// The OpenGL surface: draws through its view and leaves every input event to it (ignored
/// events go on to the parent).
class LinkageView3D::Canvas : public QOpenGLWidget
{
public:
    explicit Canvas(LinkageView3D *view)
        : QOpenGLWidget(view)
        , m_view(view)
    {
        // On this widget only: the rest of the application keeps the platform's format.
        setFormat(Renderer3D::surfaceFormat());
        setFocusPolicy(Qt::NoFocus);
    }

protected:
    void initializeGL() override { m_view->initializeGl(); }
    void paintGL() override { m_view->paintGl(); }

private:
    LinkageView3D *m_view;
};

LinkageView3D::LinkageView3D(QWidget *parent)
    : QWidget(parent)
{
    setFocusPolicy(Qt::WheelFocus);

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
    // never puts a QOpenGLWidget into a window that cannot composite it.
    static const Renderer3D::Message problem = Renderer3D::probeOpenGLMessage(); // once per process: it makes a context

    if (problem.isEmpty())
        m_canvas = new Canvas(this);
    else
        setUnavailable(problem);
}

LinkageView3D::~LinkageView3D()
{
    cleanupGl();
    // The GL widget goes now, while this object is whole: deleting it destroys its context,
    // whose aboutToBeDestroyed would otherwise reach cleanupGl() from ~QWidget, on a view that
    // is no longer a LinkageView3D.
    Canvas *canvas = m_canvas;
    m_canvas = nullptr;
    delete canvas;
}

QOpenGLWidget *LinkageView3D::glWidget() const
{
    return m_canvas;
}

void LinkageView3D::setUnavailable(const Renderer3D::Message &reason)
{
    m_glFailed = true;
    m_unavailableReason = reason;
    m_unavailableLabel->setText(unavailableText(QLatin1Char('\n')));
    m_unavailableLabel->setGeometry(rect());
    m_unavailableLabel->show();
    m_unavailableLabel->raise();
    if (m_canvas)
        m_canvas->hide();
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
    QWidget::changeEvent(event);
}

void LinkageView3D::requestFrame()
{
    if (m_canvas)
        m_canvas->update();
}

void LinkageView3D::cleanupGl()
{
    if (!m_canvas || !m_renderer.isInitialized())
        return;
    m_canvas->makeCurrent();
    m_renderer.cleanup();
    m_canvas->doneCurrent();
}

void LinkageView3D::initializeGl()
{
    // A new context after reparenting: the old objects went with the old one.
    connect(m_canvas->context(), &QOpenGLContext::aboutToBeDestroyed, this, &LinkageView3D::cleanupGl,
        Qt::UniqueConnection);
    if (!m_renderer.initialize()) {
        setUnavailable(m_renderer.errorMessage());
        return;
    }
    m_glFailed = false;
    m_unavailableReason = {};
    m_unavailableLabel->hide();
}

void LinkageView3D::paintGl()
{
    if (!m_renderer.isInitialized())
        return; // the label says why
    QElapsedTimer timer;
    timer.start();
    syncViewport();
    m_renderer.render(m_camera, m_canvas->size(), m_canvas->devicePixelRatioF());
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
    if (m_canvas && m_renderer.isInitialized() && m_canvas->isValid()) {
        m_canvas->makeCurrent();
        QImage image = m_renderer.renderImage(m_camera, size);
        if (image.isNull())
            m_imageError = m_renderer.errorString();
        m_canvas->doneCurrent();
        return image;
    }
    if (m_glFailed) {
        m_imageError = glStatus();
        return {};
    }
    // Never shown: a context of its own.
    QImage image = Renderer3D::renderOffscreen(m_scene, m_camera, size, &m_imageError);
    return image;
}

void LinkageView3D::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    m_unavailableLabel->setGeometry(rect());
    if (m_canvas)
        m_canvas->setGeometry(rect());
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
    setCursor(m_drag == Drag::Orbit ? Qt::SizeAllCursor : Qt::ClosedHandCursor);
    event->accept();
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
        unsetCursor();
    }
    event->accept();
}

void LinkageView3D::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return QWidget::mouseDoubleClickEvent(event);
    m_drag = Drag::None;
    unsetCursor();
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

// -- View3DPanel ----------------------------------------------------------------------------

View3DPanel::View3DPanel(QWidget *parent)
    : QWidget(parent)
    , m_view(new LinkageView3D(this))
{
    auto *bar = new FlowLayout; // wraps on a narrow screen rather than widening the window
    bar->setContentsMargins(6, 4, 6, 4);
    bar->setSpacing(4);
    auto addButton = [&](const QString &name) {
        auto *button = new QToolButton(this);
        button->setObjectName(name);
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        button->setAutoRaise(false);
        bar->addWidget(button);
        return button;
    };
    auto addSeparator = [&] {
        auto *line = new QFrame(this);
        line->setFrameShape(QFrame::VLine);
        line->setFrameShadow(QFrame::Sunken);
        bar->addWidget(line);
    };
    using View = Camera3D::StandardView;
    m_fitButton = addButton(QStringLiteral("fit"));
    connect(m_fitButton, &QToolButton::clicked, m_view, &LinkageView3D::fit);
    addSeparator();
    const struct {
        QToolButton **button;
        const char *name;
        View view;
    } views[] = {
        {&m_frontButton, "front", View::Front},
        {&m_topButton, "top", View::Top},
        {&m_sideButton, "side", View::Side},
        {&m_isometricButton, "isometric", View::Isometric},
    };
    for (const auto &entry : views) {
        *entry.button = addButton(QString::fromLatin1(entry.name));
        const View view = entry.view;
        connect(*entry.button, &QToolButton::clicked, m_view, [this, view] { m_view->setStandardView(view); });
    }
    addSeparator();
    m_perspectiveButton = addButton(QStringLiteral("perspective"));
    m_perspectiveButton->setCheckable(true);
    m_perspectiveButton->setChecked(m_view->projection() == Camera3D::Projection::Perspective);
    connect(m_perspectiveButton, &QToolButton::toggled, m_view, [this](bool on) {
        m_view->setProjection(on ? Camera3D::Projection::Perspective : Camera3D::Projection::Orthographic);
    });
    connect(m_view, &LinkageView3D::projectionChanged, m_perspectiveButton, [this](Camera3D::Projection projection) {
        m_perspectiveButton->setChecked(projection == Camera3D::Projection::Perspective);
    });
    m_saveButton = addButton(QStringLiteral("savePicture"));
    connect(m_saveButton, &QToolButton::clicked, this, &View3DPanel::savePictureAs);
    retranslate();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addLayout(bar);
    layout->addWidget(m_view, 1);
    m_lastDirectory = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
}

void View3DPanel::retranslate()
{
    m_fitButton->setText(tr("Fit"));
    m_fitButton->setToolTip(tr("Show the whole mechanism (F, or double-click)"));
    m_frontButton->setText(tr("Front"));
    m_frontButton->setToolTip(tr("Look at the mechanism plane, as the 2D view does (1)"));
    m_topButton->setText(tr("Top"));
    m_topButton->setToolTip(tr("Look down from above (7)"));
    m_sideButton->setText(tr("Side"));
    m_sideButton->setToolTip(tr("Look from the right (3)"));
    m_isometricButton->setText(tr("Isometric"));
    m_isometricButton->setToolTip(tr("Look from the front, right and above at once"));
    m_perspectiveButton->setText(tr("Perspective"));
    m_perspectiveButton->setToolTip(tr("Perspective when on, orthographic (true to scale) when off (5)"));
    m_saveButton->setText(tr("Save picture…"));
    m_saveButton->setToolTip(tr("Save the 3D view as a PNG picture at twice its size"));
}

void View3DPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

bool View3DPanel::savePicture(const QString &path, QString *error)
{
    const QSize base = m_view->size().isEmpty() ? m_view->sizeHint() : m_view->size();
    return savePicture(path, 2 * base, error);
}

bool View3DPanel::savePicture(const QString &path, const QSize &size, QString *error)
{
    auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    if (size.width() < 16 || size.height() < 16 || size.width() > 8000 || size.height() > 8000)
        return fail(tr("%1 × %2 pixels is not a picture size: each side must be from 16 to 8000.")
                        .arg(size.width())
                        .arg(size.height()));
    const QImage image = m_view->renderImage(size);
    if (image.isNull())
        return fail(tr("The picture could not be rendered. %1").arg(m_view->imageError()));
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(tr("“%1” could not be opened for writing: %2").arg(path, file.errorString()));
    if (!image.save(&file, "PNG")) {
        file.cancelWriting();
        return fail(tr("The picture could not be written to “%1”.").arg(path));
    }
    if (!file.commit())
        return fail(tr("“%1” could not be saved: %2").arg(path, file.errorString()));
    return true;
}

void View3DPanel::savePictureAs()
{
    const QString suggested = m_lastDirectory.isEmpty() ? QStringLiteral("mechanism-3d.png")
                                                        : m_lastDirectory + QStringLiteral("/mechanism-3d.png");
    QString path = QFileDialog::getSaveFileName(this, tr("Save picture"), suggested, tr("PNG pictures (*.png)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path.append(QStringLiteral(".png"));
    m_lastDirectory = QFileInfo(path).absolutePath();
    // the size: twice the view (sharp on a projector), or a common screen or print size
    const QSize base = m_view->size().isEmpty() ? m_view->sizeHint() : m_view->size();
    const QList<QSize> sizes = {2 * base, QSize(1920, 1080), QSize(3840, 2160), QSize(4000, 3000)};
    QStringList items;
    for (const QSize &size : sizes)
        items << tr("%1 × %2 pixels").arg(size.width()).arg(size.height());
    items[0] = tr("%1 (twice the view)").arg(items[0]);
    bool ok = false;
    const QString chosen = QInputDialog::getItem(this, tr("Save picture"), tr("Picture size:"), items, 0, false, &ok);
    if (!ok)
        return;
    QString error;
    if (!savePicture(path, sizes[items.indexOf(chosen)], &error))
        QMessageBox::warning(this, tr("Save picture"), error);
}

} // namespace pkm
