#include "export/sheet.h"

#include "document/designfile.h"
#include "export/sheetparts.h"
#include "planarworkspace.h"
#include "quantityformat.h"
#include "registry.h"
#include "report/report.h"
#include "text.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLocale>
#include <QTimeZone>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

// The generic sheet: every part that the Mechanism interface gives for any kind — parameters,
// links between joint centres, ranges of motion, key poses, the singular poses of a sweep, the
// plots of a one-input mechanism, the drawing and the design warnings. The kinds the issue
// names add their own sections in sheetkinds.cpp and sheetplanar.cpp.

namespace pkm::sheet {


using namespace detail;

namespace {


QString barKindText(BarKind kind)
{
    switch (kind) {
    case BarKind::Ground:
        return QCoreApplication::translate("Sheet", "frame");
    case BarKind::Crank:
        return QCoreApplication::translate("Sheet", "crank");
    case BarKind::Coupler:
        return QCoreApplication::translate("Sheet", "coupler");
    case BarKind::Link:
        return QCoreApplication::translate("Sheet", "link");
    case BarKind::Rod:
        return QCoreApplication::translate("Sheet", "rod");
    case BarKind::Platform:
        return QCoreApplication::translate("Sheet", "platform");
    }
    return {};
}

std::string barKindWord(BarKind kind)
{
    switch (kind) {
    case BarKind::Ground:
        return "frame";
    case BarKind::Crank:
        return "crank";
    case BarKind::Coupler:
        return "coupler";
    case BarKind::Link:
        return "link";
    case BarKind::Rod:
        return "rod";
    case BarKind::Platform:
        return "platform";
    }
    return "link";
}

/// "d = 183.10 mm, θ = 0.00°" and the pose's words ("mode X").
QString poseText(const Mechanism &mechanism, const Pose &pose)
{
    QStringList parts;
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableInfo &info = variables[i];
        parts << utf8(info.symbol) + QStringLiteral(" = ")
                + quantityText(info.unit.toDisplay(mechanism.variableValue(pose, static_cast<int>(i))), info.decimals,
                    info.unit.symbol);
    }
    for (const ReportText &word : mechanism.reportText(pose)) {
        if (word.group != ReportGroup::Pose)
            continue;
        // a mode by its symbol, as the window's mode bar shows it: "σ = open"
        const ParameterInfo *info = mechanism.findParameter(word.name);
        parts << (info ? coreLabel(info->symbol) : utf8(word.name)) + QStringLiteral(" = ") + coreLabel(word.text);
    }
    return parts.join(QStringLiteral(", "));
}

QString sheetDate()
{
    bool ok = false;
    const qint64 epoch = qEnvironmentVariable("SOURCE_DATE_EPOCH").toLongLong(&ok);
    const QDate date = ok ? QDateTime::fromSecsSinceEpoch(epoch, QTimeZone::utc()).date() : QDate::currentDate();
    return date.toString(Qt::ISODate);
}

// -- the generic sections -------------------------------------------------------------------

void addParameters(const Mechanism &mechanism, Parts &parts)
{
    Section &section = parts.parameters;
    section.key = "parameters";
    section.title = QCoreApplication::translate("Sheet", "Design parameters");
    const ParameterSet values = mechanism.parameters();
    constexpr std::array<ParameterGroup, 5> order {ParameterGroup::Geometry, ParameterGroup::Range,
        ParameterGroup::Actuator, ParameterGroup::Mode, ParameterGroup::Drawing};
    for (ParameterGroup group : order) {
        for (const ParameterInfo &info : mechanism.parameterInfo()) {
            // what the design uses: a two-legged platform's sheet lists no third leg
            if (info.group != group || !mechanism.parameterApplies(info.name))
                continue;
            Item item {info.name, utf8(info.symbol), coreLabel(info.label),
                numberCell(report::parameterDisplayValue(values, info), info.decimals), std::string(info.unit.symbol),
                std::string(parameterGroupKey(group))};
            if (group == ParameterGroup::Mode) {
                item.value.decimals = 0;
                const QString sign = (item.value.number > 0 ? QStringLiteral("+") : QString()) + cellText(item.value);
                item.value.shown = sign;
                for (const auto &[name, choice] : info.choices) {
                    if (choice == item.value.number)
                        item.value.shown = coreLabel(name) + QStringLiteral(" (") + sign + QLatin1Char(')');
                }
            }
            if (!info.stored)
                item.label += QCoreApplication::translate("Sheet", " (derived)");
            section.items.push_back(std::move(item));
        }
    }
}

/// The rigid links between joint centres and the guides, measured on the scene: what the
/// workshop cuts and drills. A bar whose length changes with the pose is not a rigid link and
/// is left out.
void addLinks(const Mechanism &mechanism, const Pose &pose, Parts &parts)
{
    Section &section = parts.dimensions;
    section.key = "dimensions";
    section.title = QCoreApplication::translate("Sheet", "Derived dimensions");
    const Scene scene = mechanism.scene(pose);
    const Scene home = mechanism.scene(mechanism.homePose());
    Table table;
    table.key = "links";
    table.title = QCoreApplication::translate("Sheet", "Links and guides (between joint centres)");
    table.labelTitle = QCoreApplication::translate("Sheet", "between");
    table.columns = {{"part", QCoreApplication::translate("Sheet", "part"), {}, {}},
        {"kind", QCoreApplication::translate("Sheet", "kind"), {}, {}},
        {"length", QCoreApplication::translate("Sheet", "length"), "mm", {}}};
    const auto jointName = [&](int index) {
        const std::string &label = scene.joints[static_cast<std::size_t>(index)].label;
        return label.empty() ? QStringLiteral("J%1").arg(index + 1) : utf8(label);
    };
    std::vector<std::string> keys;
    const auto uniqueKey = [&](std::string key) {
        std::string unique = key;
        for (int n = 2; std::find(keys.begin(), keys.end(), unique) != keys.end(); ++n)
            unique = key + "_" + std::to_string(n);
        keys.push_back(unique);
        return unique;
    };
    const auto validJoint = [](const Scene &s, int i) { return i >= 0 && i < static_cast<int>(s.joints.size()); };
    for (std::size_t b = 0; b < scene.bars.size(); ++b) {
        const SceneBar &bar = scene.bars[b];
        if (!validJoint(scene, bar.from) || !validJoint(scene, bar.to) || bar.from == bar.to)
            continue;
        const double length = (scene.joints[std::size_t(bar.to)].position - scene.joints[std::size_t(bar.from)].position).norm();
        if (b < home.bars.size() && validJoint(home, bar.from) && validJoint(home, bar.to)) {
            const double homeLength
                = (home.joints[std::size_t(bar.to)].position - home.joints[std::size_t(bar.from)].position).norm();
            if (std::abs(homeLength - length) > 1e-6 * std::max(1.0, length))
                continue; // not rigid
        }
        if (!(length > 1e-9))
            continue;
        const QString between = jointName(bar.from) + QChar(0x2013) + jointName(bar.to);
        Row row {uniqueKey(between.toStdString()), between, {}, false};
        row.cells.push_back(wordCell(bar.label.empty() ? std::string("-") : bar.label));
        row.cells.push_back(wordCell(barKindWord(bar.kind), barKindText(bar.kind)));
        row.cells.push_back(numberCell(length, 2));
        table.rows.push_back(std::move(row));
    }
    for (const SceneGuide &guide : scene.guides) {
        const double length = (guide.end - guide.start).norm();
        if (!(length > 1e-9))
            continue;
        const QString name = guide.label.empty() ? QCoreApplication::translate("Sheet", "guide") : utf8(guide.label);
        Row row {uniqueKey("guide " + (guide.label.empty() ? std::string("guide") : guide.label)), name, {}, false};
        row.cells.push_back(wordCell(guide.label.empty() ? std::string("-") : guide.label));
        row.cells.push_back(wordCell("guide", QCoreApplication::translate("Sheet", "guide (stroke)")));
        row.cells.push_back(numberCell(length, 2));
        table.rows.push_back(std::move(row));
    }
    if (!table.rows.empty())
        section.tables.push_back(std::move(table));
}

void addRanges(const Mechanism &mechanism, const Pose &pose, Parts &parts)
{
    Section &section = parts.ranges;
    section.key = "ranges";
    section.title = QCoreApplication::translate("Sheet", "Ranges of motion");
    Table table;
    table.key = "variables";
    table.labelTitle = QCoreApplication::translate("Sheet", "variable");
    table.columns = {{"role", QCoreApplication::translate("Sheet", "role"), {}, {}},
        {"pose", QCoreApplication::translate("Sheet", "this pose"), {}, {}},
        {"min", QCoreApplication::translate("Sheet", "min"), {}, {}},
        {"max", QCoreApplication::translate("Sheet", "max"), {}, {}},
        {"travel", QCoreApplication::translate("Sheet", "travel"), {}, {}},
        {"unit", QCoreApplication::translate("Sheet", "unit"), {}, {}}};
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableInfo &info = variables[i];
        const Interval range = mechanism.variableRange(static_cast<int>(i));
        const int decimals = info.decimals;
        Row row {info.name, utf8(info.symbol) + QStringLiteral(" — ") + coreLabel(info.label), {}, false};
        row.cells.push_back(info.actuated
                ? wordCell("input", QCoreApplication::translate("Sheet", "input (actuated)"))
                : wordCell("output", QCoreApplication::translate("Sheet", "output")));
        row.cells.push_back(variableCell(mechanism, pose, static_cast<int>(i)));
        row.cells.push_back(numberCell(info.unit.toDisplay(range.min), decimals));
        row.cells.push_back(numberCell(info.unit.toDisplay(range.max), decimals));
        row.cells.push_back(numberCell(info.unit.toDisplay(range.max - range.min), decimals));
        row.cells.push_back(info.unit.symbol.empty() ? wordCell("-")
                                                     : wordCell(std::string(info.unit.symbol), unitShown(info.unit.symbol)));
        table.rows.push_back(std::move(row));
    }
    section.tables.push_back(std::move(table));
}

