// The "capability" group of `pkm eval --json` and `pkm sweep` (docs/cli.md): what the
// actuators deliver at the pose, for a preset of every kind; exact 0/∞ (null, listed, with
// the singularity's reason) at a singular pose; the П-joint's numbers those of its figs.
// 15–17 (torque, speed) beside the measured stiffness.

#include "support/app.h"
#include "support/process.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTest>

#include <cmath>

using namespace pkm::test;

namespace {
const char *const scalars[] = {"force_worst", "force_best", "speed_worst", "speed_best", "resolution_worst",
                               "stiffness_worst"};
}

class TestCliCapability : public QObject
{
    Q_OBJECT

private slots:
    void everyKindHasTheGroup_data() { addPresetPerKindRows(); }
    void everyKindHasTheGroup()
    {
        PKM_FETCH_PRESET(preset);
        int exitCode = -1;
        const QJsonObject eval = pkmJson({QStringLiteral("eval"), preset, QStringLiteral("--json")}, &exitCode);
        QCOMPARE(exitCode, 0);
        const QJsonObject capability = eval.value(QLatin1String("capability")).toObject();
        for (const char *key : scalars) {
            QVERIFY2(capability.value(QLatin1String(key)).isDouble(), key);
            QVERIFY2(capability.value(QLatin1String(key)).toDouble() > 0.0, key);
        }
        QVERIFY(capability.value(QLatin1String("force_best")).toDouble()
                >= capability.value(QLatin1String("force_worst")).toDouble() * (1 - 1e-12));
        QVERIFY(capability.value(QLatin1String("undefined")).toArray().isEmpty());
        // the groups that were there before keep their place
        for (const char *key : {"parameters", "pose", "jacobian", "singularity", "derived", "mobility"})
            QVERIFY2(eval.value(QLatin1String(key)).isObject(), key);
    }

    /// The exact polygons beside the numbers: the strongest direction is the farthest vertex,
    /// the weakest the nearest edge (the numbers come from the slabs, not from the polygon).
    void polygonsMatchTheWorstAndBest_data() { addPresetPerKindRows(); }
    void polygonsMatchTheWorstAndBest()
    {
        PKM_FETCH_PRESET(preset);
        const QJsonObject capability = pkmJson({QStringLiteral("eval"), preset, QStringLiteral("--json")})
                                           .value(QLatin1String("capability"))
                                           .toObject();
        const bool platform = !preset.startsWith(QLatin1String("pjoint")) && !preset.startsWith(QLatin1String("fourbar"));
        for (const char *quantity : {"velocity", "force"}) {
            const QString key = QLatin1String(quantity) + QLatin1String("_polygon");
            QCOMPARE(capability.contains(key), platform);
            if (!platform)
                continue;
            const QJsonArray polygon = capability.value(key).toArray();
            QVERIFY2(polygon.size() >= 4 && polygon.size() % 2 == 0, qPrintable(key)); // centrally symmetric
            double farthest = 0.0, nearestEdge = INFINITY, area = 0.0;
            for (qsizetype i = 0; i < polygon.size(); ++i) {
                const QJsonArray a = polygon[i].toArray(), b = polygon[(i + 1) % polygon.size()].toArray();
                const double ax = a[0].toDouble(), ay = a[1].toDouble(), bx = b[0].toDouble(), by = b[1].toDouble();
                farthest = std::max(farthest, std::hypot(ax, ay));
                const double cross = ax * by - ay * bx;
                area += 0.5 * cross;
                nearestEdge = std::min(nearestEdge, std::abs(cross) / std::hypot(bx - ax, by - ay));
            }
            QVERIFY2(area > 0.0, "counter-clockwise");
            const QString q = QLatin1String(quantity) == QLatin1String("velocity") ? QStringLiteral("speed")
                                                                                 : QStringLiteral("force");
            const double best = capability.value(q + QLatin1String("_best")).toDouble();
            const double worst = capability.value(q + QLatin1String("_worst")).toDouble();
            QVERIFY2(std::abs(farthest - best) <= 1e-9 * best, qPrintable(QStringLiteral("%1 %2 %3").arg(key).arg(farthest).arg(best)));
            QVERIFY2(std::abs(nearestEdge - worst) <= 1e-9 * best,
                     qPrintable(QStringLiteral("%1 %2 %3").arg(key).arg(nearestEdge).arg(worst)));
        }
    }

