// How a value reads on screen (widgets/quantityformat.h): the values panel, the Design panel's
// notes and the map titles all go through formatQuantity().
#include "plotstyle.h"
#include "quantityformat.h"
#include "units.h"

#include <QApplication>
#include <QFontMetrics>
#include <QLocale>
#include <QTest>

#include <limits>
#include <numbers>

using namespace pkm;

class TestQuantityFormat : public QObject
{
    Q_OBJECT

private slots:
    void ordinaryValues()
    {
        const QLocale c = QLocale::c();
        QCOMPARE(formatQuantity(1044.0307, units::millimetre, 2, c), QStringLiteral("1044.03 mm"));
        QCOMPARE(formatQuantity(-1e-14, units::millimetre, 2, c), QStringLiteral("0.00 mm")); // never "-0.00"
        QCOMPARE(formatQuantity(99999999.0, units::none, 1, c), QStringLiteral("99999999.0"));
        // a slider's limit is read, not typed: the minus sign, never a hyphen, in every language
        QCOMPARE(formatQuantity(-std::numbers::pi, units::angle, 1, c), QStringLiteral("−180.0°"));
        QCOMPARE(formatQuantity(-4.96184, units::none, 4, QLocale(QLocale::Russian)), QStringLiteral("−4,9618"));
        // det J at a direct singularity: zero, not a row of zeros that reads as a tiny value;
        // a pose's 0.00 mm keeps its two decimals, as its neighbours in the panel have them
        QCOMPARE(formatQuantity(0.0, units::none, 8, c), QStringLiteral("0"));
        QCOMPARE(formatQuantity(-3e-12, units::none, 8, c), QStringLiteral("0"));
        QCOMPARE(formatQuantity(2e-8, units::none, 8, c), QStringLiteral("0.00000002"));
        QCOMPARE(formatQuantity(0.0, units::millimetre, 2, c), QStringLiteral("0.00 mm"));
    }

    /// Close to a singular pose a quantity grows without bound: from 10⁸ up it reads in powers
    /// of ten, never as a row of digits (a four-bar a hair from its dead centre is
    /// 1.68·10¹² N·m/rad stiff); at the pose itself it is ∞, or — where undefined.
    void hugeValuesInPowersOfTen()
    {
        const QLocale c = QLocale::c();
        QCOMPARE(formatQuantity(1680358456697.0, units::none, 1, c), QStringLiteral("1.680·10¹²"));
        QCOMPARE(formatQuantity(-286313799.9, units::none, 1, c), QStringLiteral("−2.863·10⁸"));
        QCOMPARE(formatQuantity(9.99999e9, units::none, 1, c), QStringLiteral("1.000·10¹⁰")); // rounds up a power
        QCOMPARE(formatQuantity(1e8, units::millimetre, 2, c), QStringLiteral("1.000·10⁸ mm"));
        QCOMPARE(formatQuantity(std::numeric_limits<double>::infinity(), units::none, 1, c), QStringLiteral("∞"));
        QCOMPARE(formatQuantity(std::numeric_limits<double>::quiet_NaN(), units::none, 1, c), QStringLiteral("—"));
        // the locale's decimal sign, as everywhere else
        QCOMPARE(formatQuantity(1.5e9, units::none, 1, QLocale(QLocale::Russian)), QStringLiteral("1,500·10⁹"));
    }

