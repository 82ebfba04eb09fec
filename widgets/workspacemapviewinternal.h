// What the workspace map view's files share: the result a worker hands to the GUI thread and
// the running job (the view in workspacemapview.cpp, the computation in workspacemapcompute.cpp,
// the results shown in workspacemapresults.cpp), and the determinant's colour gradient.
#pragma once

#include "capabilitymap.h"
#include "workspacemapview.h"

#include <qcustomplot.h>

#include <QFutureWatcher>

#include <atomic>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace pkm {

/// A finished computation, built entirely on the worker thread: the GUI thread only hands
/// `colours` to the colour map and copies the curves.
struct WorkspaceMapResult {
    MapSummary summary;
    MapQuantity quantity = MapQuantity::Determinant;
    std::vector<float> values;                 ///< as computed (NaN: unreachable)
    std::unique_ptr<QCPColorMapData> colours;  ///< values clipped to the colour range; null for a comparison
    double colourLimit = 0.0;                  ///< det J: ±limit; κ: 1…limit
    QVector<QCPCurveData> outline;             ///< closed polylines separated by NaN points
    QVector<QCPCurveData> inverse, direct;     ///< singular curves, separated by NaN points
    int inverseCount = 0, directCount = 0;
    std::string inverseMeaning, directMeaning; ///< for the legend
    /// A capability map's entry (English sources from core) and its specification's area.
    std::string symbol, label, unit;
    capability::SpecificationSummary specification;
};

struct WorkspaceMapView::Job {
    JobKind kind = JobKind::Map;
    int generation = 0;
    std::shared_ptr<std::atomic<bool>> cancel;
    QFutureWatcher<std::shared_ptr<WorkspaceMapResult>> *watcher = nullptr;
};

namespace workspacemap {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// det J: blue (negative) – white (0, direct singularity) – orange (positive).
QCPColorGradient determinantGradient();
/// What the actuators deliver: dark (little, near a singularity) to yellow (much).
QCPColorGradient capabilityGradient();
/// The specification: grey where a requirement fails, green where all hold.
QCPColorGradient specificationGradient();

/// "−46.3", "1.34", "1.41·10⁵": three significant digits, a real minus sign, powers of ten
/// written out for very large and very small magnitudes.
QString significant(double value);

/// A capability map or the specification (workspacemapcapability.cpp) into `result` on the
/// worker: values in display units, the entry's texts, the specification's area.
MapSummary computeCapability(const Mechanism &mechanism, const Pose &pose, MapQuantity quantity,
                             const std::vector<capability::Requirement> &requirements, const MapGrid &grid,
                             WorkspaceMapResult &result, std::span<float> margins, const std::atomic<bool> *cancel);

/// The worst-case error from `tolerances` (core units) into `result` on the worker, in mm,
/// with det J's margins; an empty map if the tolerances cannot be analysed.
MapSummary computeTolerance(const MechanismPtr &mechanism, const Pose &pose, const ParameterSet &tolerances,
                            const MapGrid &grid, WorkspaceMapResult &result, std::span<float> margins,
                            const std::atomic<bool> *cancel);

} // namespace workspacemap

} // namespace pkm
