// The four-bar in the main window, as the user does it: open fourbar-example from the
// Presets menu, drag a link-length slider (one undo step), try a length that cannot close the
// loop, read δ(α), ω₃, ε₃ and γ off the plots (figs. 4 and 6) and the largest crank off the
// sweep (fig. 5), see the transmission warning, and push α against its assembly limit.
#include "gui/mainwindow.h"

#include "document/document.h"
#include "kinds/fourbar/fourbar.h"
#include "kinds/fourbar/fourbarpanel.h"
#include "kinds/fourbar/fourbarplots.h"
#include "kinds/oxglide/oxglidepanel.h"
#include "kinds/pjoint/pjointplots.h"
#include "variablepanel.h"
#include "kinds/workspacepanel.h"
#include "support/app.h"
#include "support/process.h"

#include <qcustomplot.h>

#include <QAction>
#include <QDoubleSpinBox>
#include <QJsonObject>
#include <QLabel>
#include <QSlider>
#include <QStackedWidget>
#include <QStatusBar>
#include <QStyleOptionSlider>
#include <QTabWidget>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace pkm;
using namespace pkm::test;

namespace {
constexpr double degree = std::numbers::pi / 180.0;

/// The centre of a slider's handle, and the pixel of a value on its groove.
QPointF handleCentre(QSlider *slider)
{
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = slider->orientation();
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    return QRectF(slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider))
        .center();
}

/// The value of a graph at exactly `key`, NaN if there is no such sample.
double valueAtKey(QCPGraph *graph, double key)
{
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it) {
        if (std::abs(it->key - key) < 1e-9)
            return it->value;
    }
    return std::nan("");
}

const FourBar &fourbarOf(const MainWindow &w)
{
    return dynamic_cast<const FourBar &>(*w.document()->mechanism());
}

/// AB = AD·cos α + √((BC + CD)² − AD²·sin²α): |BD| = BC + CD, the loop just closes.
double closedFormLargestCrank(const FourBarDesign &d, double alpha)
{
    const double reach = d.coupler + d.rocker;
    return d.ground * std::cos(alpha) + std::sqrt(reach * reach - std::pow(d.ground * std::sin(alpha), 2));
}
} // namespace

