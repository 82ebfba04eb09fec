// The parameter sheet as an A4 portrait PDF for the workshop: a title block, numbered sections
// with aligned tables (units in the headers, the sheet's pose highlighted), the checks with
// PASS/FAIL in colour, the plots drawn as vectors, the workspace pictures, and the dimensioned
// drawing to a standard scale with a drawing title block. Every text is real PDF text
// (pdftotext extracts it); every page has a header and "page n of N".
//
// The layout runs twice: the first pass only measures and counts the pages, the second paints.
// This file holds the pages, the title block and the sections, and toPdf(); the tables, figures
// and plots are in sheetpdftable.cpp, sheetpdffigures.cpp and sheetpdfplots.cpp
// (sheetpdfinternal.h).

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

PdfSheet::PdfSheet(const Sheet &sheet, QPdfWriter &pdf)
    : m_sheet(sheet)
    , m_pdf(pdf)
    , m_unit(resolution / 25.4)
{
    m_body = QRectF(mm(marginLeft), mm(marginTop), mm(pageWidth - marginLeft - marginRight),
        mm(pageHeight - marginTop - marginBottom));
    m_family = QStringLiteral("DejaVu Sans");
}

int PdfSheet::run(QPainter *painter, int pages)
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

QFont PdfSheet::font(double points, bool bold, bool italic) const
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

double PdfSheet::wrappedHeight(const QFont &f, const QString &text, double width) const
{
    if (text.isEmpty())
        return 0.0;
    return metrics(f).boundingRect(QRectF(0, 0, width, 1e9), Qt::TextWordWrap, text).height();
}

void PdfSheet::text(const QRectF &box, const QFont &f, const QColor &colour, int flags, const QString &string)
{
    if (!m_painter || string.isEmpty())
        return;
    m_painter->setFont(f);
    m_painter->setPen(colour);
    m_painter->drawText(box, flags, string);
}

void PdfSheet::line(const QPointF &a, const QPointF &b, const QColor &colour, double widthMm)
{
    if (!m_painter)
        return;
    m_painter->setPen(QPen(colour, mm(widthMm)));
    m_painter->drawLine(a, b);
}

void PdfSheet::pageFrame()
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

void PdfSheet::newPage()
{
    if (m_painter)
        m_pdf.newPage();
    ++m_page;
    m_y = m_body.top();
    pageFrame();
}

void PdfSheet::need(double height)
{
    if (m_y + height > m_body.bottom() && m_y > m_body.top() + mm(1.0))
        newPage();
}

void PdfSheet::titleBlock()
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

void PdfSheet::heading(const QString &title)
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

void PdfSheet::paragraph(const QString &string, double points, const QColor &colour, bool italic)
{
    const QFont f = font(points, false, italic);
    const double height = wrappedHeight(f, string, m_body.width());
    need(height);
    text(QRectF(m_body.left(), m_y, m_body.width(), height), f, colour, Qt::TextWordWrap, string);
    m_y += height + mm(2.0);
}

void PdfSheet::subheading(const QString &string)
{
    const QFont f = font(9.5, true);
    const double height = metrics(f).height();
    need(height + mm(15.0));
    text(QRectF(m_body.left(), m_y, m_body.width(), height), f, ink, Qt::AlignLeft | Qt::AlignVCenter, string);
    m_y += height + mm(1.2);
}

void PdfSheet::addSection(const Section &section)
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

QString PdfSheet::groupTitle(const std::string &group)
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

void PdfSheet::items(const std::vector<Item> &list)
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

void PdfSheet::dataTable(const Table &source)
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

void PdfSheet::checks(const std::vector<Check> &list)
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

using detail::PdfSheet;
using detail::resolution;

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