    void pjointPrototype()
    {
        const QJsonObject eval = pkmJson(args({"eval", "pjoint-prototype", "--set", "theta=20", "--json"}));
        const QJsonObject capability = eval.value(QLatin1String("capability")).toObject();
        const QJsonObject derived = eval.value(QLatin1String("derived")).toObject();
        // one actuator: weakest and strongest are the output torque and speed of figs. 16–17
        QCOMPARE(capability.value(QLatin1String("force_worst")).toDouble(), derived.value(QLatin1String("torque")).toDouble());
        QCOMPARE(capability.value(QLatin1String("force_best")).toDouble(), derived.value(QLatin1String("torque")).toDouble());
        QVERIFY(std::abs(capability.value(QLatin1String("resolution_worst")).toDouble()
                         - 0.5 * derived.value(QLatin1String("resolution")).toDouble())
                < 1e-12);
        QCOMPARE(capability.value(QLatin1String("stiffness_measured")).toDouble(), 3.5e4);
        // the actuator's share alone is stiffer than the whole joint measured
        QVERIFY(capability.value(QLatin1String("stiffness")).toDouble() > 3.5e4);
        const QJsonObject parameters = eval.value(QLatin1String("parameters")).toObject();
        QCOMPARE(parameters.value(QLatin1String("stiffness")).toDouble(), 20000.0);
        // its actuator's limits are bounded as every other kind's (they gave 6e298 N·m)
        for (const char *name : {"force_max", "step", "speed_max", "stiffness", "lead"}) {
            const Run huge = runPkm({QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
                                     QLatin1String(name) + QStringLiteral("=1e300")});
            QCOMPARE(huge.exitCode, 2);
            QVERIFY2(QString::fromUtf8(huge.err).contains(QLatin1String(name) + QStringLiteral(" (")), huge.err.constData());
        }
    }

    void moma3a()
    {
        const QJsonObject eval = pkmJson(args({"eval", "moma-3a", "--json"}));
        const QJsonObject capability = eval.value(QLatin1String("capability")).toObject();
        const QJsonArray K = capability.value(QLatin1String("stiffness")).toArray();
        QCOMPARE(K.size(), 2);
        QCOMPARE(K[0].toArray().size(), 2);
        // a symmetric matrix whose smallest eigenvalue is stiffness_worst
        const double a = K[0].toArray()[0].toDouble(), b = K[0].toArray()[1].toDouble(), d = K[1].toArray()[1].toDouble();
        QCOMPARE(b, K[1].toArray()[0].toDouble());
        const double smallest = 0.5 * (a + d) - std::hypot(0.5 * (a - d), b);
        QVERIFY(std::abs(smallest - capability.value(QLatin1String("stiffness_worst")).toDouble()) < 1e-6 * a);
        const QJsonObject parameters = eval.value(QLatin1String("parameters")).toObject();
        for (const char *name : {"force_max1", "speed_max1", "step1", "stiffness1", "force_max2"})
            QVERIFY2(parameters.value(QLatin1String(name)).isDouble(), name);
    }