class TestFourBarWindow : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;
    FourBarPanel *panel() const { return m_window->kindPanel<FourBarPanel>(); }
    FourBarPlots *plots() const { return panel()->plots(); }
    Document *document() const { return m_window->document(); }
    const Pose &pose() const { return document()->pose(); }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1800, 1000});
        QVERIFY(m_window);
    }

    void cleanupTestCase() { delete m_window; }

    void opensFromPresetMenu()
    {
        QAction *preset = m_window->findChild<QAction *>(QStringLiteral("preset_fourbar-example"));
        QVERIFY(preset);
        preset->trigger();
        QCOMPARE(document()->mechanism()->kind(), std::string_view("fourbar"));
        QVERIFY(panel()->isVisible());
        QVERIFY(!m_window->kindPanel<PJointPlots>()->isVisible());
        QVERIFY(!m_window->workspacePanel()->isVisible());
        QVERIFY(!m_window->kindPanel<OxGlidePanel>()->isVisible());
        // the preset's links on the sliders and in the spin boxes
        QCOMPARE(panel()->lengthSpinBox(QStringLiteral("AB"))->value(), 40.0);
        QCOMPARE(panel()->lengthSlider(QStringLiteral("BC"))->value(), 120 * FourBarPanel::sliderScale);
        QCOMPARE(panel()->lengthSpinBox(QStringLiteral("AD"))->value(), 140.0);
        // Grashof in words with its numbers, and the assembly range of α
        const QString grashof = panel()->grashofLabel()->text().replace(QChar(0x00A0), QLatin1Char(' '));
        QVERIFY2(grashof.contains(QStringLiteral("Crank-rocker"))
                && grashof.contains(QStringLiteral("= 180 mm &lt; p + q"))
                && grashof.contains(QStringLiteral("= 220 mm")),
            qPrintable(grashof));
        QVERIFY2(panel()->rangeLabel()->text().contains(QStringLiteral("turns fully")),
            qPrintable(panel()->rangeLabel()->text()));
        QVERIFY(!panel()->limitLabel()->isVisible());
        QVERIFY(!panel()->transmissionWarning()); // 53°…110° over the motion
        QCOMPARE(plots()->cursorAlpha(), 60.0);
        // the instant centre P and the coupler curve are drawn in the linkage view
        const Scene scene = document()->mechanism()->scene(pose());
        QVERIFY(
            std::any_of(scene.joints.begin(), scene.joints.end(), [](const SceneJoint &j) { return j.label == "P"; }));
        QCOMPARE(scene.polylines.size(), std::size_t(1));
    }

    /// Presentation mode in Russian cut the title of fig. 6 on both sides ("— угловая скорость
    /// коромысла ω₃ ="): a plot's title breaks into lines as its subtitle does.
    void titlesBreakIntoLines()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        for (int i = 0; i < FourBarPlots::PlotCount; ++i) {
            QCustomPlot *plot = plots()->plot(i);
            // its tab in front: a hidden plot is laid out when it is shown
            for (QWidget *child = plot; child && child->parentWidget(); child = child->parentWidget()) {
                if (auto *stack = qobject_cast<QStackedWidget *>(child->parentWidget()))
                    stack->setCurrentWidget(child);
            }
            const QSize before = plot->size();
            plot->resize(260, plot->height());
            QCoreApplication::processEvents();
            for (QCPLayoutElement *element : plot->plotLayout()->elements(true)) {
                if (auto *title = qobject_cast<QCPTextElement *>(element)) {
                    const QFontMetrics metrics(title->font());
                    for (const QString &line : title->text().split(QLatin1Char('\n')))
                        QVERIFY2(metrics.horizontalAdvance(line) <= plot->width(),
                                 qPrintable(QStringLiteral("plot %1: '%2'").arg(i).arg(line)));
                }
            }
            plot->resize(before);
        }
        // the first tab in front again, as the window opened
        for (QWidget *child = plots()->plot(0); child && child->parentWidget(); child = child->parentWidget()) {
            if (auto *stack = qobject_cast<QStackedWidget *>(child->parentWidget()))
                stack->setCurrentWidget(child);
        }
    }

    void plotsHoldTheCurves()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        const FourBarDesign d = fourbarOf(*m_window).design();
        // fig. 4: δ(60°) is the CLI's δ at α = 60°
        const QJsonObject cli = pkmJson({QStringLiteral("eval"), QStringLiteral("fourbar-example"),
            QStringLiteral("--set"), QStringLiteral("alpha=60"), QStringLiteral("--json")});
        QVERIFY(!cli.isEmpty());
        const double cliDelta = cli.value(QStringLiteral("pose")).toObject().value(QStringLiteral("delta")).toDouble();
        QCPGraph *delta = plots()->curve(FourBarPlots::DeltaPlot);
        QVERIFY2(std::abs(valueAtKey(delta, 60.0) - cliDelta) < 1e-6,
            qPrintable(QStringLiteral("%1 vs %2").arg(valueAtKey(delta, 60.0)).arg(cliDelta)));
        QVERIFY(std::abs(plots()->cursorValue(FourBarPlots::DeltaPlot) - cliDelta) < 1e-6);
        // a full turn, sampled every degree, nothing missing
        QCOMPARE(delta->data()->size(), 361);
        QCOMPARE(delta->data()->constBegin()->key, 0.0);
        QCOMPARE((delta->data()->constEnd() - 1)->key, 360.0);

        // fig. 6: ω₃ and ε₃ are fourbar::motion's, and the derivatives of the δ curve
        QCPGraph *omega = plots()->curve(FourBarPlots::Omega3Plot);
        QCPGraph *epsilon = plots()->curve(FourBarPlots::Epsilon3Plot);
        QCPGraph *gamma = plots()->curve(FourBarPlots::GammaPlot);
        const double h = 1.0 * degree;
        double largest = 0.0;
        for (double key : {10.0, 60.0, 90.0, 135.0, 200.0, 270.0, 330.0}) {
            const double alpha = key * degree;
            Coordinates inputs(1);
            inputs << alpha;
            const auto solved = document()->mechanism()->solveDirect(inputs);
            QVERIFY(solved.ok());
            const fourbar::Motion m = fourbar::motion(d, alpha, solved->outputs[0], d.omega1);
            QVERIFY(std::abs(valueAtKey(omega, key) - m.omega3) < 1e-9 * std::max(1.0, std::abs(m.omega3)));
            QVERIFY(std::abs(valueAtKey(epsilon, key) - m.epsilon3) < 1e-9 * std::max(1.0, std::abs(m.epsilon3)));
            const double gammaExpected = fourbar::angles(d, alpha, solved->outputs[0]).gamma / degree;
            QVERIFY(std::abs(valueAtKey(gamma, key) - gammaExpected) < 1e-9);
            // central differences of the plotted δ (°) at constant ω₁
            const double before = valueAtKey(delta, key - 1.0) * degree, here = valueAtKey(delta, key) * degree,
                         after = valueAtKey(delta, key + 1.0) * degree;
            const double omegaFd = d.omega1 * (after - before) / (2.0 * h);
            const double epsilonFd = d.omega1 * d.omega1 * (after - 2.0 * here + before) / (h * h);
            QVERIFY2(std::abs(omegaFd - m.omega3) < 2e-3 * std::max(1.0, std::abs(m.omega3)),
                qPrintable(QStringLiteral("ω₃ at %1°: %2 vs %3").arg(key).arg(omegaFd).arg(m.omega3)));
            QVERIFY2(std::abs(epsilonFd - m.epsilon3) < 5e-3 * std::max(10.0, std::abs(m.epsilon3)),
                qPrintable(QStringLiteral("ε₃ at %1°: %2 vs %3").arg(key).arg(epsilonFd).arg(m.epsilon3)));
            largest = std::max(largest, std::abs(m.epsilon3));
        }
        QVERIFY(largest > 10.0); // ω₁ = 10 rad/s: tens of rad/s²
        // no NaN in a curve of a crank-rocker, and every value inside its plot's y range
        for (int i = FourBarPlots::DeltaPlot; i <= FourBarPlots::GammaPlot; ++i) {
            const QCPRange range = plots()->plot(i)->yAxis->range();
            for (auto it = plots()->curve(i)->data()->constBegin(); it != plots()->curve(i)->data()->constEnd(); ++it) {
                QVERIFY(std::isfinite(it->value));
                QVERIFY2(range.contains(it->value), qPrintable(QStringLiteral("plot %1 at %2°").arg(i).arg(it->key)));
            }
        }
    }

    void sweepMarksTheLargestCrank()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        for (double alphaDegrees : {60.0, 150.0}) {
            QVERIFY(document()->setVariable(FourBar::variableAlpha, alphaDegrees * degree).ok());
            const FourBarDesign d = fourbarOf(*m_window).design();
            const double alpha = pose().inputs[0];
            const double expected = closedFormLargestCrank(d, alpha);
            QVERIFY2(std::abs(plots()->largestCrankMarker() - expected) < 1e-9,
                qPrintable(QStringLiteral("%1 vs %2").arg(plots()->largestCrankMarker()).arg(expected)));
            // and it is the limit: a crank a little shorter assembles at α, a little longer does not
            for (const auto &[factor, assembles] : {std::pair {1.0 - 1e-6, true}, std::pair {1.0 + 1e-6, false}}) {
                auto made = FourBar::createFrom(
                    {{"AB", expected * factor}, {"BC", d.coupler}, {"CD", d.rocker}, {"AD", d.ground}});
                Coordinates inputs(1);
                inputs << alpha;
                const bool solved = made.ok() && (*made)->solveDirect(inputs).ok();
                QCOMPARE(solved, assembles);
            }
            // the curve passes the current pose, stops at the marker, and the legend gives the value
            QCPGraph *sweep = plots()->curve(FourBarPlots::SweepPlot);
            QVERIFY(std::abs(valueAtKey(sweep, d.crank) - pose().outputs[0] / degree) < 1e-9);
            double lastFinite = 0.0;
            for (auto it = sweep->data()->constBegin(); it != sweep->data()->constEnd(); ++it) {
                if (std::isfinite(it->value))
                    lastFinite = it->key;
            }
            QCOMPARE(lastFinite, expected);
            QVERIFY(sweep->data()->size() > 200);
            QVERIFY((sweep->data()->constEnd() - 1)->key > expected); // drawn past the limit: a gap
            bool legend = false;
            QCustomPlot *plot = plots()->plot(FourBarPlots::SweepPlot);
            for (int g = 0; g < plot->graphCount(); ++g)
                legend = legend || plot->graph(g)->name().contains(QLocale().toString(expected, 'f', 1));
            QVERIFY(legend);
        }
        // this example's crank at α = 60°: 253.6 mm, |BD| = BC + CD there
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        QVERIFY(std::abs(plots()->largestCrankMarker() - (70.0 + std::sqrt(33700.0))) < 1e-9);
    }

    void draggingALinkIsOneUndoStep()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        QSlider *slider = panel()->lengthSlider(QStringLiteral("BC"));
        QVERIFY(slider && slider->isVisible());
        const int steps = document()->undoStack()->count();
        const QPointF from = handleCentre(slider);
        drag(slider, from, from + QPointF(slider->width() / 8.0, 0.0), 10);
        const double bc = fourbarOf(*m_window).design().coupler;
        QVERIFY2(bc > 125.0, qPrintable(QString::number(bc)));
        QCOMPARE(document()->undoStack()->count(), steps + 1);
        QCOMPARE(panel()->lengthSpinBox(QStringLiteral("BC"))->value(), bc);
        // the plots follow the design
        Coordinates inputs(1);
        inputs << 60.0 * degree;
        QVERIFY(std::abs(valueAtKey(plots()->curve(FourBarPlots::DeltaPlot), 60.0)
                    - document()->mechanism()->solveDirect(inputs)->outputs[0] / degree)
            < 1e-9);
        // one undo brings the whole drag back, and the controls with it (no new step)
        document()->undoStack()->undo();
        QCOMPARE(fourbarOf(*m_window).design().coupler, 120.0);
        QCOMPARE(slider->value(), 120 * FourBarPanel::sliderScale);
        QCOMPARE(panel()->lengthSpinBox(QStringLiteral("BC"))->value(), 120.0);
        QCOMPARE(document()->undoStack()->index(), steps);
        // a second drag of the same link is a step of its own
        drag(slider, handleCentre(slider), handleCentre(slider) - QPointF(slider->width() / 20.0, 0.0), 6);
        QVERIFY(fourbarOf(*m_window).design().coupler < 118.0);
        QCOMPARE(document()->undoStack()->index(), steps + 1);
        document()->undoStack()->undo();
        QCOMPARE(fourbarOf(*m_window).design().coupler, 120.0);
    }

    void impossibleLengthIsRefused()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        const ParameterSet before = document()->mechanism()->parameters();
        const int steps = document()->undoStack()->count();
        QDoubleSpinBox *spin = panel()->lengthSpinBox(QStringLiteral("AB"));
        spin->setValue(400.0); // longer than BC + CD + AD = 360 mm
        QVERIFY(document()->mechanism()->parameters() == before);
        QCOMPARE(document()->undoStack()->count(), steps);
        QVERIFY(panel()->linkMessage()->isVisible());
        const QString message = panel()->linkMessage()->text();
        QVERIFY2(
            message.startsWith(QStringLiteral("AB = 400")) && message.contains(QStringLiteral("cannot close the loop")),
            qPrintable(message));
        QVERIFY(m_window->lastStatus().contains(QStringLiteral("cannot close the loop")));
        QCOMPARE(spin->value(), 40.0); // the control went back
        QCOMPARE(panel()->lengthSlider(QStringLiteral("AB"))->value(), 40 * FourBarPanel::sliderScale);
        // a zero length: one clear message naming the link
        panel()->lengthSpinBox(QStringLiteral("CD"))->setValue(0.0);
        QVERIFY(document()->mechanism()->parameters() == before);
        QVERIFY2(panel()->linkMessage()->text().startsWith(QStringLiteral("CD")),
            qPrintable(panel()->linkMessage()->text()));
        QCOMPARE(panel()->lengthSpinBox(QStringLiteral("CD"))->value(), 100.0);
        // dragging AB out past the limit stops at the last length that closes the loop
        QSlider *slider = panel()->lengthSlider(QStringLiteral("AB"));
        const QPointF from = handleCentre(slider);
        drag(slider, from, QPointF(slider->width() - 2.0, from.y()), 40);
        const double ab = fourbarOf(*m_window).design().crank;
        QVERIFY2(ab > 300.0 && ab < 360.0, qPrintable(QString::number(ab)));
        QCOMPARE(slider->value(), int(std::lround(ab * FourBarPanel::sliderScale)));
        QCOMPARE(document()->undoStack()->count(), steps + 1);
        QVERIFY(panel()->linkMessage()->isVisible());
        // a valid change clears the message
        document()->undoStack()->undo();
        QVERIFY(document()->mechanism()->parameters() == before);
        QVERIFY(!panel()->linkMessage()->isVisible());
    }

    void transmissionWarning()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        // AB = 70 mm: cos γ = −0.004 + 0.817·cos α, so γ falls to 35.6° at α = 0°
        QVERIFY(document()->setParameter(QStringLiteral("AB"), 70.0).ok());
        QVERIFY(document()->setVariable(FourBar::variableAlpha, 90.0 * degree).ok());
        QVERIFY(!panel()->transmissionWarning());
        QVERIFY(!panel()->transmissionLabel()->text().contains(QStringLiteral("poor")));
        QVERIFY(document()->setVariable(FourBar::variableAlpha, 0.0).ok());
        QVERIFY(panel()->transmissionWarning());
        QVERIFY2(panel()->transmissionLabel()->text().contains(QStringLiteral("poor: below 40°")),
            qPrintable(panel()->transmissionLabel()->text()));
        QVERIFY(panel()->transmissionLabel()->styleSheet().contains(QStringLiteral("#b3261e")));
        QVERIFY(std::abs(panel()->transmissionGauge()->value() - std::acos(-0.004166666 + 9800.0 / 12000.0) / degree)
            < 0.01);
        // the design's own warning agrees
        const auto warnings = document()->mechanism()->designWarnings();
        QVERIFY(std::any_of(warnings.begin(), warnings.end(),
            [](const std::string &w) { return w.find("transmission angle falls") != std::string::npos; }));
        // the γ(α) plot dips into the shaded band
        QCPGraph *gamma = plots()->curve(FourBarPlots::GammaPlot);
        QVERIFY(valueAtKey(gamma, 0.0) < FourBar::poorTransmission);
        QVERIFY(valueAtKey(gamma, 90.0) > FourBar::poorTransmission);
    }

    void alphaStopsAtItsLimitWithTheReason()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        // AB = 130 mm: s + l = 100 + 140 < 130 + 120, the rocker CD is the shortest: the crank rocks
        QVERIFY(panel()->requestLength(QStringLiteral("AB"), 130.0, false));
        const FourBar &fourbar = fourbarOf(*m_window);
        QVERIFY(!fourbar.crankTurnsFully());
        QVERIFY(panel()->grashofLabel()->text().contains(QStringLiteral("Rocker-crank")));
        QVERIFY(panel()->rangeLabel()->text().contains(QStringLiteral("dead points")));
        const Interval range = fourbar.variableRange(FourBar::variableAlpha);
        // the α spin box of the variable panel, past the upper limit
        QDoubleSpinBox *alpha = m_window->variablePanel()->spinBox(FourBar::variableAlpha);
        alpha->setValue(range.max / degree + 20.0);
        QVERIFY(std::abs(pose().inputs[0] - range.max) < 1e-9);
        QVERIFY(panel()->limitLabel()->isVisible());
        QVERIFY2(panel()->limitLabel()->text().contains(QStringLiteral("upper limit"))
                && panel()->limitLabel()->text().contains(QStringLiteral("dead point")),
            qPrintable(panel()->limitLabel()->text()));
        QTRY_VERIFY2(m_window->lastStatus().contains(QStringLiteral("dead point")), qPrintable(m_window->lastStatus()));
        QVERIFY(m_window->lastStatus().startsWith(QStringLiteral("α stops at its upper limit")));
        QCOMPARE(m_window->statusBar()->currentMessage(), m_window->lastStatus());
        // the solver past the limit, directly: refused with the same reason
        QVERIFY(
            !document()->setVariable(FourBar::variableAlpha, range.min - 1.0).ok() || pose().inputs[0] == range.min);
        QVERIFY(std::abs(pose().inputs[0] - range.min) < 1e-9);
        QTRY_VERIFY(m_window->lastStatus().startsWith(QStringLiteral("α stops at its lower limit")));
        // the plots span exactly the assembly range, and the curves exist over all of it
        QCustomPlot *plot = plots()->plot(FourBarPlots::DeltaPlot);
        QVERIFY(std::abs(plot->xAxis->range().lower - range.min / degree) < 1e-6);
        QVERIFY(std::abs(plot->xAxis->range().upper - range.max / degree) < 1e-6);
        int finite = 0;
        for (auto it = plots()->curve(FourBarPlots::DeltaPlot)->data()->constBegin();
             it != plots()->curve(FourBarPlots::DeltaPlot)->data()->constEnd(); ++it)
            finite += std::isfinite(it->value) ? 1 : 0;
        QVERIFY(finite >= 360);
        // back inside: the note goes
        QVERIFY(document()->setVariable(FourBar::variableAlpha, 0.5 * (range.min + range.max)).ok());
        QVERIFY(!panel()->limitLabel()->isVisible());
    }

    void clickOnTheDeltaPlotSetsAlpha()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        QCustomPlot *plot = plots()->plot(FourBarPlots::DeltaPlot);
        plots()->tabs()->setCurrentIndex(0);
        QVERIFY(plot->isVisible());
        plot->replot();
        const double y = plot->yAxis->coordToPixel(plot->yAxis->range().center());
        QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, QPoint(int(plot->xAxis->coordToPixel(120.0)), int(y)));
        const double pixel = plot->xAxis->range().size() / plot->axisRect()->width();
        QVERIFY2(std::abs(pose().inputs[0] / degree - 120.0) <= pixel + 1e-9,
            qPrintable(QString::number(pose().inputs[0] / degree)));
        QCOMPARE(plots()->cursorAlpha(), pose().inputs[0] / degree);
    }
};

QTEST_MAIN(TestFourBarWindow)
#include "tst_fourbarwindow.moc"
