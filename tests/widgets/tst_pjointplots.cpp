// Tests of PJointPlots and of its curves (pjointcurves.h): the curves are the closed forms of
// core/pjoint.h, the cursor shows them at θ, and near-singular designs never put a NaN, an inf
// or a runaway axis on screen.

#include "kinds/pjoint/pjoint.h"
#include "kinds/pjoint/pjointcurves.h"
#include "kinds/pjoint/pjointplots.h"
#include "plotstyle.h"

#include <qcustomplot.h>

#include <QFontMetrics>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTest>

#include <cmath>
#include <limits>

using namespace pkm;

namespace {

constexpr double degree = units::degree;

PJointDesign prototype() // Table 1
{
    PJointDesign p;
    p.a = 170.0;
    p.b = 68.0;
    p.thetaMin = -60.0 * degree;
    p.thetaMax = 60.0 * degree;
    p.lead = 2.54;
    p.step = 0.0127;
    p.speedMax = 50.0;
    p.forceMax = 130.0;
    return p;
}

/// What plot `name` must show at θ (rad), in its display unit, straight from the closed forms.
double expected(const QString &name, const PJointDesign &p, double theta)
{
    const double J = pjoint::jacobian(p, theta); // (7)
    if (name == QLatin1String("d"))
        return pjoint::diagonal(p, theta); // (2)
    if (name == QLatin1String("phi"))
        return pjoint::passiveAngle(p, theta) / degree;
    if (name == QLatin1String("mu"))
        return pjoint::transmissionAngle(p, theta) / degree;
    if (name == QLatin1String("J"))
        return J;
    if (name == QLatin1String("J_inv"))
        return 1.0 / J; // (8)
    if (name == QLatin1String("resolution"))
        return p.step / J / degree; // Δθ = Δd/J, rad/step → °/step
    if (name == QLatin1String("speed"))
        return p.speedMax / J; // θ̇ = ḋ_max/J
    if (name == QLatin1String("torque"))
        return J * p.forceMax * 1e-3; // (13) T = J·F, N·mm → N·m
    return std::numeric_limits<double>::quiet_NaN();
}

bool relativelyEqual(double actual, double wanted, double tolerance = 1e-9)
{
    return std::abs(actual - wanted) <= tolerance * std::abs(wanted);
}

QCPGraph *designGraph(const PJointPlots &plots, const QString &name)
{
    QCustomPlot *plot = plots.plot(plots.plotIndex(name));
    return plot ? plot->graph(0) : nullptr;
}

template<class Item> QList<Item *> cursorItems(QCustomPlot *plot)
{
    QList<Item *> items;
    if (QCPLayer *layer = plot->layer(QStringLiteral("cursor")))
        for (QCPLayerable *child : layer->children())
            if (auto *item = qobject_cast<Item *>(child))
                items.append(item);
    return items;
}

/// Share of the axis rect's height, in the pixel column at θ, painted in the cursor's red.
double redShareAt(QCustomPlot *plot, double thetaDegrees)
{
    const QImage image = plot->grab().toImage();
    const QRect rect = plot->axisRect()->rect();
    const int x0 = qRound(plot->xAxis->coordToPixel(thetaDegrees));
    int red = 0;
    for (int y = rect.top() + 1; y < rect.bottom(); ++y) {
        bool found = false;
        for (int x = x0 - 1; x <= x0 + 1 && !found; ++x) {
            const QColor c = image.pixelColor(x, y);
            found = c.red() > 160 && c.green() < 120 && c.blue() < 120;
        }
        red += found;
    }
    return double(red) / std::max(1, rect.height() - 2);
}

} // namespace

