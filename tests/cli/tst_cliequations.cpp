// `pkm eval DESIGN --equations` (docs/cli.md): the equations of the GUI's Equations panel in
// the text output and under "equations" in the JSON, for a preset of every kind; results that
// the report has agree with it, and at a singular pose the JSON result is null, not a huge
// number.

#include "support/app.h"
#include "support/process.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTest>

#include <cmath>

using namespace pkm::test;

class TestCliEquations : public QObject
{
    Q_OBJECT

private slots:
    void textHasTheNumbersPutIn()
    {
        const Run run = runPkm(args({"eval", "pjoint-prototype", "--set", "theta=30", "--equations"}));
        QCOMPARE(run.exitCode, 0);
        const QString text = QString::fromUtf8(run.out);
        QVERIFY(text.contains(QStringLiteral("\nEquations\nThe numbers put in are rounded as shown;")));
        QVERIFY(text.contains(QStringLiteral("Inverse kinematics (eq. (2) of the П-joint document)\n"
                                             "  d = a·√(1 + k² + 2k·sin θ)\n"
                                             "    = 170.00·√(1 + 0.4000² + 2·0.4000·sin 30.00°) = 212.33 mm\n")));
        QVERIFY(text.contains(QStringLiteral("  note: The document's acceleration (19–20)")));
        // without the option, no equations
        QVERIFY(!QString::fromUtf8(runPkm(args({"eval", "pjoint-prototype"})).out).contains(QStringLiteral("\nEquations\n")));
    }

    void jsonForEveryKind_data() { addPresetPerKindRows(); }
    void jsonForEveryKind()
    {
        PKM_FETCH_PRESET(preset);
        int exitCode = -1;
        const QJsonObject eval = pkmJson({QStringLiteral("eval"), preset, QStringLiteral("--equations"), QStringLiteral("--json")}, &exitCode);
        QCOMPARE(exitCode, 0);
        const QJsonArray equations = eval.value(QLatin1String("equations")).toArray();
        QVERIFY(equations.size() >= 4);
        for (const QJsonValue &value : equations) {
            const QJsonObject e = value.toObject();
            for (const char *key : {"title", "symbolic", "substituted", "unit", "source", "note"})
                QVERIFY2(e.value(QLatin1String(key)).isString(), key);
            QVERIFY(!e.value(QLatin1String("title")).toString().isEmpty());
            QVERIFY(!e.value(QLatin1String("substituted")).toString().contains(QLatin1Char('%')));
            QVERIFY(e.value(QLatin1String("result")).isDouble());
        }
    }

    void singularResultIsNull()
    {
        // the O-X glide at the O↔X crossing of the prototype: rods parallel, y = l
        int exitCode = -1;
        const QJsonObject eval = pkmJson(args({"eval", "oxglide-prototype", "--set", "x_AB=55", "--set", "x_CD=75",
                                               "--equations", "--json"}),
                                         &exitCode);
        QCOMPARE(exitCode, 0);
        bool sawNull = false;
        for (const QJsonValue &value : eval.value(QLatin1String("equations")).toArray()) {
            const QJsonValue result = value.toObject().value(QLatin1String("result"));
            QVERIFY(result.isNull() || std::abs(result.toDouble()) < 1e9);
            sawNull = sawNull || result.isNull();
        }
        QVERIFY(sawNull);
    }
};

QTEST_MAIN(TestCliEquations)
#include "tst_cliequations.moc"
