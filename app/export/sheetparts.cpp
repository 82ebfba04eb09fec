// The pieces of the parameter sheet that every section uses (sheetparts.h): report values as
// cells and columns, key-pose rows, sweeps over an input and their plots; and the cells and
// words of the sheet's model (sheet.h) as every format writes them.

#include "export/sheetparts.h"

#include "planarworkspace.h"
#include "quantityformat.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace pkm::sheet {

namespace detail {

QString utf8(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

Evaluation evaluateAt(const Mechanism &mechanism, const Pose &pose)
{
    Evaluation evaluation;
    evaluation.values.assign(static_cast<std::size_t>(mechanism.reportLayout().size),
        std::numeric_limits<double>::quiet_NaN());
    evaluation.singularity = mechanism.evaluate(pose, evaluation.values);
    return evaluation;
}

Column columnOf(const ReportEntry &entry)
{
    return {entry.name, utf8(entry.symbol), std::string(entry.unit.symbol), coreLabel(entry.label)};
}

Cell cellOf(const ReportEntry &entry, const Evaluation &evaluation)
{
    const auto at = static_cast<std::size_t>(entry.offset);
    const double value = at < evaluation.values.size() ? entry.unit.toDisplay(evaluation.values[at])
                                                         : std::numeric_limits<double>::quiet_NaN();
    return numberCell(value, entry.decimals);
}

Item itemOf(const ReportEntry &entry, const Evaluation &evaluation)
{
    return {entry.name, utf8(entry.symbol), coreLabel(entry.label), cellOf(entry, evaluation),
        std::string(entry.unit.symbol), {}};
}

double displayValue(const Mechanism &mechanism, std::string_view name, const Evaluation &evaluation)
{
    const ReportEntry *entry = mechanism.reportLayout().find(name);
    if (!entry || entry->rows * entry->cols != 1)
        return std::numeric_limits<double>::quiet_NaN();
    return cellOf(*entry, evaluation).number;
}

Column variableColumn(const VariableInfo &info)
{
    return {info.name, utf8(info.symbol), std::string(info.unit.symbol), coreLabel(info.label)};
}

Cell variableCell(const Mechanism &mechanism, const Pose &pose, int variable)
{
    const VariableInfo &info = mechanism.variableInfo()[static_cast<std::size_t>(variable)];
    return numberCell(info.unit.toDisplay(mechanism.variableValue(pose, variable)), info.decimals);
}

Cell singularityCell(SingularityType type)
{
    QString shown;
    switch (type) {
    case SingularityType::None:
        shown = QCoreApplication::translate("Sheet", "none");
        break;
    case SingularityType::Inverse:
        shown = QCoreApplication::translate("Sheet", "inverse");
        break;
    case SingularityType::Direct:
        shown = QCoreApplication::translate("Sheet", "direct");
        break;
    case SingularityType::Combined:
        shown = QCoreApplication::translate("Sheet", "combined");
        break;
    }
    return wordCell(std::string(singularityName(type)), shown);
}

QString verdictText(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Pass:
        return QCoreApplication::translate("Sheet", "PASS");
    case Verdict::Fail:
        return QCoreApplication::translate("Sheet", "FAIL");
    case Verdict::Info:
        break;
    }
    return QCoreApplication::translate("Sheet", "INFO");
}

QString numberText(double value, int decimals)
{
    return cellText(numberCell(value, decimals));
}

QString unitShown(std::string_view unit)
{
    if (unit.empty())
        return {};
    // The sheet's own units, for lupdate; the others are core's (units.h).
    static constexpr const char *own[] = {QT_TRANSLATE_NOOP("Sheet", "min⁻¹"), QT_TRANSLATE_NOOP("Sheet", "steps/s"),
        QT_TRANSLATE_NOOP("Sheet", "mm³")};
    const std::string source(unit);
    for (const char *symbol : own) {
        if (source == symbol)
            return QCoreApplication::translate("Sheet", symbol);
    }
    return coreLabel(unit);
}

QString quantityText(double value, int decimals, std::string_view unit)
{
    QString text = numberText(value, decimals);
    if (unit.empty())
        return text;
    if (unit != "°")
        text += QLatin1Char(' ');
    return text + unitShown(unit);
}

Item numberItem(std::string key, QString symbol, QString label, double value, int decimals, std::string unit)
{
    return {std::move(key), std::move(symbol), std::move(label), numberCell(value, decimals), std::move(unit), {}};
}

namespace {
/// The scalar report entries among `names`.
std::vector<const ReportEntry *> scalarEntries(const Mechanism &mechanism, std::span<const std::string_view> names)
{
    std::vector<const ReportEntry *> entries;
    for (std::string_view name : names) {
        const ReportEntry *entry = mechanism.reportLayout().find(name);
        if (entry && entry->rows * entry->cols == 1 && mechanism.variableIndex(name) < 0)
            entries.push_back(entry);
    }
    return entries;
}
} // namespace

std::vector<Column> keyPoseColumns(const Mechanism &mechanism, std::span<const std::string_view> names)
{
    std::vector<Column> columns;
    for (const VariableInfo &info : mechanism.variableInfo())
        columns.push_back(variableColumn(info));
    for (const ReportEntry *entry : scalarEntries(mechanism, names))
        columns.push_back(columnOf(*entry));
    columns.push_back({"singularity", QCoreApplication::translate("Sheet", "singularity"), {},
        QCoreApplication::translate("Sheet", "singularity class of the pose")});
    return columns;
}

Row keyPoseRow(const Mechanism &mechanism, const Pose &pose, std::span<const std::string_view> names, std::string key,
    QString label)
{
    Row row {std::move(key), std::move(label), {}, false};
    const Evaluation evaluation = evaluateAt(mechanism, pose);
    for (int i = 0; i < static_cast<int>(mechanism.variableInfo().size()); ++i)
        row.cells.push_back(variableCell(mechanism, pose, i));
    for (const ReportEntry *entry : scalarEntries(mechanism, names))
        row.cells.push_back(cellOf(*entry, evaluation));
    row.cells.push_back(singularityCell(evaluation.singularity.type));
    return row;
}

Sweep sweepInput(const Mechanism &mechanism, int variable, int steps)
{
    Sweep sweep;
    const VariableInfo &info = mechanism.variableInfo()[static_cast<std::size_t>(variable)];
    const Interval range = mechanism.variableRange(variable);
    const Pose home = mechanism.homePose();
    Pose last = home;
    for (int i = 0; i < steps; ++i) {
        const double value = range.min + (range.max - range.min) * i / (steps - 1);
        sweep.input.push_back(info.unit.toDisplay(value));
        Coordinates inputs = home.inputs;
        inputs[variable] = value;
        auto solved = mechanism.solveDirect(inputs, &last);
        if (!solved) {
            sweep.poses.emplace_back();
            sweep.evaluations.emplace_back();
            continue;
        }
        last = *solved;
        sweep.poses.push_back(*solved);
        sweep.evaluations.push_back(evaluateAt(mechanism, *solved));
    }
    return sweep;
}

std::pair<double, double> valueAxis(const std::vector<double> &values)
{
    double lower = std::numeric_limits<double>::infinity(), upper = -lower;
    for (double value : values) {
        if (std::isfinite(value)) {
            lower = std::min(lower, value);
            upper = std::max(upper, value);
        }
    }
    if (!(lower <= upper))
        return {0.0, 1.0};
    double span = upper - lower;
    if (span <= 0.0)
        span = std::max(0.1 * std::abs(upper), 1e-9);
    std::pair<double, double> axis {lower - 0.08 * span, upper + 0.08 * span};
    if (lower >= 0.0 && axis.first < 0.0) // a positive quantity: no invented negative values
        axis.first = 0.0;
    return axis;
}

Figure sweepPlot(const Mechanism &mechanism, const Pose &pose, int variable, const Sweep &sweep, std::string_view name,
    std::string key, QString title)
{
    const VariableInfo &input = mechanism.variableInfo()[static_cast<std::size_t>(variable)];
    const ReportEntry *entry = mechanism.reportLayout().find(name);
    Figure figure;
    figure.key = std::move(key);
    figure.title = std::move(title);
    figure.kind = FigureKind::Plot;
    if (!entry)
        return figure;
    Plot &plot = figure.plot;
    const auto label = [](const QString &symbol, std::string_view unit) {
        return unit.empty() ? symbol : QStringLiteral("%1 (%2)").arg(symbol, unitShown(unit));
    };
    plot.xLabel = label(utf8(input.symbol), input.unit.symbol);
    plot.yLabel = label(utf8(entry->symbol), entry->unit.symbol);
    PlotSeries series;
    series.name = utf8(entry->symbol);
    std::vector<double> values;
    for (std::size_t i = 0; i < sweep.input.size(); ++i) {
        const double value = sweep.evaluations[i].values.empty() ? std::numeric_limits<double>::quiet_NaN()
                                                                  : cellOf(*entry, sweep.evaluations[i]).number;
        series.points.emplace_back(sweep.input[i], std::isfinite(value) ? value : std::numeric_limits<double>::quiet_NaN());
        values.push_back(value);
    }
    plot.series.push_back(std::move(series));
    if (!sweep.input.empty()) {
        plot.xMin = sweep.input.front();
        plot.xMax = sweep.input.back();
    }
    std::tie(plot.yMin, plot.yMax) = valueAxis(values);
    plot.cursor = input.unit.toDisplay(mechanism.variableValue(pose, variable));
    figure.caption = coreLabel(entry->label);
    return figure;
}

std::vector<const ReportEntry *> reportEntries(const Mechanism &mechanism, std::span<const std::string_view> names)
{
    std::vector<const ReportEntry *> found;
    for (std::string_view name : names) {
        const ReportEntry *entry = mechanism.reportLayout().find(name);
        if (entry && entry->rows * entry->cols == 1)
            found.push_back(entry);
    }
    return found;
}

Row reportRow(const Mechanism &mechanism, const Pose &pose, const std::vector<const ReportEntry *> &columns,
    std::string key, QString label, bool highlight)
{
    const Evaluation evaluation = evaluateAt(mechanism, pose);
    Row row {std::move(key), std::move(label), {}, highlight};
    for (const ReportEntry *entry : columns)
        row.cells.push_back(cellOf(*entry, evaluation));
    return row;
}

} // namespace detail