class TestPJointPlots : public QObject
{
    Q_OBJECT

private slots:
    void plotsAndTabs();
    void diagonalCurve();
    void curvesAreClosedForms_data();
    void curvesAreClosedForms();
    void cursor_data();
    void cursor();
    void cursorLayerIsBuffered();
    void designChangeMovesCurvesKeepsCursor();
    void finiteNearSingularity_data();
    void finiteNearSingularity();
    void hiddenTabCatchesUp();
    void transmissionBand();
    void computedCurvesStayInside_data();
    void computedCurvesStayInside();
    void clipEndsAtTheEdge();
    void valueRangeSkipsNearSingularSamples();
    void valueText();
    void subtitleWrapsInANarrowPlot();
    void cursorLabelStaysWholeInANarrowPlot();
    void thetaTicksNeverCrowd();
};

void TestPJointPlots::plotsAndTabs()
{
    PJointPlots plots;
    const QStringList names {QStringLiteral("d"), QStringLiteral("phi"), QStringLiteral("mu"), QStringLiteral("J"),
        QStringLiteral("J_inv"), QStringLiteral("resolution"), QStringLiteral("speed"), QStringLiteral("torque")};
    QCOMPARE(plots.plotCount(), names.size());
    QCOMPARE(plots.tabs()->count(), 3);
    const int tabOf[] = {0, 0, 0, 1, 1, 2, 2, 2}; // Geometry, Jacobian, Actuator
    for (int i = 0; i < plots.plotCount(); ++i) {
        QCOMPARE(plots.plotName(i), names[i]);
        QCOMPARE(plots.plotIndex(names[i]), i);
        QVERIFY(plots.plot(i));
        QVERIFY2(plots.tabs()->widget(tabOf[i])->isAncestorOf(plots.plot(i)), qPrintable(names[i]));
        QVERIFY(!plots.plot(i)->xAxis->label().isEmpty());
        QVERIFY(!plots.plot(i)->yAxis->label().isEmpty());
        QVERIFY(plots.plot(i)->legend->visible());
    }
    QVERIFY(!plots.plot(plots.plotCount()));
    QCOMPARE(plots.plotIndex(QStringLiteral("nope")), -1);
}

void TestPJointPlots::diagonalCurve()
{
    PJointPlots plots;
    const PJointDesign p = prototype();
    plots.setDesign(p);
    QCPGraph *graph = designGraph(plots, QStringLiteral("d"));
    QVERIFY(graph);
    QVERIFY(graph->dataCount() >= 300);

    // Over the design range, d runs from d_min = d(−60°) to d_max = d(60°) (section 4.2).
    double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
    for (const QCPGraphData &point : *graph->data()) {
        QVERIFY(point.key >= -60.0 - 1e-9 && point.key <= 60.0 + 1e-9);
        lowest = std::min(lowest, point.value);
        highest = std::max(highest, point.value);
    }
    QCOMPARE(graph->data()->constBegin()->key, -60.0);
    QCOMPARE((graph->data()->constEnd() - 1)->key, 60.0);
    QVERIFY2(std::abs(lowest - 116.2) < 0.05, qPrintable(QString::number(lowest)));
    QVERIFY2(std::abs(highest - 231.4) < 0.05, qPrintable(QString::number(highest)));

    // The k-family of fig. 8 is drawn at the same a over −90…90°.
    QCustomPlot *plot = plots.plot(plots.plotIndex(QStringLiteral("d")));
    QCOMPARE(plot->xAxis->range().lower, -90.0);
    QCOMPARE(plot->xAxis->range().upper, 90.0);
    int familyCurves = 0;
    for (const double k : {0.3, 0.4, 0.5, 1.0, 1.5}) {
        PJointDesign member = p;
        member.b = k * p.a;
        for (int g = 1; g < plot->graphCount(); ++g) {
            const QCPGraphData &first = *plot->graph(g)->data()->constBegin();
            const QCPGraphData &last = *(plot->graph(g)->data()->constEnd() - 1);
            if (first.key == -90.0 && last.key == 90.0
                && relativelyEqual(first.value, pjoint::diagonal(member, -90.0 * degree), 1e-12)
                && relativelyEqual(last.value, pjoint::diagonal(member, 90.0 * degree), 1e-12)) {
                ++familyCurves;
                break;
            }
        }
    }
    QCOMPARE(familyCurves, 5);
}

