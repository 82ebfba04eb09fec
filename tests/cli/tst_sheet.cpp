// Tests of `pkm sheet` (docs/cli.md): every format of every preset is written and read
// back — the PDF's text through pdftotext, the JSON, the CSV — and its numbers are those of
// `pkm eval --json` and `pkm workspace --json`; bad extensions and failing writes leave no file.

#include "cli/cli.h"
#include "cli/drawingcommands.h"
#include "document/language.h"
#include "gui/mainwindow.h"
#include "support/app.h"
#include "support/process.h"
#include "text.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QTranslator>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace pkm::test;

namespace {

/// One parsed CSV record (RFC 4180 quoting).
QList<QStringList> readCsv(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QString text = QString::fromUtf8(file.readAll());
    QList<QStringList> records;
    QStringList record;
    QString field;
    bool quoted = false;
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (quoted) {
            if (c == QLatin1Char('"') && i + 1 < text.size() && text[i + 1] == QLatin1Char('"')) {
                field += c;
                ++i;
            } else if (c == QLatin1Char('"')) {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == QLatin1Char('"')) {
            quoted = true;
        } else if (c == QLatin1Char(',')) {
            record << field;
            field.clear();
        } else if (c == QLatin1Char('\n')) {
            record << field;
            records << record;
            record.clear();
            field.clear();
        } else {
            field += c;
        }
    }
    return records;
}

/// The row `key` of a sheet table.
QJsonObject tableRow(const QJsonObject &sheet, const QString &section, const QString &table, const QString &key)
{
    const QJsonArray rows = sheet[QStringLiteral("sections")][section][QStringLiteral("tables")][table][QStringLiteral("rows")].toArray();
    for (const QJsonValue &row : rows) {
        if (row[QStringLiteral("key")].toString() == key)
            return row.toObject();
    }
    return {};
}

QJsonObject section(const QJsonObject &sheet, const QString &key)
{
    return sheet[QStringLiteral("sections")][key].toObject();
}

double value(const QJsonObject &sheet, const QString &sectionKey, const QString &item)
{
    return section(sheet, sectionKey)[QStringLiteral("values")][item][QStringLiteral("value")].toDouble(std::nan(""));
}

bool close(double a, double b, double relative = 1e-12)
{
    return std::abs(a - b) <= relative * std::max(1.0, std::max(std::abs(a), std::abs(b)));
}

/// Where `translated` (a sheet in another language) differs from `english` other than in its
/// texts for people: the keys, the numbers, the words of the cells, the units and the verdicts
/// must be the same. Empty when they are.
QString differenceBeyondTexts(const QJsonValue &english, const QJsonValue &translated, const QStringList &path = {})
{
    const QString where = path.join(QLatin1Char('/'));
    if (english.type() != translated.type())
        return where + QStringLiteral(": another type");
    if (english.isObject()) {
        const QJsonObject a = english.toObject(), b = translated.toObject();
        if (a.keys() != b.keys())
            return where + QStringLiteral(": other keys");
        for (auto it = a.begin(); it != a.end(); ++it) {
            const QString why = differenceBeyondTexts(it.value(), b[it.key()], path + QStringList {it.key()});
            if (!why.isEmpty())
                return why;
        }
        return {};
    }
    if (english.isArray()) {
        const QJsonArray a = english.toArray(), b = translated.toArray();
        if (a.size() != b.size())
            return where + QStringLiteral(": another length");
        for (qsizetype i = 0; i < a.size(); ++i) {
            const QString why = differenceBeyondTexts(a[i], b[i], path + QStringList {QString::number(i)});
            if (!why.isEmpty())
                return why;
        }
        return {};
    }
    if (english.isString()) {
        static const QStringList kept {QStringLiteral("sheet"), QStringLiteral("design"), QStringLiteral("mechanism"),
            QStringLiteral("date"), QStringLiteral("version"), QStringLiteral("key"), QStringLiteral("kind"),
            QStringLiteral("unit"), QStringLiteral("result"), QStringLiteral("scale"), QStringLiteral("group"),
            QStringLiteral("value"), QStringLiteral("limit")};
        const QString last = path.value(path.size() - 1), parent = path.value(path.size() - 2);
        const bool mustKeep = kept.contains(last) || parent == QLatin1String("values");
        if (mustKeep && english.toString() != translated.toString())
            return where + QStringLiteral(": '") + english.toString() + QStringLiteral("' became '")
                + translated.toString() + QLatin1Char('\'');
        return {};
    }
    return english == translated ? QString() : where + QStringLiteral(": another value");
}

QString fixed(double number, int decimals)
{
    QString text = QString::number(number, 'f', decimals);
    if (text.startsWith(QLatin1Char('-')) && text.count(QLatin1Char('0')) + text.count(QLatin1Char('.')) == text.size() - 1)
        text.remove(0, 1); // "-0.00": the sheet prints 0.00
    return text;
}

} // namespace

class TestSheet : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();

    void pjointPdfShowsTheNumbers();
    void pjointJsonMatchesEval();
    void pjointActuatorCheck();
    void csvMatchesJson_data();
    void csvMatchesJson();
    void everyPresetEveryFormat_data();
    void everyPresetEveryFormat();
    void momaWorkspaceAndStrokes();
    void oxglideExactAreas();
    void fourbarGrashofAndTransmission();
    void setChangesTheSheet();
    void designFileByName();
    void reproducibleDate();

    void badExtension();
    void failingWriteLeavesNoFile();
    void failingPoseLeavesNoFile();
    void help();
    void inProcessJsonAndPdfNeedsGui();
    void fileMenuHasTheExport();

    void unknownLanguage();
    void englishIsTheDefault();
    void languageKeepsKeysAndNumbers();
    void russianPdfNumbers();
    void footerWordsDoNotOverlap();
    void russianSheet();
    void inProcessLanguageIsRestored();

private:
    QString pdfText(const QString &pdf, bool layout = true);
    QString path(const QString &name) const { return m_dir.filePath(name); }

    QTemporaryDir m_dir;
    QString m_pdftotext;
    QJsonObject m_prototype; ///< the prototype's sheet as JSON
};

void TestSheet::initTestCase()
{
    pkm::cli::registerDrawingCommands(); // runCli() in-process runs `pkm sheet`, as pkm-draw does
    QVERIFY(m_dir.isValid());
    QVERIFY2(QFile::exists(QStringLiteral(PKM_BINARY_DIR "/pkm")), "build the pkm target first");
    m_pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
    const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"),
        path(QStringLiteral("prototype.json"))});
    QCOMPARE(run.exitCode, 0);
    m_prototype = readJson(path(QStringLiteral("prototype.json")));
    QVERIFY(!m_prototype.isEmpty());
}

