// The parameter sheet as an A4 portrait PDF for the workshop: a title block, numbered sections
// with aligned tables (units in the headers, the sheet's pose highlighted), the checks with
// PASS/FAIL in colour, the plots drawn as vectors, the workspace pictures, and the dimensioned
// drawing to a standard scale with a drawing title block. Every text is real PDF text
// (pdftotext extracts it); every page has a header and "page n of N".
//
// The layout runs twice: the first pass only measures and counts the pages, the second paints.

#include "scenepainter.h"
#include "export/sheet.h"
#include "export/sheetparts.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QMarginsF>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QPicture>

#include <algorithm>
#include <array>
#include <cmath>

namespace pkm::sheet {

namespace {

constexpr int resolution = 600; ///< PDF device units per inch
constexpr double pageWidth = 210.0, pageHeight = 297.0; ///< A4, mm
constexpr double marginLeft = 18.0, marginRight = 18.0, marginTop = 20.0, marginBottom = 18.0; ///< mm

const QColor ink(0x1c, 0x20, 0x26);
const QColor grey(0x5f, 0x67, 0x72);
const QColor rule(0xb8, 0xc0, 0xcc);
const QColor stripe(0xf3, 0xf5, 0xf8);
const QColor headerFill(0xe3, 0xe8, 0xef);
const QColor highlightFill(0xff, 0xf4, 0xc8);
const QColor accent(0x1f, 0x4e, 0x79);
const QColor passColour(0x1b, 0x7a, 0x3a);
const QColor failColour(0xb3, 0x26, 0x1e);

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

class PdfSheet
{
public:
    PdfSheet(const Sheet &sheet, QPdfWriter &pdf)
        : m_sheet(sheet)
        , m_pdf(pdf)
        , m_unit(resolution / 25.4)
    {
        m_body = QRectF(mm(marginLeft), mm(marginTop), mm(pageWidth - marginLeft - marginRight),
            mm(pageHeight - marginTop - marginBottom));
        m_family = QStringLiteral("DejaVu Sans");
    }

    /// Lays the sheet out; paints when `painter` is given. Returns the number of pages.
    int run(QPainter *painter, int pages)
    {
        m_painter = painter;
        m_pages = pages;
        m_page = 1;
        m_y = m_body.top();
        m_section = 0;
        pageFrame();
        titleBlock();
        for (const Section &section : m_sheet.sections)
            addSection(section);
        return m_page;
    }

private:
    double mm(double millimetres) const { return millimetres * m_unit; }

    QFont font(double points, bool bold = false, bool italic = false) const
    {
        QFont f(m_family);
        f.setPointSizeF(points);
        f.setBold(bold);
        f.setItalic(italic);
        f.setStyleHint(QFont::SansSerif);
        // Any letter spacing turns the ligatures off, so that "fi" stays two letters for text
        // extraction and search (pdftotext, a PDF viewer's find).
        f.setLetterSpacing(QFont::AbsoluteSpacing, 0.05); // device units: 1/12000 inch
        return f;
    }
    QFontMetricsF metrics(const QFont &f) const { return QFontMetricsF(f, &m_pdf); }

    double wrappedHeight(const QFont &f, const QString &text, double width) const
    {
        if (text.isEmpty())
            return 0.0;
        return metrics(f).boundingRect(QRectF(0, 0, width, 1e9), Qt::TextWordWrap, text).height();
    }

    void text(const QRectF &box, const QFont &f, const QColor &colour, int flags, const QString &string)
    {
        if (!m_painter || string.isEmpty())
            return;
        m_painter->setFont(f);
        m_painter->setPen(colour);
        m_painter->drawText(box, flags, string);
    }

    void line(const QPointF &a, const QPointF &b, const QColor &colour, double widthMm)
    {
        if (!m_painter)
            return;
        m_painter->setPen(QPen(colour, mm(widthMm)));
        m_painter->drawLine(a, b);
    }

    // -- pages ----------------------------------------------------------------------------

    void pageFrame()
    {
        const double top = mm(marginTop) - mm(9.0);
        const QFont small = font(7.5);
        const QFont smallBold = font(7.5, true);
        const QRectF band(m_body.left(), top, m_body.width(), mm(5.0));
        text(band, smallBold, accent, Qt::AlignLeft | Qt::AlignVCenter, QCoreApplication::translate("Sheet", "PKM Studio · Parameter sheet"));
        text(band, small, grey, Qt::AlignRight | Qt::AlignVCenter,
            QStringLiteral("%1 · %2").arg(QString::fromStdString(m_sheet.design), m_sheet.kindTitle));
        line(QPointF(m_body.left(), top + mm(6.0)), QPointF(m_body.right(), top + mm(6.0)), accent, 0.35);

        const double bottom = mm(pageHeight - marginBottom) + mm(4.0);
        line(QPointF(m_body.left(), bottom), QPointF(m_body.right(), bottom), rule, 0.2);
        const QRectF foot(m_body.left(), bottom + mm(1.0), m_body.width(), mm(5.0));
        QString left = m_sheet.date;
        if (!m_sheet.version.empty())
            left += QStringLiteral(" · PKM Studio ") + QString::fromStdString(m_sheet.version);
        const QString right = QCoreApplication::translate("Sheet", "page %1 of %2").arg(m_page).arg(std::max(m_pages, m_page));
        text(foot, small, grey, Qt::AlignLeft | Qt::AlignVCenter, left);
        text(foot, small, grey, Qt::AlignRight | Qt::AlignVCenter, right);
        // The title between them: centred on the page where it fits, else in the room left
        // between the date and the page number, shortened with "…" if it is longer still (a
        // long title, a longer language).
        const QFontMetricsF measure = metrics(small);
        const double gap = mm(4.0);
        const double leftWidth = measure.horizontalAdvance(left) + gap, rightWidth = measure.horizontalAdvance(right) + gap;
        const double side = std::max(leftWidth, rightWidth);
        QRectF middle(foot.left() + side, foot.top(), foot.width() - 2.0 * side, foot.height());
        if (measure.horizontalAdvance(m_sheet.title) > middle.width())
            middle = QRectF(foot.left() + leftWidth, foot.top(), foot.width() - leftWidth - rightWidth, foot.height());
        text(middle, small, grey, Qt::AlignHCenter | Qt::AlignVCenter,
            measure.elidedText(m_sheet.title, Qt::ElideRight, middle.width()));
    }