void TestPJointPlots::curvesAreClosedForms_data()
{
    QTest::addColumn<QString>("name");
    for (const char *name : {"d", "phi", "mu", "J", "J_inv", "resolution", "speed", "torque"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

void TestPJointPlots::curvesAreClosedForms()
{
    QFETCH(QString, name);
    PJointPlots plots;
    const PJointDesign p = prototype();
    plots.setDesign(p);
    QCPGraph *graph = designGraph(plots, name);
    QVERIFY(graph);
    QVERIFY(graph->dataCount() >= 300);
    const QCPRange y = graph->valueAxis()->range();
    for (const QCPGraphData &point : *graph->data()) {
        const double wanted = expected(name, p, point.key * degree);
        QVERIFY2(relativelyEqual(point.value, wanted, 1e-12),
            qPrintable(QStringLiteral("θ = %1°: %2 vs %3").arg(point.key).arg(point.value).arg(wanted)));
        QVERIFY(y.contains(point.value));
    }
}

void TestPJointPlots::cursor_data()
{
    QTest::addColumn<double>("thetaDegrees");
    for (const double t : {-60.0, -45.0, -12.5, 0.0, 25.0, 40.0, 55.0, 60.0, 75.0})
        QTest::addRow("%g deg", t) << t;
}

void TestPJointPlots::cursor()
{
    QFETCH(double, thetaDegrees);
    PJointPlots plots;
    const PJointDesign p = prototype();
    plots.setDesign(p);
    plots.setTheta(thetaDegrees * degree);
    QVERIFY(std::abs(plots.cursorTheta() - thetaDegrees) <= 1e-12 * std::max(1.0, std::abs(thetaDegrees)));
    for (int i = 0; i < plots.plotCount(); ++i) {
        const QString name = plots.plotName(i);
        const double wanted = expected(name, p, thetaDegrees * degree);
        QVERIFY2(relativelyEqual(plots.cursorValue(i), wanted),
            qPrintable(QStringLiteral("%1: %2 vs %3").arg(name).arg(plots.cursorValue(i)).arg(wanted)));

        // Every plot's line is at θ, the marker on the curve, the label quotes the value.
        QCustomPlot *plot = plots.plot(i);
        const auto lines = cursorItems<QCPItemStraightLine>(plot);
        QCOMPARE(lines.size(), 1);
        QCOMPARE(lines[0]->point1->key(), plots.cursorTheta());
        QCOMPARE(lines[0]->point2->key(), plots.cursorTheta());
        const auto markers = cursorItems<QCPItemTracer>(plot);
        QCOMPARE(markers.size(), 1);
        if (plot->yAxis->range().contains(wanted)) {
            QVERIFY(markers[0]->visible());
            QCOMPARE(markers[0]->position->key(), plots.cursorTheta());
            QVERIFY(relativelyEqual(markers[0]->position->value(), wanted));
        }
        const auto labels = cursorItems<QCPItemText>(plot);
        QCOMPARE(labels.size(), 1);
        QVERIFY2(labels[0]->text().startsWith(plot->yAxis->label().section(QLatin1Char(' '), 0, 0))
                || i == PJointPlots::SpeedPlot,
            qPrintable(labels[0]->text()));
    }
}

void TestPJointPlots::cursorLayerIsBuffered()
{
    PJointPlots plots;
    for (int i = 0; i < plots.plotCount(); ++i) {
        QCPLayer *layer = plots.plot(i)->layer(QStringLiteral("cursor"));
        QVERIFY(layer);
        QCOMPARE(layer->mode(), QCPLayer::lmBuffered);
        QCOMPARE(layer->children().size(), 3); // line, marker, label: nothing else to redraw
    }
}

void TestPJointPlots::designChangeMovesCurvesKeepsCursor()
{
    PJointPlots plots;
    PJointDesign p = prototype();
    plots.setDesign(p);
    plots.setTheta(20.0 * degree);
    const int J = plots.plotIndex(QStringLiteral("J"));
    auto valueAtZero = [&]() {
        for (const QCPGraphData &point : *plots.plot(J)->graph(0)->data())
            if (std::abs(point.key) < 1e-9)
                return point.value;
        return std::numeric_limits<double>::quiet_NaN();
    };
    const double before = valueAtZero();
    QVERIFY(relativelyEqual(before, pjoint::jacobian(p, 0.0)));

    p.b = 0.5 * p.a; // k = 0.5
    plots.setDesign(p);
    const double after = valueAtZero();
    QVERIFY(relativelyEqual(after, pjoint::jacobian(p, 0.0)));
    QVERIFY(std::abs(after - before) > 1.0); // 63.1 → 76.0 mm/rad
    QCOMPARE(plots.cursorTheta(), 20.0);
    for (int i = 0; i < plots.plotCount(); ++i)
        QVERIFY2(relativelyEqual(plots.cursorValue(i), expected(plots.plotName(i), p, 20.0 * degree)),
            qPrintable(plots.plotName(i)));
}

void TestPJointPlots::finiteNearSingularity_data()
{
    QTest::addColumn<double>("k");
    QTest::addColumn<double>("thetaMin");
    QTest::addColumn<double>("thetaMax");
    QTest::newRow("k 0.4, ±89°") << 0.4 << -89.0 << 89.0;
    QTest::newRow("k 0.4, -89…0°") << 0.4 << -89.0 << 0.0;
    QTest::newRow("k 0.3, 0…89°") << 0.3 << 0.0 << 89.0;
    QTest::newRow("k 1.0, ±89°") << 1.0 << -89.0 << 89.0;
    QTest::newRow("k 1.5, ±89°") << 1.5 << -89.0 << 89.0;
    QTest::newRow("k 0.4, 85…89°") << 0.4 << 85.0 << 89.0;
}

void TestPJointPlots::finiteNearSingularity()
{
    QFETCH(double, k);
    QFETCH(double, thetaMin);
    QFETCH(double, thetaMax);
    PJointDesign p = prototype();
    p.b = k * p.a;
    p.thetaMin = thetaMin * degree;
    p.thetaMax = thetaMax * degree;
    PJointPlots plots;
    plots.setDesign(p);
    plots.setTheta(thetaMax * degree);

    for (int i = 0; i < plots.plotCount(); ++i) {
        QCustomPlot *plot = plots.plot(i);
        const QCPRange y = plot->yAxis->range();
        QVERIFY(std::isfinite(y.lower) && std::isfinite(y.upper) && y.size() > 0.0);
        QVERIFY(std::isfinite(plots.cursorValue(i)));
        for (int g = 0; g < plot->graphCount(); ++g) {
            QVERIFY(plot->graph(g)->dataCount() > 0 || g > 0);
            for (const QCPGraphData &point : *plot->graph(g)->data()) {
                QVERIFY2(std::isfinite(point.key) && std::isfinite(point.value),
                    qPrintable(QStringLiteral("%1 graph %2 at %3°").arg(plots.plotName(i)).arg(g).arg(point.key)));
                QVERIFY(y.contains(point.value)); // clipped to the axis, also for SVG export
            }
        }
    }

    // J⁻¹ → ∞ at ±90° must not flatten the curve: its axis ends near the largest value over
    // |θ| ≤ 80° (plus the 8% headroom), not at J⁻¹(89°).
    if (thetaMin <= -80.0 && thetaMax >= 80.0) {
        const QCPRange y = plots.plot(plots.plotIndex(QStringLiteral("J_inv")))->yAxis->range();
        const double at80
            = std::max(1.0 / pjoint::jacobian(p, 80.0 * degree), 1.0 / pjoint::jacobian(p, -80.0 * degree));
        QVERIFY2(y.upper >= at80 && y.upper <= 1.1 * at80, qPrintable(QString::number(y.upper)));
        QVERIFY(y.upper < 1.0 / pjoint::jacobian(p, 89.0 * degree));
    }
}

void TestPJointPlots::hiddenTabCatchesUp()
{
    PJointPlots plots;
    plots.setDesign(prototype());
    plots.resize(1400, 900);
    plots.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plots));
    plots.tabs()->setCurrentIndex(0);
    QCoreApplication::processEvents();

    // On the visible tab a cursor move redraws the cursor layer only, never the whole plot.
    QCustomPlot *d = plots.plot(plots.plotIndex(QStringLiteral("d")));
    QSignalSpy fullReplots(d, &QCustomPlot::beforeReplot);
    plots.setTheta(-30.0 * degree);
    QCOMPARE(fullReplots.count(), 0);
    QVERIFY(redShareAt(d, -30.0) > 0.5);
    QVERIFY(redShareAt(d, 0.0) < 0.1);

    // The hidden actuator plots are not drawn, but show the current cursor when their tab opens.
    QCustomPlot *torque = plots.plot(plots.plotIndex(QStringLiteral("torque")));
    QSignalSpy hiddenReplots(torque, &QCustomPlot::beforeReplot);
    PJointDesign wider = prototype();
    wider.b = 0.45 * wider.a;
    plots.setDesign(wider);
    plots.setTheta(30.0 * degree);
    QCoreApplication::processEvents();
    QCOMPARE(hiddenReplots.count(), 0);
    plots.tabs()->setCurrentIndex(2);
    QTRY_VERIFY(hiddenReplots.count() > 0);
    QVERIFY(redShareAt(torque, 30.0) > 0.5);
    QVERIFY(redShareAt(torque, -30.0) < 0.1);

    // A cursor move alone, while hidden, is caught up without a full replot.
    plots.setTheta(-45.0 * degree);
    QCoreApplication::processEvents();
    fullReplots.clear();
    plots.tabs()->setCurrentIndex(0);
    QCoreApplication::processEvents();
    QVERIFY(redShareAt(d, -45.0) > 0.5);
    QVERIFY(redShareAt(d, 30.0) < 0.1);
    QCOMPARE(fullReplots.count(), 0);
}

void TestPJointPlots::transmissionBand()
{
    // Fig. 10 marks μ < 5° (force almost along the crank), not the four-bar's μ < 40°: with this
    // μ, μ ≤ arcsin k ≤ 30° for the preferred k ≤ 0.5, so a 40° band would cover every curve.
    PJointPlots plots;
    plots.setDesign(prototype());
    QCustomPlot *plot = plots.plot(PJointPlots::TransmissionAnglePlot);
    QList<QCPItemRect *> bands;
    for (int i = 0; i < plot->itemCount(); ++i)
        if (auto *band = qobject_cast<QCPItemRect *>(plot->item(i)))
            bands.append(band);
    QCOMPARE(bands.size(), 1);
    QCOMPARE(bands[0]->topLeft->typeY(), QCPItemPosition::ptPlotCoords);
    QCOMPARE(bands[0]->topLeft->value(), 5.0);
    QCOMPARE(bands[0]->bottomRight->value(), 0.0);

    bool labelled = false;
    for (int i = 0; i < plot->plottableCount(); ++i)
        labelled |= plot->plottable(i)->name().contains(QStringLiteral("μ < 5°"));
    QVERIFY(labelled);

    // The μ axis follows the curves (k = 0.5 peaks at arcsin 0.5 = 30°), no forced 40° in view.
    const QCPRange y = plot->yAxis->range();
    QCOMPARE(y.lower, 0.0);
    QVERIFY2(std::abs(y.upper - 30.0 * 1.08) < 0.1, qPrintable(QString::number(y.upper)));
}

void TestPJointPlots::computedCurvesStayInside_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<double>("k");
    QTest::addColumn<double>("thetaMin");
    QTest::addColumn<double>("thetaMax");
    for (int i = 0; i < pjointcurves::quantityCount; ++i) {
        const char *name = pjointcurves::quantities[size_t(i)].name;
        QTest::addRow("%s, k 0.4, ±89°", name) << i << 0.4 << -89.0 << 89.0;
        QTest::addRow("%s, k 0.4, 85…89°", name) << i << 0.4 << 85.0 << 89.0;
        QTest::addRow("%s, k 1.0, −89.99…89.99°", name) << i << 1.0 << -89.99 << 89.99;
        QTest::addRow("%s, k 0.4, 30…30°", name) << i << 0.4 << 30.0 << 30.0;
    }
}

