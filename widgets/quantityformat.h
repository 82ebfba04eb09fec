#pragma once
/// How the GUI shows a number with its unit: locale-formatted, degrees glued to the number
/// ("60.0°"), other units after a space ("231.40 mm"), and never "nan" or "inf".

#include "units.h"

#include <QLocale>
#include <QString>

#include <string_view>

namespace pkm {

/// Core strings are UTF-8.
QString toQString(std::string_view text);
QString unitText(const Unit &unit);
/// `coreValue` in core units; shown in the unit's display units.
QString formatQuantity(double coreValue, const Unit &unit, int decimals, const QLocale &locale = QLocale());

} // namespace pkm