    void newPage()
    {
        if (m_painter)
            m_pdf.newPage();
        ++m_page;
        m_y = m_body.top();
        pageFrame();
    }

    /// Starts a new page unless `height` fits below the current position.
    void need(double height)
    {
        if (m_y + height > m_body.bottom() && m_y > m_body.top() + mm(1.0))
            newPage();
    }

    // -- the title block ------------------------------------------------------------------

    void titleBlock()
    {
        const QFont big = font(17.0, true);
        const QFont sub = font(11.0, true);
        text(QRectF(m_body.left(), m_y, m_body.width(), mm(9.0)), big, accent, Qt::AlignLeft | Qt::AlignVCenter,
            QCoreApplication::translate("Sheet", "Parameter sheet"));
        m_y += mm(10.0);
        const QString title = m_sheet.title.isEmpty() ? QString::fromStdString(m_sheet.design) : m_sheet.title;
        const double titleHeight = wrappedHeight(sub, title, m_body.width());
        text(QRectF(m_body.left(), m_y, m_body.width(), titleHeight), sub, ink, Qt::TextWordWrap, title);
        m_y += titleHeight + mm(3.0);

        Grid grid;
        grid.columns = {{QCoreApplication::translate("Sheet", "field"), {}, false, false}, {QCoreApplication::translate("Sheet", "value"), {}, false, true}};
        const auto add = [&](const QString &field, const QString &value) {
            grid.rows.push_back({{{field, {}, grey, true}, {value, {}, ink, false}}, false, false});
        };
        add(QCoreApplication::translate("Sheet", "Design"), QString::fromStdString(m_sheet.design));
        add(QCoreApplication::translate("Sheet", "Mechanism"), QStringLiteral("%1 (%2)").arg(m_sheet.kindTitle, QString::fromStdString(m_sheet.kind)));
        add(QCoreApplication::translate("Sheet", "Pose"), m_sheet.pose);
        add(QCoreApplication::translate("Sheet", "Date"), m_sheet.date);
        if (!m_sheet.version.empty())
            add(QCoreApplication::translate("Sheet", "Software"), QStringLiteral("PKM Studio ") + QString::fromStdString(m_sheet.version));
        if (!m_sheet.description.isEmpty())
            add(QCoreApplication::translate("Sheet", "About"), m_sheet.description);
        table(grid, false, 8.0);
        text(QRectF(m_body.left(), m_y, m_body.width(), mm(4.0)), font(7.0, false, true), grey,
            Qt::AlignLeft | Qt::AlignVCenter,
            QCoreApplication::translate("Sheet", "Units: lengths mm, angles degrees, forces N, torques N·m, times s, unless a column says otherwise."));
        m_y += mm(7.0);
    }

    // -- sections -------------------------------------------------------------------------

    void heading(const QString &title)
    {
        ++m_section;
        const QFont f = font(12.0, true);
        const double height = mm(8.0);
        need(height + mm(25.0)); // never a heading alone at the foot of a page
        const QRectF box(m_body.left(), m_y, m_body.width(), height);
        text(box, f, accent, Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("%1  %2").arg(m_section).arg(title));
        line(QPointF(m_body.left(), m_y + height), QPointF(m_body.right(), m_y + height), rule, 0.25);
        m_y += height + mm(2.5);
    }

    void paragraph(const QString &string, double points = 8.5, const QColor &colour = ink, bool italic = false)
    {
        const QFont f = font(points, false, italic);
        const double height = wrappedHeight(f, string, m_body.width());
        need(height);
        text(QRectF(m_body.left(), m_y, m_body.width(), height), f, colour, Qt::TextWordWrap, string);
        m_y += height + mm(2.0);
    }

    void subheading(const QString &string)
    {
        const QFont f = font(9.5, true);
        const double height = metrics(f).height();
        need(height + mm(15.0));
        text(QRectF(m_body.left(), m_y, m_body.width(), height), f, ink, Qt::AlignLeft | Qt::AlignVCenter, string);
        m_y += height + mm(1.2);
    }

    void addSection(const Section &section)
    {
        if (section.newPage && m_y > m_body.top() + mm(1.0))
            newPage();
        heading(section.title);
        if (!section.intro.isEmpty())
            paragraph(section.intro, 8.0, grey);
        if (!section.items.empty())
            items(section.items);
        for (const Table &t : section.tables)
            dataTable(t);
        if (!section.checks.empty())
            checks(section.checks);
        figures(section.figures);
        for (const QString &note : section.notes)
            paragraph(note, 8.5, section.key == "warnings" ? failColour : ink);
        m_y += mm(3.0);
    }

    static QString groupTitle(const std::string &group)
    {
        if (group == "geometry")
            return QCoreApplication::translate("Sheet", "Geometry");
        if (group == "range")
            return QCoreApplication::translate("Sheet", "Range of motion");
        if (group == "actuator")
            return QCoreApplication::translate("Sheet", "Actuator");
        if (group == "drawing")
            return QCoreApplication::translate("Sheet", "Drawing only");
        if (group == "mode")
            return QCoreApplication::translate("Sheet", "Working and assembly modes");
        return QString::fromStdString(group);
    }

