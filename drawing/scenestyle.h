#pragma once
/// How a scene maps onto a device and how it is styled: shared by the layout of a scene's
/// drawing (scenelayout.h), every medium that renders it and the views that pan and zoom it.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QColor>
#include <QPointF>
#include <QRectF>

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
    QColor velocity {0xd8, 0x1b, 0x60}; ///< velocity polygon and ellipse (raspberry)
    QColor force {0x39, 0x49, 0xab}; ///< force polygon and ellipse (indigo)
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

} // namespace pkm
