// The combo boxes that offer symbols (Play's variable, the sweep plot's quantity, the video's
// variable and plot) draw them lowered, as the values panel and the equations do: a projected
// "x_AB" reads as x with a small AB, in the field and in the list. Number fields show a
// negative number with the typographic minus, as the panels beside them do, and take a typed
// "-" or "−".

#include "plotstyle.h"
#include "symboltext.h"

#include <QApplication>
#include <QComboBox>
#include <QImage>
#include <QKeyEvent>
#include <QListView>
#include <QStandardItemModel>
#include <QTest>

#include <utility>

using namespace pkm;

namespace {
/// What `combo` shows, as a person sees it.
QImage shot(QComboBox &combo)
{
    combo.resize(220, combo.sizeHint().height());
    return combo.grab().toImage().convertToFormat(QImage::Format_RGB32);
}

/// The columns in which `image` has ink darker than its middle grey, left to right.
int inkColumns(const QImage &image)
{
    int columns = 0;
    for (int x = 0; x < image.width(); ++x) {
        for (int y = 0; y < image.height(); ++y) {
            if (qGray(image.pixel(x, y)) < 96) {
                ++columns;
                break;
            }
        }
    }
    return columns;
}
} // namespace

class TestSymbolText : public QObject
{
    Q_OBJECT

private slots:
    void fieldIsLowered()
    {
        // a symbol: drawn apart from the plain combo box, and the field keeps the notation
        SymbolComboBox lowered;
        QComboBox plain;
        for (QComboBox *combo : {static_cast<QComboBox *>(&lowered), &plain})
            combo->addItems({QStringLiteral("x_AB — rod joint A, B"), QStringLiteral("θ — input angle")});
        QCOMPARE(lowered.currentText(), QStringLiteral("x_AB — rod joint A, B"));
        const QImage withSymbol = shot(lowered);
        QVERIFY(withSymbol != shot(plain));
        // the '_' is gone and the subscript is smaller: the lowered text is narrower
        QCOMPARE_LT(inkColumns(withSymbol), inkColumns(shot(plain)));
        QCOMPARE_GT(inkColumns(withSymbol), inkColumns(shot(plain)) / 2); // and still there, whole

        // a text without '_' is the style's own drawing, pixel for pixel
        lowered.setCurrentIndex(1);
        plain.setCurrentIndex(1);
        QCOMPARE(shot(lowered), shot(plain));
    }

    void listIsLowered()
    {
        SymbolComboBox combo;
        combo.addItems({QStringLiteral("x_AB"), QStringLiteral("x_CD")});
        QVERIFY(dynamic_cast<SymbolDelegate *>(combo.itemDelegate()));
        QVERIFY(dynamic_cast<SymbolDelegate *>(combo.view()->itemDelegate()));
    }

    void plotTitlesAreLowered()
    {
        // a plot's title: "T_M" lowered as in the panels, a text without '_' as QCustomPlot draws it
        const auto picture = [](bool lowered, const QString &text) {
            QCustomPlot plot;
            plot.resize(320, 120);
            plot.plotLayout()->clear();
            const QFont font = QApplication::font();
            QCPTextElement *title = lowered ? plotstyle::newTextElement(&plot, font) : new QCPTextElement(&plot, QString(), font);
            title->setText(text);
            plot.plotLayout()->addElement(0, 0, title);
            plot.replot();
            return plot.toPixmap(320, 120).toImage();
        };
        const QString symbol = QStringLiteral("motor torque T_M = 0.131 N·m");
        QVERIFY(picture(true, symbol) != picture(false, symbol));
        QCOMPARE_LT(inkColumns(picture(true, symbol)), inkColumns(picture(false, symbol))); // no '_'
        const QString plain = QStringLiteral("output torque T = J·F");
        QCOMPARE(picture(true, plain), picture(false, plain));
    }

    void elidedStaysLowered()
    {
        // a narrow field ends the text in "…" and keeps the lowered symbol before it
        const QFont font = QApplication::font();
        const QString text = QStringLiteral("x_AB against θ — the rod joint of the upper pair");
        const QString shown = symbolHtmlElided(text, font, 120);
        QVERIFY2(shown.startsWith(QStringLiteral("x<sub>AB</sub>")) && shown.endsWith(QChar(0x2026)), qPrintable(shown));
    }

    /// MOMA's y = −261.50 mm: the field showed "-261.50 mm" under a range that reads
    /// "−359.5 mm".
    void spinBoxShowsTypographicMinus()
    {
        NumberSpinBox box;
        box.setRange(-400.0, 400.0);
        box.setDecimals(2);
        box.setSuffix(QStringLiteral(" mm"));
        box.setValue(-261.5);
        QCOMPARE(box.text(), QStringLiteral("\u2212261.50 mm"));
        QVERIFY(!box.text().contains(QLatin1Char('-')));
        box.show();
        QVERIFY(QTest::qWaitForWindowExposed(&box));
        // typed with the keyboard's "-", or pasted with "−": both are read, and shown with "−"
        for (const auto &[typed, value] : {std::pair {QStringLiteral("-12.5"), -12.5}, std::pair {QStringLiteral("\u221237.25"), -37.25}}) {
            box.selectAll();
            for (const QChar c : typed) { // QTest::keyClicks() types ASCII only
                QKeyEvent press(QEvent::KeyPress, Qt::Key_unknown, Qt::NoModifier, QString(c));
                QApplication::sendEvent(&box, &press);
            }
            QTest::keyClick(&box, Qt::Key_Return);
            QCOMPARE(box.value(), value);
            QVERIFY2(box.text().startsWith(QChar(0x2212)), qPrintable(box.text()));
        }
        // the arrows step through zero and back
        box.setValue(0.5);
        box.setSingleStep(1.0);
        box.stepDown();
        QCOMPARE(box.text(), QStringLiteral("\u22120.50 mm"));
        box.stepUp();
        QCOMPARE(box.value(), 0.5);
    }
};

QTEST_MAIN(TestSymbolText)
#include "tst_symboltext.moc"
