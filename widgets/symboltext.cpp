#include "symboltext.h"

#include "quantityformat.h"

#include <QAbstractItemView>
#include <QAbstractTextDocumentLayout>
#include <QApplication>
#include <QFontMetrics>
#include <QPainter>
#include <QStylePainter>
#include <QTextDocument>

#include <algorithm>
#include <cmath>

namespace pkm {

QString symbolHtmlElided(const QString &text, const QFont &font, int width)
{
    QTextDocument document;
    document.setDefaultFont(font);
    document.setDocumentMargin(0);
    document.setHtml(symbolHtml(text));
    if (document.idealWidth() <= width)
        return symbolHtml(text);
    // Shorter plain text until the lowered one fits: the notation's '_' take room a lowered
    // subscript does not, so the plain elision is a first guess from above.
    const QFontMetrics metrics(font);
    for (int room = width; room > 0; room -= std::max(1, metrics.averageCharWidth() / 2)) {
        const QString shorter = symbolHtml(metrics.elidedText(text, Qt::ElideRight, room));
        document.setHtml(shorter);
        if (document.idealWidth() <= width)
            return shorter;
    }
    return QString();
}

void drawSymbolText(QPainter *painter, const QRect &room, const QString &text, const QFont &font, const QColor &colour)
{
    QTextDocument document;
    document.setDefaultFont(font);
    document.setDocumentMargin(0);
    // a text too long for its room ends in "…", as a plain one does
    document.setHtml(symbolHtmlElided(text, font, room.width()));
    painter->save();
    painter->setClipRect(room);
    painter->translate(room.left(), room.top() + 0.5 * (room.height() - document.size().height()));
    QAbstractTextDocumentLayout::PaintContext context;
    context.palette.setColor(QPalette::Text, colour);
    document.documentLayout()->draw(painter, context);
    painter->restore();
}

void SymbolDelegate::paint(QPainter *painter, const QStyleOptionViewItem &option, const QModelIndex &index) const
{
    QStyleOptionViewItem item = option;
    initStyleOption(&item, index);
    if (!item.text.contains(QLatin1Char('_'))) {
        QStyledItemDelegate::paint(painter, option, index);
        return;
    }
    const QString text = item.text;
    item.text.clear(); // the style draws the background, a selection and the icon; the document the text
    const QWidget *widget = item.widget;
    QStyle *style = widget ? widget->style() : QApplication::style();
    style->drawControl(QStyle::CE_ItemViewItem, &item, painter, widget);
    // the margin the style leaves before a plain text (QCommonStyle's item text margin)
    const int margin = style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, widget) + 1;
    const QRect room = style->subElementRect(QStyle::SE_ItemViewItemText, &item, widget).adjusted(margin, 0, -margin, 0);
    const bool selected = item.state & QStyle::State_Selected;
    drawSymbolText(painter, room, text, item.font,
                   item.palette.color(selected ? QPalette::HighlightedText : QPalette::Text));
}

QSize SymbolDelegate::sizeHint(const QStyleOptionViewItem &option, const QModelIndex &index) const
{
    QSize size = QStyledItemDelegate::sizeHint(option, index);
    QStyleOptionViewItem item = option;
    initStyleOption(&item, index);
    // Only a mark over a letter stands above the line (ḋ, Ẋ, a combining mark): the ink of
    // other texts is not measured, a values panel asks for every row's size on each move.
    const bool marked = std::any_of(item.text.cbegin(), item.text.cend(), [](QChar c) {
        return (c.unicode() >= 0x0300 && c.unicode() <= 0x036F) || (c.unicode() >= 0x1E00 && c.unicode() <= 0x1EFF);
    });
    if (!marked)
        return size;
    // The style's row is the font's line height; a mark over a capital (Ẋ) stands above the
    // line's ascent and would be cut off by the row above it. The text is centred in its row,
    // so the row grows by twice the larger overhang.
    const QFontMetrics metrics(item.font);
    const QRect ink = metrics.tightBoundingRect(spelledDots(item.text));
    const int overhang = std::max({0, -ink.top() - metrics.ascent(), ink.bottom() - metrics.descent()});
    if (overhang > 0)
        size.setHeight(std::max(size.height(), metrics.height() + 2 * overhang + 2));
    return size;
}

