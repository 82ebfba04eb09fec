// Tests of the DXF drawings: the R12 writer itself (number format, text escapes, the file's
// structure), the drawing of a scene (lengths, dimension texts, undefined points), `pkm dxf`
// for every preset, read back by an independent reader (tests/cli/check_dxf.py with ezdxf),
// its failures (nothing written, the exit status of docs/cli.md), and the GUI's File ▸ Export
// Drawing (DXF)….

#include "cli/cli.h"
#include "cli/drawingcommands.h"
#include "dimensiontext.h"
#include "document/designfile.h"
#include "export/dxfwriter.h"
#include "gui/mainwindow.h"
#include "support/app.h"
#include "support/process.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QFileDialog>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <clocale>
#include <cmath>
#include <limits>
#include <numbers>

using namespace pkm;
using namespace pkm::test;

namespace {

QString u(const char *text)
{
    return QString::fromUtf8(text);
}

/// A DXF file as its (group code, value) pairs; a malformed file gives an empty list.
QList<QPair<int, QByteArray>> groupPairs(const QByteArray &dxf)
{
    QList<QByteArray> lines = dxf.split('\n');
    if (!lines.isEmpty() && lines.back().isEmpty())
        lines.removeLast();
    QList<QPair<int, QByteArray>> pairs;
    if (lines.size() % 2 != 0)
        return {};
    for (qsizetype i = 0; i < lines.size(); i += 2) {
        bool ok = false;
        const int code = lines[i].trimmed().toInt(&ok);
        if (!ok || lines[i].size() != 3) // group codes are right-aligned in three columns
            return {};
        pairs.append({code, lines[i + 1]});
    }
    return pairs;
}

/// The entities of a DXF file: per entity its type and group values (a code given more than
/// once, as a POLYLINE's VERTEX points, keeps every value), from the ENTITIES section.
struct Entity {
    QByteArray type;
    QMultiMap<int, QByteArray> values;
    QByteArray value(int code) const { return values.value(code); }
    double number(int code) const { return values.value(code).toDouble(); }
};

QList<Entity> entities(const QByteArray &dxf)
{
    const auto pairs = groupPairs(dxf);
    QList<Entity> result;
    bool inside = false;
    for (qsizetype i = 0; i < pairs.size(); ++i) {
        const auto &[code, value] = pairs[i];
        if (code == 2 && value == "ENTITIES" && i > 0 && pairs[i - 1].second == "SECTION") {
            inside = true;
            continue;
        }
        if (!inside)
            continue;
        if (code == 0) {
            if (value == "ENDSEC")
                break;
            if (value == "VERTEX" || value == "SEQEND")
                continue; // part of the POLYLINE before them: its points follow as more 10/20
            result.append({value, {}});
        } else if (!result.isEmpty()) {
            result.back().values.insert(code, value);
        }
    }
    return result;
}

/// The python3 that has ezdxf: $PKM_PYTHON if set, else python3 on PATH or /usr/bin/python3
/// (a pyenv or venv python3 first on PATH may lack the Debian package). Empty, with why, if
/// none.
QString pythonWithEzdxf(QString *why)
{
    QStringList candidates;
    if (qEnvironmentVariableIsSet("PKM_PYTHON"))
        candidates << qEnvironmentVariable("PKM_PYTHON"); // that one only
    const QString onPath = QStandardPaths::findExecutable(QStringLiteral("python3"));
    if (!qEnvironmentVariableIsSet("PKM_PYTHON") && !onPath.isEmpty())
        candidates << onPath;
    if (!qEnvironmentVariableIsSet("PKM_PYTHON") && QFile::exists(QStringLiteral("/usr/bin/python3")))
        candidates << QStringLiteral("/usr/bin/python3");
    if (candidates.isEmpty()) {
        *why = QStringLiteral("python3 is not installed: the DXF files are not read back (scripts/install-deps.sh)");
        return {};
    }
    for (const QString &python : candidates) {
        if (runProgram(python, {QStringLiteral("-c"), QStringLiteral("import ezdxf")}).exitCode == 0)
            return python;
    }
    *why = QStringLiteral("ezdxf is missing (Debian package python3-ezdxf, installed by scripts/install-deps.sh): "
                          "the DXF files are not read back");
    return {};
}

} // namespace

class TestDxf : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();

    // the writer
    void formatReal_data();
    void formatReal();
    void formatRealIgnoresLocale();
    void encodeText_data();
    void encodeText();
    void fileStructure();
    void nonFiniteEntitiesLeftOut();
    void arcExtents();

    // the drawing of a scene
    void sceneLinesAreTheLinks();
    void dimensionText_data();
    void dimensionText();
    void dimensionTextIsTheMeasuredLength();
    void undefinedJointLeftOut();
    void farFreePointLeftOut();
    void labelsWhereTheLayoutPutsThem_data();
    void labelsWhereTheLayoutPutsThem();

    // pkm dxf
    void everyPresetReadBack_data();
    void everyPresetReadBack();
    void posesReadBack_data();
    void posesReadBack();
    void failuresWriteNothing_data();
    void failuresWriteNothing();
    void failureKeepsExistingFile();
    void help();
    void inProcess();

    // the GUI
    void exportFromMainWindow();

