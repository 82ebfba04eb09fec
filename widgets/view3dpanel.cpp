// The 3D view's panel: a row of large text buttons a classroom can read on a projector (Fit,
// the standard views, perspective, the names of the points, Save picture) over the view.

#include "linkageview3d.h"

#include "flowlayout.h"
#include "labels3d.h"

#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFrame>
#include <QInputDialog>
#include <QMessageBox>
#include <QSaveFile>
#include <QStandardPaths>
#include <QToolButton>
#include <QVBoxLayout>

namespace pkm {

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
    m_labelsButton = addButton(QStringLiteral("labels"));
    m_labelsButton->setCheckable(true);
    m_labelsButton->setChecked(m_view->labelsShown());
    connect(m_labelsButton, &QToolButton::toggled, m_view, &LinkageView3D::setLabelsShown);
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
    m_labelsButton->setText(tr("Names"));
    m_labelsButton->setToolTip(tr("The names of the joints (A, B, … as in the 2D view) over the model"));
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