    void items(const std::vector<Item> &list)
    {
        Grid grid;
        grid.columns = {{QCoreApplication::translate("Sheet", "symbol"), {}, false, false}, {QCoreApplication::translate("Sheet", "quantity"), {}, false, true},
            {QCoreApplication::translate("Sheet", "value"), {}, true, false}, {QCoreApplication::translate("Sheet", "unit"), {}, false, false}, {QCoreApplication::translate("Sheet", "key"), {}, false, false}};
        std::string group;
        for (const Item &item : list) {
            if (!item.group.empty() && item.group != group) {
                group = item.group;
                grid.rows.push_back({{{groupTitle(group), {}, accent, true}}, false, true});
            }
            grid.rows.push_back({{{item.symbol, {}, ink, true}, {item.label, {}, ink, false},
                                     {cellText(item.value), {}, ink, false},
                                     {detail::unitShown(item.unit), {}, ink, false},
                                     {QString::fromStdString(item.key), {}, grey, false}},
                false, false});
        }
        table(grid, true, 8.0);
    }

    void dataTable(const Table &source)
    {
        if (!source.title.isEmpty())
            subheading(source.title);
        Grid grid;
        grid.columns.push_back({source.labelTitle, {}, false, true});
        for (const Column &column : source.columns) {
            // numbers right-aligned: a column whose cells are all numbers
            bool numeric = true;
            for (const Row &row : source.rows) {
                const std::size_t c = std::size_t(&column - source.columns.data());
                if (c < row.cells.size() && row.cells[c].isWord())
                    numeric = false;
            }
            grid.columns.push_back({column.title, detail::unitShown(column.unit), numeric, false});
        }
        for (const Row &row : source.rows) {
            GridRow out;
            out.highlight = row.highlight;
            out.cells.push_back({row.label, {}, ink, true});
            for (const Cell &cell : row.cells)
                out.cells.push_back({cellText(cell), {}, ink, row.highlight});
            grid.rows.push_back(std::move(out));
        }
        table(grid, true, 7.8, false);
        QStringList legend;
        for (const Column &column : source.columns) {
            if (!column.label.isEmpty() && column.title != column.label)
                legend << column.title + QStringLiteral(": ") + column.label;
        }
        if (!legend.isEmpty() && source.columns.size() > 3)
            paragraph(legend.join(QStringLiteral("; ")) + QLatin1Char('.'), 6.8, grey);
        if (!source.note.isEmpty())
            paragraph(source.note, 7.5, grey, true);
    }

    void checks(const std::vector<Check> &list)
    {
        Grid grid;
        grid.columns = {{QCoreApplication::translate("Sheet", "check"), {}, false, true}, {QCoreApplication::translate("Sheet", "value"), {}, true, false}, {QCoreApplication::translate("Sheet", "limit"), {}, true, false},
            {QCoreApplication::translate("Sheet", "unit"), {}, false, false}, {QCoreApplication::translate("Sheet", "result"), {}, false, false}};
        for (const Check &check : list) {
            QString sub = check.criterion;
            if (!check.detail.isEmpty())
                sub += QStringLiteral("\n") + check.detail;
            const bool hasLimit = check.limit.isWord() || std::isfinite(check.limit.number);
            const QColor colour = check.verdict == Verdict::Pass ? passColour
                : check.verdict == Verdict::Fail                 ? failColour
                                                                 : grey;
            QString result = QString::fromLatin1(verdictWord(check.verdict));
            const QString translated = detail::verdictText(check.verdict);
            if (translated != result) // the English word stays, for searching any language's sheet
                result = translated + QStringLiteral(" (") + result + QLatin1Char(')');
            grid.rows.push_back({{{check.title, sub, ink, true}, {cellText(check.value), {}, ink, false},
                                     {hasLimit ? cellText(check.limit) : QString(), {}, ink, false},
                                     {detail::unitShown(check.unit), {}, ink, false}, {result, {}, colour, true}},
                false, false});
        }
        table(grid, true, 8.0);
    }

    // -- tables ---------------------------------------------------------------------------