private:
    /// Runs check_dxf.py on `dxf` (with `pkm eval --json` of the same design and sets).
    void checkWithEzdxf(const QString &dxf, const QString &design, const QStringList &sets);

    QTemporaryDir m_dir;
    QString m_python;
    QString m_noPython;
};

void TestDxf::initTestCase()
{
    cli::registerDrawingCommands(); // runCli() in-process runs `pkm dxf`, as pkm-draw does
    QVERIFY(m_dir.isValid());
    m_python = pythonWithEzdxf(&m_noPython);
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
}

// -- the writer -----------------------------------------------------------------------------

void TestDxf::formatReal_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("text");
    QTest::newRow("zero") << 0.0 << u("0.0");
    QTest::newRow("minus zero") << -0.0 << u("0.0");
    QTest::newRow("rounds to zero") << -1e-12 << u("0.0");
    QTest::newRow("whole") << 160.0 << u("160.0");
    QTest::newRow("negative") << -68.5 << u("-68.5");
    QTest::newRow("tenth") << 0.1 << u("0.1");
    QTest::newRow("third") << 1.0 / 3.0 << u("0.3333333333");
    QTest::newRow("ten decimals") << 183.0956034426 << u("183.0956034426");
    QTest::newRow("large") << 1.5e6 << u("1500000.0");
    QTest::newRow("small") << 2.5e-7 << u("0.00000025");
}

void TestDxf::formatReal()
{
    QFETCH(double, value);
    QFETCH(QString, text);
    QCOMPARE(QString::fromStdString(dxf::formatReal(value)), text);
}

void TestDxf::formatRealIgnoresLocale()
{
    // A locale with ',' as the decimal separator must not leak into the file.
    const char *locales[] = {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "ru_RU.UTF-8"};
    const std::string previous = std::setlocale(LC_NUMERIC, nullptr);
    const char *used = nullptr;
    for (const char *name : locales) {
        if (std::setlocale(LC_NUMERIC, name)) {
            used = name;
            break;
        }
    }
    const std::string text = dxf::formatReal(1234.5);
    dxf::Writer writer;
    writer.line(dxf::layerLinks, {0.5, 0.25}, {1.5, 2.75});
    const std::string file = writer.finish();
    std::setlocale(LC_NUMERIC, previous.c_str());
    QCOMPARE(QString::fromStdString(text), QStringLiteral("1234.5"));
    QVERIFY(file.find("\n0.25\n") != std::string::npos);
    QVERIFY(file.find(",25") == std::string::npos);
    if (!used)
        qInfo("no comma-decimal locale is installed here: checked in the C locale only");
}

void TestDxf::encodeText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("encoded");
    QTest::newRow("ascii") << u("a = 170.00") << u("a = 170.00");
    QTest::newRow("theta and degree") << QStringLiteral("θ = 30.0°") << u("\\U+03B8 = 30.0%%d");
    QTest::newRow("П") << QStringLiteral("П-joint") << u("\\U+041F-joint");
    QTest::newRow("Cyrillic") << QStringLiteral("Шарнир") << u("\\U+0428\\U+0430\\U+0440\\U+043D\\U+0438\\U+0440");
    QTest::newRow("subscript") << QStringLiteral("p₁") << u("p\\U+2081");
    QTest::newRow("prime") << QStringLiteral("A′B′") << u("A\\U+2032B\\U+2032");
    QTest::newRow("plus-minus, diameter") << QStringLiteral("±5 ⌀4") << u("%%p5 %%c4");
    QTest::newRow("percent") << u("50%%d") << u("50\\U+0025\\U+0025d");
    QTest::newRow("backslash, caret") << u("a\\U+0041^J") << u("a\\U+005CU+0041\\U+005EJ");
    QTest::newRow("control characters") << u("a\nb\tc\r") << u("a b c ");
    QTest::newRow("beyond the BMP") << QStringLiteral("x\U0001F600y") << u("x?y");
}

void TestDxf::encodeText()
{
    QFETCH(QString, text);
    QFETCH(QString, encoded);
    const std::string result = dxf::encodeText(text.toStdString());
    QCOMPARE(QString::fromStdString(result), encoded);
    for (const char c : result)
        QVERIFY(static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7F);
}

