#pragma once
/// The one layout of a scene's drawing: a pkm::Scene in one pose becomes placed, styled
/// primitives (drawlist.h) — members, pins, the ground, guides and carriages, actuators,
/// dimensions, angles, paths and every label at the place chosen for it. The screen, the
/// pictures, the GIF frames, the sheet and the DXF file all render this list, so they show the
/// same drawing, labels included.
///
/// Geometry (positions, the motor body, the screw) scales with the mapping; symbols and text
/// (pivots, arrowheads, labels) have a fixed size in style pixels, so a zoomed-out drawing
/// stays readable on a projector.

#include "drawlist.h"
#include "scene.h"
#include "scenestyle.h"

#include <QLineF>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <limits>
#include <utility>
#include <vector>

class QPaintDevice;

namespace pkm::drawing {

/// Where each label of a drawing stood relative to what it names, by its text (a value by its
/// symbol), device units: a moving drawing's last
/// frame, so that the next keeps each label on its side while that side stays free.
using LabelPlaces = std::vector<std::pair<QString, QPointF>>;

struct LayoutOptions {
    /// The hovered or dragged handle (index into scene.handles, −1 none), drawn highlighted.
    int activeHandle = -1;
    /// A free point (an instantaneous centre) this many times the extent's size outside the
    /// range of motion is left out (shownJoints, scene.h): a file has no window to clip it.
    double farPointMargin = std::numeric_limits<double>::infinity();
    /// The device whose font metrics size the labels (a printer's differ from a screen's);
    /// null: the screen's.
    const QPaintDevice *device = nullptr;
    /// Where labels may stand, device units (the view's rectangle: a label past its edge is
    /// cut); empty: anywhere (a file's drawing grows to hold them).
    QRectF labelRoom;
    /// Lines the labels keep off where they can, device units: on screen the other modes'
    /// ghosts under the scene (MOMA's R₁ had stood on a ghost's dashes). ghostLines() gives them.
    std::vector<QLineF> avoid;
    /// Boxes drawn over the scene afterwards, device units (the scale bar): a label under one
    /// would be hidden, so the labels go there only where nothing else is left.
    std::vector<QRectF> covered;
    /// The labels' places in the frame before (null: none). Of the places as good as the best,
    /// a label takes the one nearest where it stood: during Play, MOMA's Z₁, PO₁ and S₂ had
    /// jumped between two equally free sides from one frame to the next.
    const LabelPlaces *previousLabels = nullptr;
    /// Where the labels were placed, written for the next frame (null: not wanted).
    LabelPlaces *placedLabels = nullptr;
};

/// The drawing of `scene` with `mapping` and `style`.
DrawList layoutScene(const Scene &scene, const ViewMapping &mapping, const SceneStyle &style,
    const LayoutOptions &options = {});

/// `scene` as a ghost — another pose the mechanism could take (another assembly or working
/// mode) — to go under the real one: faded, blue-grey, links dashed, no ground, guides,
/// labels, dimensions, angles or handles. `highlighted` (hovered) draws it stronger, in the
/// handle colour. Screen only.
/// The members layoutGhost() draws of `scene`, device units, for LayoutOptions::avoid.
std::vector<QLineF> ghostLines(const Scene &scene, const ViewMapping &mapping);

DrawList layoutGhost(const Scene &scene, const ViewMapping &mapping, const SceneStyle &style, bool highlighted);

/// Adds `caption` as a line of text under what `list` shows in CAD, left-aligned with it.
void addCaption(DrawList &list, const QString &caption, const SceneStyle &style, const QPaintDevice *device = nullptr);

} // namespace pkm::drawing
