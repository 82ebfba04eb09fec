// What the workspace map view's files share: the result a worker hands to the GUI thread and
// the running job (the view in workspacemapview.cpp, the computation in workspacemapcompute.cpp,
// the results shown in workspacemapresults.cpp), and the determinant's colour gradient.
#pragma once

#include "workspacemapview.h"

#include <qcustomplot.h>

#include <QFutureWatcher>

#include <atomic>
#include <limits>
#include <memory>
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

} // namespace workspacemap

} // namespace pkm