/// Key poses of any mechanism: home, this pose and every input at the ends of its range.
void addGenericKeyPoses(const Mechanism &mechanism, const Pose &pose, Parts &parts)
{
    Section &section = parts.keyPoses;
    static constexpr std::array<std::string_view, 3> names {"det_J", "cond", "margin"};
    Table table;
    table.key = "poses";
    table.labelTitle = QCoreApplication::translate("Sheet", "pose");
    table.columns = keyPoseColumns(mechanism, names);
    const Pose home = mechanism.homePose();
    // one row per pose: angles are compared modulo a turn (θ = −180° is θ = 180°)
    const auto &variables = mechanism.variableInfo();
    const auto signature = [&](const Pose &p) {
        std::vector<double> values;
        for (int i = 0; i < static_cast<int>(variables.size()); ++i) {
            double value = mechanism.variableValue(p, i);
            if (variables[std::size_t(i)].unit.symbol == "°")
                value = std::remainder(value, 2.0 * std::numbers::pi);
            values.push_back(value);
        }
        return values;
    };
    std::vector<std::vector<double>> seen;
    const auto add = [&](const Pose &p, std::string key, QString label, bool highlight) {
        const std::vector<double> values = signature(p);
        for (const std::vector<double> &other : seen) {
            bool same = other.size() == values.size();
            for (std::size_t i = 0; same && i < values.size(); ++i)
                same = std::abs(other[i] - values[i]) <= 1e-9 * std::max(1.0, std::abs(values[i]));
            if (same)
                return;
        }
        seen.push_back(values);
        Row row = keyPoseRow(mechanism, p, names, std::move(key), std::move(label));
        row.highlight = highlight;
        table.rows.push_back(std::move(row));
    };
    add(pose, "pose", QCoreApplication::translate("Sheet", "this pose"), true);
    add(home, "home", QCoreApplication::translate("Sheet", "home"), false);
    for (int i = 0; i < mechanism.inputCount(); ++i) {
        const VariableInfo &info = variables[static_cast<std::size_t>(i)];
        const Interval range = mechanism.variableRange(i);
        for (const bool upper : {false, true}) {
            Coordinates inputs = home.inputs;
            inputs[i] = upper ? range.max : range.min;
            if (auto solved = mechanism.solveDirect(inputs, &home)) {
                add(*solved, info.name + (upper ? "_max" : "_min"),
                    (upper ? QCoreApplication::translate("Sheet", "%1 max") : QCoreApplication::translate("Sheet", "%1 min"))
                        .arg(utf8(info.symbol)),
                    false);
            }
        }
    }
    table.note = QCoreApplication::translate("Sheet",
        "Every actuated input at the ends of its range with the others at the home pose, where the mechanism "
        "reaches it.");
    section.tables.push_back(std::move(table));
}