    /// Lays out `grid` at the current position, splitting it across pages between rows (the
    /// header repeated).
    void table(const Grid &grid, bool header, double points, bool stretch = true)
    {
        const QFont regular = font(points), bold = font(points, true), small = font(points - 1.2);
        const QFont unitFont = font(points - 1.2);
        const double padX = mm(1.6), padY = mm(0.9);
        const std::size_t n = grid.columns.size();
        // natural widths
        std::vector<double> widths(n, 0.0);
        const auto measure = [&](const QFont &f, const QString &s) {
            double w = 0.0;
            for (const QString &lineText : s.split(QLatin1Char('\n')))
                w = std::max(w, metrics(f).horizontalAdvance(lineText));
            return w;
        };
        for (std::size_t c = 0; c < n; ++c) {
            if (header) {
                widths[c] = std::max(measure(bold, grid.columns[c].title), measure(unitFont, grid.columns[c].unit));
            }
        }
        for (const GridRow &row : grid.rows) {
            if (row.heading)
                continue;
            for (std::size_t c = 0; c < n && c < row.cells.size(); ++c) {
                widths[c] = std::max(widths[c], measure(row.cells[c].bold ? bold : regular, row.cells[c].text));
                if (!grid.columns[c].flex)
                    widths[c] = std::max(widths[c], measure(small, row.cells[c].sub));
            }
        }
        for (double &w : widths)
            w += 2.0 * padX + mm(0.8); // a little slack: the painter's text is not always as narrow as measured
        // the flexible column wraps when the table is too wide; a stretched table fills the width
        const double total = m_body.width();
        double fixed = 0.0;
        std::size_t flex = n;
        for (std::size_t c = 0; c < n; ++c) {
            if (grid.columns[c].flex && flex == n)
                flex = c;
            else
                fixed += widths[c];
        }
        if (flex < n && (stretch || fixed + widths[flex] > total))
            widths[flex] = std::max(mm(28.0), total - fixed);
        double used = 0.0;
        for (double w : widths)
            used += w;
        if (used > total) { // too many columns: shrink the fixed ones alike
            const double keep = flex < n ? widths[flex] : 0.0;
            const double scale = (total - keep) / (used - keep);
            for (std::size_t c = 0; c < n; ++c) {
                if (c != flex)
                    widths[c] *= scale;
            }
        }
        std::vector<double> lefts(n, m_body.left());
        for (std::size_t c = 1; c < n; ++c)
            lefts[c] = lefts[c - 1] + widths[c - 1];
        const double right = lefts.back() + widths.back();

        const double lineHeight = metrics(regular).height();
        const auto rowHeight = [&](const GridRow &row) {
            if (row.heading)
                return lineHeight + 2.0 * padY;
            double height = lineHeight;
            for (std::size_t c = 0; c < n && c < row.cells.size(); ++c) {
                const GridCell &cell = row.cells[c];
                const double w = widths[c] - 2.0 * padX;
                double h = grid.columns[c].flex ? wrappedHeight(cell.bold ? bold : regular, cell.text, w)
                                                : lineHeight * std::max<qsizetype>(1, cell.text.count(QLatin1Char('\n')) + 1);
                if (!cell.sub.isEmpty())
                    h += wrappedHeight(small, cell.sub, w);
                height = std::max(height, h);
            }
            return height + 2.0 * padY;
        };
        const double headerHeight = header ? 2.0 * lineHeight + 2.0 * padY : 0.0;

        const auto paintHeader = [&] {
            if (!header)
                return;
            if (m_painter)
                m_painter->fillRect(QRectF(m_body.left(), m_y, right - m_body.left(), headerHeight), headerFill);
            for (std::size_t c = 0; c < n; ++c) {
                const GridColumn &column = grid.columns[c];
                const int align = column.right ? Qt::AlignRight : Qt::AlignLeft;
                const QRectF box(lefts[c] + padX, m_y + padY, widths[c] - 2.0 * padX, lineHeight);
                text(box, bold, ink, align | Qt::AlignVCenter, column.title);
                text(box.translated(0.0, lineHeight), unitFont, grey, align | Qt::AlignVCenter, column.unit);
            }
            m_y += headerHeight;
            line(QPointF(m_body.left(), m_y), QPointF(right, m_y), ink, 0.3);
        };

        // keep the header with at least two rows
        double start = headerHeight;
        for (std::size_t r = 0; r < std::min<std::size_t>(2, grid.rows.size()); ++r)
            start += rowHeight(grid.rows[r]);
        need(start);
        paintHeader();
        bool striped = false;
        for (const GridRow &row : grid.rows) {
            const double height = rowHeight(row);
            if (m_y + height > m_body.bottom()) {
                line(QPointF(m_body.left(), m_y), QPointF(right, m_y), ink, 0.3);
                newPage();
                paintHeader();
            }
            if (row.heading) {
                text(QRectF(m_body.left() + padX, m_y + padY, right - m_body.left() - 2.0 * padX, lineHeight), bold,
                    accent, Qt::AlignLeft | Qt::AlignVCenter, row.cells.empty() ? QString() : row.cells.front().text);
                m_y += height;
                line(QPointF(m_body.left(), m_y), QPointF(right, m_y), rule, 0.15);
                striped = false;
                continue;
            }
            if (m_painter) {
                const QRectF band(m_body.left(), m_y, right - m_body.left(), height);
                if (row.highlight)
                    m_painter->fillRect(band, highlightFill);
                else if (striped)
                    m_painter->fillRect(band, stripe);
            }
            striped = !striped;
            for (std::size_t c = 0; c < n && c < row.cells.size(); ++c) {
                const GridCell &cell = row.cells[c];
                const GridColumn &column = grid.columns[c];
                const QFont &f = cell.bold ? bold : regular;
                const double w = widths[c] - 2.0 * padX;
                const int align = column.right ? Qt::AlignRight : Qt::AlignLeft;
                double h = column.flex ? wrappedHeight(f, cell.text, w)
                                       : lineHeight * std::max<qsizetype>(1, cell.text.count(QLatin1Char('\n')) + 1);
                text(QRectF(lefts[c] + padX, m_y + padY, w, h), f, cell.colour,
                    align | Qt::AlignTop | (column.flex ? int(Qt::TextWordWrap) : 0), cell.text);
                if (!cell.sub.isEmpty()) {
                    const double subHeight = wrappedHeight(small, cell.sub, w);
                    text(QRectF(lefts[c] + padX, m_y + padY + h, w, subHeight), small, grey,
                        align | Qt::AlignTop | Qt::TextWordWrap, cell.sub);
                }
            }
            m_y += height;
        }
        line(QPointF(m_body.left(), m_y), QPointF(right, m_y), ink, 0.3);
        m_y += mm(3.0);
    }

    // -- figures --------------------------------------------------------------------------

