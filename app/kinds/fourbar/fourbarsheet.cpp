// The four-bar's sections of the parameter sheet: the Grashof class, the transmission angle
// and the plots of the four-bar and mobility document.

#include "kinds/fourbar/fourbarsheet.h"

#include "export/sheetparts.h"
#include "kinds/fourbar/fourbar.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace pkm::sheet::detail {

namespace {

// -- four-bar -------------------------------------------------------------------------------

QString grashofText(fourbar::Grashof grashof)
{
    using fourbar::Grashof;
    switch (grashof) {
    case Grashof::CrankRocker:
        return QCoreApplication::translate("Sheet", "crank-rocker");
    case Grashof::RockerCrank:
        return QCoreApplication::translate("Sheet", "rocker-crank");
    case Grashof::DoubleCrank:
        return QCoreApplication::translate("Sheet", "double-crank");
    case Grashof::DoubleRocker:
        return QCoreApplication::translate("Sheet", "double-rocker");
    case Grashof::TripleRocker:
        return QCoreApplication::translate("Sheet", "triple-rocker (non-Grashof)");
    case Grashof::ChangePoint:
        return QCoreApplication::translate("Sheet", "change-point");
    }
    return {};
}

void addFourBar(const FourBar &fourbar, const Pose &pose, Parts &parts)
{
    const FourBarDesign &d = fourbar.design();
    const fourbar::Grashof grashof = FourBar::grashof(d);
    std::array<double, 4> links {d.crank, d.coupler, d.rocker, d.ground};
    std::sort(links.begin(), links.end());
    const double sl = links[0] + links[3], pq = links[1] + links[2];
    const Interval alphaRange = fourbar.variableRange(FourBar::variableAlpha);
    const double alphaMin = units::angle.toDisplay(alphaRange.min), alphaMax = units::angle.toDisplay(alphaRange.max);

    // derived dimensions: Grashof's sums
    std::vector<Item> &items = parts.dimensions.items;
    items.push_back({"grashof", QCoreApplication::translate("Sheet", "class"),
        QCoreApplication::translate("Sheet", "Grashof class, s + l against p + q"),
        wordCell(fourbar::grashofName(grashof), grashofText(grashof)), {}, {}});
    items.push_back(numberItem("s_plus_l", QStringLiteral("s + l"),
        QCoreApplication::translate("Sheet", "shortest + longest link"), sl, 2, "mm"));
    items.push_back(numberItem("p_plus_q", QStringLiteral("p + q"),
        QCoreApplication::translate("Sheet", "the other two links"), pq, 2, "mm"));

    // the sweep over α: transmission angle, plots
    const Sweep sweep = sweepInput(fourbar, FourBar::variableAlpha, 361);
    double least = std::numeric_limits<double>::infinity(), leastAlpha = std::numeric_limits<double>::quiet_NaN();
    std::size_t leastIndex = 0;
    for (std::size_t i = 0; i < sweep.evaluations.size(); ++i) {
        const double mu = sweep.evaluations[i].values.empty() ? std::numeric_limits<double>::quiet_NaN()
                                                               : displayValue(fourbar, "transmission", sweep.evaluations[i]);
        if (std::isfinite(mu) && mu < least) {
            least = mu;
            leastAlpha = sweep.input[i];
            leastIndex = i;
        }
    }

    // key poses
    static constexpr std::array<std::string_view, 7> names {"alpha", "delta", "gamma", "transmission", "omega3",
        "epsilon3", "i31"};
    const std::vector<const ReportEntry *> columns = reportEntries(fourbar, names);
    Table table;
    table.key = "poses";
    table.title = QCoreApplication::translate("Sheet", "Key poses over the crank angle");
    table.labelTitle = QCoreApplication::translate("Sheet", "pose");
    for (const ReportEntry *entry : columns)
        table.columns.push_back(columnOf(*entry));
    std::vector<std::pair<double, std::string>> angles; // °
    if (fourbar.crankTurnsFully()) {
        for (int quarter = 0; quarter < 4; ++quarter)
            angles.emplace_back(90.0 * quarter, "alpha_" + std::to_string(90 * quarter));
    } else {
        angles.emplace_back(alphaMin, "alpha_min");
        angles.emplace_back(0.5 * (alphaMin + alphaMax), "alpha_mid");
        angles.emplace_back(alphaMax, "alpha_max");
    }
    const Pose home = fourbar.homePose();
    for (const auto &[alpha, key] : angles) {
        Coordinates inputs(1);
        inputs << units::angle.fromDisplay(alpha);
        if (auto solved = fourbar.solveDirect(inputs, &home))
            table.rows.push_back(reportRow(fourbar, *solved, columns, key, QStringLiteral("α = %1°").arg(numberText(alpha, 0))));
    }
    if (std::isfinite(least) && sweep.poses[leastIndex].inputs.size() > 0) {
        table.rows.push_back(reportRow(fourbar, sweep.poses[leastIndex], columns, "least_transmission",
            QCoreApplication::translate("Sheet", "least μ")));
    }
    table.rows.push_back(reportRow(fourbar, pose, columns, "pose", QCoreApplication::translate("Sheet", "this pose"), true));
    table.note = QCoreApplication::translate("Sheet", "At the constant crank speed ω₁ = %1 rad/s.").arg(numberText(d.omega1, 3));
    parts.keyPoses.tables.push_back(std::move(table));

    // checks
    Section &section = parts.checks;
    section.title = QCoreApplication::translate("Sheet", "Design check");
    Check grashofCheck;
    grashofCheck.key = "grashof";
    grashofCheck.title = QCoreApplication::translate("Sheet", "Grashof class");
    grashofCheck.criterion = QStringLiteral("s + l %1 p + q").arg(sl < pq - 1e-9 ? QStringLiteral("<")
            : sl > pq + 1e-9                                                    ? QStringLiteral(">")
                                                                                : QStringLiteral("="));
    grashofCheck.value = wordCell(fourbar::grashofName(grashof), grashofText(grashof));
    grashofCheck.verdict = Verdict::Info;
    grashofCheck.detail = QCoreApplication::translate("Sheet", "s + l = %1 mm, p + q = %2 mm")
                              .arg(numberText(sl, 2), numberText(pq, 2));
    section.checks.push_back(std::move(grashofCheck));

    Check range;
    range.key = "alpha_range";
    range.title = QCoreApplication::translate("Sheet", "Crank angle range");
    range.criterion = QCoreApplication::translate("Sheet", "α ∈ [%1°, %2°]").arg(numberText(alphaMin, 1), numberText(alphaMax, 1));
    range.value = numberCell(alphaMax - alphaMin, 1);
    range.limit = numberCell(360.0, 1);
    range.unit = "°";
    range.verdict = Verdict::Info;
    range.detail = fourbar.crankTurnsFully() ? QCoreApplication::translate("Sheet", "the crank AB turns fully")
                                             : QCoreApplication::translate("Sheet", "the crank AB cannot turn fully");
    section.checks.push_back(std::move(range));

    if (std::isfinite(least)) {
        Check transmission;
        transmission.key = "transmission";
        transmission.title = QCoreApplication::translate("Sheet", "Least transmission angle over the range");
        transmission.criterion = QStringLiteral("μ_min ≥ %1°").arg(numberText(FourBar::poorTransmission, 0));
        transmission.value = numberCell(least, 2);
        transmission.limit = numberCell(FourBar::poorTransmission, 2);
        transmission.unit = "°";
        transmission.verdict = least >= FourBar::poorTransmission ? Verdict::Pass : Verdict::Fail;
        transmission.detail = QCoreApplication::translate("Sheet", "at α = %1°").arg(numberText(leastAlpha, 1));
        section.checks.push_back(std::move(transmission));
    }

    // plots
    const std::array<std::pair<std::string_view, QString>, 4> plots {{
        {"delta", QCoreApplication::translate("Sheet", "Rocker angle δ(α)")},
        {"transmission", QCoreApplication::translate("Sheet", "Transmission angle μ(α)")},
        {"omega3", QCoreApplication::translate("Sheet", "Rocker angular velocity ω₃(α)")},
        {"epsilon3", QCoreApplication::translate("Sheet", "Rocker angular acceleration ε₃(α)")},
    }};
    for (const auto &[name, title] : plots) {
        Figure figure = sweepPlot(fourbar, pose, FourBar::variableAlpha, sweep, name, "plot_" + std::string(name), title);
        if (name == "transmission" && !figure.plot.series.empty()) {
            figure.plot.yMin = std::min(figure.plot.yMin, FourBar::poorTransmission - 5.0);
            figure.plot.levels.emplace_back(FourBar::poorTransmission,
                QCoreApplication::translate("Sheet", "μ = %1°: poor below").arg(numberText(FourBar::poorTransmission, 0)));
        }
        if (!figure.plot.series.empty())
            parts.plots.figures.push_back(std::move(figure));
    }
}

} // namespace

} // namespace pkm::sheet::detail

namespace pkm::fourbarkind {

void addSheetSections(const Mechanism &mechanism, const Pose &pose, sheet::detail::Parts &parts)
{
    if (const auto *fourbar = dynamic_cast<const FourBar *>(&mechanism))
        sheet::detail::addFourBar(*fourbar, pose, parts);
}

} // namespace pkm::fourbarkind