QString TestSheet::pdfText(const QString &pdf, bool layout)
{
    QProcess process;
    QStringList arguments;
    if (layout)
        arguments << QStringLiteral("-layout");
    arguments << pdf << QStringLiteral("-");
    process.start(m_pdftotext, arguments);
    if (!process.waitForFinished(60000) || process.exitCode() != 0)
        return {};
    return QString::fromUtf8(process.readAllStandardOutput());
}

void TestSheet::pjointPdfShowsTheNumbers()
{
    if (m_pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed");
    const QString pdf = path(QStringLiteral("prototype.pdf"));
    const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"), pdf});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.out.startsWith("Wrote " + pdf.toUtf8()));
    QFile file(pdf);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.read(5) == "%PDF-");
    const QString text = pdfText(pdf);
    QVERIFY2(!text.isEmpty(), "pdftotext extracted no text");
    QVERIFY(text.contains(QStringLiteral("pjoint-prototype")));
    QVERIFY(text.contains(QStringLiteral("Active П-joint")));

    // every parameter as eval gives it, with the sheet's decimals
    const QJsonObject eval = prototypeEval();
    const QJsonObject parameters = eval[QStringLiteral("parameters")].toObject();
    const QJsonObject values = section(m_prototype, QStringLiteral("parameters"))[QStringLiteral("values")].toObject();
    QVERIFY(parameters.size() >= 10);
    for (auto it = parameters.begin(); it != parameters.end(); ++it) {
        const int decimals = values[it.key()][QStringLiteral("decimals")].toInt(-1);
        QVERIFY2(decimals >= 0, qPrintable(it.key()));
        const QString shown = fixed(it.value().toDouble(), decimals);
        QVERIFY2(text.contains(shown), qPrintable(it.key() + QStringLiteral(" = ") + shown));
    }
    // the derived dimensions of section 4.2: d_min ≈ 117, d_max ≈ 232, stroke ≈ 115 mm
    const QJsonObject derived = eval[QStringLiteral("derived")].toObject();
    for (const char *name : {"d_min", "d_max", "stroke"}) {
        const QString shown = fixed(derived[QLatin1String(name)].toDouble(), 2);
        QVERIFY2(text.contains(shown), name);
    }
    QVERIFY(text.contains(QStringLiteral("116.20")));
    QVERIFY(text.contains(QStringLiteral("231.40")));
    QVERIFY(text.contains(QStringLiteral("115.21")));

    // the key poses θ_min, 0, θ_max: one line each with θ, d and the torque
    const QStringList lines = text.split(QLatin1Char('\n'));
    const struct {
        const char *set;
        const char *label;
    } poses[] = {{"theta=-60", "θ_min"}, {"theta=0", "θ = 0"}, {"theta=60", "θ_max"}};
    for (const auto &pose : poses) {
        const QJsonObject at = prototypeEval({QLatin1String(pose.set)});
        const QString d = fixed(at[QStringLiteral("pose")][QStringLiteral("d")].toDouble(), 2);
        const QString torque = fixed(at[QStringLiteral("derived")][QStringLiteral("torque")].toDouble(), 3);
        const QString label = QString::fromUtf8(pose.label);
        const bool found = std::any_of(lines.begin(), lines.end(), [&](const QString &line) {
            return line.contains(label) && line.contains(d) && line.contains(torque);
        });
        QVERIFY2(found, qPrintable(label + QStringLiteral(": d = ") + d + QStringLiteral(", T = ") + torque));
    }
    QVERIFY(text.contains(QStringLiteral("PASS")));
    QVERIFY(text.contains(QStringLiteral("FAIL")));
    QVERIFY(text.contains(QStringLiteral("Actuator check")));
    QVERIFY(text.contains(QStringLiteral("Scale 1:")));
    QVERIFY(text.contains(QStringLiteral("page 1 of ")));
    // the plots are there with their axis titles
    QVERIFY(text.contains(QStringLiteral("Output torque T")));
    QVERIFY(text.contains(QStringLiteral("θ (°)")));
}

void TestSheet::pjointJsonMatchesEval()
{
    const QJsonObject &sheet = m_prototype;
    QCOMPARE(sheet[QStringLiteral("sheet")].toString(), QStringLiteral("pkm-parameter-sheet"));
    QCOMPARE(sheet[QStringLiteral("design")].toString(), QStringLiteral("pjoint-prototype"));
    QCOMPARE(sheet[QStringLiteral("mechanism")].toString(), QStringLiteral("pjoint"));
    QCOMPARE(sheet[QStringLiteral("version")].toString(), QStringLiteral(PKM_VERSION));
    const QJsonObject eval = prototypeEval();
    const QJsonObject parameters = eval[QStringLiteral("parameters")].toObject();
    for (auto it = parameters.begin(); it != parameters.end(); ++it)
        QCOMPARE(value(sheet, QStringLiteral("parameters"), it.key()), it.value().toDouble());
    const QJsonObject derived = eval[QStringLiteral("derived")].toObject();
    for (const char *name : {"d_min", "d_max", "stroke", "recommended_min", "recommended_max", "motor_torque"})
        QCOMPARE(value(sheet, QStringLiteral("dimensions"), QLatin1String(name)), derived[QLatin1String(name)].toDouble());

    // the key poses, as eval solves them
    const struct {
        const char *row;
        const char *set;
    } rows[] = {{"theta_min", "theta=-60"}, {"zero", "theta=0"}, {"theta_max", "theta=60"}};
    for (const auto &row : rows) {
        const QJsonObject cells = tableRow(sheet, QStringLiteral("key_poses"), QStringLiteral("poses"), QLatin1String(row.row))[QStringLiteral("values")].toObject();
        QVERIFY2(!cells.isEmpty(), row.row);
        const QJsonObject at = prototypeEval({QLatin1String(row.set)});
        for (const char *name : {"theta", "d", "phi", "mu"})
            QVERIFY2(close(cells[QLatin1String(name)].toDouble(), at[QStringLiteral("pose")][QLatin1String(name)].toDouble()), name);
        QVERIFY(close(cells[QStringLiteral("J")].toDouble(), at[QStringLiteral("jacobian")][QStringLiteral("J")].toDouble()));
        for (const char *name : {"torque", "speed", "resolution"})
            QVERIFY2(close(cells[QLatin1String(name)].toDouble(), at[QStringLiteral("derived")][QLatin1String(name)].toDouble()), name);
    }
    // the recommended range's ends are rows too (θ_min is one of them for the prototype)
    QVERIFY(!tableRow(sheet, QStringLiteral("key_poses"), QStringLiteral("poses"), QStringLiteral("recommended_max")).isEmpty());
    QCOMPARE(tableRow(sheet, QStringLiteral("key_poses"), QStringLiteral("poses"), QStringLiteral("zero"))[QStringLiteral("this_pose")].toBool(), true);

    // the links between joint centres: two cranks of a, base and coupler of b
    const QJsonArray links = section(sheet, QStringLiteral("dimensions"))[QStringLiteral("tables")][QStringLiteral("links")][QStringLiteral("rows")].toArray();
    int cranks = 0, shorts = 0;
    for (const QJsonValue &link : links) {
        const double length = link[QStringLiteral("values")][QStringLiteral("length")].toDouble();
        cranks += close(length, 170.0, 1e-9) ? 1 : 0;
        shorts += close(length, 68.0, 1e-9) ? 1 : 0;
    }
    QCOMPARE(cranks, 2);
    QCOMPARE(shorts, 2);
    // the sections and the figures
    for (const char *key : {"parameters", "dimensions", "ranges", "key_poses", "checks", "plots", "drawing"})
        QVERIFY2(sheet[QStringLiteral("sections")].toObject().contains(QLatin1String(key)), key);
    QCOMPARE(section(sheet, QStringLiteral("plots"))[QStringLiteral("figures")].toArray().size(), 6);
    const QJsonObject drawing = section(sheet, QStringLiteral("drawing"))[QStringLiteral("figures")][0].toObject();
    QCOMPARE(drawing[QStringLiteral("kind")].toString(), QStringLiteral("drawing"));
    QVERIFY(drawing[QStringLiteral("scale")].toString().contains(QLatin1Char(':')));
}