void TestPJointPlots::computedCurvesStayInside()
{
    QFETCH(int, index);
    QFETCH(double, k);
    QFETCH(double, thetaMin);
    QFETCH(double, thetaMax);
    PJointDesign p = prototype();
    p.b = k * p.a;
    p.thetaMin = thetaMin * degree;
    p.thetaMax = thetaMax * degree;
    const pjointcurves::Plot plot = pjointcurves::compute(p, index);

    QVERIFY(std::isfinite(plot.theta.lower) && std::isfinite(plot.theta.upper));
    QVERIFY(plot.theta.upper - plot.theta.lower >= 0.5);
    QVERIFY(std::isfinite(plot.value.lower) && std::isfinite(plot.value.upper));
    QVERIFY(plot.value.lower < plot.value.upper);
    QVERIFY(!plot.design.empty());
    QCOMPARE(plot.extension.empty(), !pjointcurves::hasExtension(pjointcurves::quantities[size_t(index)]));
    QCOMPARE(int(plot.family.size()), pjointcurves::quantities[size_t(index)].familySize);

    std::vector<const pjointcurves::Curve *> curves {&plot.design, &plot.extension};
    for (const pjointcurves::Curve &curve : plot.family)
        curves.push_back(&curve);
    for (const pjointcurves::Curve *curve : curves) {
        for (size_t i = 0; i < curve->size(); ++i) {
            const pjointcurves::Point &point = (*curve)[i];
            QVERIFY2(std::isfinite(point.theta) && std::isfinite(point.value),
                qPrintable(QStringLiteral("at %1°").arg(point.theta)));
            QVERIFY(point.theta >= plot.theta.lower - 1e-9 && point.theta <= plot.theta.upper + 1e-9);
            QVERIFY(point.value >= plot.value.lower && point.value <= plot.value.upper);
            QVERIFY(i == 0 || point.theta >= (*curve)[i - 1].theta); // QCP is told it is sorted
        }
    }
}

