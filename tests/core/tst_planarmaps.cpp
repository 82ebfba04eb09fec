// The map rows of a 2-DOF planar parallel design (ppmaprow.cpp), worked out a block of cells
// at a time without branches: they reach exactly the cells solveInverse() reaches, and at each
// give the det J, κ(J) and margin that evaluate() gives at that pose (within 1e-6 relative),
// for every leg type, working and assembly mode, a crank of limited range and a platform of
// constant orientation; the leg-built 5R and MOMA 3a map as the five-bar and MOMA do.
#include "kinds/planarparallel/planarparallel.h"
#include "registry.h"
#include "support/kinematics.h"
#include "support/planardesigns.h"

#include <QTest>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

using namespace pkm;
using namespace pkm::test;

Q_DECLARE_METATYPE(pkm::ParameterSet)

namespace {
constexpr double deg = units::degree;

std::shared_ptr<const PlanarParallel> build(const ParameterSet &parameters)
{
    return std::dynamic_pointer_cast<const PlanarParallel>(makeKind("planar-parallel", parameters));
}

using pkm::test::legdesigns::fiveR;
using pkm::test::legdesigns::moma3a;

using pkm::test::legdesigns::fiveRPjoint;

/// |a − b| within `relative` of the larger, or both infinite of one sign.
bool close(double a, double b, double relative)
{
    if (std::isinf(a) || std::isinf(b))
        return a == b;
    return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b));
}

struct Maps {
    MapGrid grid;
    std::vector<float> det, detMargins, cond;
};

Maps maps(const PlanarWorkspace &w, const MapGrid &grid)
{
    Maps m{grid, std::vector<float>(grid.cells()), std::vector<float>(grid.cells()), std::vector<float>(grid.cells())};
    computeMap(w, MapQuantity::Determinant, grid, m.det, m.detMargins);
    computeMap(w, MapQuantity::Condition, grid, m.cond);
    return m;
}
} // namespace

class TestPlanarMaps : public QObject
{
    Q_OBJECT

private slots:
    void cellsArePoses_data()
    {
        QTest::addColumn<ParameterSet>("design");
        QTest::newRow("5R") << fiveR();
        QTest::newRow("2-PRR") << moma3a();
        QTest::newRow("5R П-joints") << fiveRPjoint();
        ParameterSet limited = fiveR(); // cranks of limited range, one of them across ±180°
        limited["theta1_min"] = 10 * deg;
        limited["theta1_max"] = 150 * deg;
        limited["theta2_min"] = 60 * deg;
        limited["theta2_max"] = 200 * deg;
        QTest::newRow("5R, limited cranks") << limited;
        ParameterSet other = fiveR(); // elbows in, the other assembly mode
        other["working1"] = -1;
        other["working2"] = 1;
        other["assembly"] = -1;
        QTest::newRow("5R, other modes") << other;
        QTest::newRow("RRR + PRR") << pkm::test::legdesigns::crankAndSlider();
        QTest::newRow("RPR + RRR") << pkm::test::legdesigns::strutAndCrank();
        ParameterSet translating = fiveRPjoint(); // resources/presets/pp-pa-pjoint.pkm.json
        translating["platform"] = 1;
        translating["B1x"] = -40;
        translating["B2x"] = 40;
        QTest::newRow("translating, П-joints") << translating;
    }

    /// Every cell of the det J and κ maps is the pose solved there: reached exactly where
    /// solveInverse() succeeds, with evaluate()'s det J, κ(J) and margin.
    void cellsArePoses()
    {
        QFETCH(ParameterSet, design);
        const auto pp = build(design);
        QVERIFY(pp);
        const MapGrid grid = squareGrid(pp->workspaceBounds(), 97);
        const Maps m = maps(*pp, grid);
        int reached = 0, compared = 0;
        for (int r = 0; r < grid.rows; ++r) {
            for (int c = 0; c < grid.columns; ++c) {
                const std::size_t i = std::size_t(r) * std::size_t(grid.columns) + std::size_t(c);
                const auto pose = pp->solveInverse(pair(grid.x(c), grid.y(r)));
                const QString where = QString("cell (%1, %2) at (%3, %4)").arg(c).arg(r).arg(grid.x(c)).arg(grid.y(r));
                QVERIFY2(std::isnan(m.det[i]) == !pose, qPrintable(where));
                QVERIFY2(std::isnan(m.cond[i]) == !pose, qPrintable(where));
                if (!pose)
                    continue;
                ++reached;
                Singularity s;
                const std::vector<double> v = evaluated(*pp, *pose, &s);
                QVERIFY2(std::abs(m.detMargins[i] - s.margin) < 1e-6, qPrintable(where));
                if (s.type != SingularityType::None)
                    continue; // evaluate() reports the exact 0 or ∞ there, the map the formula's value
                const double det = entry(*pp, v, "det_J"), cond = entry(*pp, v, "cond");
                QVERIFY2(close(m.det[i], det, 1e-6), qPrintable(where + QString(": det J %1, pose %2").arg(m.det[i]).arg(det)));
                QVERIFY2(close(m.cond[i], cond, 1e-6), qPrintable(where + QString(": κ %1, pose %2").arg(m.cond[i]).arg(cond)));
                ++compared;
            }
        }
        QVERIFY2(reached > 500, qPrintable(QString::number(reached)));
        QVERIFY(compared > reached / 2);
    }