void TestSheet::pjointActuatorCheck()
{
    const QJsonObject checks = section(m_prototype, QStringLiteral("checks"))[QStringLiteral("checks")].toObject();
    const auto result = [](const QJsonObject &list, const char *key) {
        return list[QLatin1String(key)][QStringLiteral("result")].toString();
    };
    QCOMPARE(result(checks, "motor_fits"), QStringLiteral("PASS"));
    QCOMPARE(checks[QStringLiteral("motor_fits")][QStringLiteral("value")].toDouble(), 45.0);
    QCOMPARE(result(checks, "singularity_margin"), QStringLiteral("PASS"));
    // θ_max = 60° reaches where J falls steeply (the document: θ = 40°…60°)
    QCOMPARE(result(checks, "torque"), QStringLiteral("FAIL"));
    QCOMPARE(result(checks, "speed"), QStringLiteral("FAIL"));
    QCOMPARE(result(checks, "resolution"), QStringLiteral("FAIL"));
    // the least torque is at θ_max: T = J·F_max there
    const QJsonObject atMax = prototypeEval({QStringLiteral("theta=60")});
    QVERIFY(close(checks[QStringLiteral("torque")][QStringLiteral("value")].toDouble(),
        atMax[QStringLiteral("derived")][QStringLiteral("torque")].toDouble(), 1e-9));
    QCOMPARE(result(checks, "motor_torque"), QStringLiteral("INFO"));
    QVERIFY(close(checks[QStringLiteral("motor_torque")][QStringLiteral("value")].toDouble(),
        atMax[QStringLiteral("derived")][QStringLiteral("motor_torque")].toDouble()));

    // inside the recommended range (−60°…39.2°) every check passes
    const QString json = path(QStringLiteral("recommended.json"));
    const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
        QStringLiteral("theta_max=39"), QStringLiteral("-o"), json});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject narrowed = section(readJson(json), QStringLiteral("checks"))[QStringLiteral("checks")].toObject();
    for (const char *key : {"motor_fits", "torque", "speed", "resolution", "singularity_margin"})
        QCOMPARE(result(narrowed, key), QStringLiteral("PASS"));
}

void TestSheet::csvMatchesJson_data()
{
    addPresetPerKindRows("design"); // every kind's sections and tables
}

void TestSheet::csvMatchesJson()
{
    PKM_FETCH_PRESET(design);
    const QString json = path(design + QStringLiteral("-match.json")), csv = path(design + QStringLiteral("-match.csv"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), design, QStringLiteral("-o"), json}).exitCode, 0);
    QCOMPARE(runPkm({QStringLiteral("sheet"), design, QStringLiteral("-o"), csv}).exitCode, 0);
    const QJsonObject sheet = readJson(json);
    const QList<QStringList> records = readCsv(csv);
    QVERIFY(records.size() > 20);
    QCOMPARE(records.front(), QStringList({QStringLiteral("section"), QStringLiteral("table"), QStringLiteral("row"),
                                  QStringLiteral("column"), QStringLiteral("value"), QStringLiteral("unit")}));
    const auto same = [](const QJsonValue &expected, const QString &field) {
        if (expected.isString())
            return expected.toString() == field;
        if (expected.isNull())
            return field.isEmpty();
        bool ok = false;
        const double number = field.toDouble(&ok);
        return ok && number == expected.toDouble(); // the same text: the same double
    };
    int values = 0, cells = 0, checks = 0;
    for (qsizetype i = 1; i < records.size(); ++i) {
        const QStringList &r = records[i];
        QCOMPARE(r.size(), 6);
        const QString &sectionKey = r[0], &table = r[1], &row = r[2], &column = r[3], &field = r[4];
        const QString context = r.join(QLatin1Char(','));
        if (sectionKey == QLatin1String("sheet")) {
            QVERIFY2(sheet[row].toString() == field, qPrintable(context));
            continue;
        }
        const QJsonObject s = section(sheet, sectionKey);
        QVERIFY2(!s.isEmpty(), qPrintable(context));
        if (table == QLatin1String("values")) {
            const QJsonObject item = s[QStringLiteral("values")][row].toObject();
            QVERIFY2(same(item[QStringLiteral("value")], field), qPrintable(context));
            QCOMPARE(item[QStringLiteral("unit")].toString(), r[5]);
            ++values;
        } else if (table == QLatin1String("checks")) {
            QVERIFY2(same(s[QStringLiteral("checks")][row][column], field), qPrintable(context));
            ++checks;
        } else if (table == QLatin1String("figures")) {
            bool found = false;
            for (const QJsonValue &figure : s[QStringLiteral("figures")].toArray())
                found = found || (figure[QStringLiteral("key")].toString() == row && same(figure[column], field));
            QVERIFY2(found, qPrintable(context));
        } else if (table == QLatin1String("notes")) {
            QVERIFY2(same(s[QStringLiteral("notes")][row.toInt() - 1], field), qPrintable(context));
        } else {
            const QJsonObject found = tableRow(sheet, sectionKey, table, row);
            QVERIFY2(!found.isEmpty(), qPrintable(context));
            QVERIFY2(same(found[QStringLiteral("values")][column], field), qPrintable(context));
            ++cells;
        }
    }
    // and the other way: every value and every table cell of the JSON is a line of the CSV
    int jsonValues = 0, jsonCells = 0;
    for (const QJsonValue &s : sheet[QStringLiteral("sections")].toObject()) {
        jsonValues += s[QStringLiteral("values")].toObject().size();
        for (const QJsonValue &t : s[QStringLiteral("tables")].toObject()) {
            for (const QJsonValue &row : t[QStringLiteral("rows")].toArray())
                jsonCells += row[QStringLiteral("values")].toObject().size();
        }
    }
    QCOMPARE(values, jsonValues);
    QCOMPARE(cells, jsonCells);
    QVERIFY(checks > 0);
}