void TestPJointPlots::clipEndsAtTheEdge()
{
    using pjointcurves::Point;
    const pjointcurves::Curve peak {{0.0, 0.0}, {1.0, 2.0}, {2.0, 4.0}, {3.0, 2.0}, {4.0, 0.0}};
    const pjointcurves::Curve clipped = pjointcurves::clip(peak, 0.0, 3.0);
    const std::vector<std::pair<double, double>> wanted {
        {0.0, 0.0}, {1.0, 2.0}, {1.5, 3.0}, {2.5, 3.0}, {3.0, 2.0}, {4.0, 0.0}};
    QCOMPARE(clipped.size(), wanted.size());
    for (size_t i = 0; i < wanted.size(); ++i) {
        QCOMPARE(clipped[i].theta, wanted[i].first);
        QCOMPARE(clipped[i].value, wanted[i].second);
    }
    // Below the axis, entering it: the curve starts exactly at the lower edge.
    const pjointcurves::Curve rising = pjointcurves::clip({{0.0, -1.0}, {1.0, 1.0}}, 0.0, 3.0);
    QCOMPARE(rising.size(), size_t(2));
    QCOMPARE(rising[0].theta, 0.5);
    QCOMPARE(rising[0].value, 0.0);
    QVERIFY(pjointcurves::clip({{0.0, 5.0}, {1.0, 6.0}}, 0.0, 3.0).empty());
}

