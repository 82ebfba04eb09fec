#pragma once
/// A design parameter with named values (a leg's type, the O-X glide's form, a working mode)
/// shown as a list of its values rather than as a number to remember: the Design panel's field
/// for it is the line edit of an editable combo box, which still takes a typed number or name.

#include "mechanism.h"

#include <QString>

#include <optional>

class QComboBox;
class QLineEdit;
class QWidget;

namespace pkm::choices {

/// The value's words on screen: its label ("R̲RR") or its name, translated ("crossed").
QString text(const ParameterInfo &info, std::size_t index);
/// The words of `value` (core units), or empty where it is none of the choices.
QString textOf(const ParameterInfo &info, double value);
/// The value typed or picked: a choice's name ("PiRR") or words ("П̲RR"), in any case; none
/// for anything else (a number is left to the caller).
std::optional<double> valueOf(const ParameterInfo &info, const QString &typed);

/// A parameter's value in `values` as its field shows it: a choice's words, else a number with
/// enough decimals to show the stored value, trailing zeros dropped, in the locale's form, a
/// negative one with the typographic minus (parseNumber() reads it back, and a typed "-" too).
QString fieldText(const ParameterInfo &info, const ParameterSet &values);

/// An editable list of the choices, as wide as the widest of them and at least `width` px.
QComboBox *makeBox(const ParameterInfo &info, int width, QWidget *parent);
/// The items' words again (a new language), the text shown kept.
void retranslateBox(QComboBox *box, const ParameterInfo &info);
/// Shows `text` in a parameter's field and, where the field is a list's, makes the item of
/// `value` (core units) the current one, so that the opened list marks it.
void showInField(QLineEdit *field, const QString &text, double value);

} // namespace pkm::choices