void TestDxf::fileStructure()
{
    dxf::Writer writer;
    writer.addLayer("LINKS", 5);
    writer.line(dxf::layerLinks, {0.0, 0.0}, {160.0, 0.0});
    writer.circle(dxf::layerLinks, {160.0, 0.0}, 4.0);
    writer.text(dxf::layerLinks, {80.0, 10.0}, 3.5, "θ", 0.0, dxf::HAlign::Center, dxf::VAlign::Middle);
    writer.polyline(dxf::layerLinks, {{0.0, 0.0}, {10.0, 0.0}, {10.0, 10.0}}, true);
    QCOMPARE(writer.entityCount(), 4);
    const QByteArray file = QByteArray::fromStdString(writer.finish());
    for (const char c : file)
        QVERIFY2(c == '\n' || (static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7F),
            "the file is printable ASCII");
    const auto pairs = groupPairs(file);
    QVERIFY2(!pairs.isEmpty(), "group codes in three columns, one value per line");
    QCOMPARE(pairs.back(), qMakePair(0, QByteArray("EOF")));
    // the sections in order
    QStringList sections;
    for (qsizetype i = 0; i + 1 < pairs.size(); ++i) {
        if (pairs[i] == qMakePair(0, QByteArray("SECTION")))
            sections << QString::fromLatin1(pairs[i + 1].second);
    }
    QCOMPARE(sections, args({"HEADER", "TABLES", "BLOCKS", "ENTITIES"}));
    const auto headerValue = [&](const char *variable, int code) {
        for (qsizetype i = 0; i + 1 < pairs.size(); ++i) {
            if (pairs[i] == qMakePair(9, QByteArray(variable))) {
                for (qsizetype k = i + 1; k < pairs.size() && pairs[k].first != 9 && pairs[k].first != 0; ++k) {
                    if (pairs[k].first == code)
                        return pairs[k].second;
                }
            }
        }
        return QByteArray();
    };
    QCOMPARE(headerValue("$ACADVER", 1), QByteArray("AC1009"));
    QCOMPARE(headerValue("$INSUNITS", 70), QByteArray("4"));
    QCOMPARE(headerValue("$EXTMIN", 10).toDouble(), 0.0);
    QCOMPARE(headerValue("$EXTMAX", 10).toDouble(), 164.0); // the circle's right edge
    QVERIFY(headerValue("$EXTMAX", 20).toDouble() >= 10.0);
    // line types and the layer table with layer 0
    QVERIFY(file.contains("  2\nCONTINUOUS\n"));
    QVERIFY(file.contains("  2\nDASHED\n"));
    QVERIFY(file.contains("  0\nLAYER\n  2\n0\n"));
    QVERIFY(file.contains("  0\nLAYER\n  2\nLINKS\n 70\n0\n 62\n5\n  6\nCONTINUOUS\n"));

    const QList<Entity> drawn = entities(file);
    QCOMPARE(drawn.size(), 4);
    QCOMPARE(drawn[0].type, QByteArray("LINE"));
    QCOMPARE(drawn[0].value(8), QByteArray("LINKS"));
    QCOMPARE(drawn[0].number(11), 160.0);
    QCOMPARE(drawn[1].type, QByteArray("CIRCLE"));
    QCOMPARE(drawn[1].number(40), 4.0);
    QCOMPARE(drawn[2].type, QByteArray("TEXT"));
    QCOMPARE(drawn[2].value(1), QByteArray("\\U+03B8"));
    QCOMPARE(drawn[2].value(72), QByteArray("1"));
    QCOMPARE(drawn[2].value(73), QByteArray("2"));
    QCOMPARE(drawn[3].type, QByteArray("POLYLINE"));
    QCOMPARE(drawn[3].value(70), QByteArray("1"));
    QVERIFY(file.contains("  0\nVERTEX\n"));
    QVERIFY(file.contains("  0\nSEQEND\n"));
}

void TestDxf::nonFiniteEntitiesLeftOut()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    dxf::Writer writer;
    writer.line(dxf::layerLinks, {0.0, 0.0}, {nan, 1.0});
    writer.circle(dxf::layerJoints, {0.0, 0.0}, inf);
    writer.text(dxf::layerText, {inf, 0.0}, 2.5, "x");
    writer.polyline(dxf::layerPaths, {{0.0, 0.0}, {1.0, nan}}, false);
    writer.line(dxf::layerLinks, {0.0, 0.0}, {1.0, 1.0});
    QCOMPARE(writer.entityCount(), 1);
    QCOMPARE(writer.skippedCount(), 4);
    const QByteArray file = QByteArray::fromStdString(writer.finish()).toLower();
    QVERIFY(!file.contains("nan"));
    QVERIFY(!file.contains("inf"));
}

void TestDxf::arcExtents()
{
    dxf::Writer writer;
    writer.arc(dxf::layerDimensions, {0.0, 0.0}, 10.0, 80.0, 100.0); // over the top
    const Eigen::AlignedBox2d box = writer.extents();
    QCOMPARE(box.max().y(), 10.0);
    QVERIFY(box.min().y() > 9.0);
    QVERIFY(std::abs(box.min().x() + 10.0 * std::sin(10.0 * std::numbers::pi / 180.0)) < 1e-9);
}

// -- the drawing of a scene ------------------------------------------------------------------

