// The parameter sheet as JSON and CSV: the same content as the PDF, by key. Numbers are written
// as every `pkm` output writes them (numberformat.h: up to 15 significant digits, '.' whatever
// the locale), so the sheet's numbers compare equal to those of `pkm eval --json`.

#include "document/savefile.h"
#include "report/jsonwriter.h"
#include "report/numberformat.h"
#include "export/sheet.h"

#include <cmath>

namespace pkm::sheet {

namespace {

std::string text(const QString &string)
{
    return string.toStdString();
}

void writeCell(report::JsonWriter &json, const Cell &cell)
{
    if (cell.isWord())
        json.string(cell.word);
    else
        json.number(cell.number); // null when not finite
}

void writeItems(report::JsonWriter &json, const std::vector<Item> &items)
{
    json.key("values");
    json.beginObject();
    for (const Item &item : items) {
        json.key(item.key);
        json.beginObject(true);
        json.key("symbol").string(text(item.symbol));
        json.key("label").string(text(item.label));
        json.key("value");
        writeCell(json, item.value);
        json.key("unit").string(item.unit);
        if (!item.value.isWord())
            json.key("decimals").integer(item.value.decimals);
        if (!item.value.shown.isEmpty())
            json.key("shown").string(text(item.value.shown));
        if (!item.group.empty())
            json.key("group").string(item.group);
        json.endObject();
    }
    json.endObject();
}

void writeTables(report::JsonWriter &json, const std::vector<Table> &tables)
{
    json.key("tables");
    json.beginObject();
    for (const Table &table : tables) {
        json.key(table.key);
        json.beginObject();
        json.key("title").string(text(table.title));
        json.key("label_title").string(text(table.labelTitle));
        json.key("columns");
        json.beginArray();
        for (const Column &column : table.columns) {
            json.beginObject(true);
            json.key("key").string(column.key);
            json.key("title").string(text(column.title));
            json.key("unit").string(column.unit);
            if (!column.label.isEmpty())
                json.key("label").string(text(column.label));
            json.endObject();
        }
        json.endArray();
        json.key("rows");
        json.beginArray();
        for (const Row &row : table.rows) {
            json.beginObject(true);
            json.key("key").string(row.key);
            json.key("label").string(text(row.label));
            if (row.highlight)
                json.key("this_pose").boolean(true);
            json.key("values");
            json.beginObject(true);
            for (std::size_t c = 0; c < table.columns.size() && c < row.cells.size(); ++c) {
                json.key(table.columns[c].key);
                writeCell(json, row.cells[c]);
            }
            json.endObject();
            json.endObject();
        }
        json.endArray();
        if (!table.note.isEmpty())
            json.key("note").string(text(table.note));
        json.endObject();
    }
    json.endObject();
}

void writeChecks(report::JsonWriter &json, const std::vector<Check> &checks)
{
    json.key("checks");
    json.beginObject();
    for (const Check &check : checks) {
        json.key(check.key);
        json.beginObject(true);
        json.key("title").string(text(check.title));
        json.key("criterion").string(text(check.criterion));
        json.key("value");
        writeCell(json, check.value);
        json.key("limit");
        writeCell(json, check.limit);
        json.key("unit").string(check.unit);
        json.key("result").string(verdictWord(check.verdict));
        json.key("detail").string(text(check.detail));
        json.endObject();
    }
    json.endObject();
}

void writeFigures(report::JsonWriter &json, const std::vector<Figure> &figures)
{
    json.key("figures");
    json.beginArray();
    for (const Figure &figure : figures) {
        json.beginObject(true);
        json.key("key").string(figure.key);
        json.key("kind").string(figureKindWord(figure.kind));
        json.key("title").string(text(figure.title));
        json.key("caption").string(text(figure.caption));
        if (figure.kind == FigureKind::Drawing)
            json.key("scale").string(text(scaleText(figure.scale)));
        json.endObject();
    }
    json.endArray();
}

// -- CSV ------------------------------------------------------------------------------------

void appendField(std::string &out, std::string_view field)
{
    if (field.find_first_of(",\"\r\n") == std::string_view::npos) {
        out.append(field);
        return;
    }
    out += '"';
    for (char c : field) {
        if (c == '"')
            out += '"';
        out += c;
    }
    out += '"';
}

void appendLine(std::string &out, std::string_view section, std::string_view table, std::string_view row,
    std::string_view column, std::string_view value, std::string_view unit)
{
    for (std::string_view field : {section, table, row, column}) {
        appendField(out, field);
        out += ',';
    }
    appendField(out, value);
    out += ',';
    appendField(out, unit);
    out += '\n';
}

std::string cellField(const Cell &cell)
{
    if (cell.isWord())
        return cell.word;
    if (!std::isfinite(cell.number))
        return {}; // as in `pkm sweep --csv`
    std::string number;
    report::appendNumber(number, cell.number);
    return number;
}

} // namespace

std::string toJson(const Sheet &sheet)
{
    std::string out;
    report::JsonWriter json(out, report::JsonWriter::Style::Pretty);
    json.beginObject();
    json.key("sheet").string("pkm-parameter-sheet");
    json.key("design").string(sheet.design);
    json.key("title").string(text(sheet.title));
    json.key("description").string(text(sheet.description));
    json.key("mechanism").string(sheet.kind);
    json.key("mechanism_title").string(text(sheet.kindTitle));
    json.key("date").string(text(sheet.date));
    json.key("version").string(sheet.version);
    json.key("pose").string(text(sheet.pose));
    json.key("sections");
    json.beginObject();
    for (const Section &section : sheet.sections) {
        json.key(section.key);
        json.beginObject();
        json.key("title").string(text(section.title));
        if (!section.intro.isEmpty())
            json.key("intro").string(text(section.intro));
        if (!section.items.empty())
            writeItems(json, section.items);
        if (!section.tables.empty())
            writeTables(json, section.tables);
        if (!section.checks.empty())
            writeChecks(json, section.checks);
        if (!section.figures.empty())
            writeFigures(json, section.figures);
        if (!section.notes.empty()) {
            json.key("notes");
            json.beginArray();
            for (const QString &note : section.notes)
                json.string(text(note));
            json.endArray();
        }
        json.endObject();
    }
    json.endObject();
    json.endObject();
    out += '\n';
    return out;
}

std::string toCsv(const Sheet &sheet)
{
    std::string out = "section,table,row,column,value,unit\n";
    const auto head = [&](std::string_view key, const std::string &value) {
        appendLine(out, "sheet", "", key, "value", value, "");
    };
    head("design", sheet.design);
    head("title", text(sheet.title));
    head("mechanism", sheet.kind);
    head("mechanism_title", text(sheet.kindTitle));
    head("date", text(sheet.date));
    head("version", sheet.version);
    head("pose", text(sheet.pose));
    for (const Section &section : sheet.sections) {
        for (const Item &item : section.items)
            appendLine(out, section.key, "values", item.key, "value", cellField(item.value), item.unit);
        for (const Table &table : section.tables) {
            for (const Row &row : table.rows) {
                for (std::size_t c = 0; c < table.columns.size() && c < row.cells.size(); ++c) {
                    const Cell &cell = row.cells[c];
                    appendLine(out, section.key, table.key, row.key, table.columns[c].key, cellField(cell),
                        cell.isWord() ? std::string_view() : std::string_view(table.columns[c].unit));
                }
            }
        }
        for (const Check &check : section.checks) {
            appendLine(out, section.key, "checks", check.key, "value", cellField(check.value),
                check.value.isWord() ? std::string_view() : std::string_view(check.unit));
            if (check.limit.isWord() || std::isfinite(check.limit.number))
                appendLine(out, section.key, "checks", check.key, "limit", cellField(check.limit), check.unit);
            appendLine(out, section.key, "checks", check.key, "result", verdictWord(check.verdict), "");
        }
        for (const Figure &figure : section.figures) {
            appendLine(out, section.key, "figures", figure.key, "title", text(figure.title), "");
            if (figure.kind == FigureKind::Drawing)
                appendLine(out, section.key, "figures", figure.key, "scale", text(scaleText(figure.scale)), "");
        }
        for (std::size_t n = 0; n < section.notes.size(); ++n)
            appendLine(out, section.key, "notes", std::to_string(n + 1), "text", text(section.notes[n]), "");
    }
    return out;
}

std::optional<std::string> save(const Sheet &sheet, const std::string &path)
{
    const std::optional<Format> format = formatOf(path);
    if (!format)
        return "Cannot write '" + path + "': a parameter sheet is a .pdf, .json or .csv file.";
    if (*format == Format::Pdf) {
        QString error;
        const QByteArray pdf = toPdf(sheet, &error);
        if (pdf.isEmpty()) {
            std::string why = error.toStdString();
            while (!why.empty() && (why.back() == '.' || why.back() == ' '))
                why.pop_back();
            return "Cannot write '" + path + "': " + (why.empty() ? std::string("the PDF could not be drawn") : why)
                + ".";
        }
        return files::saveBytes(path, pdf);
    }
    const std::string content = *format == Format::Json ? toJson(sheet) : toCsv(sheet);
    return files::saveBytes(path, QByteArray::fromStdString(content));
}

} // namespace pkm::sheet
