#include "quantityformat.h"

#include "text.h"

#include <QCoreApplication>

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
    return QCoreApplication::translate("core", source.c_str());
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
    QString text = std::abs(display) >= 1e8 ? powerOfTen(display, plain) : plain.toString(display, 'f', decimals);
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

} // namespace pkm