using detail::utf8;

// -- cells ------------------------------------------------------------------------------------

Cell numberCell(double value, int decimals)
{
    Cell cell;
    cell.number = value;
    cell.decimals = std::clamp(decimals, 0, 12);
    return cell;
}

Cell wordCell(std::string word, QString shown)
{
    Cell cell;
    cell.word = std::move(word);
    cell.shown = std::move(shown);
    return cell;
}

QString cellText(const Cell &cell)
{
    if (!cell.shown.isEmpty())
        return cell.shown;
    if (cell.isWord())
        return utf8(cell.word);
    if (std::isnan(cell.number))
        return QStringLiteral("—");
    if (std::isinf(cell.number))
        return cell.number > 0 ? QStringLiteral("∞") : QStringLiteral("-∞");
    // "-0.00" → "0.00": a value that rounds to zero is printed as zero.
    const QString plain = QString::number(cell.number, 'f', cell.decimals);
    const bool zero = std::all_of(plain.cbegin(), plain.cend(),
        [](QChar c) { return c == QLatin1Char('-') || c == QLatin1Char('0') || c == QLatin1Char('.'); });
    // The language's decimal separator ("116,20" in Russian), no group separators: a table of
    // dimensions reads "1044.03", as the GUI shows it.
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale.toString(zero ? 0.0 : cell.number, 'f', cell.decimals);
}

const char *verdictWord(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Pass:
        return "PASS";
    case Verdict::Fail:
        return "FAIL";
    case Verdict::Info:
        break;
    }
    return "INFO";
}

const char *figureKindWord(FigureKind kind)
{
    switch (kind) {
    case FigureKind::Plot:
        return "plot";
    case FigureKind::Drawing:
        return "drawing";
    case FigureKind::Image:
        break;
    }
    return "image";
}

QString scaleText(std::pair<int, int> scale)
{
    return QStringLiteral("%1:%2").arg(scale.first).arg(scale.second);
}

const Section *Sheet::section(std::string_view key) const
{
    for (const Section &s : sections) {
        if (s.key == key)
            return &s;
    }
    return nullptr;
}

} // namespace pkm::sheet
