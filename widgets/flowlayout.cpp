#include "flowlayout.h"

#include <QStyle>
#include <QWidget>

#include <algorithm>

namespace pkm {

FlowLayout::FlowLayout(QWidget *parent)
    : QLayout(parent)
{
}

FlowLayout::~FlowLayout()
{
    while (QLayoutItem *item = takeAt(0))
        delete item;
}

void FlowLayout::addItem(QLayoutItem *item)
{
    m_items.append(item);
}

int FlowLayout::count() const
{
    return static_cast<int>(m_items.size());
}

QLayoutItem *FlowLayout::itemAt(int index) const
{
    return m_items.value(index);
}

QLayoutItem *FlowLayout::takeAt(int index)
{
    if (index < 0 || index >= m_items.size())
        return nullptr;
    return m_items.takeAt(index);
}

Qt::Orientations FlowLayout::expandingDirections() const
{
    return {};
}

bool FlowLayout::hasHeightForWidth() const
{
    return true;
}

int FlowLayout::heightForWidth(int width) const
{
    return arrange(QRect(0, 0, width, 0), false);
}

QSize FlowLayout::minimumSize() const
{
    // one item to a row at the narrowest: as wide as the widest item at its least (a button
    // or a label as wide as its text; a text that wraps, the Russian modes line, as its
    // longest word; a list as narrow as its size policy lets it be)
    QSize size;
    for (const QLayoutItem *item : m_items) {
        if (!item->isEmpty())
            size = size.expandedTo(item->minimumSize());
    }
    const QMargins margins = contentsMargins();
    return size + QSize(margins.left() + margins.right(), margins.top() + margins.bottom());
}

QSize FlowLayout::sizeHint() const
{
    // all in one row
    int width = 0, height = 0, shown = 0;
    for (const QLayoutItem *item : m_items) {
        if (item->isEmpty())
            continue;
        const QSize hint = item->sizeHint();
        width += hint.width() + (shown++ > 0 ? gap() : 0);
        height = std::max(height, hint.height());
    }
    const QMargins margins = contentsMargins();
    return {width + margins.left() + margins.right(), height + margins.top() + margins.bottom()};
}

void FlowLayout::setGeometry(const QRect &rect)
{
    QLayout::setGeometry(rect);
    arrange(rect, true);
}

int FlowLayout::gap() const
{
    if (spacing() >= 0)
        return spacing();
    const QWidget *widget = parentWidget();
    const int styled = widget ? widget->style()->pixelMetric(QStyle::PM_LayoutHorizontalSpacing, nullptr, widget) : -1;
    return styled >= 0 ? styled : 6;
}

int FlowLayout::arrange(const QRect &rect, bool apply) const
{
    const QRect area = rect.marginsRemoved(contentsMargins());
    struct Placed {
        QLayoutItem *item;
        QSize size;
    };
    QList<QList<Placed>> rows(1);
    int x = 0;
    for (QLayoutItem *item : m_items) {
        if (item->isEmpty())
            continue;
        QSize size = item->sizeHint().boundedTo(QSize(std::max(area.width(), 1), item->maximumSize().height()));
        // a text that wraps, narrower than it would like, takes the lines it needs
        if (item->hasHeightForWidth() && size.width() < item->sizeHint().width())
            size.setHeight(item->heightForWidth(size.width()));
        if (!rows.last().isEmpty() && x + gap() + size.width() > area.width()) {
            rows.append(QList<Placed>());
            x = 0;
        }
        x += (rows.last().isEmpty() ? 0 : gap()) + size.width();
        rows.last().append({item, size});
    }
    int y = area.top();
    for (const QList<Placed> &row : rows) {
        int height = 0;
        for (const Placed &placed : row)
            height = std::max(height, placed.size.height());
        int left = area.left();
        for (const Placed &placed : row) {
            if (apply) // centred in the row's height: a label beside taller buttons
                placed.item->setGeometry(
                    QRect(QPoint(left, y + (height - placed.size.height()) / 2), placed.size));
            left += placed.size.width() + gap();
        }
        y += height + (row.isEmpty() ? 0 : gap());
    }
    const QMargins margins = contentsMargins();
    return y - gap() - area.top() + margins.top() + margins.bottom();
}

} // namespace pkm
