#pragma once
// What the parts of the design file share: designfile.cpp reads and writes the files,
// designposes.cpp finds the poses they keep.

#include <QString>

namespace pkm::designfile::detail {

/// A number in a message: the locale's decimal point and minus sign in the GUI, '.' in the CLI
/// (text::number's rules), `significant` digits as QString::number(v, 'g', significant).
QString numberText(double value, int significant = 10);

} // namespace pkm::designfile::detail
