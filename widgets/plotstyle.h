#pragma once
/// The house style of the curve plots (the П-joint's and the four-bar's): white, projector-size
/// fonts, a closed frame, the title, subtitle and legend in rows above the axis rect (so the
/// legend never covers a curve), and a buffered "cursor" layer on top so that moving the pose
/// cursor redraws it alone.

#include <qcustomplot.h>

#include <QFont>

namespace pkm::plotstyle {

inline constexpr QRgb designRgb = 0x1f5fa8; ///< the design's curve
inline constexpr QRgb cursorRgb = 0xd0312d; ///< the current pose
inline constexpr QRgb gridRgb = 0xe2e2e2;
inline constexpr QRgb axisRgb = 0x303030;
inline constexpr double tickPoints = 11, labelPoints = 12, titlePoints = 13, subtitlePoints = 10.5,
                        legendPoints = 11, cursorPoints = 11;

struct Header {
    QCPTextElement *title = nullptr;
    QCPTextElement *subtitle = nullptr;
    QCPLayer *cursorLayer = nullptr;
};

/// The pose cursor: a vertical line, a marker on the curve and its value beside the marker,
/// on the cursor layer.
struct Cursor {
    QCPItemStraightLine *line = nullptr;
    QCPItemTracer *marker = nullptr;
    QCPItemText *label = nullptr;
};
Cursor addCursor(QCustomPlot *plot, const QFont &base, QCPLayer *layer);
/// Puts the cursor's label (its text set) beside the marker at (x, y), plot coordinates: on
/// the side with more room, above or below as there is room, and moved inwards as far as it
/// must to stay whole inside the axis rect — a narrow plot on a projector cut it off before.
/// A box wider than the axis rect stays whole inside the plot, over its tick labels.
void placeCursorLabel(QCustomPlot *plot, QCPItemText *label, double x, double y);

/// A title or subtitle element of `plot` in `font` that lowers the subscripts symbolPlain()
/// cannot write in Unicode ("T_M", "x_AB", "det J_q"), as the panels do; its text keeps the
/// notation.
QCPTextElement *newTextElement(QCustomPlot *plot, const QFont &font);

/// Styles `plot` with fonts derived from `base` and adds a "bands" layer below the grid and the
/// buffered "cursor" layer; the legend is visible, in the row under the subtitle.
Header apply(QCustomPlot *plot, const QFont &base);

/// Sets the text of a title or subtitle, broken into lines where it is wider than its plot —
/// after "; " if that is enough, else between words — so that no end is cut off in a narrow
/// plot or a longer language. fitText() breaks it again for a new width (on a resize).
/// Subscripts as symbolPlain() writes them; θ̇ as dθ/dt (a combining dot is drawn apart).
void setFittedText(QCPTextElement *element, const QString &text);
void fitText(QCPTextElement *element);
/// `text` broken into lines no wider than `width` pixels in `font` (after "; " if that is
/// enough, else between words); unchanged where it fits or `width` is not positive.
QString wrapped(const QString &text, const QFont &font, int width);
/// Breaks every legend name of `plot` into lines no wider than the legend's room in one
/// column, from the name as it was first given (kept by the plottable); call again on a resize.
void wrapLegendNames(QCustomPlot *plot);
/// Lays the legend out in as many columns as the plot's width holds, balanced over the rows
/// (filled column by column); returns its height in pixels (0 without entries).
int layOutLegend(QCustomPlot *plot);
/// Shows or hides the legend in its row under the subtitle; a hidden one leaves the row, so
/// that the axes take its room (QCustomPlot keeps an invisible element's minimum size).
void setLegendShown(QCustomPlot *plot, bool shown);
/// Forgets the kept names, after the plottables were given new ones (a new language).
void forgetLegendNames(QCustomPlot *plot);

} // namespace pkm::plotstyle