    /// A 3-DOF platform's det J slice at φ = phi_map, worked out a block at a time as well:
    /// reached exactly where solveInverse() succeeds at that angle, with evaluate()'s det J and
    /// margin, for struts, sliders and cranks (one of them П-joint-driven) at several angles.
    void slicesArePoses_data()
    {
        QTest::addColumn<ParameterSet>("design");
        for (const double phi : {0.0, 12.0, -30.0}) {
            ParameterSet rpr = pkm::test::legdesigns::threeRpr(), prr = pkm::test::legdesigns::threePrr();
            rpr["phi_map"] = prr["phi_map"] = phi * deg;
            QTest::addRow("3-RPR at %g°", phi) << rpr;
            QTest::addRow("3-PRR at %g°", phi) << prr;
            // the 3-PRR with a crank and a П-joint in place of two sliders
            ParameterSet mixed = prr;
            mixed["leg1_type"] = 0;
            mixed["r1"] = 120;
            mixed["l1"] = 150;
            mixed["leg2_type"] = 3;
            mixed["a2"] = 170;
            mixed["k2"] = 0.4;
            mixed["l2"] = 200;
            mixed["q2_min"] = 116.5;
            mixed["q2_max"] = 231;
            QTest::addRow("RRR + ПRR + PRR at %g°", phi) << mixed;
        }
    }
    void slicesArePoses()
    {
        QFETCH(ParameterSet, design);
        const auto pp = build(design);
        QVERIFY(pp);
        const double phi = pp->design().mapPhi;
        const MapGrid grid = squareGrid(pp->workspaceBounds(), 90);
        std::vector<float> det(grid.cells()), margins(grid.cells());
        computeMap(*pp, MapQuantity::Determinant, grid, det, margins);
        int reached = 0, compared = 0;
        for (int r = 0; r < grid.rows; ++r) {
            for (int c = 0; c < grid.columns; ++c) {
                const std::size_t i = std::size_t(r) * std::size_t(grid.columns) + std::size_t(c);
                const auto pose = pp->solveInverse(triple(grid.x(c), grid.y(r), phi));
                const QString where = QString("cell (%1, %2) at (%3, %4)").arg(c).arg(r).arg(grid.x(c)).arg(grid.y(r));
                QVERIFY2(std::isnan(det[i]) == !pose, qPrintable(where));
                if (!pose)
                    continue;
                ++reached;
                Singularity s;
                const std::vector<double> v = evaluated(*pp, *pose, &s);
                QVERIFY2(std::abs(margins[i] - s.margin) < 1e-6, qPrintable(where + QString(": margin %1, pose %2").arg(margins[i]).arg(s.margin)));
                if (s.type != SingularityType::None)
                    continue;
                const double expected = entry(*pp, v, "det_J");
                QVERIFY2(close(det[i], expected, 1e-6), qPrintable(where + QString(": det J %1, pose %2").arg(det[i]).arg(expected)));
                ++compared;
            }
        }
        QVERIFY2(reached > 100, qPrintable(QString::number(reached)));
        QVERIFY(compared > reached / 2);
    }

    /// The leg-built 5R and MOMA 3a map as the five-bar and MOMA themselves, cell by cell on
    /// one grid.
    void builtInKinds_data()
    {
        QTest::addColumn<ParameterSet>("design");
        QTest::addColumn<QString>("kind");
        QTest::newRow("5R") << fiveR() << QStringLiteral("fivebar");
        QTest::newRow("MOMA 3a") << moma3a() << QStringLiteral("moma");
    }
    void builtInKinds()
    {
        QFETCH(ParameterSet, design);
        QFETCH(QString, kind);
        const auto pp = build(design);
        const MechanismPtr own = makeKind(kind.toStdString());
        QVERIFY(pp && own && own->planarWorkspace());
        const MapGrid grid = squareGrid(own->planarWorkspace()->workspaceBounds(), 211);
        const Maps legs = maps(*pp, grid), built = maps(*own->planarWorkspace(), grid);
        int reached = 0;
        for (std::size_t i = 0; i < grid.cells(); ++i) {
            QCOMPARE(std::isnan(legs.det[i]), std::isnan(built.det[i]));
            if (std::isnan(legs.det[i]) || built.detMargins[i] < 1e-4)
                continue;
            ++reached;
            QVERIFY2(close(legs.det[i], built.det[i], 1e-6), qPrintable(QString("cell %1: %2 against %3").arg(i).arg(legs.det[i]).arg(built.det[i])));
            QVERIFY2(close(legs.cond[i], built.cond[i], 1e-6), qPrintable(QString("cell %1: %2 against %3").arg(i).arg(legs.cond[i]).arg(built.cond[i])));
            QVERIFY(std::abs(legs.detMargins[i] - built.detMargins[i]) < 1e-6);
        }
        QVERIFY2(reached > 5000, qPrintable(QString::number(reached)));
    }