void TestSheet::everyPresetEveryFormat_data()
{
    QTest::addColumn<QString>("design");
    const QJsonObject list = QJsonDocument::fromJson(runPkm({QStringLiteral("list"), QStringLiteral("--json")}).out).object();
    const QJsonArray presets = list[QStringLiteral("presets")].toArray();
    QVERIFY(presets.size() >= 7);
    for (const QJsonValue &preset : presets) {
        const QString id = preset[QStringLiteral("id")].toString();
        QTest::newRow(qPrintable(id)) << id;
    }
}

void TestSheet::everyPresetEveryFormat()
{
    QFETCH(QString, design);
    for (const QString &extension : {QStringLiteral("pdf"), QStringLiteral("json"), QStringLiteral("csv")}) {
        const QString file = path(design + QLatin1Char('.') + extension);
        const Run run = runPkm({QStringLiteral("sheet"), design, QStringLiteral("-o"), file});
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY(run.err.isEmpty());
        QCOMPARE(QString::fromUtf8(run.out).section(QLatin1Char(' '), 0, 1), QStringLiteral("Wrote ") + file);
        QVERIFY(QFileInfo(file).size() > 100);
    }
    const QJsonObject sheet = readJson(path(design + QStringLiteral(".json")));
    QCOMPARE(sheet[QStringLiteral("design")].toString(), design);
    for (const char *key : {"parameters", "dimensions", "ranges", "key_poses", "checks", "drawing"})
        QVERIFY2(sheet[QStringLiteral("sections")].toObject().contains(QLatin1String(key)), key);
    // every check has a verdict
    for (const QJsonValue &check : section(sheet, QStringLiteral("checks"))[QStringLiteral("checks")].toObject()) {
        const QString result = check[QStringLiteral("result")].toString();
        QVERIFY(result == QLatin1String("PASS") || result == QLatin1String("FAIL") || result == QLatin1String("INFO"));
    }
    QCOMPARE(readCsv(path(design + QStringLiteral(".csv"))).value(1).value(4), design);
    if (m_pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed");
    const QString text = pdfText(path(design + QStringLiteral(".pdf")));
    QVERIFY(text.contains(design));
    QVERIFY(text.contains(QStringLiteral("Design parameters")));
    QVERIFY(text.contains(QStringLiteral("Dimensioned drawing")));
}

void TestSheet::momaWorkspaceAndStrokes()
{
    const QString json = path(QStringLiteral("moma.json"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("moma-3a"), QStringLiteral("-o"), json}).exitCode, 0);
    const QJsonObject sheet = readJson(json);
    const QJsonObject workspace
        = QJsonDocument::fromJson(runPkm({QStringLiteral("workspace"), QStringLiteral("moma-3a"), QStringLiteral("--json")}).out).object();
    // the grid areas of `pkm workspace`
    QCOMPARE(value(sheet, QStringLiteral("workspace"), QStringLiteral("area")), workspace[QStringLiteral("area")].toDouble());
    QCOMPARE(value(sheet, QStringLiteral("workspace"), QStringLiteral("area_union")), workspace[QStringLiteral("area_union")].toDouble());
    QCOMPARE(value(sheet, QStringLiteral("workspace"), QStringLiteral("reachable_cells")), workspace[QStringLiteral("reachable_cells")].toDouble());
    const QJsonArray modes = section(sheet, QStringLiteral("workspace"))[QStringLiteral("tables")][QStringLiteral("modes")][QStringLiteral("rows")].toArray();
    QCOMPARE(modes.size(), workspace[QStringLiteral("modes")].toArray().size());
    for (qsizetype i = 0; i < modes.size(); ++i)
        QCOMPARE(modes[i][QStringLiteral("values")][QStringLiteral("area")].toDouble(), workspace[QStringLiteral("modes")][i][QStringLiteral("area")].toDouble());
    // the strokes: 0…200 mm guides, used almost fully
    const QJsonObject checks = section(sheet, QStringLiteral("checks"))[QStringLiteral("checks")].toObject();
    for (const char *key : {"stroke_p1", "stroke_p2"}) {
        const QJsonObject check = checks[QLatin1String(key)].toObject();
        QCOMPARE(check[QStringLiteral("result")].toString(), QStringLiteral("PASS"));
        QCOMPARE(check[QStringLiteral("limit")].toDouble(), 200.0);
        QVERIFY(check[QStringLiteral("value")].toDouble() > 190.0 && check[QStringLiteral("value")].toDouble() <= 200.0);
    }
    const QJsonObject p1 = tableRow(sheet, QStringLiteral("ranges"), QStringLiteral("variables"), QStringLiteral("p1"));
    QCOMPARE(p1[QStringLiteral("values")][QStringLiteral("travel")].toDouble(), 200.0);
    // configuration 3a has no direct singularity (docs/mathematics.md)
    QCOMPARE(checks[QStringLiteral("direct_singular_poses")][QStringLiteral("result")].toString(), QStringLiteral("PASS"));
    QVERIFY(sheet[QStringLiteral("sections")].toObject().contains(QStringLiteral("singular")));
    const QJsonArray figures = section(sheet, QStringLiteral("workspace"))[QStringLiteral("figures")].toArray();
    QCOMPARE(figures.size(), 2);

    if (m_pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed");
    const QString pdf = path(QStringLiteral("moma.pdf"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("moma-3a"), QStringLiteral("-o"), pdf}).exitCode, 0);
    const QString text = pdfText(pdf);
    QVERIFY(text.contains(fixed(workspace[QStringLiteral("area")].toDouble(), 1)));
    QVERIFY(text.contains(QStringLiteral("Stroke of p₁")));
    QVERIFY(text.contains(QStringLiteral("200.00")));
}