    void figures(const std::vector<Figure> &list)
    {
        std::vector<const Figure *> pair;
        const auto flush = [&] {
            if (pair.empty())
                return;
            const double gap = mm(6.0);
            const double width = pair.size() == 1 && pair.front()->kind == FigureKind::Drawing
                ? m_body.width()
                : (m_body.width() - gap) / 2.0;
            double height = 0.0;
            for (const Figure *figure : pair)
                height = std::max(height, figureHeight(*figure, width));
            need(height);
            for (std::size_t i = 0; i < pair.size(); ++i)
                paintFigure(*pair[i], QRectF(m_body.left() + double(i) * (width + gap), m_y, width, height));
            m_y += height + mm(4.0);
            pair.clear();
        };
        for (const Figure &figure : list) {
            if (figure.kind == FigureKind::Drawing) {
                flush();
                pair.push_back(&figure);
                flush();
                continue;
            }
            pair.push_back(&figure);
            if (pair.size() == 2)
                flush();
        }
        flush();
    }

    double captionHeight(const Figure &figure, double width) const
    {
        return figure.caption.isEmpty() ? 0.0 : wrappedHeight(font(6.8, false, true), figure.caption, width) + mm(1.0);
    }

    /// One entry of a plot's legend: a line or a filled swatch and its name.
    struct LegendEntry {
        QPen pen; ///< Qt::NoPen: a filled swatch
        QColor fill;
        QString name;
    };

    QPen seriesPen(PlotSeries::Style style, int familyIndex) const
    {
        static const std::array<QColor, 5> family {QColor(0x7f, 0x95, 0xb5), QColor(0xc9, 0x8a, 0x4e),
            QColor(0x6f, 0xa8, 0x7e), QColor(0xa3, 0x86, 0xc4), QColor(0xb8, 0x6a, 0x6a)};
        QPen pen;
        switch (style) {
        case PlotSeries::Style::Design:
            pen = QPen(accent, mm(0.5));
            break;
        case PlotSeries::Style::Extension:
            pen = QPen(accent, mm(0.25), Qt::DashLine);
            break;
        case PlotSeries::Style::Family:
            pen = QPen(family[std::size_t(familyIndex) % family.size()], mm(0.25));
            break;
        }
        pen.setCapStyle(Qt::FlatCap);
        pen.setJoinStyle(Qt::RoundJoin);
        return pen;
    }

    static QColor bandColour(PlotBand::Kind kind)
    {
        return kind == PlotBand::Kind::Recommended ? QColor(0xdf, 0xf1, 0xe3) : QColor(0xfb, 0xe4, 0xd6);
    }

    /// What the lines alone do not say: several curves, the bands.
    std::vector<LegendEntry> legendEntries(const Plot &plot) const
    {
        std::vector<LegendEntry> entries;
        if (plot.series.size() > 1) {
            int familyIndex = 0;
            for (const PlotSeries &series : plot.series) {
                const int index = series.style == PlotSeries::Style::Family ? familyIndex++ : 0;
                entries.push_back({seriesPen(series.style, index), {}, series.name});
            }
        }
        for (const PlotBand &band : plot.bands) {
            const bool seen = std::any_of(
                entries.begin(), entries.end(), [&](const LegendEntry &entry) { return entry.name == band.name; });
            if (!seen)
                entries.push_back({QPen(Qt::NoPen), bandColour(band.kind), band.name});
        }
        return entries;
    }

    /// Lays the legend out in rows inside `width` from `origin`; returns its height. Paints
    /// when painting.
    double legend(const Plot &plot, QPointF origin, double width)
    {
        const std::vector<LegendEntry> entries = legendEntries(plot);
        if (entries.empty())
            return 0.0;
        const QFont f = font(6.5);
        const double lineHeight = metrics(f).height();
        const double swatch = mm(5.0), gap = mm(1.0), spacing = mm(3.5);
        double x = 0.0, y = 0.0;
        for (const LegendEntry &entry : entries) {
            const double textWidth = metrics(f).horizontalAdvance(entry.name) + mm(0.5);
            const double w = swatch + gap + textWidth;
            if (x > 0.0 && x + w > width) {
                x = 0.0;
                y += lineHeight;
            }
            if (m_painter) {
                const double middle = origin.y() + y + lineHeight / 2.0;
                if (entry.pen.style() == Qt::NoPen) {
                    m_painter->fillRect(QRectF(origin.x() + x, middle - lineHeight * 0.3, swatch, lineHeight * 0.6), entry.fill);
                } else {
                    m_painter->setPen(entry.pen);
                    m_painter->drawLine(QPointF(origin.x() + x, middle), QPointF(origin.x() + x + swatch, middle));
                }
            }
            text(QRectF(origin.x() + x + swatch + gap, origin.y() + y, textWidth, lineHeight), f, grey,
                Qt::AlignLeft | Qt::AlignVCenter, entry.name);
            x += w + spacing;
        }
        return y + lineHeight + mm(0.8);
    }

    double legendHeight(const Plot &plot, double width)
    {
        QPainter *painter = m_painter;
        m_painter = nullptr; // measure only
        const double height = legend(plot, QPointF(), width);
        m_painter = painter;
        return height;
    }

    double figureHeight(const Figure &figure, double width)
    {
        const double title = metrics(font(8.5, true)).height() + mm(1.0);
        switch (figure.kind) {
        case FigureKind::Plot:
            return title + mm(58.0) + legendHeight(figure.plot, width - mm(2.0)) + captionHeight(figure, width);
        case FigureKind::Image: {
            double aspect = figure.image.isNull() ? 1.0 : double(figure.image.height()) / figure.image.width();
            const double plotWidth = width - mm(14.0);
            const double imageHeight = std::min(mm(85.0), plotWidth * aspect);
            return title + imageHeight + mm(10.0) + captionHeight(figure, width);
        }
        case FigureKind::Drawing:
            return title + mm(drawingHeight) + mm(16.0) + captionHeight(figure, width);
        }
        return 0.0;
    }

