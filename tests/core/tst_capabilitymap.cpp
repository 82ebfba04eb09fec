// Maps of what the actuators deliver and the specification region (core/capabilitymap.h):
// every cell equals the capability of the pose solved there (as `pkm eval` gives it), the map
// reaches the cells the kind's own workspace map reaches, the specification is the
// intersection of its requirements, and the requirement parser names its culprit; also the
// text made safe to print (core/text.h) that its messages quote.
#include "capabilitymap.h"
#include "support/kinematics.h"
#include "support/planardesigns.h"
#include "text.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace pkm;
using namespace pkm::test;
using namespace pkm::test::legdesigns;

Q_DECLARE_METATYPE(pkm::MapQuantity)
Q_DECLARE_METATYPE(pkm::ParameterSet)

namespace {

struct Designed {
    MechanismPtr mechanism;
    capability::Actuators actuators;
    MapGrid grid;
};

Designed designed(const char *kind, const ParameterSet &parameters, int resolution = 24)
{
    Designed d;
    d.mechanism = makeKind(kind, parameters);
    d.actuators = capability::actuatorsOf(*d.mechanism);
    d.grid = squareGrid(d.mechanism->planarWorkspace()->workspaceBounds(), resolution);
    return d;
}

/// The capability entry `name` at the pose solved at (x, y) near `near`; NaN where unreachable.
double delivered(const Designed &d, const Pose &near, double x, double y, std::string_view name)
{
    Coordinates outputs = near.outputs;
    outputs[0] = x;
    outputs[1] = y;
    const auto pose = d.mechanism->solveInverse(outputs, &near);
    if (!pose)
        return std::nan("");
    Singularity singular;
    evaluated(*d.mechanism, *pose, &singular);
    const ReportLayout *layout = capability::layoutFor(d.actuators);
    std::vector<double> values(std::size_t(layout->size), std::nan(""));
    capability::evaluate(*d.mechanism, d.actuators, *pose, singular.type, values);
    return values[std::size_t(layout->find(name)->offset)];
}

} // namespace

