#pragma once
/// The 2D picture of a mechanism in a pose, on any paint device (PNG, SVG, PDF, GIF frames,
/// the parameter sheet): background and grid, the scene fitted above a band for the scale bar
/// and a caption naming the design and the pose.

#include "mechanism.h"

#include <QFont>
#include <QString>

class QPainter;
class QRectF;

namespace pkm {
struct Scene;
struct SceneStyle;
} // namespace pkm

namespace pkm::pictures {

/// The caption of a picture of any pose: "NAME — θ = 30.00°, d = 187.13 mm", every pose
/// variable in display units and the pose's words; the pose alone when `name` is empty.
QString poseCaption(const Mechanism &mechanism, const Pose &pose, const QString &name);

/// Draws the 2D picture into `area` of any paint device: background and grid, the scene fitted
/// above a band for the scale bar and the caption (none when empty), no handle rings.
void paintScenePicture(
    QPainter &painter, const QRectF &area, const Scene &scene, const SceneStyle &style, const QString &caption);

/// Draws `caption` at the bottom-left of `area` on a light knock-out, elided so that it keeps
/// clear of the scale bar's corner (`rightReserve` device units from the right edge).
void paintCaption(
    QPainter &painter, const QRectF &area, const QString &caption, const SceneStyle &style, double rightReserve);

/// The caption's font: the application's, at the scene's label size.
QFont captionFont(const SceneStyle &style);
/// What a 3D picture keeps free at the bottom for the caption: its margin, text and knock-out.
double captionBand(const SceneStyle &style);

} // namespace pkm::pictures