    void paintFigure(const Figure &figure, const QRectF &area)
    {
        const QFont titleFont = font(8.5, true);
        const double titleHeight = metrics(titleFont).height();
        text(QRectF(area.left(), area.top(), area.width(), titleHeight), titleFont, ink,
            Qt::AlignLeft | Qt::AlignVCenter, metrics(titleFont).elidedText(figure.title, Qt::ElideRight, area.width()));
        QRectF content(area.left(), area.top() + titleHeight + mm(1.0), area.width(),
            area.height() - titleHeight - mm(1.0) - captionHeight(figure, area.width()));
        switch (figure.kind) {
        case FigureKind::Plot:
            paintPlot(figure.plot, content);
            break;
        case FigureKind::Image:
            paintImage(figure, content);
            break;
        case FigureKind::Drawing:
            paintDrawing(figure, content);
            break;
        }
        if (!figure.caption.isEmpty()) {
            const QFont f = font(6.8, false, true);
            text(QRectF(area.left(), content.bottom() + mm(1.0), area.width(), captionHeight(figure, area.width())), f,
                grey, Qt::TextWordWrap, figure.caption);
        }
    }

    /// Tick step: 1, 2, 2.5 or 5 × 10ⁿ giving at most `count` intervals; angles in 15°, 30°,
    /// 45° and 90° steps.
    static double tickStep(double span, int count, bool degrees)
    {
        if (!(span > 0.0))
            return 1.0;
        if (degrees && span >= 20.0) {
            for (double step : {5.0, 10.0, 15.0, 30.0, 45.0, 90.0, 180.0}) {
                if (span / step <= count)
                    return step;
            }
        }
        const double raw = span / count;
        const double power = std::pow(10.0, std::floor(std::log10(raw)));
        for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
            if (m * power >= raw)
                return m * power;
        }
        return 10.0 * power;
    }

    static QString tickText(double value, double step)
    {
        const int decimals = std::clamp(int(std::ceil(-std::log10(step) + 1e-9)), 0, 6)
            + (std::abs(std::round(step / std::pow(10.0, std::floor(std::log10(step)))) - 2.5) < 1e-9 ? 1 : 0);
        return detail::numberText(std::abs(value) < step * 1e-9 ? 0.0 : value, std::max(0, decimals)); // locale
    }

    /// Axes with ticks and grid in `plotArea` for x in [x0, x1], y in [y0, y1].
    void paintAxes(const QRectF &plotArea, double x0, double x1, double y0, double y1, bool xDegrees, bool yDegrees,
        bool grid)
    {
        const QFont tickFont = font(6.5);
        const auto mx = [&](double x) { return plotArea.left() + (x - x0) / (x1 - x0) * plotArea.width(); };
        const auto my = [&](double y) { return plotArea.bottom() - (y - y0) / (y1 - y0) * plotArea.height(); };
        const double xStep = tickStep(x1 - x0, 6, xDegrees), yStep = tickStep(y1 - y0, 5, yDegrees);
        const double th = metrics(tickFont).height();
        for (double x = std::ceil(x0 / xStep - 1e-9) * xStep; x <= x1 + 1e-9 * xStep; x += xStep) {
            if (grid)
                line(QPointF(mx(x), plotArea.top()), QPointF(mx(x), plotArea.bottom()), QColor(0xe2, 0xe6, 0xec), 0.12);
            line(QPointF(mx(x), plotArea.bottom()), QPointF(mx(x), plotArea.bottom() + mm(0.8)), ink, 0.15);
            text(QRectF(mx(x) - mm(8.0), plotArea.bottom() + mm(1.0), mm(16.0), th), tickFont, ink,
                Qt::AlignHCenter | Qt::AlignTop, tickText(x, xStep));
        }
        for (double y = std::ceil(y0 / yStep - 1e-9) * yStep; y <= y1 + 1e-9 * yStep; y += yStep) {
            if (grid)
                line(QPointF(plotArea.left(), my(y)), QPointF(plotArea.right(), my(y)), QColor(0xe2, 0xe6, 0xec), 0.12);
            line(QPointF(plotArea.left() - mm(0.8), my(y)), QPointF(plotArea.left(), my(y)), ink, 0.15);
            text(QRectF(plotArea.left() - mm(13.0), my(y) - th / 2.0, mm(12.0), th), tickFont, ink,
                Qt::AlignRight | Qt::AlignVCenter, tickText(y, yStep));
        }
        if (m_painter) {
            m_painter->setPen(QPen(ink, mm(0.2)));
            m_painter->setBrush(Qt::NoBrush);
            m_painter->drawRect(plotArea);
        }
    }

