#pragma once
/// The text of every number in the JSON and CSV outputs of `pkm`: printf("%.15g") without the
/// locale — at most 15 significant digits (see numberformat.cpp for why), '.' as decimal
/// separator whatever LC_NUMERIC says, -0 printed as 0. The caller handles non-finite values
/// (null in JSON, an empty CSV field).

#include <string>

namespace pkm::report {

/// Appends `value` as printed in every JSON and CSV output.
void appendNumber(std::string &out, double value);

/// The same text as a new string, for messages.
std::string numberText(double value);

/// A coordinate in mm without the last-ulp noise of grid arithmetic (rounded to 1e-9 mm, -0
/// as 0): the grid's and the outline's coordinates in JSON, CSV and SVG.
double cleanCoordinate(double value);

/// Room writeNumber() may use: the text is at most 23 bytes, but the fast path copies in
/// fixed-size blocks past its end.
inline constexpr int maxNumberLength = 32;

/// The same text as appendNumber, written at `out`, which must have maxNumberLength bytes of
/// room; returns the end of the text. No allocation: the hot path of `pkm sweep --csv`.
char *writeNumber(char *out, double value);

} // namespace pkm::report