namespace {

/// A П-like scene: ground O–B, crank B–A, coupler A–C, link O–C, with a dimension.
Scene sampleScene()
{
    Scene scene;
    scene.joints = {{{0.0, 0.0, 0.0}, "O", JointKind::Ground}, {{68.0, 0.0, 0.0}, "B", JointKind::Ground},
        {{68.0 + 170.0 * std::sin(0.5), 170.0 * std::cos(0.5), 0.0}, "A", JointKind::Revolute},
        {{170.0 * std::sin(0.5), 170.0 * std::cos(0.5), 0.0}, "C", JointKind::Revolute}};
    scene.bars = {{0, 1, BarKind::Ground, ""}, {1, 2, BarKind::Crank, "a"}, {0, 3, BarKind::Crank, "a"},
        {3, 2, BarKind::Coupler, "b"}};
    scene.dimensions = {{1, 2, -25.0, "a = 169 mm"}}; // the text's number is wrong on purpose
    scene.angles = {{1, 0.5 * std::numbers::pi, -0.5, 30.0, "θ = 28.6°"}};
    scene.extent = Eigen::AlignedBox3d(Eigen::Vector3d(-20.0, -20.0, 0.0), Eigen::Vector3d(260.0, 190.0, 0.0));
    return scene;
}

double lineLength(const Entity &line)
{
    return std::hypot(line.number(11) - line.number(10), line.number(21) - line.number(20));
}

bool sameText(const QByteArray &dxfText, const char *expected)
{
    return dxfText == QByteArray(expected);
}

} // namespace

void TestDxf::sceneLinesAreTheLinks()
{
    const Scene scene = sampleScene();
    const dxf::Drawing drawing = dxf::sceneDrawing(scene);
    QCOMPARE(drawing.skipped, 0);
    const QList<Entity> drawn = entities(QByteArray::fromStdString(drawing.dxf));
    QCOMPARE(drawn.size(), drawing.entities);
    // every bar is a LINE from joint to joint, exactly (the writer keeps 10 decimals)
    for (const SceneBar &bar : scene.bars) {
        const Eigen::Vector3d p = scene.joints[std::size_t(bar.from)].position;
        const Eigen::Vector3d q = scene.joints[std::size_t(bar.to)].position;
        const QByteArray layer = bar.kind == BarKind::Ground ? "GROUND" : "LINKS";
        bool found = false;
        for (const Entity &e : drawn) {
            if (e.type == "LINE" && e.value(8) == layer && std::abs(e.number(10) - p.x()) < 1e-9
                && std::abs(e.number(20) - p.y()) < 1e-9 && std::abs(e.number(11) - q.x()) < 1e-9
                && std::abs(e.number(21) - q.y()) < 1e-9) {
                QVERIFY(std::abs(lineLength(e) - (q - p).norm()) < 1e-9);
                found = true;
            }
        }
        QVERIFY2(found, qPrintable(QStringLiteral("the LINE of bar %1–%2").arg(bar.from).arg(bar.to)));
    }
    // a pin circle at every joint, the layers of every role, names as text
    int pins = 0;
    QSet<QByteArray> layers;
    QList<QByteArray> texts;
    for (const Entity &e : drawn) {
        layers.insert(e.value(8));
        if (e.type == "CIRCLE" && e.value(8) == "JOINTS")
            ++pins;
        if (e.type == "TEXT")
            texts << e.value(1);
    }
    QCOMPARE(pins, 4);
    for (const char *layer : {"GROUND", "LINKS", "JOINTS", "DIMENSIONS", "TEXT"})
        QVERIFY2(layers.contains(layer), layer);
    for (const char *name : {"O", "B", "A", "C", "a", "b"})
        QVERIFY2(std::any_of(texts.begin(), texts.end(), [&](const QByteArray &t) { return sameText(t, name); }), name);
    QVERIFY(texts.contains("\\U+03B8 = 28.6%%d"));
    const QByteArray file = QByteArray::fromStdString(drawing.dxf);
    for (const dxf::LayerInfo &layer : dxf::linkageLayers())
        QVERIFY2(file.contains("  0\nLAYER\n  2\n" + QByteArray(layer.name) + "\n"), layer.name);
}

void TestDxf::dimensionText_data()
{
    QTest::addColumn<QString>("sceneText");
    QTest::addColumn<double>("distance");
    QTest::addColumn<QString>("text");
    QTest::newRow("name and unit") << u("a = 170.0 mm") << 170.0 << u("a = 170.00");
    QTest::newRow("the geometry wins") << u("a = 169 mm") << 170.004 << u("a = 170.00");
    QTest::newRow("rounded") << u("d = 183.1 mm") << 183.0956 << u("d = 183.10");
    QTest::newRow("signed coordinate") << QStringLiteral("p₁ = -20.0") << 20.0 << QStringLiteral("p₁ = -20.00");
    QTest::newRow("typeset minus") << QStringLiteral("p₂ = −20.0") << 20.0 << QStringLiteral("p₂ = -20.00");
    QTest::newRow("sign of another value") << u("p = -5.0") << 20.0 << u("p = 20.00");
    QTest::newRow("no text") << u("") << 12.5 << u("12.50");
    QTest::newRow("a number alone") << u("12.5") << 12.5 << u("12.50");
    QTest::newRow("a name alone") << u("s") << 20.0 << u("s = 20.00");
}

