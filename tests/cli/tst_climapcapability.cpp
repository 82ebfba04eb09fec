// `pkm map --quantity force_worst|speed_worst|resolution_worst|stiffness_worst|spec` and
// `pkm workspace --require` (docs/cli.md): the maps of what the actuators deliver equal
// `pkm eval` at their cells, the specification region is reported with its area and what
// fails where, a design file keeps its requirements, and every wrong use is one sentence.

#include "document/designfile.h"
#include "support/process.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace pkm;
using namespace pkm::test;

namespace {
double number(const QJsonObject &object, const char *key)
{
    return object.value(QLatin1String(key)).toDouble();
}
} // namespace

class TestCliMapCapability : public QObject
{
    Q_OBJECT

private slots:
    void mapsWhatTheActuatorsDeliver_data()
    {
        QTest::addColumn<QString>("quantity");
        QTest::addColumn<QString>("unit");
        QTest::newRow("force") << "force_worst" << "N";
        QTest::newRow("speed") << "speed_worst" << "mm/s";
        QTest::newRow("resolution") << "resolution_worst" << "mm";
        QTest::newRow("stiffness") << "stiffness_worst" << "N/mm";
    }
    void mapsWhatTheActuatorsDeliver()
    {
        QFETCH(QString, quantity);
        QFETCH(QString, unit);
        int exitCode = -1;
        const QJsonObject map = pkmJson({QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--quantity"),
                                         quantity, QStringLiteral("--grid"), QStringLiteral("40"), QStringLiteral("--json")},
                                        &exitCode);
        QCOMPARE(exitCode, 0);
        QCOMPARE(map.value(QLatin1String("quantity")).toString(), quantity);
        QCOMPARE(map.value(QLatin1String("unit")).toString(), unit);
        QVERIFY(number(map, "min") > 0.0);
        QVERIFY(number(map, "max") > number(map, "min"));
        // the same cells as the workspace of the closed-form maps
        const QJsonObject det = pkmJson(args({"map", "moma-3a", "--grid", "40", "--json"}));
        QVERIFY(std::abs(number(map, "reachable_cells") - number(det, "reachable_cells")) <= 2);

        // a cell of the CSV is `pkm eval` at its point
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("map.csv"));
        const Run run = runPkm({QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--quantity"), quantity,
                                QStringLiteral("--grid"), QStringLiteral("40"), QStringLiteral("-o"), csv});
        QCOMPARE(run.exitCode, 0);
        const QList<QByteArray> lines = fileBytes(csv).split('\n');
        QCOMPARE(lines.front(), QByteArray("x,y,value,margin"));
        const QList<QByteArray> cell = lines[lines.size() / 2].split(',');
        QCOMPARE(cell.size(), 4);
        const QJsonObject eval = pkmJson({QStringLiteral("eval"), QStringLiteral("moma-3a"), QStringLiteral("--set"),
                                          QStringLiteral("x=") + QString::fromLatin1(cell[0]), QStringLiteral("--set"),
                                          QStringLiteral("y=") + QString::fromLatin1(cell[1]), QStringLiteral("--json")});
        const double expected = eval.value(QLatin1String("capability")).toObject().value(quantity).toDouble();
        QVERIFY2(std::abs(cell[2].toDouble() - expected) <= 1e-6 * expected,
                 qPrintable(QStringLiteral("%1 vs %2").arg(QString::fromLatin1(cell[2])).arg(expected)));

