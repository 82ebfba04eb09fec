// Plot texts: the pose cursor's value box on a plot (plotstyle::placeCursorLabel): whole wherever the
// marker is, in a plot as narrow as the Actuator tab's figures on a 1280×720 projector, where
// "Δθ = 0.0291 °/step" is wider than the axis rectangle and lost its end to the clip (a plot
// 220 px wide fails without the fix). There it takes two lines, the unit on the second, and
// stays inside the axis rectangle rather than cover the tick labels and the axis title.
#include "plotstyle.h"
#include "plotticker.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QTest>

#include <cmath>
#include <memory>

using namespace pkm;

class TestPlotCursor : public QObject
{
    Q_OBJECT

private:
    /// A plot `width` px wide with a rising curve over θ −60…60°, its cursor showing `text`
    /// at θ = `at`; the label's box and the plot's rectangle, in the plot's pixels.
    static std::pair<QRectF, QRectF> placed(int width, const QString &text, double at, bool *clipped, QString *shown = nullptr)
    {
        auto plot = std::make_unique<QCustomPlot>();
        plot->resize(width, 240);
        plot->show(); // a hidden plot keeps its first viewport
        if (!QTest::qWaitForWindowExposed(plot.get()))
            return {};
        const plotstyle::Header header = plotstyle::apply(plot.get(), QApplication::font());
        QCPGraph *graph = plot->addGraph();
        QVector<double> x, y;
        for (int i = 0; i <= 120; ++i) {
            x << -60.0 + i;
            y << 0.01 + 0.02 * (i / 120.0) * (i / 120.0);
        }
        graph->setData(x, y);
        plot->xAxis->setRange(-60.0, 60.0);
        plot->yAxis->setRange(0.01, 0.03);
        const plotstyle::Cursor cursor = plotstyle::addCursor(plot.get(), QApplication::font(), header.cursorLayer);
        const double value = 0.01 + 0.02 * ((at + 60.0) / 120.0) * ((at + 60.0) / 120.0);
        cursor.marker->position->setCoords(at, value);
        cursor.label->setText(text);
        plot->replot(); // lays the plot out; the label is placed again then
        plotstyle::placeCursorLabel(plot.get(), cursor.label, at, value);
        plot->replot();
        *clipped = cursor.label->clipToAxisRect();
        if (shown)
            *shown = cursor.label->text();
        const QRectF box(cursor.label->topLeft->pixelPosition(), cursor.label->bottomRight->pixelPosition());
        const QRectF room = *clipped ? QRectF(plot->axisRect()->rect()) : QRectF(plot->viewport());
        return {box, room};
    }

private slots:
    void boxIsWhole_data()
    {
        QTest::addColumn<int>("width");
        QTest::addColumn<double>("at");
        for (int width : {220, 280, 420}) {
            for (double at : {-60.0, -20.0, 0.0, 40.0, 60.0})
                QTest::addRow("%d px, θ = %g°", width, at) << width << at;
        }
    }

    void boxIsWhole()
    {
        QFETCH(int, width);
        QFETCH(double, at);
        const QString text = QStringLiteral("Δθ = 0.0291 °/step");
        bool clipped = true;
        QString shown;
        const auto [box, room] = placed(width, text, at, &clipped, &shown);
        QVERIFY2(room.adjusted(-0.5, -0.5, 0.5, 0.5).contains(box),
            qPrintable(QStringLiteral("box %1…%2 × %3…%4 in %5…%6 × %7…%8 (%9)")
                           .arg(box.left()).arg(box.right()).arg(box.top()).arg(box.bottom())
                           .arg(room.left()).arg(room.right()).arg(room.top()).arg(room.bottom())
                           .arg(clipped ? QStringLiteral("clipped to the axis rect") : QStringLiteral("unclipped"))));
        // the box holds its text, on one line or two: nothing of it is drawn outside
        const QFontMetrics metrics(QApplication::font());
        QCOMPARE(QString(shown).replace(QLatin1Char('\n'), QLatin1Char(' ')), text);
        for (const QString &line : shown.split(QLatin1Char('\n')))
            QCOMPARE_GE(box.width(), 0.9 * metrics.horizontalAdvance(line));
        // in the narrowest plot it takes two lines and stays over the curve, off the ticks
        if (width == 220) {
            QVERIFY2(shown.contains(QLatin1Char('\n')) && clipped, qPrintable(shown));
        } else if (width == 420) {
            QCOMPARE(shown, text);
        }
    }