SymbolComboBox::SymbolComboBox(QWidget *parent)
    : QComboBox(parent)
{
    // the list's entries alike; the delegate's rows are as tall as the style's menu rows
    setItemDelegate(new SymbolDelegate(this));
}

void SymbolComboBox::paintEvent(QPaintEvent *event)
{
    QStyleOptionComboBox option;
    initStyleOption(&option);
    if (!option.currentText.contains(QLatin1Char('_')) || isEditable()) {
        QComboBox::paintEvent(event);
        return;
    }
    // QComboBox::paintEvent() without its text: the frame, the arrow and an icon, then the
    // lowered text where the style would put the plain one.
    QStylePainter painter(this);
    painter.setPen(palette().color(QPalette::Text));
    painter.drawComplexControl(QStyle::CC_ComboBox, option);
    const QString text = option.currentText;
    option.currentText.clear();
    painter.drawControl(QStyle::CE_ComboBoxLabel, option);
    QRect room = style()->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, this);
    if (!option.currentIcon.isNull())
        room.setLeft(room.left() + option.iconSize.width() + 4);
    room.adjust(1, 0, -1, 0); // QCommonStyle's CE_ComboBoxLabel leaves a pixel each side
    const QColor colour = palette().color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::ButtonText);
    drawSymbolText(&painter, room, text, font(), colour);
}

// -- numbers with a typographic minus ------------------------------------------------------

QString typographicMinus(QString text)
{
    return text.replace(QLatin1Char('-'), QChar(0x2212));
}

QString plainMinus(QString text)
{
    return text.replace(QChar(0x2212), QLatin1Char('-'));
}

QString NumberSpinBox::textFromValue(double value) const
{
    return typographicMinus(QDoubleSpinBox::textFromValue(value));
}

double NumberSpinBox::valueFromText(const QString &text) const
{
    return QDoubleSpinBox::valueFromText(plainMinus(text));
}

QValidator::State NumberSpinBox::validate(QString &input, int &pos) const
{
    // Qt's validator reads only "-"; one character for another keeps the cursor where it is.
    QString plain = plainMinus(input);
    QValidator::State state = QDoubleSpinBox::validate(plain, pos);
    input = typographicMinus(plain);
    // A number past the range is typed on, not cut: "199" where the range ends at 196.1
    // kept "19". Entered, it stops at the range's end (fixup()).
    if (state == QValidator::Invalid && beyondRange(plain))
        state = QValidator::Intermediate;
    return state;
}

std::optional<double> NumberSpinBox::beyondRange(const QString &plain) const
{
    QString body = plain;
    if (!prefix().isEmpty() && body.startsWith(prefix()))
        body.remove(0, prefix().size());
    if (!suffix().isEmpty() && body.endsWith(suffix()))
        body.chop(suffix().size());
    body = body.trimmed();
    bool ok = false;
    const double value = locale().toDouble(body, &ok);
    const qsizetype point = body.indexOf(locale().decimalPoint());
    const bool fewDecimals = point < 0 || body.size() - point - 1 <= decimals();
    if (!ok || !std::isfinite(value) || !fewDecimals || body.contains(locale().groupSeparator())
        || (value >= minimum() && value <= maximum()))
        return std::nullopt;
    return std::clamp(value, minimum(), maximum());
}

void NumberSpinBox::fixup(QString &input) const
{
    // Qt's own correction of a number past the range goes to the bound nearest zero.
    if (const std::optional<double> end = beyondRange(plainMinus(input))) {
        input = prefix() + textFromValue(*end) + suffix();
        return;
    }
    QString plain = plainMinus(input);
    QDoubleSpinBox::fixup(plain);
    input = typographicMinus(plain);
}

} // namespace pkm
