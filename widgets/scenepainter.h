#pragma once
/// Draws a pkm::Scene as a clean engineering drawing onto any QPainter — a widget, a QImage,
/// a QSvgGenerator or a QPdfWriter — so the screen and every export show the same picture.
///
/// Geometry (positions, the motor body, the screw) scales with the mapping; symbols and text
/// (pivots, arrowheads, labels) have a fixed size in style pixels, so a zoomed-out drawing
/// stays readable on a projector.

#include "scene.h"

#include <Eigen/Core>

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QString>

class QPainter;

namespace pkm {

/// Scene mm (y up) to device coordinates (y down).
struct ViewMapping {
    double scale = 1.0; ///< device units per mm
    QPointF origin; ///< device point of scene (0, 0)

    /// Any 2- or 3-vector (z ignored) or expression of one.
    template<class Derived> QPointF toDevice(const Eigen::MatrixBase<Derived> &mm) const
    {
        return {origin.x() + scale * double(mm.x()), origin.y() - scale * double(mm.y())};
    }
    Eigen::Vector2d toScene(const QPointF &device) const
    {
        return {(device.x() - origin.x()) / scale, (origin.y() - device.y()) / scale};
    }

    /// The mapping that shows `extent` (its x–y box) centred in `target`, `margin` device
    /// units inside each edge. An empty extent maps 1 mm to 1 unit about the target's centre.
    static ViewMapping fit(const Eigen::AlignedBox3d &extent, const QRectF &target, double margin);
};

/// Colours and sizes. Sizes are in style pixels; `pixelSize` converts them to device units,
/// so an exporter to a 600 dpi device sets pixelSize = 600/96 and gets the screen's proportions.
struct SceneStyle {
    double pixelSize = 1.0; ///< device units per style pixel

    QColor background {0xfb, 0xfc, 0xfe};
    QColor gridMinor {0xec, 0xef, 0xf4};
    QColor gridMajor {0xd8, 0xde, 0xe8};
    QColor ink {0x1c, 0x20, 0x26}; ///< outlines, ground, dimensions, text
    QColor crank {0x1f, 0x5f, 0xbf}; ///< blue
    QColor coupler {0xd9, 0x6a, 0x10}; ///< orange
    QColor link {0x2e, 0x8b, 0x57}; ///< green
    QColor rod {0x6a, 0x3d, 0x9a}; ///< purple
    QColor platform {0x00, 0x83, 0x8f}; ///< teal
    QColor motorBody {0x3b, 0x41, 0x4a};
    QColor motorCap {0x9a, 0xa4, 0xb0};
    QColor screw {0xb4, 0xbc, 0xc6}; ///< metallic
    QColor screwShade {0x5d, 0x66, 0x72}; ///< screw outline and thread
    QColor angle {0x9c, 0x1f, 0x6e}; ///< arcs and their labels
    QColor path {0x8a, 0x5a, 0xa8}; ///< coupler curves and other paths, drawn thin
    QColor dimension {0x2b, 0x33, 0x3d};
    QColor handle {0x1e, 0x88, 0xe5};
    QColor guideFill {0xdc, 0xe2, 0xea}; ///< light steel rail
    QColor guideOutline {0x4e, 0x59, 0x67}; ///< rail outline, end stops, hatching, its label
    QColor carriage {0x7b, 0x8a, 0x9e}; ///< slider block on a rail
    QColor ghost {0x4c, 0x5e, 0x7a}; ///< desaturated blue-grey of the other modes' poses

    double groundWidth = 2.5; ///< ground bar pen
    double barWidth = 7.0; ///< crank, coupler, link pen
    double pivotRadius = 6.0;
    double arrowLength = 11.0;
    double arrowWidth = 7.0;
    double fontPixels = 16.0; ///< dimension, angle and bar labels (≈ 12 pt at 96 dpi)
    double jointFontPixels = 18.0; ///< bold joint names
    double minimumScrewWidth = 3.0;
    double ghostOpacity = 0.35; ///< of a ghost scene; a hovered one is drawn stronger
    bool showHandles = true; ///< rings around draggable joints (off for exported drawings)
};

class ScenePainter
{
public:
    /// Draws the scene (not the background). `activeHandle` (index into scene.handles, −1
    /// none) is the hovered or dragged handle, drawn strongly highlighted.
    static void paint(QPainter &painter, const Scene &scene, const ViewMapping &mapping, const SceneStyle &style,
        int activeHandle = -1);
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
    /// A scale bar ("50 mm") in the bottom-right corner of `area`.
    static void paintScaleBar(
        QPainter &painter, const QRectF &area, const ViewMapping &mapping, const SceneStyle &style);
    /// A one-line message in a rounded box at the bottom-left of `area`; nothing when empty.
    static void paintMessage(QPainter &painter, const QRectF &area, const QString &message, const SceneStyle &style);

    /// Grid spacing in mm: the smallest 1/2/5×10ⁿ with spacing × scale ≥ minimumDevice.
    static double niceStep(double minimumDevice, double scale);
};

} // namespace pkm