void TestSheet::oxglideExactAreas()
{
    const QString json = path(QStringLiteral("oxglide.json"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("oxglide-prototype"), QStringLiteral("-o"), json}).exitCode, 0);
    const QJsonObject sheet = readJson(json);
    // docs/mathematics.md: the X workspace is the larger; exactly 753.33 and 2125.33 mm²
    QVERIFY(std::abs(value(sheet, QStringLiteral("workspace"), QStringLiteral("area_O")) - 753.33) < 0.01);
    QVERIFY(std::abs(value(sheet, QStringLiteral("workspace"), QStringLiteral("area_X")) - 2125.33) < 0.01);
    QCOMPARE(value(sheet, QStringLiteral("workspace"), QStringLiteral("area")), value(sheet, QStringLiteral("workspace"), QStringLiteral("area_O")));
    // the volume over the z travel of 150 mm
    QVERIFY(close(value(sheet, QStringLiteral("workspace"), QStringLiteral("volume")),
        150.0 * value(sheet, QStringLiteral("workspace"), QStringLiteral("area")), 1e-9));
    // the slider strokes within the 130 mm guides
    const QJsonObject checks = section(sheet, QStringLiteral("checks"))[QStringLiteral("checks")].toObject();
    QCOMPARE(checks[QStringLiteral("stroke_x_AB")][QStringLiteral("result")].toString(), QStringLiteral("PASS"));
    QCOMPARE(checks[QStringLiteral("stroke_x_AB")][QStringLiteral("limit")].toDouble(), 130.0);
    // the O↔X crossing is reachable at the top of the O workspace (y = l): a direct singularity
    QCOMPARE(checks[QStringLiteral("direct_singular_poses")][QStringLiteral("result")].toString(), QStringLiteral("FAIL"));
    if (m_pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed");
    const QString pdf = path(QStringLiteral("oxglide.pdf"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("oxglide-prototype"), QStringLiteral("-o"), pdf}).exitCode, 0);
    const QString text = pdfText(pdf);
    QVERIFY(text.contains(QStringLiteral("753.3")));
    QVERIFY(text.contains(QStringLiteral("2125.3")));
}

void TestSheet::fourbarGrashofAndTransmission()
{
    const QString json = path(QStringLiteral("fourbar.json"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("-o"), json}).exitCode, 0);
    const QJsonObject sheet = readJson(json);
    const QJsonObject checks = section(sheet, QStringLiteral("checks"))[QStringLiteral("checks")].toObject();
    QCOMPARE(checks[QStringLiteral("grashof")][QStringLiteral("value")].toString(), QStringLiteral("crank-rocker"));
    QCOMPARE(section(sheet, QStringLiteral("dimensions"))[QStringLiteral("values")][QStringLiteral("grashof")][QStringLiteral("value")].toString(),
        QStringLiteral("crank-rocker"));
    QCOMPARE(checks[QStringLiteral("alpha_range")][QStringLiteral("value")].toDouble(), 360.0);
    // the example's transmission angle stays between 53° and 110° (its description): PASS at 40°
    const QJsonObject transmission = checks[QStringLiteral("transmission")].toObject();
    QCOMPARE(transmission[QStringLiteral("result")].toString(), QStringLiteral("PASS"));
    QCOMPARE(transmission[QStringLiteral("limit")].toDouble(), 40.0);
    QVERIFY(std::abs(transmission[QStringLiteral("value")].toDouble() - 53.13) < 0.05);
    QCOMPARE(section(sheet, QStringLiteral("plots"))[QStringLiteral("figures")].toArray().size(), 4);
    // a crank that barely works: a long coupler lowers the transmission angle below 40°
    const QString poor = path(QStringLiteral("fourbar-poor.json"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("--set"),
                 QStringLiteral("AB=70"), QStringLiteral("-o"), poor})
                 .exitCode,
        0);
    QCOMPARE(section(readJson(poor), QStringLiteral("checks"))[QStringLiteral("checks")][QStringLiteral("transmission")][QStringLiteral("result")].toString(),
        QStringLiteral("FAIL"));
    if (m_pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed");
    const QString pdf = path(QStringLiteral("fourbar.pdf"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("-o"), pdf}).exitCode, 0);
    const QString text = pdfText(pdf);
    QVERIFY(text.contains(QStringLiteral("crank-rocker")));
    QVERIFY(text.contains(QStringLiteral("Grashof class")));
    QVERIFY(text.contains(QStringLiteral("53.13")));
}

void TestSheet::setChangesTheSheet()
{
    const QString json = path(QStringLiteral("set.json"));
    const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
        QStringLiteral("a=200"), QStringLiteral("--set"), QStringLiteral("theta=30"), QStringLiteral("-o"), json});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject sheet = readJson(json);
    QCOMPARE(value(sheet, QStringLiteral("parameters"), QStringLiteral("a")), 200.0);
    const QJsonObject eval = QJsonDocument::fromJson(runPkm({QStringLiteral("eval"), QStringLiteral("pjoint-prototype"),
        QStringLiteral("--set"), QStringLiteral("a=200"), QStringLiteral("--set"), QStringLiteral("theta=30"), QStringLiteral("--json")})
                                                         .out)
                                 .object();
    QCOMPARE(value(sheet, QStringLiteral("dimensions"), QStringLiteral("d_max")),
        eval[QStringLiteral("derived")][QStringLiteral("d_max")].toDouble());
    const QJsonObject pose = tableRow(sheet, QStringLiteral("key_poses"), QStringLiteral("poses"), QStringLiteral("pose"));
    QCOMPARE(pose[QStringLiteral("this_pose")].toBool(), true);
    QVERIFY(close(pose[QStringLiteral("values")][QStringLiteral("theta")].toDouble(), 30.0));
    QVERIFY(sheet[QStringLiteral("pose")].toString().contains(QStringLiteral("θ = 30.00°")));
}

void TestSheet::designFileByName()
{
    const QString json = path(QStringLiteral("custom.json"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral(PKM_TEST_DATA_DIR "/custom.pkm.json"), QStringLiteral("-o"), json}).exitCode, 0);
    const QJsonObject sheet = readJson(json);
    QCOMPARE(sheet[QStringLiteral("design")].toString(), QStringLiteral("custom.pkm.json")); // not this machine's path
    QCOMPARE(value(sheet, QStringLiteral("parameters"), QStringLiteral("a")), 200.0);
}

void TestSheet::reproducibleDate()
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("SOURCE_DATE_EPOCH"), QStringLiteral("86400"));
    const QString json = path(QStringLiteral("dated.json"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("-o"), json}, environment).exitCode, 0);
    QCOMPARE(readJson(json)[QStringLiteral("date")].toString(), QStringLiteral("1970-01-02"));
}

