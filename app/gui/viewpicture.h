#pragma once
/// File ▸ Save 2D View Picture…: the current design and pose as PNG (a chosen size and DPI),
/// SVG or PDF, drawn as `pkm render` draws it (pictures::paintScenePicture(): background, mm grid,
/// the mechanism fitted, scale bar, and a caption naming the design and the pose). The dialogs
/// and the size rules are the plots' (pictureexport.h): a picture larger than the view is the
/// view enlarged, its labels and lines in proportion.

#include "mechanism.h"
#include "pictureexport.h"
#include "scenepainter.h"

#include <QByteArray>
#include <QSize>
#include <QString>

class QWidget;

namespace pkm {
struct Scene;
}

namespace pkm::viewpicture {

/// The 2D picture of `scene` with `caption` (none when empty) in `format` ("png", "svg",
/// "pdf"), laid out as a view of `shown` pixels would be. Empty bytes with `error` set on failure.
QByteArray scenePicture(const Scene &scene, const SceneStyle &style, const QString &caption, const QString &format,
    const PictureOptions &options, const QSize &shown, QString *error);

/// The picture of `mechanism` in `pose`, captioned pictures::poseCaption(mechanism, pose, name):
/// the mechanism's scene, or `drawn` (the view's, with what it adds) when given.
QByteArray posePicture(const Mechanism &mechanism, const Pose &pose, const QString &name, const SceneStyle &style,
    const QString &format, const PictureOptions &options, const QSize &shown, QString *error,
    const Scene *drawn = nullptr);

/// The file name offered for the picture, without a suffix: "pjoint-prototype-2d" for a preset
/// (its id), "my-design-2d" for my-design.pkm.json.
QString suggestedName(const QString &filePath, const QString &designId);

/// Asks for the file, size and DPI (askForPicture()), draws and writes the picture. The path
/// written, or empty when cancelled or failed (the failure shown in a message box over `parent`).
QString savePictureAs(QWidget *parent, const Mechanism &mechanism, const Pose &pose, const QString &name,
    const QString &fileName, const QSize &shown, const SceneStyle &style, const Scene *drawn = nullptr);

} // namespace pkm::viewpicture
