// `pkm tolerance` (docs/cli.md): the first-order worst case and the Monte Carlo at the pose for
// a preset of every kind, the ways of writing ±, the refusals that name the parameter, the
// design file's "tolerances", the map summary and reproducibility of the seed; and the map of
// the worst case (`pkm map --quantity tolerance`), whose cells are `pkm tolerance` at their point.

#include "support/app.h"
#include "support/process.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace pkm;
using namespace pkm::test;

namespace {
/// The geometric lengths of a design (`pkm show --json`), stored ones, for a tolerance on one.
QStringList lengths(const QString &preset)
{
    QStringList names;
    const QJsonObject show = pkmJson({QStringLiteral("show"), preset, QStringLiteral("--json")});
    const QJsonObject parameters = show.value(QLatin1String("parameters")).toObject();
    for (auto it = parameters.begin(); it != parameters.end(); ++it) {
        const QJsonObject o = it.value().toObject();
        if (o.value(QLatin1String("group")).toString() == QLatin1String("geometry")
            && o.value(QLatin1String("unit")).toString() == QLatin1String("mm") && o.value(QLatin1String("stored")).toBool())
            names << it.key();
    }
    return names;
}
} // namespace

class TestCliTolerance : public QObject
{
    Q_OBJECT

private slots:
    void everyKind_data() { addPresetPerKindRows(); }
    /// Every kind: a finite first order at its preset's pose, a Monte Carlo without failures
    /// whose spread is the first order's and whose maximum stays within the worst case.
    void everyKind()
    {
        PKM_FETCH_PRESET(preset);
        // the first length that moves the output (a leg library's unused crank has no say)
        int exitCode = -1;
        QJsonObject r;
        for (const QString &name : lengths(preset)) {
            r = pkmJson({QStringLiteral("tolerance"), preset, QStringLiteral("--tol"), name + QStringLiteral("=±0.01"),
                         QStringLiteral("--samples"), QStringLiteral("800"), QStringLiteral("--json")},
                        &exitCode);
            // (the O-X glide's guide length L moves nothing: its error is 0, rightly)
            if (exitCode == 0 && r.value(QLatin1String("first_order")).toObject().value(QLatin1String("worst_norm")).toDouble() > 0)
                break;
        }
        QCOMPARE(exitCode, 0);
        const QJsonObject first = r.value(QLatin1String("first_order")).toObject();
        QVERIFY(first.value(QLatin1String("finite")).toBool());
        QVERIFY(first.value(QLatin1String("reason")).isNull());
        const double worst = first.value(QLatin1String("worst_norm")).toDouble();
        QVERIFY(worst > 0.0);
        const QJsonArray parts = first.value(QLatin1String("contributions")).toArray();
        QCOMPARE(parts.size(), 1);
        QCOMPARE(parts[0].toObject().value(QLatin1String("share")).toDouble(), 1.0);
        QCOMPARE(parts[0].toObject().value(QLatin1String("contribution")).toDouble(), worst);
        const QJsonObject mc = r.value(QLatin1String("monte_carlo")).toObject();
        QCOMPARE(mc.value(QLatin1String("samples")).toInt(), 800);
        QCOMPARE(mc.value(QLatin1String("failed")).toInt(), 0);
        QCOMPARE(mc.value(QLatin1String("seed")).toString(), QStringLiteral("19"));
        QVERIFY(mc.value(QLatin1String("norm")).toObject().value(QLatin1String("max")).toDouble() <= worst * (1 + 1e-3));
        // one parameter, uniform: |Δx| is |∂x/∂p|·|δp|, whose σ is worst/√3 · … per output
        const QJsonObject sigma = first.value(QLatin1String("sigma")).toObject();
        const QJsonObject std = mc.value(QLatin1String("std")).toObject();
        for (auto it = sigma.begin(); it != sigma.end(); ++it) {
            const double predicted = it.value().toDouble();
            if (predicted < 1e-9)
                continue;
            QVERIFY2(std::abs(std.value(it.key()).toDouble() / predicted - 1) < 0.08, qPrintable(it.key()));
        }
    }

    /// "±0.05", "+-0.05" and "0.05" are the same; a table is printed without --json.
    void plusMinusForms()
    {
        QByteArray outputs[3];
        int i = 0;
        for (const char *tol : {"l1=±0.05", "l1=+-0.05", "l1=0.05"}) {
            const Run run = runPkm(args({"tolerance", "moma-3a", "--tol", tol, "--samples", "100"}));
            QCOMPARE(run.exitCode, 0);
            outputs[i++] = run.out;
        }
        QCOMPARE(outputs[0], outputs[1]);
        QCOMPARE(outputs[0], outputs[2]);
        QVERIFY(outputs[0].contains("First-order worst case (method: implicit)"));
        QVERIFY(outputs[0].contains("Monte Carlo (100 samples, seed 19, uniform in ±tol)"));
        QVERIFY(outputs[0].contains("|Δ(x, y)|"));
    }

