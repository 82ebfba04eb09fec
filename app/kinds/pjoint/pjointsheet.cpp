// The П-joint's sections of the parameter sheet: its dimensions, key poses, the actuator
// check and the plots of the П-joint document's section 4.2 and figs. 8–17.

#include "kinds/pjoint/pjointsheet.h"

#include "export/sheetparts.h"
#include "kinds/pjoint/pjoint.h"
#include "kinds/pjoint/pjointcurves.h"
#include "kinds/pjoint/pjointplots.h"
#include "planarworkspace.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace pkm::sheet::detail {

namespace {

// -- П-joint --------------------------------------------------------------------------------

/// θ (rad) to display decimals in sentences.
QString angleText(double radians)
{
    return quantityText(radians / units::degree, 2, "°");
}

void addPJointDimensions(const PJoint &joint, const Evaluation &here, Parts &parts)
{
    const PJointDesign &d = joint.design();
    const ReportLayout &layout = joint.reportLayout();
    std::vector<Item> &items = parts.dimensions.items;
    for (const char *name : {"d_min", "d_max", "stroke", "recommended_min", "recommended_max"}) {
        if (const ReportEntry *entry = layout.find(name))
            items.push_back(itemOf(*entry, here));
    }
    items.push_back(numberItem("screw_out_min", QStringLiteral("d_min − L_M"),
        QCoreApplication::translate("Sheet", "screw beyond the motor body at d_min"), joint.dMin() - d.motorLength, 2,
        "mm"));
    items.push_back(numberItem("screw_out_max", QStringLiteral("d_max − L_M"),
        QCoreApplication::translate("Sheet", "screw beyond the motor body at d_max (least free screw length)"),
        joint.dMax() - d.motorLength, 2, "mm"));
    items.push_back(numberItem("steps_per_revolution", QStringLiteral("h/Δd"),
        QCoreApplication::translate("Sheet", "motor steps per revolution of the screw"), d.lead / d.step, 1, ""));
    items.push_back(numberItem("motor_speed", QStringLiteral("n"),
        QCoreApplication::translate("Sheet", "motor speed at ḋ_max, 60·ḋ_max/h"), 60.0 * d.speedMax / d.lead, 0,
        "min⁻¹"));
    items.push_back(numberItem("step_rate", QStringLiteral("f"),
        QCoreApplication::translate("Sheet", "step rate at ḋ_max, ḋ_max/Δd"), d.speedMax / d.step, 0, "steps/s"));
    if (const ReportEntry *entry = layout.find("motor_torque"))
        items.push_back(itemOf(*entry, here));
}

void addPJointKeyPoses(const PJoint &joint, const Pose &pose, Parts &parts)
{
    const PJointDesign &d = joint.design();
    static constexpr std::array<std::string_view, 8> names {"theta", "d", "phi", "mu", "J", "torque", "speed",
        "resolution"};
    const std::vector<const ReportEntry *> columns = reportEntries(joint, names);
    Table table;
    table.key = "poses";
    table.title = QCoreApplication::translate("Sheet", "Key poses over the range and the recommended range");
    table.labelTitle = QCoreApplication::translate("Sheet", "pose");
    for (const ReportEntry *entry : columns)
        table.columns.push_back(columnOf(*entry));

    struct Candidate {
        double theta;
        std::string key;
        QString label;
    };
    const Interval recommended = joint.recommendedRange();
    std::vector<Candidate> candidates {{d.thetaMin, "theta_min", QStringLiteral("θ_min")},
        {d.thetaMax, "theta_max", QStringLiteral("θ_max")}};
    if (d.thetaMin < 0.0 && d.thetaMax > 0.0)
        candidates.push_back({0.0, "zero", QStringLiteral("θ = 0")});
    candidates.push_back({recommended.min, "recommended_min", QCoreApplication::translate("Sheet", "θ_rec,min")});
    candidates.push_back({recommended.max, "recommended_max", QCoreApplication::translate("Sheet", "θ_rec,max")});
    const double theta = pose.outputs.size() > 0 ? pose.outputs[0] : 0.0;
    std::stable_sort(candidates.begin(), candidates.end(),
        [](const Candidate &a, const Candidate &b) { return a.theta < b.theta; });
    // One row per angle: the recommended range often starts at θ_min (the prototype's −60°).
    std::vector<Candidate> rows;
    for (const Candidate &candidate : candidates) {
        auto same = std::find_if(rows.begin(), rows.end(),
            [&](const Candidate &row) { return std::abs(row.theta - candidate.theta) < 1e-9; });
        if (same == rows.end())
            rows.push_back(candidate);
        else
            same->label += QStringLiteral(" = ") + candidate.label;
    }
    bool poseShown = false;
    for (const Candidate &candidate : rows) {
        Coordinates outputs(1);
        outputs << candidate.theta;
        auto solved = joint.solveInverse(outputs, &pose);
        if (!solved)
            continue;
        const bool atPose = std::abs(candidate.theta - theta) < 1e-9;
        poseShown = poseShown || atPose;
        table.rows.push_back(reportRow(joint, *solved, columns, candidate.key,
            atPose ? candidate.label + QCoreApplication::translate("Sheet", " (this pose)") : candidate.label, atPose));
    }
    if (!poseShown) {
        Row row = reportRow(joint, pose, columns, "pose", QCoreApplication::translate("Sheet", "this pose"), true);
        const auto at = std::find_if(table.rows.begin(), table.rows.end(),
            [&](const Row &r) { return r.cells.front().number > units::angle.toDisplay(theta); });
        table.rows.insert(at, std::move(row));
    }
    table.note = QCoreApplication::translate("Sheet",
        "T at F_max = %1 N, θ̇ at ḋ_max = %2 mm/s, Δθ per motor step Δd = %3 mm. The recommended range keeps "
        "J — and with it T, θ̇ and Δθ — within %4 % of its best over the range (the document: θ = −60°…40°).")
                     .arg(numberText(d.forceMax, 1), numberText(d.speedMax, 2), numberText(d.step, 5),
                         numberText(pjoint::recommendedTorqueShare * 100.0, 0));
    parts.keyPoses.tables.push_back(std::move(table));
}

void addPJointChecks(const PJoint &joint, Parts &parts)
{
    const PJointDesign &d = joint.design();
    Section &section = parts.checks;
    section.title = QCoreApplication::translate("Sheet", "Actuator check");
    section.intro = QCoreApplication::translate("Sheet",
        "The chosen motor: lead h = %1 mm, step Δd = %2 mm, ḋ_max = %3 mm/s, thrust F_max = %4 N, screw "
        "efficiency η = %5; body %6 mm long.")
                        .arg(numberText(d.lead, 4), numberText(d.step, 5), numberText(d.speedMax, 2),
                            numberText(d.forceMax, 1), numberText(d.efficiency, 3), numberText(d.motorLength, 1));

    Check fits;
    fits.key = "motor_fits";
    fits.title = QCoreApplication::translate("Sheet", "Motor body fits the shortest diagonal");
    fits.criterion = QStringLiteral("L_M < d_min");
    fits.value = numberCell(d.motorLength, 2);
    fits.limit = numberCell(joint.dMin(), 2);
    fits.unit = "mm";
    fits.verdict = d.motorLength < joint.dMin() ? Verdict::Pass : Verdict::Fail;
    fits.detail = QCoreApplication::translate("Sheet", "stroke d_max − d_min = %1 mm")
                      .arg(numberText(joint.dMax() - joint.dMin(), 2));
    section.checks.push_back(std::move(fits));

    // T, θ̇ and Δθ all follow J (13, 8, fig. 15): the worst pose of the range is where J is least.
    constexpr int samples = 4001;
    double best = -1.0, bestTheta = d.thetaMin, worst = std::numeric_limits<double>::infinity(), worstTheta = d.thetaMin;
    for (int i = 0; i < samples; ++i) {
        const double theta = d.thetaMin + (d.thetaMax - d.thetaMin) * i / (samples - 1);
        const double J = pjoint::jacobian(d, theta);
        if (J > best) {
            best = J;
            bestTheta = theta;
        }
        if (J < worst) {
            worst = J;
            worstTheta = theta;
        }
    }
    const double share = pjoint::recommendedTorqueShare;
    const bool withinShare = worst >= share * best * (1.0 - 1e-9);
    const Interval recommended = joint.recommendedRange();
    const QString where = QCoreApplication::translate("Sheet", "worst at θ = %1, best at θ = %2; recommended range %3…%4")
                              .arg(angleText(worstTheta), angleText(bestTheta), angleText(recommended.min),
                                  angleText(recommended.max));
    const QString percent = numberText(share * 100.0, 0);

    Check torque;
    torque.key = "torque";
    torque.title = QCoreApplication::translate("Sheet", "Output torque T = J·F_max (13)");
    torque.criterion = QCoreApplication::translate("Sheet", "least T ≥ %1 % of the best").arg(percent);
    torque.value = numberCell(pjoint::outputTorque(d, worstTheta, d.forceMax), 3);
    torque.limit = numberCell(share * pjoint::outputTorque(d, bestTheta, d.forceMax), 3);
    torque.unit = "N·m";
    torque.verdict = withinShare ? Verdict::Pass : Verdict::Fail;
    torque.detail = where;
    section.checks.push_back(std::move(torque));

    Check speed;
    speed.key = "speed";
    speed.title = QCoreApplication::translate("Sheet", "Output speed θ̇ = ḋ_max/J (8)");
    speed.criterion = QCoreApplication::translate("Sheet", "greatest θ̇ ≤ the least ÷ %1").arg(numberText(share, 2));
    speed.value = numberCell(pjoint::outputSpeed(d, worstTheta, d.speedMax), 4);
    speed.limit = numberCell(pjoint::outputSpeed(d, bestTheta, d.speedMax) / share, 4);
    speed.unit = "rad/s";
    speed.verdict = withinShare ? Verdict::Pass : Verdict::Fail;
    speed.detail = where;
    section.checks.push_back(std::move(speed));

    Check resolution;
    resolution.key = "resolution";
    resolution.title = QCoreApplication::translate("Sheet", "Output resolution Δθ = Δd/J");
    resolution.criterion = QCoreApplication::translate("Sheet", "coarsest Δθ ≤ the finest ÷ %1").arg(numberText(share, 2));
    resolution.value = numberCell(units::anglePerStep.toDisplay(pjoint::outputResolution(d, worstTheta, d.step)), 5);
    resolution.limit
        = numberCell(units::anglePerStep.toDisplay(pjoint::outputResolution(d, bestTheta, d.step)) / share, 5);
    resolution.unit = "°/step";
    resolution.verdict = withinShare ? Verdict::Pass : Verdict::Fail;
    resolution.detail = where;
    section.checks.push_back(std::move(resolution));

    Check singular;
    singular.key = "singularity_margin";
    singular.title = QCoreApplication::translate("Sheet", "No singular pose in the range (θ = ±90°)");
    const double margin = std::min(joint.singularity(d.thetaMin).margin, joint.singularity(d.thetaMax).margin);
    singular.criterion = QCoreApplication::translate("Sheet", "|cos θ| ≥ %1").arg(numberText(nearSingularMargin, 2));
    singular.value = numberCell(margin, 3);
    singular.limit = numberCell(nearSingularMargin, 3);
    singular.verdict = margin >= nearSingularMargin ? Verdict::Pass : Verdict::Fail;
    section.checks.push_back(std::move(singular));

    Check motor;
    motor.key = "motor_torque";
    motor.title = QCoreApplication::translate("Sheet", "Motor torque to push F_max");
    motor.criterion = QStringLiteral("T_M = F_max·h/(2π·η) (15)");
    motor.value = numberCell(pjoint::motorTorque(d, d.forceMax), 4);
    motor.unit = "N·m";
    motor.verdict = Verdict::Info;
    motor.detail = QCoreApplication::translate("Sheet", "the motor must give it at %1 min⁻¹ (%2 steps/s)")
                       .arg(numberText(60.0 * d.speedMax / d.lead, 0), numberText(d.speedMax / d.step, 0));
    section.checks.push_back(std::move(motor));

    if (!withinShare) {
        section.notes.push_back(QCoreApplication::translate("Sheet",
            "FAIL above means that the range of θ reaches where J falls steeply: keep the joint in the recommended "
            "range %1…%2 where it must give its torque, speed and resolution.")
                                    .arg(angleText(recommended.min), angleText(recommended.max)));
    }
}

void addPJointPlots(const PJoint &joint, const Pose &pose, Parts &parts)
{
    using namespace pjointcurves;
    const PJointDesign &d = joint.design();
    const Interval recommended = joint.recommendedRange();
    const double theta = pose.outputs.size() > 0 ? units::angle.toDisplay(pose.outputs[0]) : 0.0;
    struct Shown {
        int index;
        const char *key;
        QString title;
    };
    const std::array<Shown, 6> shown {{
        {PJointPlots::DiagonalPlot, "plot_d", QCoreApplication::translate("Sheet", "Diagonal length d(θ) (2), fig. 8")},
        {PJointPlots::TransmissionAnglePlot, "plot_mu",
            QCoreApplication::translate("Sheet", "Transmission angle μ(θ), fig. 10")},
        {PJointPlots::JacobianPlot, "plot_J", QCoreApplication::translate("Sheet", "Jacobian J(θ) = ∂d/∂θ (7), fig. 11")},
        {PJointPlots::TorquePlot, "plot_torque",
            QCoreApplication::translate("Sheet", "Output torque T = J·F_max (13), fig. 17")},
        {PJointPlots::SpeedPlot, "plot_speed",
            QCoreApplication::translate("Sheet", "Output speed θ̇ = ḋ_max/J, fig. 16")},
        {PJointPlots::ResolutionPlot, "plot_resolution",
            QCoreApplication::translate("Sheet", "Output resolution Δθ = Δd/J, fig. 15")},
    }};
    const auto toPoints = [](const Curve &curve) {
        std::vector<std::pair<double, double>> points;
        points.reserve(curve.size());
        for (const Point &point : curve)
            points.emplace_back(point.theta, point.value);
        return points;
    };
    for (const Shown &item : shown) {
        const pjointcurves::Plot computed = compute(d, item.index);
        const Quantity &quantity = quantities[std::size_t(item.index)];
        Figure figure;
        figure.key = item.key;
        figure.title = item.title;
        figure.kind = FigureKind::Plot;
        sheet::Plot &plot = figure.plot;
        plot.xLabel = QCoreApplication::translate("Sheet", "θ (°)");
        const QString symbol = item.index == PJointPlots::SpeedPlot ? QStringLiteral("dθ/dt") : symbolOf(item.index);
        plot.yLabel = QStringLiteral("%1 (%2)").arg(symbol, unitOf(item.index));
        plot.xMin = computed.theta.lower;
        plot.xMax = computed.theta.upper;
        plot.yMin = computed.value.lower;
        plot.yMax = computed.value.upper;
        for (int j = 0; j < quantity.familySize; ++j) {
            plot.series.push_back({QStringLiteral("k = %1").arg(numberText(familyK[std::size_t(j)], 1)),
                toPoints(computed.family[std::size_t(j)]), PlotSeries::Style::Family});
        }
        if (computed.extensionBeyond) {
            plot.series.push_back({QCoreApplication::translate("Sheet", "beyond the θ range"),
                toPoints(computed.extension), PlotSeries::Style::Extension});
        }
        plot.series.push_back({QCoreApplication::translate("Sheet", "this design (k = %1)").arg(numberText(d.k(), 2)),
            toPoints(computed.design), PlotSeries::Style::Design});
        if (quantity.tab != Tab::Geometry) {
            const double from = units::angle.toDisplay(recommended.min), to = units::angle.toDisplay(recommended.max);
            plot.bands.push_back({from, to, PlotBand::Kind::Recommended,
                QCoreApplication::translate("Sheet", "recommended range")});
            if (from > units::angle.toDisplay(d.thetaMin) + 1e-9)
                plot.bands.push_back({units::angle.toDisplay(d.thetaMin), from, PlotBand::Kind::Steep,
                    QCoreApplication::translate("Sheet", "steep region")});
            if (to < units::angle.toDisplay(d.thetaMax) - 1e-9)
                plot.bands.push_back({to, units::angle.toDisplay(d.thetaMax), PlotBand::Kind::Steep,
                    QCoreApplication::translate("Sheet", "steep region")});
        }
        plot.cursor = theta;
        figure.caption = quantity.familySize > 0
            ? QCoreApplication::translate("Sheet", "a = %1 mm; the family k = 0.3 … 1.5 at the same a")
                  .arg(numberText(d.a, 2))
            : QString();
        parts.plots.figures.push_back(std::move(figure));
    }
}

void addPJoint(const PJoint &joint, const Pose &pose, Parts &parts)
{
    const Evaluation here = evaluateAt(joint, pose);
    addPJointDimensions(joint, here, parts);
    addPJointKeyPoses(joint, pose, parts);
    addPJointChecks(joint, parts);
    addPJointPlots(joint, pose, parts);
}

} // namespace

} // namespace pkm::sheet::detail

namespace pkm::pjointkind {

void addSheetSections(const Mechanism &mechanism, const Pose &pose, sheet::detail::Parts &parts)
{
    if (const auto *joint = dynamic_cast<const PJoint *>(&mechanism))
        sheet::detail::addPJoint(*joint, pose, parts);
}

} // namespace pkm::pjointkind
