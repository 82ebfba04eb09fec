// `pkm map DESIGN --quantity range` (docs/cli.md): the orientation range of a platform that
// turns, in degrees, as JSON, text and a picture; a design whose platform does not turn is a
// usage error naming the option.

#include "support/process.h"

#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace pkm::test;

namespace {
double jsonNumber(const QJsonObject &object, const char *key)
{
    return object.value(QLatin1String(key)).toDouble();
}
} // namespace

class TestCliMapRange : public QObject
{
    Q_OBJECT

private slots:
    void mapsTheOrientationRange()
    {
        int exitCode = -1;
        const QJsonObject root = pkmJson(args({"map", "pp-3rrr", "--quantity", "range", "--grid", "60", "--json"}), &exitCode);
        QCOMPARE(exitCode, 0);
        QCOMPARE(root.value(QStringLiteral("quantity")).toString(), QStringLiteral("range"));
        QVERIFY(jsonNumber(root, "reachable_cells") > 100);
        QVERIFY(jsonNumber(root, "min") > 0.0);
        QVERIFY(jsonNumber(root, "max") <= 360.0 + 1e-9);
        QVERIFY(jsonNumber(root, "max") > jsonNumber(root, "min"));
        // the platform is held somewhere at some φ, so the range map covers the slice's map
        const QJsonObject slice = pkmJson(args({"map", "pp-3rrr", "--grid", "60", "--json"}));
        QVERIFY(jsonNumber(root, "reachable_cells") >= jsonNumber(slice, "reachable_cells"));
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("range.png"));
        const Run text = runPkm({QStringLiteral("map"), QStringLiteral("pp-3rrr"), QStringLiteral("--quantity"), QStringLiteral("range"),
                                 QStringLiteral("--grid"), QStringLiteral("60"), QStringLiteral("-o"), png});
        QCOMPARE(text.exitCode, 0);
        QVERIFY(text.out.contains("Map of orientation range (°)"));
        QVERIFY(text.out.contains("[0, 360]"));
        QVERIFY(fileBytes(png).startsWith("\x89PNG"));
    }

    void refusedWhereThePlatformDoesNotTurn()
    {
        for (const char *design : {"pp-5r", "moma-3a"}) {
            const Run run = runPkm(args({"map", design, "--quantity", "range"}));
            QCOMPARE(run.exitCode, 2);
            QVERIFY(run.out.isEmpty());
            QCOMPARE(run.err.count('\n'), 1);
            QVERIFY2(run.err.contains("--quantity") && run.err.contains(design), run.err.constData());
        }
        const Run bad = runPkm(args({"map", "pp-3rrr", "--quantity", "width"}));
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(bad.err.contains("'range'"));
    }
};

QTEST_MAIN(TestCliMapRange)
#include "tst_climaprange.moc"