/// A one-input mechanism swept over its input: the least singularity margin.
void addSweepCheck(const Mechanism &mechanism, const Sweep &sweep, Parts &parts)
{
    double least = std::numeric_limits<double>::infinity();
    double where = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < sweep.evaluations.size(); ++i) {
        if (sweep.poses[i].inputs.size() == 0)
            continue;
        if (sweep.evaluations[i].singularity.margin < least) {
            least = sweep.evaluations[i].singularity.margin;
            where = sweep.input[i];
        }
    }
    if (!std::isfinite(least))
        return;
    const VariableInfo &input = mechanism.variableInfo().front();
    Check check;
    check.key = "singularity_margin";
    check.title = QCoreApplication::translate("Sheet", "No singular pose in the range of motion");
    check.criterion = QCoreApplication::translate("Sheet", "singularity margin ≥ %1").arg(numberText(nearSingularMargin, 2));
    check.value = numberCell(least, 3);
    check.limit = numberCell(nearSingularMargin, 3);
    check.verdict = least >= nearSingularMargin ? Verdict::Pass : Verdict::Fail;
    check.detail = QCoreApplication::translate("Sheet", "least at %1 = %2")
                       .arg(utf8(input.symbol), quantityText(where, input.decimals, input.unit.symbol));
    parts.checks.checks.push_back(std::move(check));
}

