#pragma once
/// How the GUI shows a number with its unit: locale-formatted, degrees glued to the number
/// ("60.0°"), other units after a space ("231.40 mm"), negatives with the minus sign
/// ("−180.0°", not a hyphen), and never "nan" or "inf".

#include "units.h"

#include <QLocale>
#include <QString>

#include <string_view>

namespace pkm {

/// Core strings are UTF-8.
QString toQString(std::string_view text);
/// The unit's symbol in the current language ("mm", Russian "мм").
QString unitText(const Unit &unit);
/// A fixed English label from a core table (ParameterInfo::label, VariableInfo::label,
/// ReportEntry::label, ReportText::label and ::text, ModeAlternative::label, SingularCurve::label,
/// MechanismKind::title), marked there with QT_TRANSLATE_NOOP("core", …), in the current language.
QString coreLabel(std::string_view label);
/// `coreValue` in core units; shown in the unit's display units.
QString formatQuantity(double coreValue, const Unit &unit, int decimals, const QLocale &locale = QLocale());

} // namespace pkm
