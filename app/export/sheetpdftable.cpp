// The sheet PDF's tables: a grid of cells laid out at the current position with units in the
// header, numbers right-aligned, the sheet's pose highlighted, wrapping columns, and split across
// pages between rows with the header repeated.

#include "export/sheetpdfinternal.h"

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

namespace detail {

void PdfSheet::table(const Grid &grid, bool header, double points, bool stretch)
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

} // namespace detail

} // namespace pkm::sheet