void TestSheet::badExtension()
{
    const QString bad = path(QStringLiteral("sheet.txt"));
    const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"), bad});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.out.isEmpty());
    QVERIFY2(run.err.contains("sheet.txt"), run.err.constData());
    QVERIFY(run.err.contains(".pdf, .json or .csv"));
    QVERIFY(!QFile::exists(bad));
    // no -o at all
    const Run missing = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype")});
    QCOMPARE(missing.exitCode, 2);
    QVERIFY(missing.err.contains("-o"));
    // no extension
    const QString none = path(QStringLiteral("sheet"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"), none}).exitCode, 2);
    QVERIFY(!QFile::exists(none));
}

void TestSheet::failingWriteLeavesNoFile()
{
    // the parent "directory" is a file: nothing can be created below it
    const QString blocker = path(QStringLiteral("blocker"));
    {
        QFile file(blocker);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("not a directory");
    }
    for (const QString &extension : {QStringLiteral("pdf"), QStringLiteral("json"), QStringLiteral("csv")}) {
        const QString target = blocker + QStringLiteral("/sheet.") + extension;
        const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"), target});
        QCOMPARE(run.exitCode, 1);
        QVERIFY(run.out.isEmpty());
        QVERIFY2(run.err.startsWith("pkm: Cannot write '" + target.toUtf8() + "'"), run.err.constData());
        QVERIFY(!QFile::exists(target));
    }
    QDir directory(m_dir.path());
    const QStringList leftovers = directory.entryList({QStringLiteral("*.pdf.*"), QStringLiteral("*.json.*"), QStringLiteral("*.csv.*")});
    QVERIFY2(leftovers.isEmpty(), qPrintable(leftovers.join(QLatin1Char(' '))));
}

void TestSheet::failingPoseLeavesNoFile()
{
    // an existing sheet is left as it was when the command fails
    const QString existing = path(QStringLiteral("existing.json"));
    {
        QFile file(existing);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("old");
    }
    const Run unreachable = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
        QStringLiteral("theta=75"), QStringLiteral("-o"), existing});
    QCOMPARE(unreachable.exitCode, 3);
    const Run unknown = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
        QStringLiteral("nonsense=1"), QStringLiteral("-o"), existing});
    QCOMPARE(unknown.exitCode, 2);
    QVERIFY(unknown.err.contains("nonsense"));
    QFile file(existing);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("old"));
    const QString fresh = path(QStringLiteral("fresh.pdf"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("no-such-design"), QStringLiteral("-o"), fresh}).exitCode, 2);
    QVERIFY(!QFile::exists(fresh));
}

void TestSheet::help()
{
    const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("--help")});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.out.contains("Usage: pkm sheet DESIGN"));
    QVERIFY(run.out.contains("section,table,row,column,value,unit"));
    const Run main = runPkm({QStringLiteral("--help")});
    QVERIFY(main.out.contains("sheet  DESIGN"));
}

void TestSheet::inProcessJsonAndPdfNeedsGui()
{
    // runCli() in this process: JSON needs no GUI; the PDF needs a QGuiApplication, which this
    // test (a QApplication) has.
    const QString json = path(QStringLiteral("inprocess.json"));
    std::FILE *out = std::tmpfile();
    std::FILE *err = std::tmpfile();
    QVERIFY(out && err);
    QCOMPARE(pkm::runCli({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("-o"), json}, out, err), 0);
    QCOMPARE(readJson(json)[QStringLiteral("mechanism")].toString(), QStringLiteral("fourbar"));
    const QString pdf = path(QStringLiteral("inprocess.pdf"));
    QCOMPARE(pkm::runCli({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("-o"), pdf}, out, err), 0);
    QVERIFY(QFileInfo(pdf).size() > 1000);
    std::fclose(out);
    std::fclose(err);
}

void TestSheet::fileMenuHasTheExport()
{
    QStandardPaths::setTestModeEnabled(true); // no autosave or settings in the user's directories
    pkm::MainWindow window;
    auto *action = window.findChild<QAction *>(QStringLiteral("exportSheetAction"));
    QVERIFY(action);
    QVERIFY(action->text().contains(QStringLiteral("Parameter Sheet")));
    QMenu *file = window.menuBar()->actions().front()->menu();
    QVERIFY(file && file->actions().contains(action));

    // File ▸ Export Parameter Sheet…: the dialog gets a name, the sheet of the open design is written
    for (const QString &name : {QStringLiteral("gui.json"), QStringLiteral("gui.pdf")}) {
        const QString target = path(name);
        bool answered = false;
        QTimer poll; // the dialog runs its own event loop: answer it from there once it shows
        poll.setInterval(50);
        connect(&poll, &QTimer::timeout, &window, [&] {
            for (QWidget *widget : QApplication::topLevelWidgets()) {
                auto *dialog = qobject_cast<QFileDialog *>(widget);
                if (!dialog || !dialog->isVisible())
                    continue;
                dialog->selectFile(target);
                // queued: from the dialog's own event loop, once exec() runs it
                // selectFile() leaves the name field alone while it has the focus: type the name
                if (auto *name = dialog->findChild<QLineEdit *>(QStringLiteral("fileNameEdit")))
                    name->setText(target);
                QMetaObject::invokeMethod(dialog, "accept", Qt::QueuedConnection);
                answered = true;
                poll.stop();
                return;
            }
        });
        poll.start();
        QTimer giveUp; // a dialog that never shows up fails the test rather than hanging it
        giveUp.setSingleShot(true);
        connect(&giveUp, &QTimer::timeout, &window, [] {
            for (QWidget *widget : QApplication::topLevelWidgets()) {
                if (auto *dialog = qobject_cast<QDialog *>(widget); dialog && dialog->isVisible())
                    QMetaObject::invokeMethod(dialog, "reject", Qt::QueuedConnection);
            }
        });
        giveUp.start(30000);
        action->trigger();
        giveUp.stop();
        poll.stop();
        QVERIFY(answered);
        // computed off the GUI thread: the status bar says when it is written
        QTRY_VERIFY2_WITH_TIMEOUT(window.lastStatus().startsWith(QStringLiteral("Wrote the parameter sheet"))
                                      && window.lastStatus().contains(name),
                                  qPrintable(window.lastStatus()), 60000);
        QVERIFY2(QFileInfo(target).size() > 100, qPrintable(target));
    }
    const QJsonObject sheet = readJson(path(QStringLiteral("gui.json")));
    QCOMPARE(sheet[QStringLiteral("mechanism")].toString(), QStringLiteral("pjoint"));
    QCOMPARE(value(sheet, QStringLiteral("parameters"), QStringLiteral("a")), 170.0);
}