        const QString png = dir.filePath(QStringLiteral("map.png"));
        const Run picture = runPkm({QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--quantity"),
                                    quantity, QStringLiteral("--grid"), QStringLiteral("40"), QStringLiteral("-o"), png});
        QCOMPARE(picture.exitCode, 0);
        QVERIFY(picture.out.contains("colours"));
        QVERIFY(picture.out.contains("[0, "));
        QVERIFY(fileBytes(png).startsWith("\x89PNG"));
    }

    void specificationRegion()
    {
        const QJsonObject force = pkmJson(args({"map", "moma-3a", "--quantity", "force_worst", "--grid", "40", "--json"}));
        const double threshold = 0.5 * (number(force, "min") + number(force, "max"));
        const QString require = QStringLiteral("force_worst>=%1").arg(threshold, 0, 'g', 10);
        int exitCode = -1;
        const QJsonObject workspace = pkmJson({QStringLiteral("workspace"), QStringLiteral("moma-3a"), QStringLiteral("--grid"),
                                               QStringLiteral("40"), QStringLiteral("--require"), require,
                                               QStringLiteral("--require"), QStringLiteral("resolution_worst<=1"),
                                               QStringLiteral("--json")},
                                              &exitCode);
        QCOMPARE(exitCode, 0);
        const QJsonObject spec = workspace.value(QLatin1String("specification")).toObject();
        const QJsonArray requirements = spec.value(QLatin1String("requirements")).toArray();
        QCOMPARE(requirements.size(), 2);
        const QJsonObject first = requirements[0].toObject();
        QCOMPARE(first.value(QLatin1String("name")).toString(), QStringLiteral("force_worst"));
        QVERIFY(first.value(QLatin1String("at_least")).toBool());
        QCOMPARE(first.value(QLatin1String("unit")).toString(), QStringLiteral("N"));
        QVERIFY(number(first, "failing_cells") > 0);
        QVERIFY(number(spec, "area") > 0.0);
        QVERIFY(number(spec, "area") < number(workspace, "area"));
        QVERIFY(std::abs(number(spec, "fraction") - number(spec, "area") / number(workspace, "area")) < 1e-9);

        // `map --require` maps the same region
        const QJsonObject map = pkmJson({QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--grid"),
                                         QStringLiteral("40"), QStringLiteral("--require"), require,
                                         QStringLiteral("--require"), QStringLiteral("resolution_worst<=1"),
                                         QStringLiteral("--json")});
        QCOMPARE(map.value(QLatin1String("quantity")).toString(), QStringLiteral("spec"));
        QCOMPARE(number(map.value(QLatin1String("specification")).toObject(), "area"), number(spec, "area"));

        const Run text = runPkm({QStringLiteral("workspace"), QStringLiteral("moma-3a"), QStringLiteral("--grid"),
                                 QStringLiteral("40"), QStringLiteral("--require"), require});
        QCOMPARE(text.exitCode, 0);
        QVERIFY(text.out.contains("Specification"));
        QVERIFY(text.out.contains("force_worst ≥"));
        QVERIFY(text.out.contains("area met"));
    }

    void theDesignFileKeepsItsRequirements()
    {
        auto design = designfile::load(QStringLiteral("moma-3a"));
        QVERIFY(design);
        design->id.clear();
        design->requirements = {{"force_worst", true, 5.0}, {"resolution_worst", false, 0.05}};
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("spec.pkm.json"));
        QVERIFY(designfile::save(*design, path));
        QVERIFY(fileBytes(path).contains("\"force_worst >= 5\""));
        const auto back = designfile::load(path);
        QVERIFY(back);
        QVERIFY(back->requirements == design->requirements);
        // the file's requirements without --require
        const QJsonObject workspace = pkmJson({QStringLiteral("workspace"), path, QStringLiteral("--grid"),
                                               QStringLiteral("30"), QStringLiteral("--json")});
        QCOMPARE(workspace.value(QLatin1String("specification")).toObject().value(QLatin1String("requirements")).toArray().size(),
                 2);
        const QJsonObject map = pkmJson({QStringLiteral("map"), path, QStringLiteral("--quantity"), QStringLiteral("spec"),
                                         QStringLiteral("--grid"), QStringLiteral("30"), QStringLiteral("--json")});
        QCOMPARE(map.value(QLatin1String("quantity")).toString(), QStringLiteral("spec"));

        // a damaged requirement refuses the file, naming it
        QByteArray bytes = fileBytes(path);
        bytes.replace("\"force_worst >= 5\"", "\"force_worst >> five\"");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(bytes);
        file.close();
        const Run run = runPkm({QStringLiteral("workspace"), path});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("requirements") && run.err.contains("force_worst >> five"), run.err.constData());
    }

    /// The sheet's actuator checks: the load within the actuators' limits by virtual work (no
    /// load inside the force polygon's inscribed circle fails, none beyond its farthest vertex
    /// holds), the requirements at the pose and over the workspace as `pkm workspace` finds.
    void sheetChecksTheActuators()
    {
        const QJsonObject eval = pkmJson(args({"eval", "moma-3a", "--json"}));
        const QJsonObject capability = eval.value(QLatin1String("capability")).toObject();
        const double weakest = number(capability, "force_worst"), strongest = number(capability, "force_best");
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sheet.json"));
        auto checks = [&](double fx, double fy) {
            const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("moma-3a"), QStringLiteral("--set"),
                                    QStringLiteral("load_x=%1").arg(fx, 0, 'g', 12), QStringLiteral("--set"),
                                    QStringLiteral("load_y=%1").arg(fy, 0, 'g', 12), QStringLiteral("-o"), path});
            [&] { QCOMPARE(run.exitCode, 0); }();
            return QJsonDocument::fromJson(fileBytes(path))
                .object()
                .value(QLatin1String("sections"))
                .toObject()
                .value(QLatin1String("capability"))
                .toObject()
                .value(QLatin1String("checks"))
                .toObject();
        };
        for (const double angle : {0.0, 0.7, 2.0, 4.0}) {
            const double c = std::cos(angle), s = std::sin(angle);
            const QJsonObject inside = checks(0.99 * weakest * c, 0.99 * weakest * s);
            const QJsonObject held = inside.value(QLatin1String("load_held")).toObject();
            QCOMPARE(held.value(QLatin1String("result")).toString(), QStringLiteral("PASS"));
            const double share = number(held, "value");
            QVERIFY(share <= 1.0);
            const QJsonObject outside = checks(1.01 * strongest * c, 1.01 * strongest * s);
            const QJsonObject failed = outside.value(QLatin1String("load_held")).toObject();
            QCOMPARE(failed.value(QLatin1String("result")).toString(), QStringLiteral("FAIL"));
            // linear in the load
            QVERIFY(std::abs(number(failed, "value") / share - 1.01 * strongest / (0.99 * weakest)) < 1e-9 * number(failed, "value") / share);
            // the preset's requirements: 50 N and 0.01 mm, met at the pose and everywhere
            QCOMPARE(inside.value(QLatin1String("requirement_1")).toObject().value(QLatin1String("result")).toString(),
                     QStringLiteral("PASS"));
            QCOMPARE(number(inside.value(QLatin1String("requirements_workspace")).toObject(), "value"), 100.0);
        }
        // without a load the check says so
        const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pp-3rrr"), QStringLiteral("-o"), path});
        QCOMPARE(run.exitCode, 0);
        const QJsonObject sheet = QJsonDocument::fromJson(fileBytes(path)).object();
        const QJsonObject ppChecks = sheet.value(QLatin1String("sections")).toObject().value(QLatin1String("capability"))
                                         .toObject().value(QLatin1String("checks")).toObject();
        QCOMPARE(ppChecks.value(QLatin1String("load_held")).toObject().value(QLatin1String("result")).toString(),
                 QStringLiteral("INFO"));
        // the share over the workspace is the one `pkm workspace --require` finds at its grid
        const QJsonObject region = ppChecks.value(QLatin1String("requirements_workspace")).toObject();
        const QJsonObject workspace = pkmJson(args({"workspace", "pp-3rrr", "--json"}));
        const double fraction = number(workspace.value(QLatin1String("specification")).toObject(), "fraction");
        QVERIFY(std::abs(number(region, "value") - 100.0 * fraction) < 1e-9);
        QCOMPARE(region.value(QLatin1String("result")).toString(), fraction < 1.0 ? QStringLiteral("FAIL") : QStringLiteral("PASS"));
    }

    void wrongUsesAreOneSentence_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QByteArray>("culprit");
        QTest::newRow("no comparison") << args({"workspace", "moma-3a", "--require", "force_worst"}) << QByteArray("--require");
        QTest::newRow("a matrix") << args({"workspace", "moma-3a", "--require", "stiffness>=3"}) << QByteArray("stiffness");
        QTest::newRow("not a number") << args({"map", "moma-3a", "--require", "force_worst>=lots"}) << QByteArray("finite");
        QTest::newRow("spec without") << args({"map", "moma-3b", "--quantity", "spec"}) << QByteArray("--require");
        QTest::newRow("with det") << args({"map", "moma-3a", "--quantity", "det", "--require", "force_worst>=1"})
                                  << QByteArray("--quantity spec");
        QTest::newRow("unknown quantity") << args({"map", "moma-3a", "--quantity", "force"}) << QByteArray("force_worst");
        QTest::newRow("no workspace") << args({"map", "pjoint-prototype", "--quantity", "force_worst"})
                                      << QByteArray("planar workspace");
        QTest::newRow("escape") << args({"workspace", "moma-3a", "--require", "\x1b[2J\x1b[31mforce>=1"})
                                << QByteArray("\\x1B[2J");
    }
    void wrongUsesAreOneSentence()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QByteArray, culprit);
        const Run run = runPkm(arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.out.isEmpty());
        QCOMPARE(run.err.count('\n'), 1);
        QVERIFY(!run.err.contains('\x1b'));
        QVERIFY2(run.err.contains(culprit), run.err.constData());
    }
};

QTEST_MAIN(TestCliMapCapability)
#include "tst_climapcapability.moc"