    // One display rule for the notation's subscripts: lowered in rich text, Unicode subscript
    // letters in plain text only where each letter has one, never half.
    void subscripts()
    {
        QCOMPARE(symbolHtml(QStringLiteral("F_max")), QStringLiteral("F<sub>max</sub>"));
        QCOMPARE(symbolHtml(QStringLiteral("det J_q")), QStringLiteral("det J<sub>q</sub>"));
        QCOMPARE(symbolHtml(QStringLiteral("T_max₁")), QStringLiteral("T<sub>max</sub>₁"));
        QCOMPARE(symbolHtml(QStringLiteral("|Δx_L|")), QStringLiteral("|Δx<sub>L</sub>|"));
        QCOMPARE(symbolHtml(QStringLiteral("J_p = diag(2p_i − 2B_i)")),
                 QStringLiteral("J<sub>p</sub> = diag(2p<sub>i</sub> − 2B<sub>i</sub>)"));
        QCOMPARE(symbolHtml(QStringLiteral("a<b & _x")), QStringLiteral("a&lt;b &amp; _x")); // escaped; a lone '_' stays
        QCOMPARE(symbolHtml(QStringLiteral("one side")), QStringLiteral("one side"));
        QCOMPARE(symbolPlain(QStringLiteral("T = J·F_max, (13)")), QStringLiteral("T = J·Fₘₐₓ, (13)"));
        QCOMPARE(symbolPlain(QStringLiteral("ḋ = J·θ̇; ḋ_max")), QStringLiteral("ḋ = J·dθ/dt; ḋₘₐₓ"));
        // The screen's font draws no dot over θ or q (the export dialog's list showed
        // "ḋ = J·θ"): spelled out, with a power kept on the whole derivative.
        QCOMPARE(spelledDots(QStringLiteral("d̈ = J·θ̈ + (∂J/∂θ)·θ̇²")), QStringLiteral("d̈ = J·d²θ/dt² + (∂J/∂θ)·(dθ/dt)²"));
        QCOMPARE(spelledDots(QStringLiteral("q̇ = J·Ẋ, ẋ")), QStringLiteral("dq/dt = J·Ẋ, ẋ"));
        QCOMPARE(symbolHtml(QStringLiteral("θ̇ = ḋ_max / J")), QStringLiteral("dθ/dt = ḋ<sub>max</sub> / J"));
        QCOMPARE(coreLabel("Jacobian ḋ = J·θ̇"), QStringLiteral("Jacobian ḋ = J·dθ/dt"));
        QCOMPARE(symbolPlain(QStringLiteral("det J_q, x_AB")), QStringLiteral("det J_q, x_AB"));
        QCOMPARE(symbolPlain(QStringLiteral("m_inv and v_max₁")), QStringLiteral("mᵢₙᵥ and vₘₐₓ₁"));
    }

    // A sentence lowers only the symbols it is given, as whole words, the longest first.
    /// A formula in a wrapped text breaks nowhere: the Serbian Design panel showed "k = b/"
    /// over "a", a legend "(k" over "= 0,40)", MOMA's title "γ₂" over "= +5°".
    void formulasStayWhole()
    {
        QCOMPARE(unbreakable(QStringLiteral("ratio k = b/a")), QStringLiteral("ratio k\u00A0=\u00A0b/\u2060a"));
        QCOMPARE(unbreakable(QStringLiteral("1/2 and a / b")), QStringLiteral("1/\u20602 and a / b"));
        // a form's short name stays with its noun; other hyphens may still break
        QCOMPARE(unbreakable(QStringLiteral("прототип П-шарнира")), QStringLiteral("прототип П-\u2060шарнира"));
        QCOMPARE(unbreakable(QStringLiteral("the O-X glide, a 3-RPR")), QStringLiteral("the O-\u2060X glide, a 3-\u2060RPR"));
        QCOMPARE(unbreakable(QStringLiteral("four-bar, leg-built")), QStringLiteral("four-bar, leg-built"));
        QCOMPARE(unbreakable(QStringLiteral("· det J from")), QStringLiteral("· det\u00A0J from")); // a symbol, one word
        // a legend wrapped in a narrow plot keeps "(k = 0,40)" on one line
        const QFont font = QApplication::font();
        const QString legend = QStringLiteral("эта конструкция (k = 0,40)");
        const int width = QFontMetrics(font).horizontalAdvance(QStringLiteral("эта конструкция (k ="));
        const QStringList lines = plotstyle::wrapped(legend, font, width).split(QLatin1Char('\n'));
        QCOMPARE_GT(lines.size(), 1);
        QVERIFY2(lines.last().startsWith(QStringLiteral("(k")), qPrintable(lines.join(QStringLiteral(" | "))));
    }

    void knownSymbols()
    {
        const QStringList symbols {QStringLiteral("x_AB"), QStringLiteral("J_q"), QStringLiteral("det J_q"),
                                   QStringLiteral("θ"), QStringLiteral("θ_min")};
        QCOMPARE(symbolHtmlKnown(QStringLiteral("x_CD − x_AB = s, saved to my_x_AB.pkm"), symbols),
                 QStringLiteral("x_CD − x<sub>AB</sub> = s, saved to my_x_AB.pkm"));
        QCOMPARE(symbolHtmlKnown(QStringLiteral("det J_q = 0 & J_q < 1"), symbols),
                 QStringLiteral("det J<sub>q</sub> = 0 &amp; J<sub>q</sub> &lt; 1"));
        QCOMPARE(symbolHtmlKnown(QStringLiteral("θ_min > θ_minimum\nnext"), symbols),
                 QStringLiteral("θ<sub>min</sub> &gt; θ_minimum<br>next"));
        QCOMPARE(symbolHtmlKnown(QStringLiteral("x_AB"), {}), QStringLiteral("x_AB"));
    }
};

QTEST_MAIN(TestQuantityFormat)
#include "tst_quantityformat.moc"
