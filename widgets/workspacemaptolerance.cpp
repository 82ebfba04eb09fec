// The workspace map of the worst-case error from the design's tolerances (core/tolerancemap.h):
// an entry of the Map list while the design has tolerances, computed on the worker with det J's
// margins, shown like the maps of what the actuators deliver (a scale from 0, a title in words).

#include "workspacemapview.h"
#include "workspacemapviewinternal.h"

#include "tolerancemap.h"

#include <QComboBox>

namespace pkm {

namespace {
const char *const toleranceItem = QT_TRANSLATE_NOOP("pkm::WorkspaceMapView", "worst-case error from the tolerances");
} // namespace

namespace workspacemap {

MapSummary computeTolerance(const MechanismPtr &mechanism, const Pose &pose, const ParameterSet &tolerances,
                            const MapGrid &grid, WorkspaceMapResult &result, std::span<float> margins,
                            const std::atomic<bool> *cancel)
{
    const PlanarWorkspace *workspace = mechanism->planarWorkspace();
    auto analysis = tolerance::Analysis::make(mechanism, tolerances);
    MapSummary summary;
    summary.grid = grid;
    if (!workspace || !analysis) { // the document's tolerances are checked: not reached in use
        std::fill(result.values.begin(), result.values.end(), std::numeric_limits<float>::quiet_NaN());
        return summary;
    }
    // det J's margins (where a singularity is near) on the same grid, then the error itself
    const MapSummary closed = computeMap(*workspace, MapQuantity::Determinant, grid, result.values, margins, cancel);
    const Pose start = capability::mapStart(
        *mechanism, pose.outputs.size() == mechanism->homePose().outputs.size() ? pose : mechanism->homePose());
    summary = tolerance::computeMap(*analysis, start, grid, result.values, cancel);
    summary.nearSingularCells = closed.nearSingularCells;
    summary.cancelled = summary.cancelled || closed.cancelled;
    result.symbol = "|Δx|";
    result.label = QT_TRANSLATE_NOOP("core", "worst-case error from the tolerances");
    result.unit = tolerance::normUnit(*mechanism).symbol;
    return summary;
}

} // namespace workspacemap

void WorkspaceMapView::syncToleranceItem()
{
    const bool offered = m_mechanism && m_mechanism->planarWorkspace() && !m_tolerances.empty();
    const int index = m_quantityBox->findData(int(MapQuantity::ToleranceWorst));
    if (offered == (index >= 0))
        return;
    const QSignalBlocker blocker(m_quantityBox);
    if (offered) {
        m_quantityBox->addItem(tr(toleranceItem), int(MapQuantity::ToleranceWorst));
        return;
    }
    m_quantityBox->removeItem(index);
    if (m_quantity == MapQuantity::ToleranceWorst) {
        m_quantity = MapQuantity::Determinant;
        requestMap();
    }
    m_quantityBox->setCurrentIndex(m_quantityBox->findData(int(m_quantity)));
}

void WorkspaceMapView::retranslateToleranceItem()
{
    if (const int index = m_quantityBox->findData(int(MapQuantity::ToleranceWorst)); index >= 0)
        m_quantityBox->setItemText(index, tr(toleranceItem));
}

} // namespace pkm
