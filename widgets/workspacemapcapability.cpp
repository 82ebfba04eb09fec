// The workspace map of what the actuators deliver (force, speed, resolution, stiffness at the
// platform) and of the specification region: computed on the worker by solving every cell
// (core/capabilitymap.h), shown with a sequential colour scale from 0, titled in words.

#include "workspacemapview.h"
#include "workspacemapviewinternal.h"

#include "plotstyle.h"
#include "quantityformat.h"

#include <qcustomplot.h>

#include <QComboBox>

#include <array>

namespace pkm {

namespace {

struct CapabilityItem {
    MapQuantity quantity;
    const char *text; ///< tr() source, in the context WorkspaceMapView
};
constexpr std::array<CapabilityItem, 5> capabilityItems = {{
    {MapQuantity::ForceWorst, QT_TRANSLATE_NOOP("pkm::WorkspaceMapView", "force in the weakest direction")},
    {MapQuantity::SpeedWorst, QT_TRANSLATE_NOOP("pkm::WorkspaceMapView", "speed in the slowest direction")},
    {MapQuantity::ResolutionWorst, QT_TRANSLATE_NOOP("pkm::WorkspaceMapView", "worst resolution")},
    {MapQuantity::StiffnessWorst, QT_TRANSLATE_NOOP("pkm::WorkspaceMapView", "stiffness in the weakest direction")},
    {MapQuantity::Specification, QT_TRANSLATE_NOOP("pkm::WorkspaceMapView", "where the requirements hold")},
}};

} // namespace

namespace workspacemap {

QCPColorGradient capabilityGradient()
{
    // viridis: dark where the platform gets little (a singularity is near), bright where much
    QCPColorGradient gradient;
    gradient.setColorInterpolation(QCPColorGradient::ciRGB);
    gradient.setColorStopAt(0.0, QColor(0x440154));
    gradient.setColorStopAt(0.25, QColor(0x3b528b));
    gradient.setColorStopAt(0.5, QColor(0x21918c));
    gradient.setColorStopAt(0.75, QColor(0x5ec962));
    gradient.setColorStopAt(1.0, QColor(0xfde725));
    gradient.setNanHandling(QCPColorGradient::nhTransparent);
    return gradient;
}

QCPColorGradient specificationGradient()
{
    QCPColorGradient gradient;
    gradient.setLevelCount(2);
    gradient.setColorStopAt(0.0, QColor(0xd6d6d6));
    gradient.setColorStopAt(1.0, QColor(0x2e9e4f));
    gradient.setNanHandling(QCPColorGradient::nhTransparent);
    return gradient;
}

MapSummary computeCapability(const Mechanism &mechanism, const Pose &pose, MapQuantity quantity,
                             const std::vector<capability::Requirement> &requirements, const MapGrid &grid,
                             WorkspaceMapResult &result, std::span<float> margins, const std::atomic<bool> *cancel)
{
    const capability::Actuators actuators = capability::actuatorsOf(mechanism);
    const Pose start = capability::mapStart(
        mechanism, pose.outputs.size() == mechanism.homePose().outputs.size() ? pose : mechanism.homePose());
    MapSummary summary = capability::computeMap(mechanism, actuators, quantity, requirements, start, grid,
                                                result.values, margins, &result.specification, cancel);
    if (const ReportEntry *entry = capability::toDisplayUnits(actuators, quantity, result.values, summary)) {
        result.symbol = entry->symbol;
        result.label = entry->label;
        result.unit = entry->unit.symbol;
    }
    return summary;
}

} // namespace workspacemap

void WorkspaceMapView::syncCapabilityItems()
{
    const bool declared = m_mechanism && capability::layoutFor(capability::actuatorsOf(*m_mechanism));
    const bool shown = m_quantityBox->findData(int(MapQuantity::ForceWorst)) >= 0;
    if (declared == shown)
        return;
    const QSignalBlocker blocker(m_quantityBox);
    for (const CapabilityItem &item : capabilityItems) {
        if (declared)
            m_quantityBox->addItem(tr(item.text), int(item.quantity));
        else
            m_quantityBox->removeItem(m_quantityBox->findData(int(item.quantity)));
    }
    if (!declared && isCapability(m_quantity))
        m_quantity = MapQuantity::Determinant;
    m_quantityBox->setCurrentIndex(m_quantityBox->findData(int(m_quantity)));
}

void WorkspaceMapView::retranslateCapabilityItems()
{
    for (const CapabilityItem &item : capabilityItems)
        if (const int index = m_quantityBox->findData(int(item.quantity)); index >= 0)
            m_quantityBox->setItemText(index, tr(item.text));
}

void WorkspaceMapView::updateCapabilityTitle()
{
    using workspacemap::significant;
    const QString area = areaText();
    if (m_shownQuantity == MapQuantity::Specification) {
        const double share = m_summary.area > 0.0 ? 100.0 * m_specificationArea / m_summary.area : 0.0;
        setTitle(m_requirements.empty()
                ? tr("No requirements stated (Edit ▸ Requirements…): the whole workspace %1 meets them").arg(area)
                : tr("Requirements met in %1 of the workspace %2 (%3 %)")
                      .arg(formatQuantity(m_specificationArea, units::squareMillimetre, 0), area,
                           QLocale().toString(share, 'f', 1)));
        setScaleLabel(tr("green: every requirement holds; grey: one fails"));
        QStringList lines;
        const capability::Actuators actuators = capability::actuatorsOf(*m_mechanism);
        for (const capability::Requirement &requirement : m_requirements)
            lines << QString::fromStdString(capability::requirementText(requirement, actuators));
        setMapToolTip(lines.isEmpty() ? tr("State what the actuators must deliver with Edit ▸ Requirements….")
                                           : tr("Required: %1").arg(lines.join(QStringLiteral("; "))));
        return;
    }
    const QString unit = m_shownUnit.empty() ? QString() : QStringLiteral(" ") + coreLabel(m_shownUnit);
    setTitle(tr("Workspace %1 · %2 from %3 to %4%5 at the grid points")
                                          .arg(area, toQString(m_shownSymbol), significant(m_summary.min),
                                               significant(m_summary.max), unit));
    setScaleLabel(tr("%1 (%2): %3, colours end at %4")
                      .arg(toQString(m_shownSymbol), coreLabel(m_shownUnit), coreLabel(m_shownLabel),
                           significant(m_colourLimit)),
                  m_shownUnit.empty() ? toQString(m_shownSymbol)
                                      : QStringLiteral("%1 (%2)").arg(toQString(m_shownSymbol), coreLabel(m_shownUnit)));
    setMapToolTip(m_shownQuantity == MapQuantity::ToleranceWorst
            ? tr("The first-order worst-case error of the platform point at each point of the workspace, from the "
                 "tolerances of the Tolerances panel: ∞ at a direct singularity.")
            : tr("What the actuators deliver at each point of the workspace, from their limits in the design: 0 or ∞ "
                 "exactly at a singularity. Every cell is the value of the pose solved there."));
}

} // namespace pkm