void TestPJointPlots::valueRangeSkipsNearSingularSamples()
{
    // 1/cos θ: the sample at 89° (57.3) must not stretch the axis set by |θ| ≤ 80° (5.76).
    pjointcurves::Curve curve;
    for (const double t : {-80.0, 0.0, 80.0, 89.0})
        curve.push_back({t, 1.0 / std::cos(t * degree)});
    const double at80 = 1.0 / std::cos(80.0 * degree);
    const pjointcurves::Range guarded = pjointcurves::valueRange({&curve}, 80.0);
    QVERIFY(std::abs(guarded.upper - (at80 + 0.08 * (at80 - 1.0))) < 1e-9);
    QVERIFY(std::abs(guarded.lower - (1.0 - 0.08 * (at80 - 1.0))) < 1e-9);
    const pjointcurves::Range open = pjointcurves::valueRange({&curve}, std::numeric_limits<double>::infinity());
    QVERIFY(open.upper > 57.0);
    // Nothing inside the guard: all samples count.
    const pjointcurves::Curve beyond {{85.0, 2.0}, {89.0, 4.0}};
    const pjointcurves::Range fallback = pjointcurves::valueRange({&beyond}, 80.0);
    QVERIFY(fallback.lower < 2.0 && fallback.upper > 4.0);
    // Positive values never get a negative axis from the headroom.
    const pjointcurves::Curve positive {{0.0, 0.1}, {1.0, 10.0}};
    QCOMPARE(pjointcurves::valueRange({&positive}, 80.0).lower, 0.0);
}