    /// Every cell and margin of a map is written: the buffers a map is computed into are
    /// not zeroed first (MapCells), so a cell left out would show what the memory held. Each
    /// kind with a planar workspace, in each quantity it offers, on buffers of a marker.
    void everyCellWritten_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<ParameterSet>("design");
        for (const MechanismKind &kind : mechanismKinds()) {
            const MechanismPtr made = makeKind(kind.id);
            if (made && made->planarWorkspace()) // the П-joint and the four-bar have none
                QTest::newRow(std::string(kind.id).c_str()) << QString::fromUtf8(kind.id.data(), qsizetype(kind.id.size())) << ParameterSet();
        }
        QTest::newRow("RRR + PRR") << QStringLiteral("planar-parallel") << pkm::test::legdesigns::crankAndSlider();
        QTest::newRow("5R П-joints") << QStringLiteral("planar-parallel") << fiveRPjoint();
    }
    void everyCellWritten()
    {
        QFETCH(QString, kind);
        QFETCH(ParameterSet, design);
        const MechanismPtr mechanism = makeKind(kind.toStdString(), design);
        QVERIFY(mechanism);
        const PlanarWorkspace *workspace = mechanism->planarWorkspace();
        QVERIFY(workspace);
        const MapGrid grid = squareGrid(workspace->workspaceBounds(), 173);
        const std::uint32_t marker = 0x7fc0dead; // a NaN no computation gives
        for (MapQuantity quantity : {MapQuantity::Determinant, MapQuantity::Condition, MapQuantity::OrientationRange}) {
            if (!workspace->offers(quantity))
                continue;
            MapCells values(grid.cells()), margins(grid.cells());
            std::fill(values.begin(), values.end(), std::bit_cast<float>(marker));
            std::fill(margins.begin(), margins.end(), std::bit_cast<float>(marker));
            computeMap(*workspace, quantity, grid, values, margins);
            for (std::size_t i = 0; i < grid.cells(); ++i) {
                QVERIFY2(std::bit_cast<std::uint32_t>(values[i]) != marker, qPrintable(QString("value of cell %1").arg(i)));
                QVERIFY2(std::bit_cast<std::uint32_t>(margins[i]) != marker, qPrintable(QString("margin of cell %1").arg(i)));
            }
        }
    }

    /// A row cut anywhere gives the same cells: the blocks of the row and the cells solved
    /// as poses join without a seam.
    void rowsInPieces()
    {
        const auto pp = build(fiveRPjoint());
        const Eigen::AlignedBox2d box = pp->workspaceBounds();
        const int count = 1001;
        const double dx = box.sizes().x() / count;
        for (const double y : {box.min().y() + 0.3 * box.sizes().y(), box.center().y(), box.max().y() - 0.2 * box.sizes().y()}) {
            std::vector<float> whole(count), margins(count), pieces(count), pieceMargins(count);
            pp->fillMapRow(MapQuantity::Determinant, y, box.min().x(), dx, whole, margins);
            for (int start = 0, size = 1; start < count; start += size, size = size * 3 % 257 + 1) {
                const int n = std::min(size, count - start);
                pp->fillMapRow(MapQuantity::Determinant, y, box.min().x() + start * dx, dx,
                               std::span<float>(pieces).subspan(std::size_t(start), std::size_t(n)),
                               std::span<float>(pieceMargins).subspan(std::size_t(start), std::size_t(n)));
            }
            int reached = 0;
            for (int i = 0; i < count; ++i) {
                QCOMPARE(std::isnan(whole[std::size_t(i)]), std::isnan(pieces[std::size_t(i)]));
                if (std::isnan(whole[std::size_t(i)]))
                    continue;
                ++reached;
                QVERIFY(close(whole[std::size_t(i)], pieces[std::size_t(i)], 1e-6));
                QVERIFY(std::abs(margins[std::size_t(i)] - pieceMargins[std::size_t(i)]) < 1e-6);
            }
            QVERIFY(reached > 50);
        }
    }
};

QTEST_MAIN(TestPlanarMaps)
#include "tst_planarmaps.moc"
