// The parameter sheet's PDF writer, shared by its files: the page geometry and colours, the
// laid-out table grid, and the class that lays the sheet out on A4 pages — the pages, title
// block and sections in sheetpdf.cpp, the tables in sheetpdftable.cpp, the figures in
// sheetpdffigures.cpp and the plots in sheetpdfplots.cpp. The layout runs twice: the first
// pass only measures and counts the pages, the second paints.
#pragma once

#include "export/sheet.h"

#include <QColor>
#include <QFont>
#include <QFontMetricsF>
#include <QPdfWriter>
#include <QPen>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <string>
#include <vector>

class QPainter;

namespace pkm::sheet::detail {

inline constexpr int resolution = 600; ///< PDF device units per inch
inline constexpr double pageWidth = 210.0, pageHeight = 297.0; ///< A4, mm
inline constexpr double marginLeft = 18.0, marginRight = 18.0, marginTop = 20.0, marginBottom = 18.0; ///< mm

inline const QColor ink(0x1c, 0x20, 0x26);
inline const QColor grey(0x5f, 0x67, 0x72);
inline const QColor rule(0xb8, 0xc0, 0xcc);
inline const QColor stripe(0xf3, 0xf5, 0xf8);
inline const QColor headerFill(0xe3, 0xe8, 0xef);
inline const QColor highlightFill(0xff, 0xf4, 0xc8);
inline const QColor accent(0x1f, 0x4e, 0x79);
inline const QColor passColour(0x1b, 0x7a, 0x3a);
inline const QColor failColour(0xb3, 0x26, 0x1e);

/// A cell of a laid-out table.
struct GridCell {
    QString text;
    QString sub; ///< smaller grey lines under the text (a criterion, a detail)
    QColor colour = ink;
    bool bold = false;
};
struct GridColumn {
    QString title;
    QString unit;
    bool right = false; ///< numbers: right-aligned
    bool flex = false; ///< takes the remaining width and wraps
};
struct GridRow {
    std::vector<GridCell> cells;
    bool highlight = false;
    bool heading = false; ///< a group heading spanning the table (cells[0])
};
struct Grid {
    std::vector<GridColumn> columns;
    std::vector<GridRow> rows;
};


/// Lays a sheet out on A4 pages of a PDF writer: run() once to count the pages, again to paint.
class PdfSheet
{
public:
    PdfSheet(const Sheet &sheet, QPdfWriter &pdf);

    /// Lays the sheet out; paints when `painter` is given. Returns the number of pages.
    int run(QPainter *painter, int pages);

private:
    double mm(double millimetres) const { return millimetres * m_unit; }

    QFont font(double points, bool bold = false, bool italic = false) const;
    QFontMetricsF metrics(const QFont &f) const { return QFontMetricsF(f, &m_pdf); }

    double wrappedHeight(const QFont &f, const QString &text, double width) const;
    void text(const QRectF &box, const QFont &f, const QColor &colour, int flags, const QString &string);
    void line(const QPointF &a, const QPointF &b, const QColor &colour, double widthMm);

    // -- pages ----------------------------------------------------------------------------

    void pageFrame();
    void newPage();

    /// Starts a new page unless `height` fits below the current position.
    void need(double height);

    // -- the title block ------------------------------------------------------------------

    void titleBlock();

    // -- sections -------------------------------------------------------------------------

    void heading(const QString &title);
    void paragraph(const QString &string, double points = 8.5, const QColor &colour = ink, bool italic = false);
    void subheading(const QString &string);
    void addSection(const Section &section);
    static QString groupTitle(const std::string &group);
    void items(const std::vector<Item> &list);
    void dataTable(const Table &source);
    void checks(const std::vector<Check> &list);

    // -- tables ---------------------------------------------------------------------------

    /// Lays out `grid` at the current position, splitting it across pages between rows (the
    /// header repeated).
    void table(const Grid &grid, bool header, double points, bool stretch = true);

    // -- figures --------------------------------------------------------------------------

    void figures(const std::vector<Figure> &list);
    double captionHeight(const Figure &figure, double width) const;

    /// One entry of a plot's legend: a line or a filled swatch and its name.
    struct LegendEntry {
        QPen pen; ///< Qt::NoPen: a filled swatch
        QColor fill;
        QString name;
    };
    QPen seriesPen(PlotSeries::Style style, int familyIndex) const;
    static QColor bandColour(PlotBand::Kind kind);

    /// What the lines alone do not say: several curves, the bands.
    std::vector<LegendEntry> legendEntries(const Plot &plot) const;

    /// Lays the legend out in rows inside `width` from `origin`; returns its height. Paints
    /// when painting.
    double legend(const Plot &plot, QPointF origin, double width);
    double legendHeight(const Plot &plot, double width);
    double figureHeight(const Figure &figure, double width);
    void paintFigure(const Figure &figure, const QRectF &area);

    /// Tick step: 1, 2, 2.5 or 5 × 10ⁿ giving at most `count` intervals; angles in 15°, 30°,
    /// 45° and 90° steps.
    static double tickStep(double span, int count, bool degrees);
    static QString tickText(double value, double step);

    /// Axes with ticks and grid in `plotArea` for x in [x0, x1], y in [y0, y1].
    void paintAxes(const QRectF &plotArea, double x0, double x1, double y0, double y1, bool xDegrees, bool yDegrees,
        bool grid);
    void paintPlot(const Plot &plot, const QRectF &area);
    void paintImage(const Figure &figure, const QRectF &area);
    void paintDrawing(const Figure &figure, const QRectF &area);
    const Sheet &m_sheet;
    QPdfWriter &m_pdf;
    double m_unit; ///< device units per mm
    QRectF m_body;
    QString m_family;
    QPainter *m_painter = nullptr;
    int m_pages = 1;
    int m_page = 1;
    int m_section = 0;
    double m_y = 0.0;
};

} // namespace pkm::sheet::detail