void TestPJointPlots::valueText()
{
    const QLocale saved;
    QLocale::setDefault(QLocale::c());
    QCOMPARE(pjointcurves::valueText(PJointPlots::TransmissionAnglePlot, 21.84), QStringLiteral("μ = 21.8°"));
    QCOMPARE(pjointcurves::valueText(PJointPlots::DiagonalPlot, 183.14), QStringLiteral("d = 183.1 mm"));
    QCOMPARE(
        pjointcurves::valueText(PJointPlots::InverseJacobianPlot, 0.0123456), QStringLiteral("J⁻¹ = 0.0123 rad/mm"));
    QCOMPARE(pjointcurves::valueText(PJointPlots::SpeedPlot, std::numeric_limits<double>::infinity()),
        QStringLiteral("dθ/dt = ∞ rad/s"));
    QLocale::setDefault(saved);
}

// A subtitle wider than its plot is broken into lines, at "; " where that is enough, and joins
// again when the plot grows; every line fits, so no end is cut off.
void TestPJointPlots::subtitleWrapsInANarrowPlot()
{
    QCustomPlot plot;
    plot.resize(260, 300);
    auto *subtitle = new QCPTextElement(&plot, QString());
    plot.plotLayout()->insertRow(0);
    plot.plotLayout()->addElement(0, 0, subtitle);
    const QString text = QStringLiteral("a = 170 mm, k = 0.40, θ −60°…60°; family at the same a");
    const QFontMetrics metrics(subtitle->font());
    QVERIFY(metrics.horizontalAdvance(text) > 260 - 16);
    plotstyle::setFittedText(subtitle, text);
    // shown as read: no break around '=' (a no-break space) nor after '/' (a word joiner)
    const auto shown = [subtitle] { return subtitle->text().replace(QChar(0x00A0), QLatin1Char(' ')).remove(QChar(0x2060)); };
    QVERIFY(subtitle->text().contains(QStringLiteral("k\u00A0=\u00A00.40")));
    QCOMPARE(shown(), QStringLiteral("a = 170 mm, k = 0.40, θ −60°…60°;\nfamily at the same a"));
    plot.resize(160, 300); // narrower still: between words
    plotstyle::fitText(subtitle);
    const QStringList lines = shown().split(QLatin1Char('\n'));
    QVERIFY(lines.size() >= 3);
    for (const QString &line : lines)
        QVERIFY2(metrics.horizontalAdvance(line) <= 160 - 16, qPrintable(line));
    QCOMPARE(lines.join(QLatin1Char(' ')), text);
    plot.resize(1200, 300);
    plotstyle::fitText(subtitle);
    QCOMPARE(subtitle->text(), text);
}