    /// The box hides none of the curve where a corner around the marker leaves it free: the
    /// four-bar's "δ = 79.5°" at α = 60°, past the peak of δ(α), lay on the falling curve.
    void boxKeepsOffTheCurve()
    {
        QCustomPlot plot;
        plot.resize(420, 380);
        plot.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plot));
        const plotstyle::Header header = plotstyle::apply(&plot, QApplication::font());
        QFont large = QApplication::font();
        large.setPointSizeF(large.pointSizeF() * 1.5);
        QCPGraph *graph = plot.addGraph();
        QVector<double> x, y;
        for (int i = 0; i <= 360; ++i) {
            x << i;
            y << 58.0 + 24.0 * std::sin((i + 45.0) * M_PI / 180.0); // a hump at 45°, as δ(α)
        }
        graph->setData(x, y);
        plot.xAxis->setRange(0.0, 360.0);
        plot.yAxis->setRange(30.0, 86.0);
        const plotstyle::Cursor cursor = plotstyle::addCursor(&plot, large, header.cursorLayer);
        const double at = 60.0, value = 58.0 + 24.0 * std::sin(105.0 * M_PI / 180.0);
        cursor.marker->position->setCoords(at, value);
        cursor.label->setText(QStringLiteral("δ = 79.5°"));
        plot.replot();
        plotstyle::placeCursorLabel(&plot, cursor.label, at, value);
        plot.replot();
        const QRectF box(cursor.label->topLeft->pixelPosition(), cursor.label->bottomRight->pixelPosition());
        for (int i = 0; i <= 360; ++i) {
            const QPointF point(plot.xAxis->coordToPixel(x[i]), plot.yAxis->coordToPixel(y[i]));
            QVERIFY2(!box.contains(point), qPrintable(QStringLiteral("the box hides the curve at %1°").arg(i)));
        }
    }

    /// A legend of two long entries and five short ones takes columns down the rows where two
    /// long ones side by side do not fit: fig. 8's seven rows left its curves 145 px at 1280×720.
    void legendFillsColumnsDown()
    {
        QCustomPlot plot;
        plotstyle::apply(&plot, QApplication::font());
        const QStringList names {QStringLiteral("this design (k = 0.40)"), QStringLiteral("beyond its θ range"),
                                 QStringLiteral("k = 0.3"), QStringLiteral("k = 0.4"), QStringLiteral("k = 0.5"),
                                 QStringLiteral("k = 1.0"), QStringLiteral("k = 1.5")};
        for (const QString &name : names)
            plot.addGraph()->setName(name);
        int longest = 0, shortest = 0;
        for (int j = 0; j < plot.legend->itemCount(); ++j) {
            const int width = plot.legend->item(j)->minimumOuterSizeHint().width();
            longest = j == 0 ? width : std::max(longest, width);
            shortest = j == 2 ? width : j > 2 ? std::max(shortest, width) : shortest;
        }
        // room for a long and a short column, not for two long ones
        const QMargins margins = plot.legend->margins();
        plot.resize(longest + plot.legend->columnSpacing() + shortest + margins.left() + margins.right() + 4, 400);
        QVERIFY(2 * longest + plot.legend->columnSpacing() + margins.left() + margins.right() > plot.width());
        const int height = plotstyle::layOutLegend(&plot);
        const int row = plot.legend->item(0)->minimumOuterSizeHint().height() + plot.legend->rowSpacing();
        QCOMPARE(height, 4 * row);
        QCOMPARE(plot.legend->fillOrder(), QCPLayoutGrid::foRowsFirst);
        QCOMPARE(plot.legend->wrap(), 4);
    }

    /// A figure's subtitle with θ̇ (fig. 12: "θ̇ = J⁻¹·ḋ") drew the combining dot apart from
    /// its θ, at the start of the title's line above; plot texts write dθ/dt instead.
    void noCombiningDotInPlotTexts()
    {
        QCustomPlot plot;
        plot.resize(400, 200);
        auto *subtitle = new QCPTextElement(&plot, QString());
        plotstyle::setFittedText(subtitle, QStringLiteral("θ̇ = J⁻¹·ḋ; ḋ_max = 50 mm/s"));
        QCOMPARE(subtitle->text().replace(QChar(0x00A0), QLatin1Char(' ')).remove(QChar(0x2060)),
            QStringLiteral("dθ/dt = J⁻¹·ḋ; ḋₘₐₓ = 50 mm/s"));
        QVERIFY(!subtitle->text().contains(QChar(0x0307)));
        delete subtitle;
    }

    /// The last tick label of the x axis is drawn whole: QCustomPlot leaves out a label the
    /// widget's edge would cut, and with large text the θ axis lost its 90°.
    void lastTickLabelHasRoom()
    {
        QCustomPlot plot;
        plot.resize(360, 240);
        plot.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plot));
        plotstyle::apply(&plot, QApplication::font());
        plotstyle::setLegendShown(&plot, false); // an empty legend would narrow its column
        QFont large = plot.xAxis->tickLabelFont();
        large.setPointSizeF(large.pointSizeF() * 2.5); // presentation mode's largest text
        plot.xAxis->setTickLabelFont(large);
        auto ticker = QSharedPointer<QCPAxisTickerFixed>::create(); // every 30°, as the П-joint's θ
        ticker->setTickStep(30.0);
        plot.xAxis->setTicker(ticker);
        plot.xAxis->setRange(-90.0, 90.0);
        plot.replot(); // the labels are known after a first layout
        plot.replot();
        const QString last = plot.xAxis->tickVectorLabels().last();
        const double half = 0.5 * QFontMetrics(plot.xAxis->tickLabelFont()).horizontalAdvance(last);
        QCOMPARE(plot.xAxis->tickVector().last(), 90.0);
        QVERIFY2(plot.axisRect()->rect().right() + half <= plot.viewport().right(),
                 qPrintable(QStringLiteral("“%1” needs %2 px right of the axis, has %3")
                                .arg(last).arg(half).arg(plot.viewport().right() - plot.axisRect()->rect().right())));
    }

    /// A short axis with large text still has two labelled ticks: the MOMA map's x axis in
    /// presentation mode, −95 … 95 mm, showed "0" alone.
    void aShortAxisKeepsTwoTicks()
    {
        QCustomPlot plot;
        plot.resize(150, 200);
        plot.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plot));
        plotstyle::apply(&plot, QApplication::font());
        plotstyle::setLegendShown(&plot, false);
        QFont large = plot.xAxis->tickLabelFont();
        large.setPointSizeF(large.pointSizeF() * 1.5);
        plot.xAxis->setTickLabelFont(large);
        plot.xAxis->setTicker(QSharedPointer<MinusTicker>::create(plot.xAxis));
        for (const auto &[lower, upper] : {std::pair(-95.0, 95.0), std::pair(-150.0, 250.0), std::pair(-320.0, -180.0)}) {
            plot.xAxis->setRange(lower, upper);
            plot.replot();
            plot.replot();
            QVERIFY2(plot.xAxis->tickVector().size() >= 2,
                     qPrintable(QStringLiteral("%1 … %2: ticks %3").arg(lower).arg(upper).arg(plot.xAxis->tickVectorLabels().join(u' '))));
        }
    }

    /// Small or large values share one power of ten: along the 3-R̲RR's det J scale the 'g'
    /// format had mixed "0.00015" with "5e−05"; the labels also keep their numbers' order.
    void tinyTicksShareAPowerOfTen()
    {
        QCustomPlot plot;
        plot.resize(200, 300);
        plotstyle::apply(&plot, QApplication::font());
        plot.yAxis->setTicker(QSharedPointer<MinusTicker>::create(plot.yAxis));
        plot.yAxis->setNumberFormat(QStringLiteral("gb"));
        plot.yAxis->setNumberPrecision(3);
        for (const double end : {1.5e-4, 4e-3, 2.5e6}) {
            plot.yAxis->setRange(-end, end);
            plot.replot();
            const QStringList labels = plot.yAxis->tickVectorLabels();
            const QVector<double> ticks = plot.yAxis->tickVector();
            QVERIFY(ticks.size() >= 3);
            const QString power = QStringLiteral("·10") + (end < 1.0 ? QStringLiteral("⁻") : QString());
            for (int i = 0; i < ticks.size(); ++i) {
                const QString &label = labels[i];
                QVERIFY2(!label.contains(u'e', Qt::CaseInsensitive) && (ticks[i] == 0.0 ? label == u"0" : label.contains(power)),
                         qPrintable(labels.join(u' ')));
                // the mantissa times the shared power is the tick
                const QString mantissa = label.section(QStringLiteral("·"), 0, 0).replace(QChar(0x2212), u'-');
                const int exponent = int(std::floor(std::log10(end)));
                QVERIFY(std::abs(mantissa.toDouble() * std::pow(10.0, exponent) - ticks[i]) <= 1e-9 * end);
            }
        }
        plot.yAxis->setRange(-120.0, 180.0); // ordinary numbers keep their own form
        plot.replot();
        QVERIFY(plot.yAxis->tickVectorLabels().contains(QStringLiteral("−100")));
    }
};

QTEST_MAIN(TestPlotCursor)
#include "tst_plotcursor.moc"