void TestDxf::dimensionText()
{
    QFETCH(QString, sceneText);
    QFETCH(double, distance);
    QFETCH(QString, text);
    QCOMPARE(QString::fromStdString(drawing::dimensionText(sceneText.toStdString(), distance)), text);
}

void TestDxf::dimensionTextIsTheMeasuredLength()
{
    const dxf::Drawing drawing = dxf::sceneDrawing(sampleScene());
    const QList<Entity> drawn = entities(QByteArray::fromStdString(drawing.dxf));
    QList<QByteArray> texts;
    QList<QPointF> tips; // of the arrowheads: a dimension is the distance between its two
    for (const Entity &e : drawn) {
        if (e.value(8) != "DIMENSIONS")
            continue;
        if (e.type == "TEXT")
            texts << e.value(1);
        if (e.type == "SOLID")
            tips << QPointF(e.number(10), e.number(20));
    }
    QVERIFY(texts.contains("a = 170.00")); // not the scene's 169
    bool measured = false;
    for (const QPointF &a : tips) {
        for (const QPointF &b : tips)
            measured = measured || std::abs(std::hypot(b.x() - a.x(), b.y() - a.y()) - 170.0) < 1e-9;
    }
    QVERIFY2(measured, "two arrow tips are exactly the distance apart");
}

void TestDxf::undefinedJointLeftOut()
{
    Scene scene = sampleScene();
    scene.joints[3].position.x() = std::numeric_limits<double>::quiet_NaN();
    ScenePolyline path;
    path.points = {{0.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0},
        {2.0, 2.0, 0.0}, {3.0, 2.0, 0.0}};
    path.closed = true;
    scene.polylines.push_back(path);
    const dxf::Drawing drawing = dxf::sceneDrawing(scene);
    QVERIFY(drawing.skipped > 0);
    const QByteArray file = QByteArray::fromStdString(drawing.dxf).toLower();
    QVERIFY(!file.contains("nan"));
    int polylines = 0;
    for (const Entity &e : entities(QByteArray::fromStdString(drawing.dxf))) {
        if (e.type == "POLYLINE" && e.value(8) == "PATHS") {
            ++polylines;
            QCOMPARE(e.value(70), QByteArray("0")); // broken: not closed
        }
    }
    QCOMPARE(polylines, 2); // split at the undefined point
}

void TestDxf::farFreePointLeftOut()
{
    Scene scene = sampleScene();
    scene.joints.push_back({{5000.0, 9000.0, 0.0}, "P", JointKind::Point}); // an instant centre
    const dxf::Drawing drawing = dxf::sceneDrawing(scene);
    QVERIFY(drawing.extents.max().x() < 400.0);
    QVERIFY(drawing.extents.max().y() < 400.0);
}

namespace {

/// The corners of a text's knock-out box, device units.
std::array<QPointF, 4> textCorners(const drawing::Text &text)
{
    const double a = -text.rotationDegrees * std::numbers::pi / 180.0;
    const QPointF u = QPointF(std::cos(a), -std::sin(a)) * (0.5 * text.box.width());
    const QPointF v = QPointF(u.y(), -u.x()) * (text.box.height() / text.box.width());
    return {text.centre - u - v, text.centre + u - v, text.centre + u + v, text.centre - u + v};
}

/// Whether segment a–b, `halfWidth` wide, meets the convex quad (separating axes).
bool segmentMeetsBox(const QPointF &a, const QPointF &b, double halfWidth, const std::array<QPointF, 4> &box)
{
    const QPointF d = b - a;
    const double length = std::hypot(d.x(), d.y());
    if (length <= 0.0)
        return false;
    const QPointF u = d / length, n(-u.y(), u.x());
    const std::array<QPointF, 4> band {a - halfWidth * n, b - halfWidth * n, b + halfWidth * n, a + halfWidth * n};
    auto separated = [](const std::array<QPointF, 4> &p, const std::array<QPointF, 4> &q, const QPointF &axis) {
        auto range = [&axis](const std::array<QPointF, 4> &c) {
            double lo = 1e300, hi = -1e300;
            for (const QPointF &x : c) {
                const double t = x.x() * axis.x() + x.y() * axis.y();
                lo = std::min(lo, t);
                hi = std::max(hi, t);
            }
            return std::pair {lo, hi};
        };
        const auto [p0, p1] = range(p);
        const auto [q0, q1] = range(q);
        return p1 <= q0 || q1 <= p0;
    };
    for (const auto *quad : {&band, &box}) {
        for (int i = 0; i < 2; ++i) {
            const QPointF edge = (*quad)[std::size_t(i + 1)] - (*quad)[std::size_t(i)];
            if (separated(band, box, QPointF(-edge.y(), edge.x())))
                return false;
        }
    }
    return true;
}

} // namespace

