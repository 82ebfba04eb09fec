#pragma once
/// How the GUI shows a number with its unit: locale-formatted, degrees glued to the number
/// ("60.0°"), other units after a space ("231.40 mm"), negatives with the minus sign
/// ("−180.0°", not a hyphen), and never "nan" or "inf".

#include "units.h"

#include <QLocale>
#include <QString>
#include <QStringList>

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
/// `text` with a time derivative that the screen's fonts cannot draw spelled out: a combining
/// dot (U+0307) or two (U+0308) over a Greek letter or q has no mark position in DejaVu Sans
/// and is left out or drawn apart, so "θ̇" reads "dθ/dt", "θ̈" "d²θ/dt²" and "θ̇²" "(dθ/dt)²".
/// Precomposed letters (ḋ, ẋ, Ẋ) and Latin ones the font places (d̈) stay. coreLabel(),
/// symbolHtml() and symbolPlain() apply it: every text on screen, in pictures and in video.
QString spelledDots(const QString &text);
/// The program's symbols write a subscript after '_' ("F_max", "det J_q", "x_AB", "T_max₁"):
/// the one display rule for them. symbolHtml() escapes `text` and lowers each subscript,
/// "F<sub>max</sub>", for rich text (labels, the values panel, the equations); a run of letters
/// and digits after '_' is the subscript, up to a character that already is one ("₁").
QString symbolHtml(const QString &text);
/// For plain text (plot titles, legends): each subscript in Unicode subscript letters where
/// every one of them has such a letter ("F_max" → "Fₘₐₓ"); left with its '_' where not
/// ("J_q", "x_AB"), so that a symbol is never half lowered.
QString symbolPlain(const QString &text);
/// symbolHtml() for a sentence that may hold other words with '_' (a file called
/// "my_design.pkm"): escapes `text` and lowers only the whole words that are one of `symbols`
/// ("x_AB" in "x_CD − x_AB = s"), and turns line breaks into <br>.
QString symbolHtmlKnown(const QString &text, const QStringList &symbols);
/// `text` with its formulas kept whole where it wraps: no line break around " = " nor after a
/// '/' between letters ("k = b/a", "(k = 0.40)", "γ₂ = +5°" broke as "k = b/" and "a"), nor
/// after a hyphen that follows a word of one or two letters ("П-шарнир", "O-X", "3-RPR").
QString unbreakable(QString text);
/// `coreValue` in core units; shown in the unit's display units.
QString formatQuantity(double coreValue, const Unit &unit, int decimals, const QLocale &locale = QLocale());

/// Parses a number typed by a person: the locale's form or the C form ("0,4" and "0.4" in a
/// comma locale), with an optional trailing unit symbol. Returns false for anything else.
bool parseNumber(const QString &text, const QString &unitSymbol, double *value);
/// The same with any one of several unit symbols (the translated one and the English one:
/// "12 мм" and "12 mm").
bool parseNumber(const QString &text, const QStringList &unitSymbols, double *value);

} // namespace pkm
