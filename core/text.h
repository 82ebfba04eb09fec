#pragma once
/// The words a person reads, from a library without Qt.
///
/// Core keeps its texts in English and marks them for lupdate, all in the one context "core":
/// - a sentence made at run time goes through text::translate("core", "…%1…") and
///   text::format(), with numbers from text::number();
/// - a fixed label kept in a table (ParameterInfo::label, a unit symbol) is marked with
///   QT_TRANSLATE_NOOP("core", "…") and translated where it is shown (text::label()), so that
///   it follows a change of language.
///
/// A program with catalogues (the GUI, `pkm sheet --lang`) installs Hooks that look the texts
/// up and format numbers by locale. Without hooks (the CLI's JSON and messages, the tests) the
/// texts stay English and numbers are written with a '.', whatever the system locale.

#include <initializer_list>
#include <string>
#include <utility>
#include <string_view>

#ifndef QT_TRANSLATE_NOOP
#define QT_TRANSLATE_NOOP(scope, x) x
#endif

namespace pkm::text {

struct Hooks {
    /// Looks `source` up (QCoreApplication::translate); `n` ≥ 0 picks a plural form and
    /// replaces "%n". Null: English.
    std::string (*translate)(const char *context, const char *source, const char *disambiguation, int n) = nullptr;
    /// The locale's decimal point and minus sign (UTF-8). Empty: "." and "-".
    std::string decimalPoint;
    std::string minusSign;
};

/// Installs the hooks; call before other threads read texts, and again on a language change.
void install(Hooks hooks);
/// The hooks installed (for a program that swaps them for a while, like `pkm sheet --lang`).
Hooks installed();

/// The translation of a source text (with "%n" replaced by `n` when n ≥ 0).
std::string translate(const char *context, const char *source, const char *disambiguation = nullptr, int n = -1);
/// A label marked with QT_TRANSLATE_NOOP("core", …), translated now.
std::string label(std::string_view source);
/// "%1 … %2" filled with `args` in order, as QString::arg does ("%%" is not special).
std::string format(std::string_view pattern, std::initializer_list<std::string_view> args);
/// A number for a sentence: up to `decimals` decimals, trailing zeros dropped, the locale's
/// decimal point and minus sign.
std::string number(double value, int decimals = 3);
/// A number with exactly `decimals` decimals, the locale's decimal point and minus sign: a value
/// that moves with the pose ("θ = 40.0°", "d = 216.4 mm"), whose text would jump in width and
/// precision from pose to pose with trailing zeros dropped.
std::string fixed(double value, int decimals);
/// A value said to be outside [lo, hi], with as many decimals (from `decimals` up to 12) as it
/// takes not to read as the bound it passes: 60.000001 beside a bound of 60 is "60.000001",
/// not "60" (display units, as text::number).
std::string numberOutside(double value, double lo, double hi, int decimals = 3);
/// A length for a sentence: "12.5 mm".
std::string millimetres(double value);
/// Two lengths a sentence compares ("it lies 200.0001 mm from A, more than 200 mm"): both with
/// the fewest decimals, from 2 up to 12, at which they no longer read as equal.
std::pair<std::string, std::string> millimetresApart(double a, double b);
/// Text from outside (a file, the command line) made safe to print inside a message: control
/// characters and invalid UTF-8 as \xHH escapes (no ESC reaches a terminal, no newline fakes
/// a line), cut after `maxCharacters` characters with "…".
std::string printable(std::string_view outside, std::size_t maxCharacters = 80);

} // namespace pkm::text
