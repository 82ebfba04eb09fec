#pragma once
/// The plot beside the mechanism in an animation's frames: one scalar quantity of the report
/// (Mechanism::reportLayout) over the swept variable, with a cursor and a read-out of its value
/// at each frame's pose — `pkm render … --plot QUANTITY -o FILE.mp4`, and the GUI's export
/// when it plots a quantity rather than the plot on screen. Drawn with QPainter alone, so it is
/// thread-safe and needs no widget.
///
/// The curve is solved along the animation's own path: each sample from the one before, from
/// the animation's first pose, so it stays in the assembly mode the mechanism is shown in.
/// A sample without a pose and a value that is not finite (at a singular pose) break the line.

#include "export/animation.h"

#include <QImage>
#include <QPointF>
#include <QSize>
#include <QString>

#include <string>
#include <vector>

namespace pkm {

/// The quantities an animation of `variable` can plot: the report's scalar entries, the swept
/// variable's own left out.
std::vector<const ReportEntry *> animationPlotQuantities(const Mechanism &mechanism, int variable);

struct AnimationPlot {
    QString title;  ///< "diagonal length against crank angle"
    QString xLabel; ///< "θ (°)"
    QString yLabel; ///< "d (mm)"
    std::vector<QPointF> curve; ///< display units; NaN in y breaks the line
    double xMin = 0.0, xMax = 1.0, yMin = 0.0, yMax = 1.0;
    int variable = 0;
    ReportEntry entry; ///< the quantity: where it is in the buffer, its unit and symbol
};

/// Samples along the swept range.
inline constexpr int animationPlotSamples = 241;

/// The plot of `quantity` (a report entry's name) over the animation's range from `start`;
/// the failure names the quantity when the mechanism has no such scalar.
Result<AnimationPlot> animationPlot(const Mechanism &mechanism, const Pose &start, const AnimationSettings &settings,
                                    const std::string &quantity);

/// What the plot reads out at `pose`: "d = 183.07 mm"; "∞" or "—" where a singular pose leaves
/// the value infinite or undefined (settleSingularValues), never a huge number.
QString animationPlotReadout(const AnimationPlot &plot, const Mechanism &mechanism, const Pose &pose);

/// The plot at `size` pixels with its cursor at `pose`; thread-safe.
QImage animationPlotImage(const AnimationPlot &plot, const Mechanism &mechanism, const Pose &pose, QSize size);

} // namespace pkm