    /// The same seed gives the same numbers; another seed other ones; --normal draws tol = 3σ.
    void seedAndDistribution()
    {
        const auto run = [](const char *seed, bool normal) {
            QStringList a = args({"tolerance", "fivebar-example", "--tol", "AB=0.1", "--samples", "300", "--seed", seed, "--json"});
            if (normal)
                a << QStringLiteral("--normal");
            return pkmJson(a).value(QLatin1String("monte_carlo")).toObject();
        };
        QCOMPARE(run("5", false), run("5", false));
        QVERIFY(run("5", false) != run("6", false));
        const QJsonObject normal = run("5", true);
        QCOMPARE(normal.value(QLatin1String("distribution")).toString(), QStringLiteral("normal"));
    }

    void refusals_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown") << args({"tolerance", "pjoint-prototype", "--tol", "nope=0.1"})
                                 << "--tol nope=0.1: The design has no parameter named 'nope'";
        QTest::newRow("actuator") << args({"tolerance", "pjoint-prototype", "--tol", "lead=0.1"})
                                  << "'lead' (lead of the screw) is not a geometric parameter";
        QTest::newRow("derived") << args({"tolerance", "pjoint-prototype", "--tol", "k=0.01"}) << "'k' is derived";
        QTest::newRow("negative") << args({"tolerance", "pjoint-prototype", "--tol", "a=-1"}) << "VALUE ≥ 0";
        QTest::newRow("not a number") << args({"tolerance", "pjoint-prototype", "--tol", "a=±x"}) << "'x' is not a number";
        QTest::newRow("too large") << args({"tolerance", "pjoint-prototype", "--tol", "a=500"}) << "outside its allowed values";
        QTest::newRow("none") << args({"tolerance", "pjoint-prototype"}) << "needs at least one --tol";
        QTest::newRow("samples") << args({"tolerance", "pjoint-prototype", "--tol", "a=1", "--samples", "1e9"}) << "--samples";
        QTest::newRow("seed") << args({"tolerance", "pjoint-prototype", "--tol", "a=1", "--seed", "-3"}) << "--seed";
        QTest::newRow("no map") << args({"tolerance", "pjoint-prototype", "--tol", "a=1", "--grid", "20"})
                                << "no planar workspace";
        // the map of the worst case
        QTest::newRow("map, no tolerance") << args({"map", "moma-3a", "--quantity", "tolerance"}) << "--tol NAME=±VALUE";
        QTest::newRow("map, another quantity") << args({"map", "moma-3a", "--quantity", "det", "--tol", "l1=±0.1"})
                                               << "does not go with '--quantity det'";
        QTest::newRow("map, grid too fine") << args({"map", "moma-3a", "--tol", "l1=±0.1", "--grid", "401"})
                                            << "at most 400 cells";
        QTest::newRow("map, not a parameter") << args({"map", "moma-3a", "--tol", "speed=±1"}) << "speed";
    }
    /// One message naming the culprit, exit status 2, nothing on standard output.
    void refusals()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const Run run = runPkm(arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.out.isEmpty());
        QVERIFY2(QString::fromUtf8(run.err).contains(message), run.err.constData());
        QCOMPARE(run.err.count('\n'), 1);
    }

    /// A design file's "tolerances" are used; --tol NAME=0 removes one, --tol adds or overrides.
    void designFileTolerances()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("moma.pkm.json"));
        {
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(R"({"format": "pkm-studio-design", "version": 2, "mechanism": "moma",
                           "parameters": {}, "tolerances": {"l1": 0.05, "l2": 0.05}})");
        }
        int exitCode = -1;
        const QJsonObject both = pkmJson({QStringLiteral("tolerance"), path, QStringLiteral("--samples"), QStringLiteral("0"),
                                          QStringLiteral("--json")},
                                         &exitCode);
        QCOMPARE(exitCode, 0);
        QCOMPARE(both.value(QLatin1String("tolerances")).toObject().size(), 2);
        QVERIFY(both.value(QLatin1String("monte_carlo")).isNull());
        const QJsonObject one = pkmJson({QStringLiteral("tolerance"), path, QStringLiteral("--tol"), QStringLiteral("l2=0"),
                                         QStringLiteral("--samples"), QStringLiteral("0"), QStringLiteral("--json")});
        QCOMPARE(one.value(QLatin1String("tolerances")).toObject().keys(), QStringList{QStringLiteral("l1")});
        QVERIFY(one.value(QLatin1String("first_order")).toObject().value(QLatin1String("worst_norm")).toDouble()
                < both.value(QLatin1String("first_order")).toObject().value(QLatin1String("worst_norm")).toDouble());
        // a file with a bad tolerance is refused, naming it
        QFile bad(dir.filePath(QStringLiteral("bad.pkm.json")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(R"({"format": "pkm-studio-design", "version": 2, "mechanism": "moma", "parameters": {},
                      "tolerances": {"p_min": 0.05}})");
        bad.close();
        const Run run = runPkm({QStringLiteral("tolerance"), bad.fileName()});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("the tolerance of 'p_min' is refused"), run.err.constData());
    }

    /// --grid adds the worst case over the workspace (the ∞ of a direct singularity: tst_tolerance).
    void mapAndSingularity()
    {
        const QJsonObject r = pkmJson(args({"tolerance", "moma-3a", "--tol", "l1=0.05", "--samples", "0", "--grid", "20", "--json"}));
        const QJsonObject map = r.value(QLatin1String("map")).toObject();
        QVERIFY(map.value(QLatin1String("reachable_cells")).toInt() > 0);
        QVERIFY(map.value(QLatin1String("max")).toDouble() >= map.value(QLatin1String("min")).toDouble());
        QVERIFY(map.value(QLatin1String("min")).toDouble() > 0);
    }

    /// `pkm map --tol`: every sampled cell of the CSV is the worst case `pkm tolerance` gives at
    /// the pose solved there, for a 2-DOF and a 3-DOF platform (at φ = phi_map).
    void mapCellsAreTheWorstCase_data()
    {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QStringList>("tolerances");
        QTest::addRow("MOMA") << QStringLiteral("moma-3a") << args({"--tol", "l1=±0.1", "--tol", "R1x=±0.05"});
        QTest::addRow("3-RRR") << QStringLiteral("pp-3rrr") << args({"--tol", "l1=±0.1", "--tol", "r2=±0.05"});
    }
    void mapCellsAreTheWorstCase()
    {
        QFETCH(QString, preset);
        QFETCH(QStringList, tolerances);
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("error.csv"));
        const QJsonObject r = pkmJson(QStringList{QStringLiteral("map"), preset} + args({"--grid", "30", "--json", "-o"})
                                      + QStringList{csv} + tolerances);
        QCOMPARE(r.value(QLatin1String("quantity")).toString(), QStringLiteral("tolerance")); // --tol alone
        QCOMPARE(r.value(QLatin1String("unit")).toString(), QStringLiteral("mm"));
        QVERIFY(r.value(QLatin1String("tolerances")).toObject().contains(QLatin1String("l1")));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().split('\n');
        QCOMPARE(lines.front(), QByteArray("x,y,value,margin"));
        int compared = 0;
        for (qsizetype i = 1; i + 1 < lines.size(); i += std::max<qsizetype>(1, lines.size() / 7)) {
            const QList<QByteArray> cells = lines[i].split(',');
            QCOMPARE(cells.size(), 4);
            QStringList at = QStringList{QStringLiteral("tolerance"), preset} + args({"--samples", "0", "--json", "--set"})
                + QStringList{QStringLiteral("x=") + QString::fromLatin1(cells[0]), QStringLiteral("--set"),
                              QStringLiteral("y=") + QString::fromLatin1(cells[1])};
            if (preset.startsWith(QLatin1String("pp-3")))
                at += args({"--set", "phi=0"});
            const QJsonObject pose = pkmJson(at + tolerances);
            const double expected = pose.value(QLatin1String("first_order")).toObject()
                                        .value(QLatin1String("worst_norm")).toDouble();
            const double cell = cells[2].toDouble();
            QVERIFY2(std::abs(cell - expected) <= 1e-6 * expected,
                     qPrintable(QStringLiteral("%1: %2 against %3").arg(QString::fromLatin1(lines[i])).arg(cell).arg(expected)));
            ++compared;
        }
        QVERIFY(compared >= 5);
        // the picture, through the drawing half of the command line
        const QString png = dir.filePath(QStringLiteral("error.png"));
        QCOMPARE(runPkm(QStringList{QStringLiteral("map"), preset} + args({"--grid", "30", "-o"}) + QStringList{png}
                        + tolerances).exitCode, 0);
        QVERIFY(QFile::exists(png));
    }
};

QTEST_MAIN(TestCliTolerance)
#include "tst_clitolerance.moc"
