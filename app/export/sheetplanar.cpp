// The parameter sheet of a mechanism whose outputs are a point of the plane (MOMA, the O-X
// glide, any new one with a PlanarWorkspace): the workspace as `pkm workspace` computes it —
// the same grid, the same areas per mode, the same pictures as `pkm workspace -o` and
// `pkm map -o` — with the areas a workspace knows exactly (the O-X glide's, docs/mathematics.md),
// the singular poses inside the workspace and the strokes the workspace uses.

#include "export/sheetparts.h"
#include "export/workspacepictures.h"
#include "quantityformat.h"
#include "report/workspaceanalysis.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace pkm::sheet::detail {

namespace {

/// The strokes of the actuated inputs that the workspace uses: the inputs of its reachable
/// cells (at most about `samples` of them), solved by inverse kinematics.
struct Used {
    std::vector<double> min, max; ///< core units, per variable
};
Used usedInputs(const Mechanism &mechanism, const Pose &pose, const MapGrid &grid, std::span<const float> values,
    std::size_t samples)
{
    const int inputs = mechanism.inputCount();
    Used used {std::vector<double>(std::size_t(inputs), std::numeric_limits<double>::infinity()),
        std::vector<double>(std::size_t(inputs), -std::numeric_limits<double>::infinity())};
    std::size_t reachable = 0;
    for (float value : values)
        reachable += std::isnan(value) ? 0 : 1;
    const std::size_t stride = std::max<std::size_t>(1, reachable / std::max<std::size_t>(1, samples));
    std::size_t seen = 0;
    for (int r = 0; r < grid.rows; ++r) {
        for (int c = 0; c < grid.columns; ++c) {
            const float value = values[std::size_t(r) * std::size_t(grid.columns) + std::size_t(c)];
            if (std::isnan(value) || seen++ % stride != 0)
                continue;
            Coordinates outputs(2);
            outputs << grid.x(c), grid.y(r);
            auto solved = mechanism.solveInverse(outputs, &pose);
            if (!solved)
                continue;
            for (int i = 0; i < inputs; ++i) {
                used.min[std::size_t(i)] = std::min(used.min[std::size_t(i)], solved->inputs[i]);
                used.max[std::size_t(i)] = std::max(used.max[std::size_t(i)], solved->inputs[i]);
            }
        }
    }
    return used;
}

/// The point halfway along a polyline.
Eigen::Vector2d halfway(const std::vector<Eigen::Vector2d> &points)
{
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i)
        length += (points[i] - points[i - 1]).norm();
    double left = 0.5 * length;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double step = (points[i] - points[i - 1]).norm();
        if (step > 0.0 && left <= step)
            return points[i - 1] + (points[i] - points[i - 1]) * (left / step);
        left -= step;
    }
    return points.front();
}

QString typeText(SingularCurve::Type type)
{
    return type == SingularCurve::Type::Direct ? QCoreApplication::translate("Sheet", "direct")
                                               : QCoreApplication::translate("Sheet", "inverse");
}

