// The actuator checks of the sheet's capability section, for every kind with actuators: the
// design's load held within every actuator's limit at the sheet's pose, and each requirement
// the design states (core/capabilitymap.h) at the pose and — where the outputs are a point of
// the plane — over the whole workspace.
#include "export/sheetparts.h"

#include "planarworkspace.h"
#include "quantityformat.h"
#include "report/report.h"

#include <Eigen/LU>

#include <QCoreApplication>

#include <cmath>
#include <limits>

namespace pkm::sheet::detail {

namespace {

/// Core torques are N·m and lengths mm: a moment or a rotary actuator's torque enters the
/// virtual work in N·mm (as in core/capability.cpp).
constexpr double perMetre = 1e3;

struct LoadShare {
    bool loaded = false;
    double largest = 0.0; ///< max_i |τ_i| / τ_max,i; ∞ where the platform cannot be held
    int actuator = -1;    ///< the one at `largest`
};

/// The efforts that hold the design's load F at `pose`: F = Jᵀ·τ (virtual work, with q̇ = J·ẋ
/// over the actuated inputs and the platform's coordinates), so τ = J⁻ᵀ·F; each as a share of
/// its actuator's limit. At a direct singularity no effort holds a load: ∞.
LoadShare loadShare(const Mechanism &mechanism, const capability::Actuators &actuators, const Pose &pose,
                    SingularityType type)
{
    LoadShare share;
    const int n = actuators.count;
    Eigen::VectorXd load(n);
    for (int i = 0; i < n; ++i) {
        // an angular output (the output link, the platform's φ) takes a moment in N·m
        const bool moment = actuators.rotaryOutput || i == 2;
        load[i] = actuators.load[std::size_t(i)] * (moment ? perMetre : 1.0);
    }
    share.loaded = n > 0 && load.cwiseAbs().maxCoeff() > 0.0;
    if (!share.loaded)
        return share;
    const Eigen::MatrixXd full = mechanism.jacobians(pose).full;
    Eigen::MatrixXd J(n, n);
    for (int r = 0; r < n; ++r)
        J.row(r) = full.row(actuators.inputs[std::size_t(r)]).head(n);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(J.transpose());
    if (type == SingularityType::Direct || type == SingularityType::Combined || !J.allFinite() || !lu.isInvertible()) {
        share.largest = std::numeric_limits<double>::infinity();
        return share;
    }
    const Eigen::VectorXd effort = lu.solve(load);
    for (int i = 0; i < n; ++i) {
        const capability::Actuator &a = actuators.items[std::size_t(i)];
        const double ratio = std::abs(effort[i]) / (a.rotary ? perMetre : 1.0) / a.force;
        if (ratio > share.largest) {
            share.largest = ratio;
            share.actuator = i;
        }
    }
    return share;
}

QString percentText(double share)
{
    return numberText(100.0 * share, 1);
}

} // namespace

void addActuatorChecks(const Mechanism &mechanism, const Pose &pose,
                       const std::vector<capability::Requirement> &requirements, Parts &parts)
{
    const capability::Actuators actuators = capability::actuatorsOf(mechanism);
    const ReportLayout *layout = capability::layoutFor(actuators);
    if (!layout)
        return;
    const Singularity singularity = evaluateAt(mechanism, pose).singularity;
    std::vector<Check> &checks = parts.capability.checks;

    Check load;
    load.key = "load_held";
    load.title = QCoreApplication::translate("Sheet", "The actuators hold the design's load at this pose");
    load.criterion = QCoreApplication::translate("Sheet", "max |τ_i| / τ_max,i ≤ 1");
    const LoadShare share = loadShare(mechanism, actuators, pose, singularity.type);
    if (!share.loaded) {
        load.value = wordCell("no load", QCoreApplication::translate("Sheet", "no load"));
        load.verdict = Verdict::Info;
        load.detail = QCoreApplication::translate("Sheet", "The design states no load (load_x, load_y, load_moment or "
                                                           "load_torque in the actuator group).");
    } else {
        load.value = std::isfinite(share.largest) ? numberCell(share.largest, 3) : wordCell("infinite", QStringLiteral("∞"));
        load.limit = numberCell(1.0, 0);
        load.verdict = share.largest <= 1.0 ? Verdict::Pass : Verdict::Fail;
        load.detail = std::isfinite(share.largest)
            ? QCoreApplication::translate("Sheet", "actuator %1 at %2 % of its limit").arg(share.actuator + 1).arg(percentText(share.largest))
            : QCoreApplication::translate("Sheet", "at a direct singularity no effort of the actuators holds a load");
    }
    checks.push_back(std::move(load));

    // each requirement at the pose
    const report::CapabilityReport here = report::evaluateCapability(mechanism, pose, singularity.type);
    for (std::size_t k = 0; k < requirements.size(); ++k) {
        const capability::Requirement &r = requirements[k];
        const ReportEntry *entry = layout->find(r.name);
        if (!entry)
            continue;
        const double value = here.values[std::size_t(entry->offset)];
        Check check;
        check.key = "requirement_" + std::to_string(k + 1);
        check.title = QCoreApplication::translate("Sheet", "Required at this pose: %1").arg(coreLabel(entry->label));
        check.criterion = QString::fromStdString(capability::requirementText(r, actuators));
        check.value = std::isnan(value) ? wordCell("undefined", QCoreApplication::translate("Sheet", "undefined"))
                      : std::isinf(value) ? wordCell("infinite", QStringLiteral("∞"))
                                          : numberCell(entry->unit.toDisplay(value), entry->decimals);
        check.limit = numberCell(entry->unit.toDisplay(r.value), entry->decimals);
        check.unit = std::string(entry->unit.symbol);
        check.verdict = capability::meets(r, *layout, here.values) ? Verdict::Pass : Verdict::Fail;
        checks.push_back(std::move(check));
    }

    // all of them over the workspace, on the grid of `pkm workspace`
    const PlanarWorkspace *workspace = mechanism.planarWorkspace();
    if (requirements.empty() || !workspace)
        return;
    const MapGrid grid = squareGrid(workspace->workspaceBounds(), workspaceGrid);
    std::vector<float> met(grid.cells());
    capability::SpecificationSummary specification;
    const MapSummary summary = capability::computeMap(mechanism, actuators, MapQuantity::Specification, requirements,
                                                      capability::mapStart(mechanism, pose), grid, met, {},
                                                      &specification);
    if (summary.reachableCells == 0)
        return;
    const double fraction = double(specification.metCells) / double(summary.reachableCells);
    Check region;
    region.key = "requirements_workspace";
    region.title = QCoreApplication::translate("Sheet", "Every requirement holds over the whole workspace");
    region.criterion = QCoreApplication::translate("Sheet", "area met = workspace area");
    region.value = numberCell(100.0 * fraction, 1);
    region.limit = numberCell(100.0, 0);
    region.unit = "%";
    region.verdict = specification.metCells == summary.reachableCells ? Verdict::Pass : Verdict::Fail;
    region.detail = QCoreApplication::translate("Sheet", "met in %1 mm² of %2 mm² (grid of %3 × %4 cells)")
                        .arg(numberText(specification.metArea, 1), numberText(summary.area, 1))
                        .arg(grid.columns)
                        .arg(grid.rows);
    checks.push_back(std::move(region));
}

} // namespace pkm::sheet::detail