void TestSheet::unknownLanguage()
{
    const QString json = path(QStringLiteral("german.json"));
    const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("--lang"),
        QStringLiteral("de"), QStringLiteral("-o"), json});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.out.isEmpty());
    QVERIFY2(run.err.startsWith("pkm: --lang de: unknown language 'de'"), run.err.constData());
    QVERIFY2(run.err.contains("en, sr, sr_Latn or ru"), run.err.constData());
    QCOMPARE(run.err.count('\n'), 1); // one sentence
    QVERIFY(!QFile::exists(json));
    // no value, and a command without the option
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"), json,
                 QStringLiteral("--lang")})
                 .exitCode,
        2);
    const Run eval = runPkm({QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--lang"),
        QStringLiteral("ru")});
    QCOMPARE(eval.exitCode, 2);
    QVERIFY2(eval.err.contains("'--lang' is not an option of 'pkm eval'"), eval.err.constData());
    // the help says which languages there are
    const Run help = runPkm({QStringLiteral("sheet"), QStringLiteral("--help")});
    QVERIFY(help.out.contains("--lang CODE"));
    QVERIFY(help.out.contains("sr_Latn"));
}

void TestSheet::englishIsTheDefault()
{
    // English whatever the system's locale: scripts read the sheet
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("SOURCE_DATE_EPOCH"), QStringLiteral("86400"));
    environment.insert(QStringLiteral("LC_ALL"), QStringLiteral("ru_RU.UTF-8"));
    environment.insert(QStringLiteral("LANG"), QStringLiteral("ru_RU.UTF-8"));
    for (const QString &extension : {QStringLiteral("json"), QStringLiteral("csv")}) {
        const QString plain = path(QStringLiteral("default.") + extension), english = path(QStringLiteral("english.") + extension);
        QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("-o"), plain}, environment).exitCode, 0);
        QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("--lang"),
                     QStringLiteral("en"), QStringLiteral("-o"), english},
                     environment)
                     .exitCode,
            0);
        QFile a(plain), b(english);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll(), b.readAll());
    }
    const QJsonObject sheet = readJson(path(QStringLiteral("default.json")));
    QCOMPARE(section(sheet, QStringLiteral("parameters"))[QStringLiteral("title")].toString(), QStringLiteral("Design parameters"));
    if (m_pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed");
    const QString pdf = path(QStringLiteral("default.pdf"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"), pdf}, environment).exitCode, 0);
    const QString text = pdfText(pdf);
    QVERIFY(text.contains(QStringLiteral("116.20")));
    QVERIFY(text.contains(QStringLiteral("Parameter sheet")));
}

void TestSheet::languageKeepsKeysAndNumbers()
{
    // Another language: the same keys, numbers, cell words, units and verdicts as in English;
    // only the texts for people differ.
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("SOURCE_DATE_EPOCH"), QStringLiteral("86400"));
    const auto sheet = [&](const QString &design, const QString &code, const QString &file) {
        QStringList arguments {QStringLiteral("sheet"), design, QStringLiteral("-o"), file};
        if (!code.isEmpty())
            arguments << QStringLiteral("--lang") << code;
        return runPkm(arguments, environment);
    };
    for (const QString &design : {QStringLiteral("pjoint-prototype"), QStringLiteral("oxglide-prototype")}) {
        const QString english = path(design + QStringLiteral("-en.json")), englishCsv = path(design + QStringLiteral("-en.csv"));
        QCOMPARE(sheet(design, {}, english).exitCode, 0);
        QCOMPARE(sheet(design, {}, englishCsv).exitCode, 0);
        const QJsonObject reference = readJson(english);
        QVERIFY(!reference.isEmpty());
        for (const QString &code : {QStringLiteral("ru"), QStringLiteral("sr_Latn")}) {
            const QString json = path(design + QLatin1Char('-') + code + QStringLiteral(".json"));
            const Run run = sheet(design, code, json);
            QVERIFY2(run.exitCode == 0, run.err.constData());
            QVERIFY(run.out.startsWith("Wrote " + json.toUtf8() + " (parameter sheet of ")); // the CLI stays English
            const QString why = differenceBeyondTexts(reference, readJson(json));
            QVERIFY2(why.isEmpty(), qPrintable(design + QLatin1Char(' ') + code + QStringLiteral(": ") + why));
            // the preset's title and description are in the language
            const QJsonObject translated = readJson(json);
            for (const char *key : {"title", "description"}) {
                const QString text = translated.value(QLatin1String(key)).toString();
                QVERIFY2(!text.isEmpty() && text != reference.value(QLatin1String(key)).toString(), qPrintable(text));
            }
        }
        // the CSV has the same values: only the texts of the title block (a preset's title and
        // description are translated too), figures and notes may differ
        const QString csv = path(design + QStringLiteral("-ru.csv"));
        QCOMPARE(sheet(design, QStringLiteral("ru"), csv).exitCode, 0);
        const QList<QStringList> a = readCsv(englishCsv), b = readCsv(csv);
        QCOMPARE(a.size(), b.size());
        for (qsizetype i = 0; i < a.size(); ++i) {
            static const QStringList sheetTexts = {QStringLiteral("title"), QStringLiteral("description"),
                                                   QStringLiteral("mechanism_title"), QStringLiteral("pose")};
            const bool text = (a[i][0] == QLatin1String("sheet") && sheetTexts.contains(a[i][2]))
                || a[i][3] == QLatin1String("title") || a[i][3] == QLatin1String("text");
            if (text)
                QCOMPARE(b[i].mid(0, 4), a[i].mid(0, 4));
            else
                QCOMPARE(b[i], a[i]);
        }
    }
}

void TestSheet::footerWordsDoNotOverlap()
{
    if (m_pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed");
    // The foot of every page: the date, the title and the page number side by side, none
    // written over another however long the title is in the language.
    static const QRegularExpression word(QStringLiteral(
        "<word xMin=\"([0-9.]+)\" yMin=\"([0-9.]+)\" xMax=\"([0-9.]+)\" yMax=\"[0-9.]+\">([^<]*)</word>"));
    for (const QString &code : {QStringLiteral("en"), QStringLiteral("sr"), QStringLiteral("ru")}) {
        const QString pdf = path(QStringLiteral("foot-") + code + QStringLiteral(".pdf"));
        const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("--lang"), code,
                                QStringLiteral("-o"), pdf});
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QProcess process;
        process.start(m_pdftotext, {QStringLiteral("-bbox"), pdf, QStringLiteral("-")});
        QVERIFY(process.waitForFinished(30000));
        const QStringList pages = QString::fromUtf8(process.readAllStandardOutput()).split(QStringLiteral("<page "));
        QVERIFY(pages.size() > 2);
        for (const QString &page : pages.mid(1)) {
            QList<std::pair<double, double>> foot; // the words below 790 pt of the 842 pt page
            QString line;
            for (auto it = word.globalMatch(page); it.hasNext();) {
                const auto match = it.next();
                if (match.captured(2).toDouble() > 790.0) {
                    foot.append({match.captured(1).toDouble(), match.captured(3).toDouble()});
                    line += match.captured(4) + QLatin1Char(' ');
                }
            }
            QVERIFY2(foot.size() >= 5, qPrintable(code + QStringLiteral(": ") + line));
            std::sort(foot.begin(), foot.end());
            for (qsizetype i = 1; i < foot.size(); ++i)
                QVERIFY2(foot[i - 1].second <= foot[i].first + 0.5, qPrintable(code + QStringLiteral(": ") + line));
        }
    }
}

