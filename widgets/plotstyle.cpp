#include "plotstyle.h"

#include "plotfont.h"
#include "quantityformat.h"

#include <QAbstractTextDocumentLayout>
#include <QFontMetrics>
#include <QTextDocument>

#include <algorithm>
#include <vector>
#include <limits>

namespace pkm::plotstyle {

namespace {
/// QCPTextElement, with a text that holds '_' drawn as rich text: "T_M" as T with a lowered M.
/// Its size is the plain text's, a little wider than the lowered one, so nothing is cut.
class SymbolTextElement : public QCPTextElement
{
public:
    using QCPTextElement::QCPTextElement;

protected:
    void draw(QCPPainter *painter) override
    {
        if (!mText.contains(QLatin1Char('_'))) {
            QCPTextElement::draw(painter);
            return;
        }
        painter->setFont(mainFont());
        mTextBoundingRect = painter->boundingRect(mRect, mTextFlags, mText); // for a click, as the base keeps it
        const QString align = (mTextFlags & Qt::AlignLeft) ? QStringLiteral("left")
            : (mTextFlags & Qt::AlignRight)               ? QStringLiteral("right")
                                                          : QStringLiteral("center");
        QTextDocument document;
        document.setDefaultFont(mainFont());
        document.setDocumentMargin(0);
        document.setTextWidth(mRect.width());
        document.setHtml(QStringLiteral("<div align=\"%1\">%2</div>")
                             .arg(align, symbolHtml(mText).replace(QLatin1Char('\n'), QStringLiteral("<br>"))));
        painter->save();
        painter->translate(mRect.left(), mRect.top() + 0.5 * (mRect.height() - document.size().height()));
        QAbstractTextDocumentLayout::PaintContext context;
        context.palette.setColor(QPalette::Text, mainTextColor());
        document.documentLayout()->draw(painter, context);
        painter->restore();
    }
};
} // namespace

QCPTextElement *newTextElement(QCustomPlot *plot, const QFont &font)
{
    return new SymbolTextElement(plot, QString(), font);
}

Header apply(QCustomPlot *plot, const QFont &base)
{
    Header header;
    plot->setBackground(Qt::white);
    plot->addLayer(QStringLiteral("bands"), plot->layer(QStringLiteral("grid")), QCustomPlot::limBelow);
    // The overlay (buffered by default for QCP's selection rect, which these read-only plots
    // never show) shares the main buffer; the cursor has its own.
    plot->layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    plot->addLayer(QStringLiteral("cursor"), plot->layer(QStringLiteral("overlay")), QCustomPlot::limAbove);
    header.cursorLayer = plot->layer(QStringLiteral("cursor"));
    header.cursorLayer->setMode(QCPLayer::lmBuffered);

    QCPLayoutGrid *grid = plot->plotLayout();
    for (int row = 0; row < 3; ++row)
        grid->insertRow(0);
    header.title = newTextElement(plot, fontOf(base, titlePoints, true));
    header.subtitle = newTextElement(plot, fontOf(base, subtitlePoints));
    header.subtitle->setTextColor(QColor(0x505050));
    grid->addElement(0, 0, header.title);
    grid->addElement(1, 0, header.subtitle);
    plot->axisRect()->insetLayout()->take(plot->legend);
    grid->addElement(2, 0, plot->legend);
    for (int row = 0; row < 3; ++row)
        grid->setRowStretchFactor(row, 0.001);
    grid->setRowSpacing(2);
    plot->legend->setVisible(true);
    plot->legend->setFont(fontOf(base, legendPoints));
    plot->legend->setBorderPen(Qt::NoPen);
    plot->legend->setIconSize(30, 14);
    plot->legend->setColumnSpacing(18);
    plot->legend->setRowSpacing(1);
    plot->legend->setMargins(QMargins(8, 2, 8, 2));

    for (QCPAxis *axis : {plot->xAxis, plot->yAxis, plot->xAxis2, plot->yAxis2}) {
        const QPen pen(QColor(axisRgb), 1.2);
        axis->setBasePen(pen);
        axis->setTickPen(pen);
        axis->setSubTickPen(QPen(QColor(axisRgb), 1.0));
        axis->setTickLabelFont(fontOf(base, tickPoints));
        axis->setLabelFont(fontOf(base, labelPoints));
        axis->grid()->setPen(QPen(QColor(gridRgb), 1.0));
        axis->grid()->setZeroLinePen(Qt::NoPen);
    }
    for (QCPAxis *axis : {plot->xAxis2, plot->yAxis2}) { // a closed frame, no second scale
        axis->setVisible(true);
        axis->setTicks(false);
        axis->setTickLabels(false);
    }
    plot->xAxis->setSubTicks(false);
    // QCustomPlot leaves out a tick label that the widget's edge would cut: in presentation
    // mode's larger text the θ axis lost its 90° (fig. 8) and the four-bar's its 360°. The axis
    // rect keeps half the last label's width free at its right (known after a first replot).
    QObject::connect(plot, &QCustomPlot::beforeReplot, plot, [plot] {
        const QVector<QString> labels = plot->xAxis->tickVectorLabels();
        if (labels.isEmpty())
            return;
        const int half = QFontMetrics(plot->xAxis->tickLabelFont()).horizontalAdvance(labels.last()) / 2 + 2;
        QMargins margins = plot->axisRect()->minimumMargins();
        if (margins.right() != half) {
            margins.setRight(half);
            plot->axisRect()->setMinimumMargins(margins);
        }
    });
    return header;
}

Cursor addCursor(QCustomPlot *plot, const QFont &base, QCPLayer *layer)
{
    const QColor red(cursorRgb);
    Cursor cursor;
    cursor.line = new QCPItemStraightLine(plot);
    cursor.line->setPen(QPen(red, 1.5));
    cursor.marker = new QCPItemTracer(plot);
    cursor.marker->setStyle(QCPItemTracer::tsCircle);
    cursor.marker->setSize(11);
    cursor.marker->setPen(QPen(red, 2.0));
    cursor.marker->setBrush(Qt::white);
    cursor.label = new QCPItemText(plot);
    cursor.label->setFont(fontOf(base, cursorPoints, true));
    cursor.label->setColor(QColor(0x202020));
    cursor.label->setBrush(QColor(255, 255, 255, 235));
    cursor.label->setPen(QPen(red, 1.0));
    cursor.label->setPadding(QMargins(6, 3, 6, 3));
    cursor.label->position->setParentAnchor(cursor.marker->position);
    cursor.label->position->setType(QCPItemPosition::ptAbsolute); // pixel offsets from the marker
    for (QCPAbstractItem *item : std::initializer_list<QCPAbstractItem *>{cursor.line, cursor.marker, cursor.label}) {
        item->setLayer(layer);
        item->setSelectable(false);
    }
    // The axis rect's size is known only once a replot has laid the plot out (the first
    // showing, a resize): the label is placed again then, before it is drawn.
    QCPItemText *label = cursor.label;
    QCPItemTracer *marker = cursor.marker;
    QObject::connect(plot, &QCustomPlot::afterLayout, label, [plot, label, marker] {
        const QPointF at = marker->position->coords();
        placeCursorLabel(plot, label, at.x(), at.y());
    });
    return cursor;
}

namespace {
const char *cursorTextProperty = "pkmCursorText"; ///< the read-out on one line
const char *brokenTextProperty = "pkmBrokenText"; ///< the same on two lines, as shown

/// The size of `label`'s box with `text` in it, measured as the item draws it (the bounding
/// rectangle of the laid-out text, which a bold face or a combining dot can make wider than
/// the advance), so that the box is whole.
QSizeF boxSize(const QCustomPlot *plot, const QCPItemText *label, const QString &text)
{
    const QFontMetrics metrics(label->font(), plot);
    const QRect bounds = metrics.boundingRect(0, 0, 0, 0, Qt::TextDontClip | label->textAlignment(), text);
    int textWidth = bounds.width();
    for (const QString &line : text.split(QLatin1Char('\n')))
        textWidth = std::max(textWidth, metrics.horizontalAdvance(line));
    const QMargins padding = label->padding();
    return {textWidth + padding.left() + padding.right() + 1.0, bounds.height() + padding.top() + padding.bottom() + 1.0};
}
/// How many points of the plot's curves (sampled, a few hundred each) lie in `box` (pixels).
int curvePointsIn(QCustomPlot *plot, const QRectF &box)
{
    int count = 0;
    for (int p = 0; p < plot->plottableCount(); ++p) {
        QCPAbstractPlottable *plottable = plot->plottable(p);
        QCPPlottableInterface1D *data = plottable ? plottable->interface1D() : nullptr;
        if (!data || !plottable->visible() || plottable->keyAxis() == nullptr || plottable->valueAxis() == nullptr)
            continue;
        const int n = data->dataCount();
        const int stride = std::max(1, n / 400);
        for (int i = 0; i < n; i += stride) {
            const QPointF point = plottable->coordsToPixels(data->dataMainKey(i), data->dataMainValue(i));
            count += box.contains(point) ? stride : 0;
        }
    }
    return count;
}
} // namespace

void placeCursorLabel(QCustomPlot *plot, QCPItemText *label, double x, double y)
{
    constexpr double gap = 12.0; // pixels between the marker and the label
    const QRect rect = plot->axisRect()->rect();
    // A read-out wider than a narrow plot ("J⁻¹ = 0.0158 rad/mm" in fig. 12) takes two lines,
    // the unit on the second, rather than cover the tick labels and the axis title.
    QString full = label->text();
    if (full == label->property(brokenTextProperty).toString())
        full = label->property(cursorTextProperty).toString();
    QString shown = full;
    QSizeF size = boxSize(plot, label, full);
    const qsizetype unitAt = full.lastIndexOf(QLatin1Char(' '));
    if (size.width() + 4.0 > rect.width() && unitAt > 0 && !full.contains(QLatin1Char('\n'))) {
        const QString broken = full.left(unitAt) + QLatin1Char('\n') + full.mid(unitAt + 1);
        const QSizeF brokenSize = boxSize(plot, label, broken);
        if (brokenSize.width() < size.width()) {
            shown = broken;
            size = brokenSize;
        }
    }
    if (shown != label->text()) {
        label->setProperty(cursorTextProperty, full);
        label->setProperty(brokenTextProperty, shown);
        label->setText(shown);
    }
    const double width = size.width(), height = size.height();
    const QPointF marker(plot->xAxis->coordToPixel(x), plot->yAxis->coordToPixel(y));
    // beside the marker, on the side with more room first, then inwards until it is whole
    const auto place = [](double at, double low, double high, double size, bool flip) {
        const bool before = (at - low > high - at) != flip;
        const double highest = std::max(low + 2.0, high - 2.0 - size);
        return std::clamp(before ? at - gap - size : at + gap, low + 2.0, highest);
    };
    // Inside the axis rectangle where it fits; a box wider (or taller) than a narrow plot's
    // axis rectangle goes over the tick labels rather than lose its end to the clip.
    const QRect wide = plot->viewport();
    const bool fitsAcross = width + 4.0 <= rect.width(), fitsDown = height + 4.0 <= rect.height();
    label->setClipToAxisRect(fitsAcross && fitsDown);
    const QRect across = fitsAcross ? rect : wide, down = fitsDown ? rect : wide;
    // Of the four corners around the marker, the one that hides least of the curves (the
    // four-bar's "δ = 79.5°" lay across the δ(α) curve beside the marker), the roomier first
    // among equals.
    double left = 0.0, top = 0.0;
    int fewest = std::numeric_limits<int>::max();
    for (const int corner : {0, 1, 2, 3}) {
        const double l = place(marker.x(), across.left(), across.right(), width, corner & 1);
        const double t = place(marker.y(), down.top(), down.bottom(), height, corner & 2);
        const int hidden = curvePointsIn(plot, QRectF(l, t, width, height));
        if (hidden < fewest) {
            fewest = hidden;
            left = l;
            top = t;
        }
        if (hidden == 0)
            break;
    }
    label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
    label->position->setCoords(left - marker.x(), top - marker.y());
}

namespace {
const char *fullTextProperty = "pkmFullText"; ///< the text before it was broken into lines
} // namespace

void setFittedText(QCPTextElement *element, const QString &text)
{
    // θ̇ has no precomposed letter: the combining dot after θ was drawn apart from it, at the
    // start of the line above, in the figures' subtitles; symbolPlain() spells it dθ/dt.
    const QString plain = symbolPlain(text); // "T = J·Fₘₐₓ"
    element->setProperty(fullTextProperty, plain);
    fitText(element);
}

QString wrapped(const QString &input, const QFont &font, int width)
{
    const QFontMetrics metrics(font);
    const auto fits = [&metrics, width](const QString &line) { return metrics.horizontalAdvance(line) <= width; };
    if (width <= 0 || fits(input))
        return input;
    const QString text = unbreakable(input); // where it breaks, "(k = 0.40)" stays on one line
    const QStringList clauses = text.split(QStringLiteral("; "));
    if (clauses.size() > 1 && std::all_of(clauses.cbegin(), clauses.cend(), fits))
        return clauses.join(QStringLiteral(";\n"));
    QStringList lines;
    QString line;
    for (const QString &word : text.split(QLatin1Char(' '))) {
        const QString longer = line.isEmpty() ? word : line + QLatin1Char(' ') + word;
        if (!line.isEmpty() && !fits(longer)) {
            lines << line;
            line = word;
        } else {
            line = longer;
        }
    }
    lines << line;
    // No short word alone on the last line ("(fig." over "5)"): the word before it goes down
    // with it, where the line still fits.
    if (lines.size() > 1 && lines.last().size() <= 3) {
        QString &before = lines[lines.size() - 2];
        const qsizetype space = before.lastIndexOf(QLatin1Char(' '));
        const QString moved = space > 0 ? before.mid(space + 1) + QLatin1Char(' ') + lines.last() : QString();
        if (space > 0 && fits(moved)) {
            lines.last() = moved;
            before.truncate(space);
        }
    }
    return lines.join(QLatin1Char('\n'));
}

void fitText(QCPTextElement *element)
{
    const QString text = element->property(fullTextProperty).toString();
    // a little air at both ends
    element->setText(wrapped(text, element->font(), element->parentPlot()->width() - 16));
}

namespace {
const char *fullNameProperty = "pkmFullName"; ///< a legend name before it was broken into lines
} // namespace

void wrapLegendNames(QCustomPlot *plot)
{
    const QCPLegend *legend = plot->legend;
    const int room = plot->width() - legend->margins().left() - legend->margins().right() - legend->iconSize().width()
        - legend->iconTextPadding() - 12;
    for (int j = 0; j < plot->plottableCount(); ++j) {
        QCPAbstractPlottable *plottable = plot->plottable(j);
        if (!plottable->property(fullNameProperty).isValid())
            plottable->setProperty(fullNameProperty, plottable->name());
        plottable->setName(wrapped(plottable->property(fullNameProperty).toString(), legend->font(), room));
    }
}

void forgetLegendNames(QCustomPlot *plot)
{
    for (int j = 0; j < plot->plottableCount(); ++j)
        plot->plottable(j)->setProperty(fullNameProperty, QVariant());
}

void setLegendShown(QCustomPlot *plot, bool shown)
{
    QCPLayoutGrid *grid = plot->plotLayout();
    const bool inRow = grid->hasElement(2, 0) && grid->element(2, 0) == plot->legend;
    plot->legend->setVisible(shown);
    if (shown && !inRow && !grid->hasElement(2, 0))
        grid->addElement(2, 0, plot->legend);
    else if (!shown && inRow)
        grid->take(plot->legend);
}

int layOutLegend(QCustomPlot *plot)
{
    QCPLegend *legend = plot->legend;
    std::vector<int> widths;
    int tallest = 0;
    for (int j = 0; j < legend->itemCount(); ++j) { // cells of the grid, some of them empty
        if (const QCPAbstractLegendItem *item = legend->item(j)) {
            widths.push_back(item->minimumOuterSizeHint().width());
            tallest = std::max(tallest, item->minimumOuterSizeHint().height());
        }
    }
    const int count = int(widths.size());
    if (count == 0)
        return 0;
    const int available = plot->width() - legend->margins().left() - legend->margins().right();
    // The most columns whose own widths fit, filled row by row (item i in column i mod n) or,
    // where that fits fewer, column by column: the П-joint's fig. 8 has two long entries ("this
    // design (k = 0.40)", "beyond its θ range") and five short "k = …", and took seven rows
    // where the widest entry times two did not fit; down the columns they take four.
    // The width of `rows` rows: across (item i in column i mod n) or down the columns.
    const auto width = [&](int rows, bool down) {
        const int columns = (count + rows - 1) / rows;
        int total = -legend->columnSpacing();
        for (int c = 0; c < columns; ++c) {
            int widest = 0;
            for (int i = 0; i < count; ++i) {
                if ((down ? i / rows : i % columns) == c)
                    widest = std::max(widest, widths[std::size_t(i)]);
            }
            total += widest + legend->columnSpacing();
        }
        return total;
    };
    int rows = 1;
    while (rows < count && width(rows, false) > available && width(rows, true) > available)
        ++rows;
    const bool down = rows < count && width(rows, false) > available;
    const QCPLayoutGrid::FillOrder order = down ? QCPLayoutGrid::foRowsFirst : QCPLayoutGrid::foColumnsFirst;
    const int wrap = down ? rows : (count + rows - 1) / rows; // rows down a column, or columns across
    if (wrap != legend->wrap() || legend->fillOrder() != order) {
        legend->setWrap(wrap);
        legend->setFillOrder(order, true);
    }
    return rows * (tallest + legend->rowSpacing());
}

} // namespace pkm::plotstyle