void TestDxf::labelsWhereTheLayoutPutsThem_data()
{
    // every preset: among them pjoint-study-k03, k05 and moma-3d, whose labels crowded the
    // links when the DXF placed its labels by rules of its own
    pkm::test::addEveryPresetRows();
}

void TestDxf::labelsWhereTheLayoutPutsThem()
{
    PKM_FETCH_PRESET(preset);
    const Result<Design> design = designfile::load(preset);
    QVERIFY2(design, design ? "" : design.failure().message.c_str());
    const Scene scene = design->mechanism->scene(design->pose);
    const dxf::DrawingLayout layout = dxf::drawingLayout(scene);
    const QList<Entity> drawn = entities(QByteArray::fromStdString(dxf::sceneDrawing(scene).dxf));

    // the DXF's texts are the layout's, in its order, centred where it put them
    QList<Entity> texts;
    for (const Entity &e : drawn) {
        if (e.type == "TEXT")
            texts << e;
    }
    QList<const drawing::Text *> laidOut;
    for (const drawing::Primitive &item : layout.list.items) {
        if (const auto *text = std::get_if<drawing::Text>(&item.shape))
            laidOut << text;
    }
    QCOMPARE(texts.size(), laidOut.size());
    for (qsizetype i = 0; i < texts.size(); ++i) {
        const Eigen::Vector2d at = layout.mapping.toScene(laidOut[i]->centre);
        QVERIFY(std::abs(texts[i].number(11) - at.x()) < 1e-6);
        QVERIFY(std::abs(texts[i].number(21) - at.y()) < 1e-6);
    }

    // and it put them clear of the links and of each other
    for (const drawing::Text *text : laidOut) {
        const std::array<QPointF, 4> box = textCorners(*text);
        for (const drawing::Primitive &item : layout.list.items) {
            if (const auto *member = std::get_if<drawing::Member>(&item.shape)) {
                QVERIFY2(!segmentMeetsBox(member->a, member->b, 0.5 * member->width, box),
                    qPrintable(QStringLiteral("the label %1 covers a link").arg(text->text)));
            } else if (const auto *other = std::get_if<drawing::Text>(&item.shape); other && other != text) {
                const std::array<QPointF, 4> otherBox = textCorners(*other);
                QVERIFY2(!segmentMeetsBox(0.5 * (otherBox[0] + otherBox[3]), 0.5 * (otherBox[1] + otherBox[2]),
                             0.5 * other->box.height(), box),
                    qPrintable(QStringLiteral("the labels %1 and %2 overlap").arg(text->text, other->text)));
            }
        }
    }
}

// -- pkm dxf ---------------------------------------------------------------------------------

void TestDxf::checkWithEzdxf(const QString &dxfPath, const QString &design, const QStringList &sets)
{
    if (m_python.isEmpty())
        QSKIP(qPrintable(m_noPython));
    QStringList evalArguments {QStringLiteral("eval"), design, QStringLiteral("--json")};
    for (const QString &set : sets)
        evalArguments << QStringLiteral("--set") << set;
    const Run eval = runPkm(evalArguments);
    QCOMPARE(eval.exitCode, 0);
    const QString evalPath = dxfPath + QStringLiteral(".eval.json");
    QFile evalFile(evalPath);
    QVERIFY(evalFile.open(QIODevice::WriteOnly));
    evalFile.write(eval.out);
    evalFile.close();
    const Run check
        = runProgram(m_python, {QStringLiteral(PKM_DXF_CHECKER), dxfPath, QStringLiteral("--eval"), evalPath});
    if (check.exitCode == 77)
        QSKIP("ezdxf is missing");
    QVERIFY2(check.exitCode == 0, (check.out + check.err).constData());
    QVERIFY2(check.out.startsWith("ok: "), check.out.constData());
}

void TestDxf::everyPresetReadBack_data()
{
    QTest::addColumn<QString>("preset");
    QTest::addColumn<QString>("kind");
    const Run list = runPkm(args({"list", "--json"}));
    QCOMPARE(list.exitCode, 0);
    const QJsonArray presets = QJsonDocument::fromJson(list.out).object().value(QStringLiteral("presets")).toArray();
    QVERIFY(presets.size() >= 7);
    QSet<QString> kinds;
    for (const QJsonValue &value : presets) {
        const QJsonObject preset = value.toObject();
        const QString id = preset.value(QStringLiteral("id")).toString();
        kinds.insert(preset.value(QStringLiteral("mechanism")).toString());
        QTest::newRow(qPrintable(id)) << id << preset.value(QStringLiteral("mechanism")).toString();
    }
    // every mechanism kind there is has a preset, so every kind is drawn
    const QJsonArray mechanisms
        = QJsonDocument::fromJson(list.out).object().value(QStringLiteral("mechanisms")).toArray();
    for (const QJsonValue &value : mechanisms) {
        const QString id = value.toObject().value(QStringLiteral("id")).toString();
        if (!kinds.contains(id))
            qWarning("mechanism kind %s has no preset: its DXF drawing is not tested", qPrintable(id));
    }
}