    void singularPoseIsNullAndListed()
    {
        // the five-bar with both legs stretched (an inverse singularity, tst_cli): J unbounded,
        // so the strongest force and the stiffness are ∞, the slowest speed 0 (the marks)
        const QJsonObject eval = pkmJson(args({"eval", "fivebar-example", "--set", "x=50", "--set", "y=193.64916731037084",
                                               "--json"}));
        QCOMPARE(eval.value(QLatin1String("singularity")).toObject().value(QLatin1String("type")).toString(),
                 QStringLiteral("inverse"));
        QVERIFY(!eval.value(QLatin1String("singularity")).toObject().value(QLatin1String("reason")).toString().isEmpty());
        const QJsonObject capability = eval.value(QLatin1String("capability")).toObject();
        QVERIFY(capability.value(QLatin1String("force_best")).isNull());
        QCOMPARE(capability.value(QLatin1String("speed_worst")).toDouble(), 0.0);
        const QJsonArray infinite = capability.value(QLatin1String("infinite")).toArray();
        QVERIFY(infinite.contains(QStringLiteral("force_best")));
        QVERIFY(infinite.contains(QStringLiteral("stiffness")));
        QVERIFY(capability.value(QLatin1String("undefined")).toArray().contains(QStringLiteral("force_best")));
        // both legs stretched at once: J_q = 0, the platform is locked in every direction, so even
        // the weakest direction holds any force and nothing moves it (exact, not 1e13)
        QVERIFY(infinite.contains(QStringLiteral("force_worst")));
        QVERIFY(infinite.contains(QStringLiteral("stiffness_worst")));
        QCOMPARE(capability.value(QLatin1String("speed_best")).toDouble(), 0.0);
        QCOMPARE(capability.value(QLatin1String("resolution_worst")).toDouble(), 0.0);
        // the force polygon is the whole plane, the velocity polygon the platform point alone
        QVERIFY(capability.value(QLatin1String("force_polygon")).isNull());
        QVERIFY(infinite.contains(QStringLiteral("force_polygon")));
        QVERIFY(capability.value(QLatin1String("undefined")).toArray().contains(QStringLiteral("force_polygon")));
        for (const QJsonValue &vertex : capability.value(QLatin1String("velocity_polygon")).toArray())
            QCOMPARE(std::hypot(vertex.toArray()[0].toDouble(), vertex.toArray()[1].toDouble()), 0.0);
    }

    void nearSingularPoseSaysSo()
    {
        // 10⁻¹¹ mm below the stretched legs the kind calls the pose regular, but the rigid model's
        // 6.6·10⁷ N from 2 N·m motors would be meaningless: the group reports it as at an inverse
        // singularity (null and listed, speed 0) and says why
        const QJsonObject near = pkmJson(args({"eval", "fivebar-example", "--set", "x=50", "--set", "y=193.64916731037",
                                               "--json"}));
        QCOMPARE(near.value(QLatin1String("singularity")).toObject().value(QLatin1String("type")).toString(),
                 QStringLiteral("none"));
        const QJsonObject capability = near.value(QLatin1String("capability")).toObject();
        QCOMPARE(capability.value(QLatin1String("singular")).toString(), QStringLiteral("inverse"));
        QVERIFY(capability.value(QLatin1String("reason")).toString().contains(QLatin1String("1/1000")));
        for (const char *name : {"force_worst", "force_best", "stiffness_worst"}) {
            QVERIFY2(capability.value(QLatin1String(name)).isNull(), name);
            QVERIFY2(capability.value(QLatin1String("infinite")).toArray().contains(QLatin1String(name)), name);
        }
        QCOMPARE(capability.value(QLatin1String("speed_worst")).toDouble(), 0.0);
        // J and det J follow the same rule (−2.2·10⁹ rad²/mm² before): null, listed as ∞, and why
        const QJsonObject singularity = near.value(QLatin1String("singularity")).toObject();
        const QJsonObject jacobian = near.value(QLatin1String("jacobian")).toObject();
        for (const char *name : {"J", "det_J", "cond"})
            QVERIFY2(singularity.value(QLatin1String("infinite")).toArray().contains(QLatin1String(name)), name);
        QVERIFY(jacobian.value(QLatin1String("det_J")).isNull());
        QVERIFY(jacobian.value(QLatin1String("cond")).isNull());
        QVERIFY(jacobian.value(QLatin1String("J")).toArray()[0].toArray()[0].isNull());
        QCOMPARE(jacobian.value(QLatin1String("det_Jq")).toDouble(), 0.0);
        QVERIFY(singularity.value(QLatin1String("reason")).toString().contains(QLatin1String("near an inverse")));
        const Run text = runPkm(args({"eval", "fivebar-example", "--set", "x=50", "--set", "y=193.64916731037"}));
        QVERIFY(QString::fromUtf8(text.out).contains(QLatin1String("capability as at a singular pose, near an inverse")));
        // a regular pose: its own class and no reason
        const QJsonObject regular = pkmJson(args({"eval", "fivebar-example", "--set", "x=50", "--set", "y=150", "--json"}))
                                        .value(QLatin1String("capability")).toObject();
        QCOMPARE(regular.value(QLatin1String("singular")).toString(), QStringLiteral("none"));
        QVERIFY(regular.value(QLatin1String("reason")).isNull());
        QVERIFY(regular.value(QLatin1String("force_worst")).toDouble() > 20.0);
        const QJsonObject regularPose = pkmJson(args({"eval", "fivebar-example", "--set", "x=50", "--set", "y=150", "--json"}));
        QVERIFY(std::isfinite(regularPose.value(QLatin1String("jacobian")).toObject().value(QLatin1String("det_J")).toDouble(
            std::nan(""))));
        QVERIFY(regularPose.value(QLatin1String("singularity")).toObject().value(QLatin1String("reason")).isNull());
    }

