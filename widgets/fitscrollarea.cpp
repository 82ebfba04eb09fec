#include "fitscrollarea.h"

#include <QEvent>
#include <QFrame>
#include <QResizeEvent>
#include <QScrollBar>

#include <algorithm>

namespace pkm {

FitScrollArea::FitScrollArea(QWidget *content, QWidget *parent)
    : QScrollArea(parent)
{
    setFrameShape(QFrame::NoFrame);
    setWidgetResizable(true);
    // Sideways would hide the end of every line: the content is never wider than the area.
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setWidget(content);
    // Transparent, so that the texts stand on the panel as they did without the area.
    viewport()->setAutoFillBackground(false);
    content->setAutoFillBackground(false);
    content->installEventFilter(this);
    QSizePolicy policy = sizePolicy();
    policy.setVerticalPolicy(QSizePolicy::Preferred);
    setSizePolicy(policy);
}

int FitScrollArea::contentWidth() const
{
    // as a layout takes it: the least width it was given, else the one it asks for (a
    // GridReflow's box asks for its rows two to a line, and takes one to a line if narrower)
    const QWidget *content = widget();
    if (!content)
        return 0;
    return content->minimumWidth() > 0 ? content->minimumWidth() : content->minimumSizeHint().width();
}

int FitScrollArea::contentHeight() const
{
    const QWidget *content = widget();
    if (!content)
        return 0;
    const int width = std::max(viewport()->width(), contentWidth());
    return content->hasHeightForWidth() ? content->heightForWidth(width) : content->sizeHint().height();
}

QSize FitScrollArea::sizeHint() const
{
    const QWidget *content = widget();
    if (!content)
        return QScrollArea::sizeHint();
    const QMargins frame = contentsMargins();
    return {content->sizeHint().width() + frame.left() + frame.right(), contentHeight() + frame.top() + frame.bottom()};
}

QSize FitScrollArea::minimumSizeHint() const
{
    const QWidget *content = widget();
    if (!content)
        return QScrollArea::minimumSizeHint();
    // As narrow as the content can be with the scroll bar beside it; as low as three lines
    // (less than that shows too little to be worth scrolling), or the whole content if less.
    const QMargins frame = contentsMargins();
    const int lines = 3 * fontMetrics().lineSpacing();
    return {contentWidth() + verticalScrollBar()->sizeHint().width() + frame.left() + frame.right(),
        std::min(contentHeight(), lines) + frame.top() + frame.bottom()};
}

bool FitScrollArea::eventFilter(QObject *watched, QEvent *event)
{
    // New texts (another design, another language) need another height: the layout asks again.
    if (watched == widget() && event->type() == QEvent::LayoutRequest)
        updateGeometry();
    return QScrollArea::eventFilter(watched, event);
}

void FitScrollArea::resizeEvent(QResizeEvent *event)
{
    QScrollArea::resizeEvent(event);
    // At another width the words wrap on more or fewer lines.
    if (event->size().width() != event->oldSize().width())
        updateGeometry();
}

} // namespace pkm