class TestCapabilityMap : public QObject
{
    Q_OBJECT

private slots:
    void cellsAreThePosesValues_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<ParameterSet>("parameters");
        QTest::addColumn<pkm::MapQuantity>("quantity");
        const std::pair<const char *, MapQuantity> quantities[] = {{"force", MapQuantity::ForceWorst},
            {"speed", MapQuantity::SpeedWorst}, {"resolution", MapQuantity::ResolutionWorst},
            {"stiffness", MapQuantity::StiffnessWorst}};
        for (const auto &[name, quantity] : quantities) {
            QTest::addRow("moma %s", name) << "moma" << ParameterSet{} << quantity;
            QTest::addRow("fivebar %s", name) << "fivebar" << ParameterSet{} << quantity;
            QTest::addRow("oxglide %s", name) << "oxglide" << ParameterSet{} << quantity;
            QTest::addRow("5R legs %s", name) << "planar-parallel" << fiveR() << quantity;
            QTest::addRow("5R П-joints %s", name) << "planar-parallel" << legdesigns::fiveRPjoint() << quantity;
            QTest::addRow("2-PRR %s", name) << "planar-parallel" << legdesigns::moma3a() << quantity;
            QTest::addRow("3-PRR %s", name) << "planar-parallel" << threePrr() << quantity;
            // a 3-DOF slice away from φ = 0, through the rows that work the legs out in blocks
            ParameterSet turned = legdesigns::threeRpr();
            turned["phi_map"] = 12.0 * std::numbers::pi / 180.0;
            QTest::addRow("3-RPR at 12° %s", name) << "planar-parallel" << turned << quantity;
        }
    }
    void cellsAreThePosesValues()
    {
        QFETCH(QString, kind);
        QFETCH(ParameterSet, parameters);
        QFETCH(pkm::MapQuantity, quantity);
        const Designed d = designed(kind.toLatin1().constData(), parameters);
        QVERIFY(capability::layoutFor(d.actuators));
        const Pose near = capability::mapStart(*d.mechanism, d.mechanism->homePose());
        std::vector<float> values(d.grid.cells()), margins(d.grid.cells());
        const MapSummary summary
            = capability::computeMap(*d.mechanism, d.actuators, quantity, {}, near, d.grid, values, margins);
        QVERIFY(summary.reachableCells > 20);
        QVERIFY(!summary.cancelled);
        const std::string_view name = capability::entryName(quantity);
        int checked = 0;
        for (int r = 0; r < d.grid.rows; ++r)
            for (int c = 0; c < d.grid.columns; ++c) {
                const float cell = values[std::size_t(r) * std::size_t(d.grid.columns) + std::size_t(c)];
                const double expected = delivered(d, near, d.grid.x(c), d.grid.y(r), name);
                QCOMPARE(std::isnan(cell), std::isnan(expected));
                if (std::isnan(cell))
                    continue;
                QVERIFY(cell >= 0.0f);
                if (std::isfinite(expected)) {
                    QVERIFY2(std::abs(cell - expected) <= 1e-6 * std::abs(expected) + 1e-30,
                             qPrintable(QStringLiteral("%1 vs %2").arg(cell).arg(expected)));
                    ++checked;
                }
            }
        QVERIFY(checked > 20);
        QVERIFY(summary.min <= summary.max);
    }

    /// A 2-DOF design's capability map covers the cells of its own closed-form workspace map.
    void reachesTheWorkspace_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<ParameterSet>("parameters");
        QTest::addRow("moma") << "moma" << ParameterSet{};
        QTest::addRow("fivebar") << "fivebar" << ParameterSet{};
        QTest::addRow("5R legs") << "planar-parallel" << fiveR();
    }
    void reachesTheWorkspace()
    {
        QFETCH(QString, kind);
        QFETCH(ParameterSet, parameters);
        const Designed d = designed(kind.toLatin1().constData(), parameters, 40);
        std::vector<float> det(d.grid.cells()), force(d.grid.cells());
        const MapSummary closed = computeMap(*d.mechanism->planarWorkspace(), MapQuantity::Determinant, d.grid, det);
        const MapSummary solved = capability::computeMap(*d.mechanism, d.actuators, MapQuantity::ForceWorst, {},
                                                         d.mechanism->homePose(), d.grid, force);
        std::size_t differ = 0;
        for (std::size_t i = 0; i < det.size(); ++i)
            differ += std::isnan(det[i]) != std::isnan(force[i]);
        // both decide reachability from the same closed forms: at most a boundary cell or two
        // may fall on either side of a range limit through rounding
        QVERIFY2(differ <= 2, qPrintable(QStringLiteral("%1 of %2 cells differ").arg(differ).arg(closed.reachableCells)));
        QVERIFY(solved.reachableCells > 100);
    }

    void specificationIsTheIntersection()
    {
        const Designed d = designed("moma", {}, 30);
        const Pose near = d.mechanism->homePose();
        std::vector<float> force(d.grid.cells()), speed(d.grid.cells()), spec(d.grid.cells());
        capability::computeMap(*d.mechanism, d.actuators, MapQuantity::ForceWorst, {}, near, d.grid, force);
        capability::computeMap(*d.mechanism, d.actuators, MapQuantity::SpeedWorst, {}, near, d.grid, speed);
        // thresholds at the medians, half-way to the next larger value so that no cell sits on
        // one (mirrored cells of a symmetric design have equal values): each requirement alone
        // fails in about half the workspace
        auto median = [](std::vector<float> v) {
            std::erase_if(v, [](float x) { return !std::isfinite(x); });
            std::sort(v.begin(), v.end());
            const float middle = v[v.size() / 2];
            return 0.5 * (double(middle) + double(*std::upper_bound(v.begin(), v.end(), middle)));
        };
        const std::vector<capability::Requirement> requirements{{"force_worst", true, median(force)},
                                                                {"speed_worst", true, median(speed)}};
        capability::SpecificationSummary summary;
        const MapSummary map = capability::computeMap(*d.mechanism, d.actuators, MapQuantity::Specification, requirements,
                                                      near, d.grid, spec, {}, &summary);
        std::size_t met = 0, forceFails = 0, speedFails = 0;
        for (std::size_t i = 0; i < spec.size(); ++i) {
            QCOMPARE(std::isnan(spec[i]), std::isnan(force[i]));
            if (std::isnan(force[i]))
                continue;
            const bool strong = force[i] >= float(requirements[0].value);
            const bool fast = speed[i] >= float(requirements[1].value);
            QCOMPARE(spec[i], strong && fast ? 1.0f : 0.0f);
            met += strong && fast;
            forceFails += !strong;
            speedFails += !fast;
        }
        QCOMPARE(summary.metCells, met);
        QCOMPARE(summary.failing.size(), std::size_t(2));
        QCOMPARE(summary.failing[0], forceFails);
        QCOMPARE(summary.failing[1], speedFails);
        QVERIFY(met > 0 && met < map.reachableCells);
        QCOMPARE(summary.metArea, double(met) * d.grid.cellArea());
    }

    void cancelledBeforeTheFirstRow()
    {
        const Designed d = designed("moma", {});
        std::vector<float> values(d.grid.cells());
        const std::atomic<bool> cancel{true};
        const MapSummary summary = capability::computeMap(*d.mechanism, d.actuators, MapQuantity::ForceWorst, {},
                                                          d.mechanism->homePose(), d.grid, values, {}, nullptr, &cancel);
        QVERIFY(summary.cancelled);
        QCOMPARE(summary.reachableCells, std::size_t(0));
    }

    void parsesRequirements()
    {
        const capability::Actuators moma = capability::actuatorsOf(*makeKind("moma"));
        auto r = capability::parseRequirement("force_worst>=50", moma);
        QVERIFY(r);
        QCOMPARE(r->name, std::string("force_worst"));
        QVERIFY(r->atLeast);
        QCOMPARE(r->value, 50.0);
        r = capability::parseRequirement("  resolution_worst <= 0.02 ", moma);
        QVERIFY(r);
        QVERIFY(!r->atLeast);
        QCOMPARE(r->value, 0.02);
        QCOMPARE(capability::requirementText(*r, moma), std::string("resolution_worst ≤ 0.02 mm"));
        // an angular output's speed is given in °/s and kept in rad/s
        const capability::Actuators pjoint = capability::actuatorsOf(*makeKind("pjoint"));
        r = capability::parseRequirement("speed_worst>90", pjoint);
        QVERIFY(r);
        QVERIFY(std::abs(r->value - std::numbers::pi / 2) < 1e-12);

        const auto refused = [&](const char *text, const char *word) {
            const auto parsed = capability::parseRequirement(text, moma);
            QVERIFY2(!parsed, text);
            QVERIFY2(parsed.failure().message.find(word) != std::string::npos, parsed.failure().message.c_str());
        };
        refused("force_worst=50", "no comparison");
        refused("stiffness>=3", "no single capability value");
        refused("pressure>=3", "force_worst, force_best");
        refused("force_worst>=abc", "finite number");
        refused("force_worst>=nan", "finite number");
        refused("force_worst>=", "finite number");
        // what the user typed is quoted safely: no escape sequence reaches a terminal
        const auto hostile = capability::parseRequirement("\x1b[2Jforce>=1", moma);
        QVERIFY(!hostile);
        QVERIFY(hostile.failure().message.find('\x1b') == std::string::npos);
        QVERIFY(hostile.failure().message.find("\\x1B[2J") != std::string::npos);
    }

    void printableText()
    {
        QCOMPARE(text::printable("П-joint θ = 20°"), std::string("П-joint θ = 20°"));
        QCOMPARE(text::printable("a\x1b[31mb\nc\x07"), std::string("a\\x1B[31mb\\x0Ac\\x07"));
        QCOMPARE(text::printable("\xff\xc3("), std::string("\\xFF\\xC3("));      // invalid UTF-8
        QCOMPARE(text::printable("\xc2\x9b"), std::string("\\xC2\\x9B"));        // C1 control (CSI)
        QCOMPARE(text::printable(std::string(1000, 'x'), 10), std::string(10, 'x') + "…");
        QCOMPARE(text::printable("ППП", 2), std::string("ПП…"));
    }
};

QTEST_APPLESS_MAIN(TestCapabilityMap)
#include "tst_capabilitymap.moc"