void TestSheet::russianPdfNumbers()
{
    if (m_pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed");
    // The PDF writes numbers as the language does: a decimal comma in Russian and Serbian.
    for (const QString &code : {QStringLiteral("ru"), QStringLiteral("sr")}) {
        const QString pdf = path(QStringLiteral("prototype-") + code + QStringLiteral(".pdf"));
        const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("--lang"), code,
            QStringLiteral("-o"), pdf});
        QVERIFY2(run.exitCode == 0, run.err.constData());
        const QString text = pdfText(pdf);
        QVERIFY2(!text.isEmpty(), "pdftotext extracted no text");
        QVERIFY(text.contains(QStringLiteral("pjoint-prototype")));
        for (const char *number : {"116,20", "231,40", "115,21"})
            QVERIFY2(text.contains(QLatin1String(number)), number);
        QVERIFY(!text.contains(QStringLiteral("116.20")));
        // the English verdicts stay, for searching any language's sheet
        QVERIFY(text.contains(QStringLiteral("PASS")));
        QVERIFY(text.contains(QStringLiteral("FAIL")));
    }
}

void TestSheet::russianSheet()
{
    // The Russian catalogue translates the sheet; until it does, there is nothing to see.
    QTranslator catalogue;
    if (!catalogue.load(QStringLiteral(":/i18n/pkm_studio_ru")) || catalogue.translate("Sheet", "Parameter sheet").isEmpty())
        QSKIP("the Russian catalogue does not translate the parameter sheet yet");
    const QString json = path(QStringLiteral("prototype-ru.json"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("--lang"), QStringLiteral("ru"),
                 QStringLiteral("-o"), json})
                 .exitCode,
        0);
    const QJsonObject sheet = readJson(json);
    QCOMPARE(section(sheet, QStringLiteral("parameters"))[QStringLiteral("title")].toString(), QStringLiteral("Параметры конструкции"));
    QCOMPARE(section(sheet, QStringLiteral("checks"))[QStringLiteral("title")].toString(), QStringLiteral("Проверка привода"));
    QCOMPARE(section(sheet, QStringLiteral("drawing"))[QStringLiteral("title")].toString(), QStringLiteral("Чертёж с размерами"));
    // core's labels, where the catalogue has them
    const QJsonObject english = section(m_prototype, QStringLiteral("parameters"))[QStringLiteral("values")].toObject();
    const QJsonObject russian = section(sheet, QStringLiteral("parameters"))[QStringLiteral("values")].toObject();
    for (auto it = english.begin(); it != english.end(); ++it) {
        const QByteArray label = it.value()[QStringLiteral("label")].toString().toUtf8();
        const QString translated = catalogue.translate("core", label.constData());
        if (!translated.isEmpty())
            QCOMPARE(russian[it.key()][QStringLiteral("label")].toString(), translated);
    }
    const QString kind = catalogue.translate("core", m_prototype[QStringLiteral("mechanism_title")].toString().toUtf8().constData());
    if (!kind.isEmpty())
        QCOMPARE(sheet[QStringLiteral("mechanism_title")].toString(), kind);

    if (m_pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed");
    const QString pdf = path(QStringLiteral("prototype-ru.pdf"));
    QCOMPARE(runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("--lang"), QStringLiteral("ru"),
                 QStringLiteral("-o"), pdf})
                 .exitCode,
        0);
    const QString text = pdfText(pdf);
    for (const char *heading : {"Лист параметров", "Параметры конструкции", "Производные размеры", "Диапазоны движения",
             "Характерные положения", "Проверка привода", "Графики", "Чертёж с размерами", "стр. 1 из "})
        QVERIFY2(text.contains(QString::fromUtf8(heading)), heading);
    QVERIFY(text.contains(QStringLiteral("ВЫПОЛНЕНО (PASS)")));
    QVERIFY(text.contains(QStringLiteral("НЕ ВЫПОЛНЕНО (FAIL)")));
    QVERIFY(!text.contains(QStringLiteral("Design parameters")));
    if (catalogue.translate("core", "mm") == QStringLiteral("мм"))
        QVERIFY(text.contains(QStringLiteral("мм")));
}

void TestSheet::inProcessLanguageIsRestored()
{
    // runCli() in this process: --lang changes the language only while the sheet is made.
    const QString locale = QLocale().name();
    const QString title = QCoreApplication::translate("Sheet", "Parameter sheet");
    const std::string number = pkm::text::number(-1.5, 1);
    std::FILE *out = std::tmpfile();
    std::FILE *err = std::tmpfile();
    QVERIFY(out && err);
    const QString russian = path(QStringLiteral("inprocess-ru.json"));
    QCOMPARE(pkm::runCli({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("--lang"),
                 QStringLiteral("ru"), QStringLiteral("-o"), russian},
                 out, err),
        0);
    QCOMPARE(QLocale().name(), locale);
    QCOMPARE(QCoreApplication::translate("Sheet", "Parameter sheet"), title);
    QCOMPARE(pkm::text::number(-1.5, 1), number);
    const QString english = path(QStringLiteral("inprocess-en.json"));
    QCOMPARE(pkm::runCli({QStringLiteral("sheet"), QStringLiteral("fourbar-example"), QStringLiteral("-o"), english}, out, err), 0);
    QCOMPARE(section(readJson(english), QStringLiteral("parameters"))[QStringLiteral("title")].toString(),
        QStringLiteral("Design parameters"));
    std::fclose(out);
    std::fclose(err);
}

QTEST_MAIN(TestSheet)
#include "tst_sheet.moc"