    void sweepHasTheColumns()
    {
        const Run csv = runPkm(args({"sweep", "moma-3a", "--var", "p1", "--from", "50", "--to", "150", "--steps", "3"}));
        QCOMPARE(csv.exitCode, 0);
        const QString header = QString::fromUtf8(csv.out).section(QLatin1Char('\n'), 0, 0);
        for (const char *column : {"force_worst", "speed_best", "stiffness[1][1]", "stiffness_worst"})
            QVERIFY2(header.split(QLatin1Char(',')).contains(QLatin1String(column)), column);
        // a parameter sweep of the П-joint: its parameter stiffness and the capability's apart
        const Run parameters = runPkm(args({"sweep", "pjoint-prototype", "--var", "stiffness", "--from", "10000", "--to",
                                            "40000", "--steps", "2"}));
        QCOMPARE(parameters.exitCode, 0);
        const QStringList columns = QString::fromUtf8(parameters.out).section(QLatin1Char('\n'), 0, 0).split(QLatin1Char(','));
        QVERIFY(columns.contains(QStringLiteral("stiffness")));
        QVERIFY(columns.contains(QStringLiteral("capability.stiffness")));
        const QJsonObject json = pkmJson(args({"sweep", "pjoint-prototype", "--var", "theta", "--from", "-60", "--to", "60",
                                               "--steps", "3", "--json"}));
        const QJsonArray rows = json.value(QLatin1String("rows")).toArray();
        QCOMPARE(rows.size(), 3);
        for (const QJsonValue &row : rows)
            QVERIFY(row.toObject().value(QLatin1String("capability")).toObject().value(QLatin1String("force_worst")).isDouble());
        // a sweep's rows carry the polygons and the class as eval's group does, up to the
        // stretched legs of the five-bar, where the force polygon is the whole plane
        const QJsonArray fivebar = pkmJson(args({"sweep", "fivebar-example", "--var", "y", "--from", "150", "--to",
                                                 "193.64916731037", "--steps", "3", "--json"}))
                                       .value(QLatin1String("rows")).toArray();
        QCOMPARE(fivebar.size(), 3);
        const QJsonObject first = fivebar[0].toObject().value(QLatin1String("capability")).toObject();
        QCOMPARE(first, pkmJson(args({"eval", "fivebar-example", "--json"})).value(QLatin1String("capability")).toObject());
        QVERIFY(first.value(QLatin1String("force_polygon")).toArray().size() >= 3);
        const QJsonObject last = fivebar[2].toObject().value(QLatin1String("capability")).toObject();
        QCOMPARE(last.value(QLatin1String("singular")).toString(), QStringLiteral("inverse"));
        QVERIFY(last.value(QLatin1String("force_polygon")).isNull());
        QVERIFY(last.value(QLatin1String("infinite")).toArray().contains(QStringLiteral("force_polygon")));
    }
};

QTEST_MAIN(TestCliCapability)
#include "tst_clicapability.moc"
