#pragma once
/// The text size the user chose (View ▸ Text Size, 100 % to 250 %): every font the program
/// makes is its size in points times this factor (plotfont.h), and a change rescales the fonts
/// already made, so that a classroom reads the labels, plots and maps from the back row.

class QTabWidget;
class QWidget;

namespace pkm::textscale {

inline constexpr double minimum = 1.0;
inline constexpr double maximum = 2.5;

/// The application's font at 100 %: the desktop's, but at least 10.5 pt, a size larger than
/// the usual default that reads from the back row. PKM Studio and the tests that check what
/// fits a projector both start from it.
void applyBaseFont();

/// The factor now, 1 unless the user chose another text size.
double factor();
/// Sets the factor (clamped to [minimum, maximum]) for fonts made from now on; returns it.
double setFactor(double factor);

/// Multiplies by `ratio` every font under `root` that is not simply inherited: widgets given a
/// font of their own, and in every plot the axes' tick and label fonts, the legend and its
/// items, the title elements and the text items. The fonts a widget inherits follow the
/// application's font (QApplication::setFont), which the caller scales.
void rescale(QWidget *root, double ratio);

/// Keeps every tab of `tabs` in sight whatever the text size: where the titles do not fit the
/// bar, each shows its part before " — " ("δ(α)" for "δ(α) — fig. 4"; the plot's own title
/// says the rest), and where even those do not fit, they end with "…". No scroll arrows. The
/// titles stay the caller's to set (in its retranslation).
void keepTabsInSight(QTabWidget *tabs);

} // namespace pkm::textscale