void TestPJointPlots::cursorLabelStaysWholeInANarrowPlot()
{
    // The Geometry tab as a projector at 1280×720 shows it (560×600, fig. 8's axis rect under
    // 200 px wide): with the cursor near the middle, the label beside the marker ran past the
    // axis rect, which cut it off ("d = 183.1" without its unit).
    PJointPlots plots;
    plots.resize(560, 600);
    plots.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plots));
    plots.setDesign(prototype());
    int checked = 0;
    for (const double theta : {-60.0, -30.0, -2.0, 0.0, 0.05, 2.0, 30.0, 60.0}) {
        plots.setTheta(theta * degree);
        for (int i = 0; i < plots.plotCount(); ++i) {
            QCustomPlot *plot = plots.plot(i);
            if (!plot->isVisible())
                continue; // on another tab
            plot->replot(); // lays the plot out; the label is placed again before it is drawn
            const auto labels = cursorItems<QCPItemText>(plot);
            QCOMPARE(labels.size(), 1);
            const QRectF label = QRectF(labels[0]->topLeft->pixelPosition(), labels[0]->bottomRight->pixelPosition()).normalized();
            const QRectF rect = plot->axisRect()->rect();
            if (rect.width() < label.width() + 4)
                continue; // no room for it anywhere
            QVERIFY2(rect.contains(label),
                qPrintable(QStringLiteral("θ = %1°, %2: label %3 at x %4…%5 outside the axis rect x %6…%7")
                               .arg(theta).arg(plots.plotName(i), labels[0]->text()).arg(label.left()).arg(label.right())
                               .arg(rect.left()).arg(rect.right())));
            ++checked;
        }
    }
    QVERIFY(checked >= 16);
}

void TestPJointPlots::thetaTicksNeverCrowd()
{
    // θ from −90° to 90°: the step leaves every label ("−60°", ~34 px) at least 44 px, so a
    // plot 150 px wide (figs 9 and 10 on a projector) gets 45° steps, not 30° ones that overlap.
    QCOMPARE(pjointcurves::thetaStep(180, 800), 15.0);
    QCOMPARE(pjointcurves::thetaStep(180, 400), 30.0);
    QCOMPARE(pjointcurves::thetaStep(180, 200), 45.0);
    QCOMPARE(pjointcurves::thetaStep(180, 120), 90.0);
    for (int pixels = 80; pixels <= 1200; pixels += 10) {
        const double step = pjointcurves::thetaStep(180, pixels);
        QVERIFY2(step == 90.0 || pixels * step / 180 >= 44.0, qPrintable(QString::number(pixels)));
    }
    QCOMPARE(pjointcurves::thetaStep(30, 100), 5.0);
    // twice the text (presentation mode): twice the room a step
    QCOMPARE(pjointcurves::thetaStep(180, 400, 68.0), 45.0);
    for (int pixels = 80; pixels <= 1200; pixels += 10) {
        const double step = pjointcurves::thetaStep(180, pixels, 68.0);
        QVERIFY2(step == 90.0 || pixels * step / 180 >= 78.0, qPrintable(QString::number(pixels)));
    }
}

QTEST_MAIN(TestPJointPlots)
#include "tst_pjointplots.moc"