/// The plots of a one-input mechanism without plots of its own: its outputs over the input.
void addGenericPlots(const Mechanism &mechanism, const Pose &pose, const Sweep &sweep, Parts &parts)
{
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        if (variables[i].actuated)
            continue;
        Figure figure = sweepPlot(mechanism, pose, 0, sweep, variables[i].name, "plot_" + variables[i].name,
            QCoreApplication::translate("Sheet", "%1 over %2").arg(utf8(variables[i].symbol), utf8(variables.front().symbol)));
        if (!figure.plot.series.empty())
            parts.plots.figures.push_back(std::move(figure));
    }
}

void addWarnings(const Mechanism &mechanism, Parts &parts)
{
    Section &section = parts.notes;
    section.key = "warnings";
    section.title = QCoreApplication::translate("Sheet", "Design warnings");
    for (const std::string &warning : mechanism.designWarnings())
        section.notes.push_back(utf8(warning));
}

bool empty(const Section &section)
{
    return section.items.empty() && section.tables.empty() && section.checks.empty() && section.figures.empty()
        && section.notes.empty();
}

} // namespace

// -- the sheet ------------------------------------------------------------------------------

Sheet build(const Mechanism &mechanism, const Pose &pose, const Source &source, KindSections kindSections)
{
    Sheet sheet;
    sheet.design = source.design;
    // a preset's title and description in the sheet's language (a design of one's own as written)
    sheet.title = designfile::presetText(source.title);
    sheet.description = designfile::presetText(source.description);
    sheet.kind = std::string(mechanism.kind());
    const MechanismKind *kind = findMechanismKind(mechanism.kind());
    sheet.kindTitle = kind ? coreLabel(kind->title) : utf8(mechanism.kind());
    sheet.date = sheetDate();
#ifdef PKM_VERSION
    sheet.version = PKM_VERSION;
#endif
    sheet.pose = poseText(mechanism, pose);

    Parts parts;
    addParameters(mechanism, parts);
    addLinks(mechanism, pose, parts);
    addRanges(mechanism, pose, parts);
    parts.keyPoses.key = "key_poses";
    parts.keyPoses.title = QCoreApplication::translate("Sheet", "Key poses");
    parts.checks.key = "checks";
    parts.checks.title = QCoreApplication::translate("Sheet", "Checks");
    parts.plots.key = "plots";
    parts.plots.title = QCoreApplication::translate("Sheet", "Plots");
    parts.plots.newPage = true;

    if (kindSections)
        kindSections(mechanism, pose, parts);
    if (const PlanarWorkspace *workspace = mechanism.planarWorkspace())
        addPlanar(mechanism, *workspace, pose, parts);

    // What a kind without sections of its own still gets from the interface.
    if (parts.keyPoses.tables.empty())
        addGenericKeyPoses(mechanism, pose, parts);
    if (mechanism.inputCount() == 1 && (parts.checks.checks.empty() || parts.plots.figures.empty())) {
        const Sweep sweep = sweepInput(mechanism, 0, 241);
        if (parts.checks.checks.empty())
            addSweepCheck(mechanism, sweep, parts);
        if (parts.plots.figures.empty())
            addGenericPlots(mechanism, pose, sweep, parts);
    }
    addDrawing(mechanism, pose, sheet.pose, parts);
    addWarnings(mechanism, parts);
    addCapability(mechanism, pose, parts);
    addActuatorChecks(mechanism, pose, source.requirements, parts);

    for (Section *section : {&parts.parameters, &parts.dimensions, &parts.ranges, &parts.keyPoses, &parts.checks,
             &parts.capability, &parts.notes, &parts.workspace, &parts.singular, &parts.plots, &parts.drawing}) {
        if (!empty(*section))
            sheet.sections.push_back(std::move(*section));
    }
    return sheet;
}

std::optional<Format> formatOf(const std::string &path)
{
    const QString name = QString::fromStdString(path).section(QLatin1Char('/'), -1);
    const qsizetype dot = name.lastIndexOf(QLatin1Char('.'));
    if (dot <= 0)
        return std::nullopt;
    const QString extension = name.mid(dot + 1).toLower();
    if (extension == QLatin1String("pdf"))
        return Format::Pdf;
    if (extension == QLatin1String("json"))
        return Format::Json;
    if (extension == QLatin1String("csv"))
        return Format::Csv;
    return std::nullopt;
}

} // namespace pkm::sheet
