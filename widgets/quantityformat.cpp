#include "quantityformat.h"

#include "text.h"

#include <QCoreApplication>
#include <QLocale>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace pkm {

QString toQString(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString unitText(const Unit &unit)
{
    return coreLabel(unit.symbol);
}

QString coreLabel(std::string_view label)
{
    if (label.empty())
        return {};
    const std::string source(label);
    return spelledDots(QCoreApplication::translate("core", source.c_str()));
}

QString spelledDots(const QString &input)
{
    const QChar dot(0x0307), twoDots(0x0308);
    if (!input.contains(dot) && !input.contains(twoDots))
        return input;
    QString text;
    for (qsizetype i = 0; i < input.size(); ++i) {
        const QChar base = input[i];
        const QChar mark = i + 1 < input.size() ? input[i + 1] : QChar();
        const bool greek = base.unicode() >= 0x0370 && base.unicode() <= 0x03FF;
        if ((mark != dot && mark != twoDots) || !(greek || base == QLatin1Char('q'))) {
            text += base;
            continue;
        }
        const QString derivative = mark == dot ? QStringLiteral("d%1/dt").arg(base) : QStringLiteral("d²%1/dt²").arg(base);
        i += 1;
        // a power after it belongs to the whole derivative: (dθ/dt)²
        if (i + 1 < input.size() && QStringLiteral("²³").contains(input[i + 1]))
            text += QLatin1Char('(') + derivative + QLatin1Char(')');
        else
            text += derivative;
    }
    return text;
}

namespace {
/// "1.680·10¹²" in the locale's decimal point and minus sign.
QString powerOfTen(double value, const QLocale &locale)
{
    int exponent = int(std::floor(std::log10(std::abs(value))));
    double mantissa = value / std::pow(10.0, exponent);
    if (std::abs(std::round(mantissa * 1000.0) / 1000.0) >= 10.0) { // 9.9996 rounds up to 10.000
        mantissa /= 10.0;
        ++exponent;
    }
    static const char16_t superscripts[] = u"⁰¹²³⁴⁵⁶⁷⁸⁹";
    QString power;
    for (const QChar digit : QString::number(exponent))
        power += QChar(superscripts[digit.digitValue()]);
    return locale.toString(mantissa, 'f', 3) + QStringLiteral("·10") + power;
}
} // namespace

QString formatQuantity(double coreValue, const Unit &unit, int decimals, const QLocale &locale)
{
    double display = unit.toDisplay(coreValue);
    // Unbounded at a singular pose (its sign depends on the side it is neared from), or
    // undefined there.
    if (std::isinf(display))
        return QStringLiteral("∞");
    if (!std::isfinite(display))
        return QStringLiteral("—");
    // A value that rounds to zero shows as 0, never "-0.00" (a platform at x = −1e-14 mm).
    if (std::abs(display) < 0.5 * std::pow(10.0, -std::max(0, decimals)))
        display = 0.0;
    // No group separators: "1044.03", as the spin boxes and fields show it.
    QLocale plain = locale;
    plain.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    // A huge value (close to a singular pose, where a quantity grows without bound: a four-bar
    // a hair's breadth from its dead centre is 10¹² N·m/rad stiff) in powers of ten, four
    // digits: "1.680·10¹²", never a row of thirteen digits.
    // A fine-grained quantity that is zero (det J at a direct singularity) reads "0", not
    // "0.00000000": a row of zeros suggests a tiny value where there is none.
    const bool bareZero = display == 0.0 && decimals > 3;
    QString text = std::abs(display) >= 1e8 ? powerOfTen(display, plain)
                                            : plain.toString(display, 'f', bareZero ? 0 : decimals);
    // Read, not typed: the typographic minus ("−180.0°", as the drawings and the equations
    // print it), where the locale offers only the hyphen. Fields and spin boxes keep the hyphen
    // a keyboard gives.
    if (text.startsWith(QLatin1Char('-')))
        text.replace(0, 1, QChar(0x2212));
    const QString symbol = unitText(unit);
    if (symbol.isEmpty())
        return text;
    if (symbol.startsWith(QChar(0x00B0))) // degrees: no space, as in "60°" and "0.01°/step"
        return text + symbol;
    return text + QLatin1Char(' ') + symbol;
}

namespace {
/// The length of the subscript that starts at `from` (after a '_'): letters and digits, up to
/// one that already is a subscript (U+2080…U+209C: "₁").
qsizetype subscriptLength(const QString &text, qsizetype from)
{
    qsizetype end = from;
    while (end < text.size() && text[end].isLetterOrNumber() && !(text[end].unicode() >= 0x2080 && text[end].unicode() <= 0x209C))
        ++end;
    return end - from;
}

/// The Unicode subscript of `c`, or a null QChar where there is none (no subscript b, c, d,
/// f, g, q, w, y, z and no capitals).
QChar subscriptOf(QChar c)
{
    static const QString from = QStringLiteral("0123456789aehijklmnoprstuvxβγρφχ");
    static const QString to = QStringLiteral("₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓᵦᵧᵨᵩᵪ");
    const qsizetype at = from.indexOf(c);
    return at < 0 ? QChar() : to[at];
}
} // namespace

QString symbolHtml(const QString &input)
{
    const QString text = spelledDots(input);
    QString html;
    qsizetype done = 0;
    for (qsizetype at = text.indexOf(QLatin1Char('_')); at >= 0; at = text.indexOf(QLatin1Char('_'), at + 1)) {
        const qsizetype length = subscriptLength(text, at + 1);
        if (length == 0 || at == 0 || text[at - 1].isSpace())
            continue; // a lone '_' is text
        html += text.mid(done, at - done).toHtmlEscaped() + QStringLiteral("<sub>")
            + text.mid(at + 1, length).toHtmlEscaped() + QStringLiteral("</sub>");
        done = at + 1 + length;
        at = done - 1;
    }
    return html + text.mid(done).toHtmlEscaped();
}

QString symbolPlain(const QString &input)
{
    const QString text = spelledDots(input);
    QString plain;
    qsizetype done = 0;
    for (qsizetype at = text.indexOf(QLatin1Char('_')); at >= 0; at = text.indexOf(QLatin1Char('_'), at + 1)) {
        const qsizetype length = subscriptLength(text, at + 1);
        QString lowered;
        for (qsizetype i = at + 1; i < at + 1 + length && lowered.size() == i - at - 1; ++i) {
            if (const QChar sub = subscriptOf(text[i]); !sub.isNull())
                lowered += sub;
        }
        if (at == 0 || text[at - 1].isSpace() || length == 0 || lowered.size() != length)
            continue;
        plain += text.mid(done, at - done) + lowered;
        done = at + 1 + length;
        at = done - 1;
    }
    return plain + text.mid(done);
}

QString symbolHtmlKnown(const QString &text, const QStringList &symbols)
{
    QStringList known;
    for (const QString &symbol : symbols) {
        if (symbol.contains(QLatin1Char('_')) && !known.contains(symbol))
            known << symbol;
    }
    // the longest first, so that "det J_q" is one symbol and not "det" and "J_q"
    std::sort(known.begin(), known.end(), [](const QString &a, const QString &b) { return a.size() > b.size(); });
    const auto inWord = [&text](qsizetype at) {
        return at >= 0 && at < text.size() && (text[at].isLetterOrNumber() || text[at] == QLatin1Char('_'));
    };
    const auto escaped = [](const QString &plain) {
        return plain.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>"));
    };
    QString html;
    qsizetype done = 0;
    for (qsizetype at = 0; at < text.size(); ++at) {
        if (inWord(at - 1))
            continue;
        for (const QString &symbol : std::as_const(known)) {
            if (QStringView(text).mid(at).startsWith(symbol) && !inWord(at + symbol.size())) {
                html += escaped(text.mid(done, at - done)) + symbolHtml(symbol);
                done = at + symbol.size();
                at = done - 1;
                break;
            }
        }
    }
    return html + escaped(text.mid(done));
}

QString unbreakable(QString text)
{
    static const QRegularExpression slash(QStringLiteral("(?<=\\w)/(?=\\w)"), QRegularExpression::UseUnicodePropertiesOption); // "рад/с" too
    // a hyphen after a letter or two that name a form: "П-шарнира" broke as "П-" and "шарнира"
    static const QRegularExpression shortPrefix(QStringLiteral("(?:(?<=\\b\\w)|(?<=\\b\\w\\w))-(?=\\w)"),
                                                QRegularExpression::UseUnicodePropertiesOption); // Cyrillic letters are \w too
    static const QRegularExpression determinant(QStringLiteral("\\bdet (?=\\S)")); // "det J" broke as "det" and "J"
    text.replace(QStringLiteral(" = "), QStringLiteral("\u00A0=\u00A0"));
    text.replace(determinant, QStringLiteral("det\u00A0"));
    text.replace(shortPrefix, QStringLiteral("-\u2060"));
    return text.replace(slash, QStringLiteral("/\u2060")); // the word joiner: no break after '/'
}

bool parseNumber(const QString &text, const QString &unitSymbol, double *value)
{
    return parseNumber(text, QStringList {unitSymbol}, value);
}

bool parseNumber(const QString &text, const QStringList &unitSymbols, double *value)
{
    QString t = text.trimmed();
    for (const QString &unitSymbol : unitSymbols) {
        if (!unitSymbol.isEmpty() && t.endsWith(unitSymbol)) {
            t = t.left(t.size() - unitSymbol.size()).trimmed();
            break;
        }
    }
    t.replace(QChar(0x2212), QLatin1Char('-')); // typographic minus
    bool ok = false;
    double v = QLocale().toDouble(t, &ok);
    if (!ok)
        v = QLocale::c().toDouble(t, &ok);
    if (!ok || !std::isfinite(v))
        return false;
    *value = v;
    return true;
}

} // namespace pkm