    void paintPlot(const Plot &plot, const QRectF &area)
    {
        const QFont labelFont = font(7.0);
        const double labelHeight = metrics(labelFont).height();
        const double legendSpace = legendHeight(plot, area.width() - mm(2.0));
        const QRectF plotArea(area.left() + mm(15.5), area.top() + mm(1.0), area.width() - mm(17.0),
            area.height() - mm(1.0) - mm(4.0) - labelHeight - legendSpace);
        const bool xDegrees = plot.xLabel.contains(QStringLiteral("°"));
        const bool yDegrees = plot.yLabel.contains(QStringLiteral("(°)"));
        const double x0 = plot.xMin, x1 = plot.xMax > plot.xMin ? plot.xMax : plot.xMin + 1.0;
        const double y0 = plot.yMin, y1 = plot.yMax > plot.yMin ? plot.yMax : plot.yMin + 1.0;
        const auto mx = [&](double x) { return plotArea.left() + (x - x0) / (x1 - x0) * plotArea.width(); };
        const auto my = [&](double y) { return plotArea.bottom() - (y - y0) / (y1 - y0) * plotArea.height(); };

        if (m_painter) {
            for (const PlotBand &band : plot.bands) {
                const double a = std::clamp(mx(band.from), plotArea.left(), plotArea.right());
                const double b = std::clamp(mx(band.to), plotArea.left(), plotArea.right());
                m_painter->fillRect(QRectF(a, plotArea.top(), b - a, plotArea.height()), bandColour(band.kind));
            }
        }
        paintAxes(plotArea, x0, x1, y0, y1, xDegrees, yDegrees, true);
        text(QRectF(plotArea.left(), plotArea.bottom() + mm(4.0), plotArea.width(), labelHeight), labelFont, ink,
            Qt::AlignHCenter | Qt::AlignTop, plot.xLabel);
        if (m_painter) {
            m_painter->save();
            m_painter->translate(area.left() + labelHeight * 0.1, plotArea.center().y());
            m_painter->rotate(-90.0);
            text(QRectF(-plotArea.height() / 2.0, 0.0, plotArea.height(), labelHeight), labelFont, ink,
                Qt::AlignHCenter | Qt::AlignTop, plot.yLabel);
            m_painter->restore();
        }
        if (m_painter) {
            m_painter->save();
            m_painter->setClipRect(plotArea);
            m_painter->setRenderHint(QPainter::Antialiasing, true);
            int familyIndex = 0;
            for (const PlotSeries &series : plot.series) {
                const QPen pen
                    = seriesPen(series.style, series.style == PlotSeries::Style::Family ? familyIndex++ : 0);
                m_painter->setPen(pen);
                m_painter->setBrush(Qt::NoBrush);
                QPainterPath path;
                bool open = false;
                for (const auto &[x, y] : series.points) {
                    if (!std::isfinite(x) || !std::isfinite(y)) {
                        open = false;
                        continue;
                    }
                    const QPointF p(mx(x), my(std::clamp(y, y0 - (y1 - y0), y1 + (y1 - y0))));
                    if (open)
                        path.lineTo(p);
                    else
                        path.moveTo(p);
                    open = true;
                }
                m_painter->drawPath(path);
            }
            for (const auto &[level, name] : plot.levels) {
                m_painter->setPen(QPen(failColour, mm(0.3), Qt::DashLine));
                m_painter->drawLine(QPointF(plotArea.left(), my(level)), QPointF(plotArea.right(), my(level)));
                text(QRectF(plotArea.left() + mm(1.0), my(level) - labelHeight - mm(0.3), plotArea.width() - mm(2.0),
                         labelHeight),
                    font(6.3), failColour, Qt::AlignRight | Qt::AlignBottom, name);
            }
            if (plot.cursor && *plot.cursor >= x0 && *plot.cursor <= x1) {
                m_painter->setPen(QPen(QColor(0x9c, 0x1f, 0x6e), mm(0.25), Qt::DotLine));
                m_painter->drawLine(QPointF(mx(*plot.cursor), plotArea.top()), QPointF(mx(*plot.cursor), plotArea.bottom()));
                text(QRectF(mx(*plot.cursor) + mm(0.8), plotArea.top() + mm(0.5), mm(25.0), labelHeight), font(6.0),
                    QColor(0x9c, 0x1f, 0x6e), Qt::AlignLeft | Qt::AlignTop, QCoreApplication::translate("Sheet", "this pose"));
            }
            m_painter->restore();
        }
        if (legendSpace > 0.0)
            legend(plot, QPointF(area.left() + mm(2.0), area.bottom() - legendSpace), area.width() - mm(2.0));
    }

    void paintImage(const Figure &figure, const QRectF &area)
    {
        if (figure.image.isNull())
            return;
        const double aspect = double(figure.image.height()) / figure.image.width();
        double width = area.width() - mm(14.0);
        double height = width * aspect;
        const double available = area.height() - mm(10.0);
        if (height > available) {
            height = available;
            width = height / aspect;
        }
        const QRectF target(area.left() + mm(13.0) + (area.width() - mm(14.0) - width) / 2.0, area.top() + mm(1.0), width,
            height);
        if (m_painter) {
            m_painter->save();
            m_painter->setRenderHint(QPainter::LosslessImageRendering, true);
            m_painter->setRenderHint(QPainter::SmoothPixmapTransform, false);
            m_painter->drawImage(target, figure.image);
            m_painter->restore();
        }
        if (!figure.imageBounds.isEmpty()) {
            paintAxes(target, figure.imageBounds.min().x(), figure.imageBounds.max().x(), figure.imageBounds.min().y(),
                figure.imageBounds.max().y(), false, false, false);
            const QFont labelFont = font(6.5);
            const double labelHeight = metrics(labelFont).height();
            text(QRectF(target.left(), target.bottom() + mm(4.2), target.width(), labelHeight), labelFont, ink,
                Qt::AlignHCenter | Qt::AlignTop, QCoreApplication::translate("Sheet", "x (mm)"));
            text(QRectF(area.left(), target.bottom() + mm(4.2), mm(12.0), labelHeight), labelFont, ink,
                Qt::AlignRight | Qt::AlignTop, QCoreApplication::translate("Sheet", "y (mm)"));
        }
    }

