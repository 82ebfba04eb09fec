#include "wraplabel.h"

#include <algorithm>

namespace pkm {

WrapLabel::WrapLabel(int lines, QWidget *parent)
    : QLabel(parent)
    , m_lines(std::max(lines, 1))
{
    setWordWrap(true);
}

QSize WrapLabel::minimumSizeHint() const
{
    const QSize least = QLabel::minimumSizeHint();
    if (!wordWrap() || text().isEmpty())
        return least;
    const int width = std::max(least.width(), widthForLines(this, m_lines));
    return {width, std::max(least.height(), heightForWidth(width))};
}

int WrapLabel::widthForLines(const QLabel *label, int lines)
{
    // The label's own layout decides where the text breaks (rich text, margins): the least
    // width whose height is that of `lines` lines, found by halving (a height never grows
    // with the width).
    const int oneLine = label->heightForWidth(QWIDGETSIZE_MAX);
    if (oneLine <= 0)
        return label->QLabel::minimumSizeHint().width();
    const int allowed = oneLine + (lines - 1) * label->fontMetrics().lineSpacing();
    int narrow = label->QLabel::minimumSizeHint().width(), wide = std::max(narrow, 1);
    while (label->heightForWidth(wide) > allowed && wide < 8192)
        wide *= 2;
    if (label->heightForWidth(narrow) <= allowed)
        return narrow;
    while (wide - narrow > 1) { // heightForWidth(narrow) > allowed >= heightForWidth(wide)
        const int middle = (narrow + wide) / 2;
        (label->heightForWidth(middle) > allowed ? narrow : wide) = middle;
    }
    return wide;
}

} // namespace pkm
