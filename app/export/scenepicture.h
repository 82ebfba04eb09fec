#pragma once
/// The 2D picture of a mechanism in a pose, on any paint device (PNG, SVG, PDF, GIF frames,
/// the parameter sheet): background and grid, the scene fitted above a band for the scale bar
/// and a caption naming the design and the pose.

#include "mechanism.h"

#include <QFont>
#include <QFontMetricsF>
#include <QPointF>
#include <QStringList>
#include <QString>

#include <utility>
#include <vector>

class QPaintDevice;
class QPainter;
class QRectF;

namespace pkm {
struct Scene;
struct SceneStyle;
struct ViewMapping;
} // namespace pkm

namespace pkm::pictures {

/// The caption of a picture of any pose: "NAME — θ = 30.00°, d = 187.13 mm", every pose
/// variable in display units and the pose's words; the pose alone when `name` is empty.
QString poseCaption(const Mechanism &mechanism, const Pose &pose, const QString &name);

/// How a picture fits its scene: a still as Fit on the screen, smaller where a label would be
/// cut at the edge (MOMA's γ₁ beside its guide); an animation's frame to the motion range
/// alone, so that every frame has the same scale whatever its labels.
enum class PictureFit { LabelsWhole, MotionRange };

/// The mapping paintScenePicture() draws `scene` with into `area` on `device`.
ViewMapping pictureMapping(const QRectF &area, const Scene &scene, const SceneStyle &style, PictureFit fit,
    const QPaintDevice *device);

/// Draws the 2D picture into `area` of any paint device: background and grid, the scene fitted
/// above a band for the scale bar and the caption (none when empty), no handle rings.
/// `labelPlaces`: an animation's, kept from frame to frame (ScenePainter::paint()).
void paintScenePicture(QPainter &painter, const QRectF &area, const Scene &scene, const SceneStyle &style,
    const QString &caption, PictureFit fit = PictureFit::LabelsWhole,
    std::vector<std::pair<QString, QPointF>> *labelPlaces = nullptr);

/// `caption` as it is drawn in `available` device units of width: one line, or two broken
/// after a comma where one is too long; a line still too long ends in "…".
QStringList captionLines(const QString &caption, const QFontMetricsF &metrics, double available);

/// Draws `caption` at the bottom-left of `area` on a light knock-out (captionLines()), so that
/// it keeps clear of the scale bar's corner (`rightReserve` device units from the right edge).
void paintCaption(
    QPainter &painter, const QRectF &area, const QString &caption, const SceneStyle &style, double rightReserve);

/// The caption's font: the application's, at the scene's label size.
QFont captionFont(const SceneStyle &style);
/// What a 3D picture keeps free at the bottom for the caption: its margin, text and knock-out.
double captionBand(const SceneStyle &style);

} // namespace pkm::pictures