/// The exact area of the workspace in the modes of `mode` (NaN where none is known).
double exactModeArea(const Mechanism &mechanism, const std::vector<const ParameterInfo *> &modes,
    const report::ModeArea &mode)
{
    ParameterSet changes;
    for (std::size_t i = 0; i < modes.size(); ++i)
        changes[modes[i]->name] = modes[i]->unit.fromDisplay(mode.values[i]);
    const auto changed = mechanism.withParameters(changes);
    if (changed) {
        if (const PlanarWorkspace *workspace = (*changed)->planarWorkspace()) {
            for (const ExactArea &known : workspace->exactAreas()) {
                if (known.key == "area")
                    return known.area;
            }
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

} // namespace

void addPlanar(const Mechanism &mechanism, const PlanarWorkspace &workspace, const Pose &pose, Parts &parts)
{
    MapCells values, margins;
    const MapSummary summary
        = report::computeInto(workspace, MapQuantity::Determinant, workspaceGrid, values, &margins);
    const MapGrid &grid = summary.grid;
    const Eigen::AlignedBox2d box = report::reachableBounds(grid, values);
    const std::vector<const ParameterInfo *> modes = report::modeParameters(mechanism);
    MapCells buffer;
    const std::vector<report::ModeArea> areas = report::modeAreas(mechanism, modes, summary, workspaceGrid, buffer);
    const report::ModeRegions united = modes.empty() ? report::ModeRegions {} : report::modeRegions(mechanism, modes, workspaceGrid);
    const auto named = report::namedModeAreas(modes, areas);
    const std::optional<double> travel = report::carriedTravel(mechanism);
    const ParameterSet parameters = mechanism.parameters();

    // -- the workspace ---------------------------------------------------------------------
    Section &section = parts.workspace;
    section.key = "workspace";
    section.title = QCoreApplication::translate("Sheet", "Workspace");
    // "β₁ = −1, σ = +1" or a named choice in the current language ("σ = open"), as the mode bar
    QStringList modeWords;
    for (const ParameterInfo *info : modes) {
        const auto it = parameters.find(info->name);
        if (it != parameters.end())
            modeWords << coreLabel(info->symbol) + QStringLiteral(" = ")
                    + coreLabel(report::modeValueText(*info, info->unit.toDisplay(it->second)));
    }
    const QString modeNow = modeWords.join(QStringLiteral(", "));
    section.intro = QCoreApplication::translate("Sheet",
        "The platform positions reachable with every actuated input inside its range%1, on a grid of %2 × %3 "
        "square cells of %4 mm (as 'pkm workspace --grid %5').")
                        .arg(modeNow.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(modeNow))
                        .arg(grid.columns)
                        .arg(grid.rows)
                        .arg(numberText(grid.dx(), 3))
                        .arg(workspaceGrid);
    std::vector<Item> &items = section.items;
    std::optional<double> exactOwn;
    const std::vector<ExactArea> exact = workspace.exactAreas();
    if (!exact.empty()) {
        for (const ExactArea &known : exact) {
            if (known.key == "area")
                exactOwn = known.area;
            items.push_back(numberItem(known.key, utf8(known.symbol),
                QCoreApplication::translate("Sheet", known.label.c_str()), known.area, 1, "mm²"));
        }
        items.push_back(numberItem("area_grid", QStringLiteral("A_grid"),
            QCoreApplication::translate("Sheet", "area of this form on the grid"), summary.area, 1, "mm²"));
    } else {
        items.push_back(numberItem("area", QStringLiteral("A"),
            QCoreApplication::translate("Sheet", "area of the workspace (grid)"), summary.area, 1, "mm²"));
        for (const auto &[name, area] : named) {
            items.push_back(numberItem("area_" + name, QStringLiteral("A_") + utf8(name),
                QCoreApplication::translate("Sheet", "area in mode %1 (grid)").arg(coreLabel(name)), area, 1, "mm²"));
        }
    }
    if (!modes.empty()) {
        items.push_back(numberItem("area_union", QStringLiteral("A_∪"),
            QCoreApplication::translate("Sheet", "area of the union of all modes (grid)"), united.unionArea, 1, "mm²"));
    }
    if (travel) {
        const double own = exactOwn.value_or(summary.area);
        items.push_back(numberItem("travel", QStringLiteral("z"),
            QCoreApplication::translate("Sheet", "travel of the carrying axis"), *travel, 2, "mm"));
        items.push_back(numberItem("volume", QStringLiteral("V"),
            QCoreApplication::translate("Sheet", "volume: the area extruded over the travel"), own * *travel, 0, "mm³"));
    }
    if (!box.isEmpty()) {
        items.push_back(numberItem("x_min", QStringLiteral("x_min"),
            QCoreApplication::translate("Sheet", "reachable cells from x"), box.min().x(), 2, "mm"));
        items.push_back(numberItem("x_max", QStringLiteral("x_max"),
            QCoreApplication::translate("Sheet", "reachable cells to x"), box.max().x(), 2, "mm"));
        items.push_back(numberItem("y_min", QStringLiteral("y_min"),
            QCoreApplication::translate("Sheet", "reachable cells from y"), box.min().y(), 2, "mm"));
        items.push_back(numberItem("y_max", QStringLiteral("y_max"),
            QCoreApplication::translate("Sheet", "reachable cells to y"), box.max().y(), 2, "mm"));
    }
    items.push_back(numberItem("reachable_cells", QCoreApplication::translate("Sheet", "cells"),
        QCoreApplication::translate("Sheet", "reachable cells of the grid"), double(summary.reachableCells), 0, ""));

    if (!areas.empty()) {
        Table table;
        table.key = "modes";
        table.title = QCoreApplication::translate("Sheet", "Area per working and assembly mode");
        table.labelTitle = QCoreApplication::translate("Sheet", "mode");
        for (const ParameterInfo *info : modes)
            table.columns.push_back({info->name, utf8(info->symbol), {}, coreLabel(info->label)});
        table.columns.push_back({"area", QCoreApplication::translate("Sheet", "area (grid)"), "mm²", {}});
        if (exactOwn)
            table.columns.push_back({"area_exact", QCoreApplication::translate("Sheet", "area (exact)"), "mm²", {}});
        table.columns.push_back({"note", QCoreApplication::translate("Sheet", "note"), {}, {}});
        for (std::size_t m = 0; m < areas.size(); ++m) {
            const report::ModeArea &mode = areas[m];
            Row row;
            QStringList label;
            for (std::size_t i = 0; i < modes.size(); ++i) {
                const std::string text = report::modeValueText(*modes[i], mode.values[i]);
                label << coreLabel(modes[i]->symbol) + QStringLiteral(" = ") + coreLabel(text);
                Cell cell = numberCell(mode.values[i], 0);
                cell.shown = coreLabel(text);
                row.cells.push_back(cell);
            }
            row.key = "mode_" + std::to_string(m + 1);
            row.label = label.join(QStringLiteral(", "));
            row.cells.push_back(numberCell(mode.area, 1));
            if (exactOwn)
                row.cells.push_back(numberCell(exactModeArea(mechanism, modes, mode), 1));
            if (mode.current)
                row.cells.push_back(wordCell("current", QCoreApplication::translate("Sheet", "this design")));
            else if (mode.area > 0.0)
                row.cells.push_back(wordCell("-"));
            else
                row.cells.push_back(wordCell("empty", QCoreApplication::translate("Sheet", "no workspace")));
            row.highlight = mode.current;
            table.rows.push_back(std::move(row));
        }
        section.tables.push_back(std::move(table));
    }

    Figure picture;
    picture.key = "workspace";
    picture.kind = FigureKind::Image;
    if (!named.empty() && united.reached.size() > 1) {
        picture.image = pictures::modeRegionsImage(united);
        picture.imageBounds = united.grid.bounds;
        picture.title = QCoreApplication::translate("Sheet", "Workspaces of the modes");
        picture.caption = QCoreApplication::translate("Sheet",
            "As 'pkm workspace -o FILE.png': this design's mode dark blue over the others' light blue, the "
            "outline of their union dark.");
    } else {
        picture.image = pictures::workspaceImage(grid, values);
        picture.imageBounds = grid.bounds;
        picture.title = QCoreApplication::translate("Sheet", "Workspace");
        picture.caption = QCoreApplication::translate("Sheet",
            "As 'pkm workspace -o FILE.png': the reachable cells light blue with a dark outline.");
    }
    if (!picture.image.isNull())
        section.figures.push_back(std::move(picture));

    Figure map;
    map.key = "map";
    map.kind = FigureKind::Image;
    const double limit = report::mapColourLimit(values, MapQuantity::Determinant);
    const std::vector<SingularCurve> curves = workspace.singularCurves();
    map.image = pictures::mapImage(grid, values, MapQuantity::Determinant, limit, curves);
    map.imageBounds = grid.bounds;
    map.title = QCoreApplication::translate("Sheet", "Singularity map: det J");
    map.caption = QCoreApplication::translate("Sheet",
        "As 'pkm map -o FILE.png': det J blue below 0, white at 0 (a direct singularity), red above 0, "
        "clipped at ±%1; the inverse singular curves dark red, the direct ones dashed.")
                      .arg(numberText(limit, 3));
    if (!map.image.isNull())
        section.figures.push_back(std::move(map));

    // -- singular poses --------------------------------------------------------------------
    Section &singular = parts.singular;
    singular.key = "singular";
    singular.title = QCoreApplication::translate("Sheet", "Singular poses in the workspace");
    singular.items.push_back(numberItem("near_singular_cells", QCoreApplication::translate("Sheet", "cells"),
        QCoreApplication::translate("Sheet", "near-singular cells (margin < %1, about 3° from a singular pose)")
            .arg(numberText(nearSingularMargin, 2)),
        double(summary.nearSingularCells), 0, ""));
    singular.items.push_back(numberItem("near_singular_area", QStringLiteral("A_s"),
        QCoreApplication::translate("Sheet", "their area"), double(summary.nearSingularCells) * grid.cellArea(), 1,
        "mm²"));
    if (!curves.empty()) {
        Table table;
        table.key = "curves";
        table.title = QCoreApplication::translate("Sheet", "Singular curves, each with one of its poses");
        table.labelTitle = QCoreApplication::translate("Sheet", "where");
        table.columns.push_back({"type", QCoreApplication::translate("Sheet", "type"), {}, {}});
        const auto &variables = mechanism.variableInfo();
        for (std::size_t i = 0; i < variables.size(); ++i) {
            if (!variables[i].independent)
                table.columns.push_back(variableColumn(variables[i]));
        }
        table.columns.push_back({"length", QCoreApplication::translate("Sheet", "curve length"), "mm", {}});
        for (std::size_t k = 0; k < curves.size(); ++k) {
            const SingularCurve &curve = curves[k];
            if (curve.points.empty())
                continue;
            Row row;
            row.key = "curve_" + std::to_string(k + 1);
            row.label = coreLabel(curve.label);
            row.cells.push_back(wordCell(curve.type == SingularCurve::Type::Direct ? "direct" : "inverse", typeText(curve.type)));
            const Eigen::Vector2d middle = halfway(curve.points);
            Coordinates outputs(2);
            outputs << middle.x(), middle.y();
            auto solved = mechanism.solveInverse(outputs, &pose);
            for (std::size_t i = 0; i < variables.size(); ++i) {
                if (variables[i].independent)
                    continue;
                if (solved) {
                    row.cells.push_back(variableCell(mechanism, *solved, int(i)));
                } else if (!variables[i].actuated) { // the outputs are the point itself
                    const int output = int(i) - mechanism.inputCount();
                    row.cells.push_back(numberCell(output == 0 ? middle.x() : middle.y(), variables[i].decimals));
                } else {
                    row.cells.push_back(numberCell(std::numeric_limits<double>::quiet_NaN(), variables[i].decimals));
                }
            }
            double length = 0.0;
            for (std::size_t p = 1; p < curve.points.size(); ++p)
                length += (curve.points[p] - curve.points[p - 1]).norm();
            row.cells.push_back(numberCell(length, 1));
            table.rows.push_back(std::move(row));
        }
        table.note = QCoreApplication::translate("Sheet",
            "Inverse: a leg loses a degree of freedom (a link perpendicular to its guide); direct: the platform "
            "gains one (the links in line). The pose given is the middle of each curve.");
        singular.tables.push_back(std::move(table));
    } else {
        singular.notes.push_back(QCoreApplication::translate("Sheet", "No singular curve lies inside the workspace."));
    }

    // -- checks ----------------------------------------------------------------------------
    Section &checks = parts.checks;
    if (checks.checks.empty())
        checks.title = QCoreApplication::translate("Sheet", "Design check");
    const Used used = usedInputs(mechanism, pose, grid, values, 20000);
    const auto &variables = mechanism.variableInfo();
    for (int i = 0; i < mechanism.inputCount(); ++i) {
        const VariableInfo &info = variables[std::size_t(i)];
        if (info.independent || !std::isfinite(used.min[std::size_t(i)]))
            continue;
        const Interval range = mechanism.variableRange(i);
        const double tolerance = 1e-6 * std::max(1.0, range.max - range.min);
        const bool inside = used.min[std::size_t(i)] >= range.min - tolerance && used.max[std::size_t(i)] <= range.max + tolerance;
        Check stroke;
        stroke.key = "stroke_" + info.name;
        stroke.title = QCoreApplication::translate("Sheet", "Stroke of %1 the workspace uses").arg(utf8(info.symbol));
        stroke.criterion = (info.unit.symbol == "mm" ? QCoreApplication::translate("Sheet", "within the guide %1 … %2")
                                                      : QCoreApplication::translate("Sheet", "within its range %1 … %2"))
                               .arg(quantityText(info.unit.toDisplay(range.min), info.decimals, info.unit.symbol),
                                   quantityText(info.unit.toDisplay(range.max), info.decimals, info.unit.symbol));
        stroke.value = numberCell(info.unit.toDisplay(used.max[std::size_t(i)] - used.min[std::size_t(i)]), info.decimals);
        stroke.limit = numberCell(info.unit.toDisplay(range.max - range.min), info.decimals);
        stroke.unit = std::string(info.unit.symbol);
        stroke.verdict = inside ? Verdict::Pass : Verdict::Fail;
        stroke.detail = QCoreApplication::translate("Sheet", "used from %1 to %2")
                            .arg(quantityText(info.unit.toDisplay(used.min[std::size_t(i)]), info.decimals, info.unit.symbol),
                                quantityText(info.unit.toDisplay(used.max[std::size_t(i)]), info.decimals, info.unit.symbol));
        checks.checks.push_back(std::move(stroke));
    }
    // A direct singularity lets the platform move with the actuators locked: the design must
    // keep it out of reach. An inverse one (a leg at the end of its reach) bounds the workspace.
    for (const SingularCurve::Type type : {SingularCurve::Type::Direct, SingularCurve::Type::Inverse}) {
        const bool direct = type == SingularCurve::Type::Direct;
        std::set<std::string> labels;
        QStringList listed;
        int count = 0;
        for (const SingularCurve &curve : curves) {
            if (curve.type != type)
                continue;
            ++count;
            if (labels.insert(curve.label).second)
                listed << coreLabel(curve.label);
        }
        Check check;
        check.key = direct ? "direct_singular_poses" : "inverse_singular_poses";
        check.title = direct ? QCoreApplication::translate("Sheet", "Direct singular poses in the workspace")
                             : QCoreApplication::translate("Sheet", "Inverse singular poses in the workspace");
        check.criterion = direct
            ? QCoreApplication::translate("Sheet", "none: the platform would move with the actuators locked")
            : QCoreApplication::translate("Sheet", "where a leg reaches the end of its reach; keep away in use");
        check.value = numberCell(double(count), 0);
        if (direct)
            check.limit = numberCell(0.0, 0);
        check.verdict = direct ? (count == 0 ? Verdict::Pass : Verdict::Fail) : Verdict::Info;
        check.detail = listed.isEmpty() ? QCoreApplication::translate("Sheet", "no singular curve of this kind")
                                        : listed.join(QStringLiteral("; "));
        checks.checks.push_back(std::move(check));
    }
}

} // namespace pkm::sheet::detail
