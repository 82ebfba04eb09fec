#include "gui/viewpicture.h"

#include "export/scenepicture.h"

#include <qcustomplot.h>

#include <QCoreApplication>
#include <QFileInfo>
#include <QMessageBox>
#include <QRectF>

namespace pkm::viewpicture {

QByteArray scenePicture(const Scene &scene, const SceneStyle &style, const QString &caption, const QString &format,
    const PictureOptions &options, const QSize &shown, QString *error)
{
    const double scale = options.scale > 0.0 ? options.scale : pictureScale(options.size, shown);
    // The scene's labels are sized in pixels: the DPI the fonts are drawn at does not matter.
    return paintPicture(
        format, options, 96,
        [&](QCPPainter &painter, const QRectF &area) {
            SceneStyle drawn = style;
            // device units per style pixel: the picture's pixels at the scale (a PDF's device
            // units are not its pixels)
            drawn.pixelSize = style.pixelSize * scale * area.width() / options.size.width();
            pictures::paintScenePicture(painter, area, scene, drawn, caption);
        },
        error);
}

QByteArray posePicture(const Mechanism &mechanism, const Pose &pose, const QString &name, const SceneStyle &style,
    const QString &format, const PictureOptions &options, const QSize &shown, QString *error, const Scene *drawn)
{
    PictureOptions picture = options;
    const QString caption = pictures::poseCaption(mechanism, pose, name);
    if (picture.title.isEmpty())
        picture.title = caption;
    return scenePicture(drawn ? *drawn : mechanism.scene(pose), style, caption, format, picture, shown, error);
}

QString suggestedName(const QString &filePath, const QString &designId)
{
    QString base = QFileInfo(filePath.isEmpty() ? designId : filePath).fileName();
    for (const QLatin1String suffix : {QLatin1String(".json"), QLatin1String(".pkm")}) {
        if (base.endsWith(suffix, Qt::CaseInsensitive))
            base.chop(suffix.size());
    }
    return (base.isEmpty() ? QStringLiteral("linkage") : base) + QStringLiteral("-2d");
}

QString savePictureAs(QWidget *parent, const Mechanism &mechanism, const Pose &pose, const QString &name,
    const QString &fileName, const QSize &shown, const SceneStyle &style, const Scene *drawn)
{
    const QString title = QCoreApplication::translate("pkm::ViewPicture", "Save 2D View Picture");
    const std::optional<PictureRequest> request = askForPicture(parent, title, fileName, shown);
    if (!request)
        return {};
    QString error;
    const QByteArray bytes
        = posePicture(mechanism, pose, name, style, request->format, request->options, shown, &error, drawn);
    if (bytes.isEmpty() || !savePictureFile(request->path, bytes, &error)) {
        QMessageBox::warning(parent, title, error);
        return {};
    }
    return request->path;
}

} // namespace pkm::viewpicture