void TestDxf::everyPresetReadBack()
{
    QFETCH(QString, preset);
    const QString path = m_dir.filePath(preset + QStringLiteral(".dxf"));
    const Run run = runPkm({QStringLiteral("dxf"), preset, QStringLiteral("-o"), path});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY(run.out.startsWith("Wrote " + path.toUtf8() + " (AutoCAD R12 DXF, mm, "));
    QVERIFY(run.err.isEmpty());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray content = file.readAll();
    QVERIFY(content.contains("$ACADVER\n  1\nAC1009\n"));
    QVERIFY(!groupPairs(content).isEmpty());
    checkWithEzdxf(path, preset, {});
}

void TestDxf::posesReadBack_data()
{
    QTest::addColumn<QString>("design");
    QTest::addColumn<QStringList>("sets");
    QTest::newRow("pjoint theta=30") << u("pjoint-prototype") << args({"theta=30"});
    QTest::newRow("pjoint theta=-45, a=200") << u("pjoint-prototype") << args({"a=200", "theta=-45"});
    QTest::newRow("pjoint d=200") << u("pjoint-prototype") << args({"d=200"});
    QTest::newRow("fourbar alpha=200") << u("fourbar-example") << args({"alpha=200"});
    QTest::newRow("moma p1, p2") << u("moma-3a") << args({"p1=20", "p2=150"});
    QTest::newRow("oxglide mode=X") << u("oxglide-prototype") << args({"mode=X"});
    QTest::newRow("design file") << QStringLiteral(PKM_TEST_DATA_DIR "/custom.pkm.json") << QStringList();
}

void TestDxf::posesReadBack()
{
    QFETCH(QString, design);
    QFETCH(QStringList, sets);
    const QString path = m_dir.filePath(
        QStringLiteral("pose-%1.dxf")
            .arg(QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('_'))));
    QStringList arguments {QStringLiteral("dxf"), design};
    for (const QString &set : sets)
        arguments << QStringLiteral("--set") << set;
    arguments << QStringLiteral("--output") << path;
    const Run run = runPkm(arguments);
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY(QFile::exists(path));
    checkWithEzdxf(path, design, sets);
}

void TestDxf::failuresWriteNothing_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("culprit"); ///< a word the message must contain
    QTest::newRow("not a number") << args({"pjoint-prototype", "--set", "a=abc"}) << 2 << u("a=abc");
    QTest::newRow("comma decimal") << args({"pjoint-prototype", "--set", "a=1,5"}) << 2 << u("'.'");
    QTest::newRow("no NAME=VALUE") << args({"pjoint-prototype", "--set", "theta"}) << 2 << u("NAME=VALUE");
    QTest::newRow("unknown name") << args({"pjoint-prototype", "--set", "zeta=1"}) << 2 << u("zeta");
    QTest::newRow("invalid parameter") << args({"pjoint-prototype", "--set", "a=-5"}) << 2 << u("a=-5");
    QTest::newRow("pose out of range") << args({"pjoint-prototype", "--set", "theta=89"}) << 3 << u("theta=89");
    QTest::newRow("unreachable pose") << args({"moma-3a", "--set", "x=5000", "--set", "y=0"}) << 3 << u("--set");
    QTest::newRow("unknown preset") << args({"no-such-design"}) << 2 << u("no-such-design");
    QTest::newRow("unknown option") << args({"pjoint-prototype", "--json"}) << 2 << u("--json");
    QTest::newRow("second design") << args({"pjoint-prototype", "moma-3a"}) << 2 << u("moma-3a");
    QTest::newRow("no design") << QStringList() << 2 << u("DESIGN");
}

void TestDxf::failuresWriteNothing()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, culprit);
    const QString path = m_dir.filePath(QStringLiteral("failure.dxf"));
    QFile::remove(path);
    const Run run = runPkm(QStringList {QStringLiteral("dxf")} + arguments + QStringList {QStringLiteral("-o"), path});
    QCOMPARE(run.exitCode, exitCode);
    QVERIFY(run.out.isEmpty());
    QVERIFY2(run.err.startsWith("pkm: ") && run.err.count('\n') == 1, run.err.constData());
    QVERIFY2(QString::fromUtf8(run.err).contains(culprit), run.err.constData());
    QVERIFY(!QFile::exists(path));
    const QStringList left = QDir(m_dir.path()).entryList({QStringLiteral("failure*")}, QDir::Files | QDir::Hidden);
    QVERIFY2(left.isEmpty(), qPrintable(left.join(QLatin1Char(' ')))); // no temporary file either
}

