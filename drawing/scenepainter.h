#pragma once
/// Draws a pkm::Scene as a clean engineering drawing onto any QPainter — a widget, a QImage,
/// a QSvgGenerator or a QPdfWriter — so the screen and every export show the same picture:
/// the scene's one layout (scenelayout.h), rendered by paintDrawList(), with what a view adds
/// around it (background grid, scale bar, message).

#include "scene.h"
#include "scenestyle.h"

#include <Eigen/Core>

#include <QColor>
#include <QFont>
#include <QList>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <utility>
#include <vector>

class QPainter;
class QPaintDevice;

namespace pkm {

class ScenePainter
{
public:
    /// Draws the scene (not the background). `activeHandle` (index into scene.handles, −1
    /// none) is the hovered or dragged handle, drawn strongly highlighted; the labels keep off
    /// the `ghosts` drawn under it and the `scaleBar` box drawn over it where they can.
    /// `labelPlaces` (a view's, kept from frame to frame; null: none) holds where the labels
    /// stood in the frame before, which they keep while it is as good, and gets where they stand.
    static void paint(QPainter &painter, const Scene &scene, const ViewMapping &mapping, const SceneStyle &style,
        int activeHandle = -1, const QList<Scene> &ghosts = {}, const QRectF &scaleBar = {},
        std::vector<std::pair<QString, QPointF>> *labelPlaces = nullptr);
    /// Draws `scene` as a ghost — another pose the mechanism could take (another assembly or
    /// working mode) — to go under the real one: faded, blue-grey, links dashed, no ground,
    /// guides, labels, dimensions, angles or handles. `highlighted` (hovered) draws it
    /// stronger, in the handle colour.
    static void paintGhost(QPainter &painter, const Scene &scene, const ViewMapping &mapping, const SceneStyle &style,
        bool highlighted = false);

    /// Fills `area` with the background and a mm grid whose spacing (1/2/5×10ⁿ mm) keeps the
    /// lines at least `minimumGridPixels` style pixels apart.
    static void paintBackground(QPainter &painter, const QRectF &area, const ViewMapping &mapping,
        const SceneStyle &style, double minimumGridPixels = 40.0);
    /// The translucent rounded box in the background colour that keeps text readable over
    /// the drawing (under the scale bar, a caption).
    static void paintKnockout(QPainter &painter, const QRectF &box, const SceneStyle &style);
    /// How much of the bottom of an area the scale bar takes: its margin, tick, text and
    /// knock-out (paintScaleBar()), device units of `device` (null: the screen's).
    static double scaleBarHeight(const SceneStyle &style, const QPaintDevice *device);
    /// ViewMapping::fit() of `extent` into `room`, fitted again in less room where a label of
    /// the drawing, which keeps its size in pixels, is cut by the edge of `labelRoom` (the
    /// view less what the scale bar covers): a narrow view then shows "B · 2a" whole instead
    /// of its first letters. Labels wholly outside (a far instantaneous centre's) do not count.
    static ViewMapping fitWithLabels(const Scene &scene, const Eigen::AlignedBox3d &extent, const QRectF &room,
        const QRectF &labelRoom, double margin, const SceneStyle &style);
    /// A scale bar ("50 mm") in the bottom-right corner of `area`.
    /// The box the scale bar covers in `area` (its white knockout), device units.
    static QRectF scaleBarBox(const QRectF &area, const ViewMapping &mapping, const SceneStyle &style,
        const QPaintDevice *device);
    static void paintScaleBar(
        QPainter &painter, const QRectF &area, const ViewMapping &mapping, const SceneStyle &style);
    /// The scene's legend (Scene::legend: what the capability shapes are and their scales) in a
    /// box at the top-left of `area`, each line after a sample of its pen: solid for the
    /// polygon, dashed for the ellipse; long lines wrap. Nothing when the legend is empty.
    static void paintLegend(QPainter &painter, const QRectF &area, const Scene &scene, const SceneStyle &style);
    /// A picture of the scene in `area`, clipped to it: background, scene, scale bar and legend;
    /// `labelPlaces` as paint()'s (an animation's frames).
    static void paintPicture(QPainter &painter, const QRectF &area, const Scene &scene, const ViewMapping &mapping,
        const SceneStyle &style, std::vector<std::pair<QString, QPointF>> *labelPlaces = nullptr);
    /// How much of the top of `area` the legend takes, its margin included (0: no legend): a
    /// fit leaves it free, so that the legend covers none of the mechanism.
    static double legendHeight(const QRectF &area, const Scene &scene, const SceneStyle &style, QPaintDevice *device);
    /// A message in a rounded box at the bottom-left of `area`, wrapped onto as many lines as it
    /// needs (never cut); nothing when empty.
    /// Where the joints of `scene` are drawn, with their rings and a label's height round them.
    static QRectF jointBounds(const Scene &scene, const ViewMapping &mapping, const SceneStyle &style);
    /// `drawing`, where the mechanism is drawn (device), is kept clear where the message can go
    /// at the top of `area` instead of the bottom and covers less of it there; `joints`, where
    /// its joints are (device), above all.
    static void paintMessage(QPainter &painter, const QRectF &area, const QString &message, const SceneStyle &style,
        const QRectF &drawing = QRectF(), const std::vector<QPointF> &joints = {});
    /// Where the joints of `scene` are drawn (device), points of interest left out.
    static std::vector<QPointF> jointPoints(const Scene &scene, const ViewMapping &mapping);
    /// Where paintMessage() puts `message` on `device`: the box, the rectangle of the text
    /// inside it, the font and flags it is drawn with, and what it says (the message, or its
    /// headline when the whole one would cover the drawing wherever it went).
    struct MessageLayout {
        QRectF box;
        QRectF text;
        QString message;
        QFont font;
        int flags = 0;
    };
    static MessageLayout messageLayout(const QRectF &area, const QString &message, const SceneStyle &style,
        QPaintDevice *device, const QRectF &drawing = QRectF(), const std::vector<QPointF> &joints = {});

    /// Grid spacing in mm: the smallest 1/2/5×10ⁿ with spacing × scale ≥ minimumDevice.
    static double niceStep(double minimumDevice, double scale);
};

} // namespace pkm
