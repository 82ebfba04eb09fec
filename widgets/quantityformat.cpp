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
    QString text = plain.toString(display, 'f', decimals);
    const QString symbol = unitText(unit);
    if (symbol.isEmpty())
        return text;
    if (symbol.startsWith(QChar(0x00B0))) // degrees: no space, as in "60°" and "0.01°/step"
        return text + symbol;
    return text + QLatin1Char(' ') + symbol;
}

} // namespace pkm