    void paintDrawing(const Figure &figure, const QRectF &area)
    {
        const Scene &scene = figure.scene;
        const QRectF frame(area.left(), area.top(), area.width(), mm(drawingHeight));
        const double ratio = double(figure.scale.first) / figure.scale.second; // paper mm per mm
        ViewMapping mapping;
        mapping.scale = mm(1.0) * ratio;
        const Eigen::Vector2d centre = !figure.imageBounds.isEmpty() ? Eigen::Vector2d(figure.imageBounds.center())
            : scene.extent.isEmpty()                                  ? Eigen::Vector2d(Eigen::Vector2d::Zero())
                                                                      : Eigen::Vector2d(scene.extent.center().head<2>());
        mapping.origin = QPointF(frame.center().x() - mapping.scale * centre.x(), frame.center().y() + mapping.scale * centre.y());
        SceneStyle style = detail::drawingStyle(m_unit);
        if (m_painter) {
            m_painter->save();
            m_painter->setClipRect(frame);
            m_painter->setRenderHint(QPainter::Antialiasing, true);
            m_painter->setRenderHint(QPainter::TextAntialiasing, true);
            ScenePainter::paint(*m_painter, scene, mapping, style);
            m_painter->restore();
            m_painter->setPen(QPen(ink, mm(0.35)));
            m_painter->setBrush(Qt::NoBrush);
            m_painter->drawRect(frame);
        }
        // the drawing's title block, under the frame
        const double top = frame.bottom() + mm(2.0);
        const QFont field = font(6.5), value = font(8.0, true);
        // the scale bar has a cell of its own, so that it never covers the drawing
        const std::array<std::pair<QString, QString>, 5> cells {{
            {QCoreApplication::translate("Sheet", "scale (A4)"), scaleText(figure.scale)},
            {QCoreApplication::translate("Sheet", "scale bar"), QString()},
            {QCoreApplication::translate("Sheet", "units"), QCoreApplication::translate("Sheet", "mm, degrees")},
            {QCoreApplication::translate("Sheet", "design"), QString::fromStdString(m_sheet.design)},
            {QCoreApplication::translate("Sheet", "date"), m_sheet.date},
        }};
        const std::array<double, 5> shares {0.12, 0.27, 0.16, 0.28, 0.17};
        double x = frame.left();
        const double height = mm(11.0);
        for (std::size_t i = 0; i < cells.size(); ++i) {
            const double w = frame.width() * shares[i];
            const QRectF box(x, top, w, height);
            if (m_painter) {
                m_painter->setPen(QPen(ink, mm(0.25)));
                m_painter->setBrush(Qt::NoBrush);
                m_painter->drawRect(box);
            }
            text(box.adjusted(mm(1.5), mm(0.8), -mm(1.5), 0.0), field, grey, Qt::AlignLeft | Qt::AlignTop, cells[i].first);
            text(box.adjusted(mm(1.5), 0.0, -mm(1.5), -mm(1.2)), value, ink, Qt::AlignLeft | Qt::AlignBottom,
                metrics(value).elidedText(cells[i].second, Qt::ElideRight, w - mm(3.0)));
            if (i == 1 && m_painter) {
                m_painter->save();
                ScenePainter::paintScaleBar(*m_painter, box.adjusted(0.0, 0.0, 0.0, mm(1.2)), mapping, style);
                m_painter->restore();
            }
            x += w;
        }
    }

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

} // namespace

namespace detail {

SceneStyle drawingStyle(double unitsPerMillimetre)
{
    SceneStyle style;
    style.pixelSize = unitsPerMillimetre * 25.4 / 150.0; // the screen's 16-pixel labels at about 7.7 pt
    style.background = Qt::white;
    style.showHandles = false;
    return style;
}

std::optional<Eigen::AlignedBox2d> drawnBounds(const Scene &scene, double ratio)
{
    if (!qobject_cast<QGuiApplication *>(QCoreApplication::instance()))
        return std::nullopt;
    constexpr double units = 10.0; // picture units per paper mm: 0.1 mm steps
    ViewMapping mapping;
    mapping.scale = units * ratio;
    mapping.origin = QPointF(0.0, 0.0);
    QPicture picture;
    QPainter painter(&picture);
    ScenePainter::paint(painter, scene, mapping, drawingStyle(units));
    painter.end();
    const QRect box = picture.boundingRect();
    if (!box.isValid())
        return std::nullopt;
    return Eigen::AlignedBox2d(Eigen::Vector2d(box.left() / units, -box.bottom() / units),
        Eigen::Vector2d(box.right() / units, -box.top() / units));
}

} // namespace detail

QByteArray toPdf(const Sheet &sheet, QString *error)
{
    const auto fail = [&](const QString &why) {
        if (error)
            *error = why;
        return QByteArray();
    };
    if (!qobject_cast<QGuiApplication *>(QCoreApplication::instance()))
        return fail(QStringLiteral("drawing a PDF needs Qt's GUI module (a QGuiApplication)"));
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter pdf(&buffer);
        pdf.setResolution(resolution);
        pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait, QMarginsF()));
        const QString name = sheet.title.isEmpty() ? QString::fromStdString(sheet.design) : sheet.title;
        pdf.setTitle(QCoreApplication::translate("Sheet", "Parameter sheet: %1").arg(name));
        pdf.setCreator(QStringLiteral("PKM Studio ") + QString::fromStdString(sheet.version));
        PdfSheet layout(sheet, pdf);
        const int pages = layout.run(nullptr, 1); // measure
        QPainter painter;
        if (!painter.begin(&pdf))
            return fail(QStringLiteral("the PDF could not be drawn"));
        layout.run(&painter, pages);
        painter.end();
    }
    if (bytes.isEmpty())
        return fail(QStringLiteral("the PDF could not be drawn"));
    return bytes;
}

} // namespace pkm::sheet