void TestDxf::failureKeepsExistingFile()
{
    const QString path = m_dir.filePath(QStringLiteral("existing.dxf"));
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("previous drawing\n");
    }
    const auto unchanged = [&] {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) && file.readAll() == "previous drawing\n";
    };
    Run run = runPkm({QStringLiteral("dxf"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
        QStringLiteral("theta=89"), QStringLiteral("-o"), path});
    QCOMPARE(run.exitCode, 3);
    QVERIFY(unchanged());

    // an output that cannot be written: status 1, the file named, nothing left behind
    const QString missing = m_dir.filePath(QStringLiteral("no-such-dir/x.dxf"));
    run = runPkm({QStringLiteral("dxf"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"), missing});
    QCOMPARE(run.exitCode, 1);
    QVERIFY(run.out.isEmpty());
    QVERIFY2(run.err.startsWith("pkm: Cannot write '" + missing.toUtf8() + "'"), run.err.constData());
    QVERIFY(!QFile::exists(missing));

    // a directory that is read-only (root may write anyway: then the write succeeds)
    const QString locked = m_dir.filePath(QStringLiteral("locked"));
    QVERIFY(QDir().mkpath(locked));
    QFile::setPermissions(locked, QFile::ReadOwner | QFile::ExeOwner);
    const QString inLocked = locked + QStringLiteral("/x.dxf");
    run = runPkm({QStringLiteral("dxf"), QStringLiteral("fourbar-example"), QStringLiteral("-o"), inLocked});
    if (run.exitCode != 0) {
        QCOMPARE(run.exitCode, 1);
        QVERIFY(QDir(locked).entryList(QDir::Files | QDir::Hidden).isEmpty());
    }
    QFile::setPermissions(locked, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);

    // the wrong kind of file name, or none
    run = runPkm({QStringLiteral("dxf"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"),
        m_dir.filePath(QStringLiteral("x.png"))});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.err.contains(".dxf"));
    run = runPkm({QStringLiteral("dxf"), QStringLiteral("pjoint-prototype")});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.err.contains("-o FILE"));
    run = runPkm({QStringLiteral("dxf"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o")});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.err.contains("needs a value"));
}

void TestDxf::help()
{
    const Run help = runPkm(args({"dxf", "--help"}));
    QCOMPARE(help.exitCode, 0);
    QVERIFY(help.out.startsWith("Usage: pkm dxf DESIGN"));
    QVERIFY(help.out.contains("DIMENSIONS"));
    QCOMPARE(runPkm(args({"help", "dxf"})).out, help.out);
    QCOMPARE(runPkm(args({"dxf", "pjoint-prototype", "--bogus", "-h"})).out, help.out); // help wins
    const Run overview = runPkm(args({"--help"}));
    QCOMPARE(overview.exitCode, 0);
    QVERIFY(overview.out.contains("  dxf    DESIGN [--set N=V]... -o FILE.dxf"));
}

void TestDxf::inProcess()
{
    const QString path = m_dir.filePath(QStringLiteral("in-process.dxf"));
    std::FILE *out = std::tmpfile();
    std::FILE *err = std::tmpfile();
    QVERIFY(out && err);
    const int status = runCli({QStringLiteral("dxf"), QStringLiteral("fourbar-example"),
                                  QStringLiteral("--set=alpha=90"), QStringLiteral("--output=") + path},
        out, err);
    std::fclose(out);
    std::fclose(err);
    QCOMPARE(status, 0);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray content = file.readAll();
    // the caption names the design and the pose, escaped
    QVERIFY2(content.contains("fourbar-example \\U+2014 \\U+03B1 = 90"), content.left(200).constData());
}

// -- the GUI -----------------------------------------------------------------------------------

void TestDxf::exportFromMainWindow()
{
    MainWindow window;
    QVERIFY(window.openDesign(QStringLiteral("fourbar-example")));
    auto *action = window.findChild<QAction *>(QStringLiteral("exportDxfAction"));
    QVERIFY(action);
    QVERIFY(action->text().contains(QStringLiteral("DXF")));
    const QString path = m_dir.filePath(QStringLiteral("from-window")); // the .dxf is added
    bool answered = false;
    QTimer::singleShot(0, this, [&] {
        // the file dialog is modal: fill it in once it shows
        for (int attempt = 0; attempt < 200 && !answered; ++attempt) {
            if (auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget())) {
                dialog->selectFile(path);
                static_cast<QDialog *>(dialog)->accept(); // QFileDialog::accept(), public in QDialog
                answered = true;
                return;
            }
            QTest::qWait(10);
        }
    });
    action->trigger();
    QVERIFY2(answered, "the file dialog did not show");
    QFile file(path + QStringLiteral(".dxf"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray content = file.readAll();
    QVERIFY(content.contains("$ACADVER\n  1\nAC1009\n"));
    // the same drawing as `pkm dxf`: the links from joint to joint
    int links = 0;
    for (const Entity &e : entities(content)) {
        if (e.type == "LINE" && e.value(8) == "LINKS" && std::abs(lineLength(e) - 120.0) < 1e-6)
            ++links; // BC, and its outline
    }
    QVERIFY(links >= 1);
    QVERIFY(window.lastStatus().contains(QStringLiteral("from-window.dxf")));
}

QTEST_MAIN(TestDxf)
#include "tst_dxf.moc"
