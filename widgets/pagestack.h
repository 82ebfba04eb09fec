#pragma once
/// Pages one at a time that ask for the room of the page in sight only: QStackedWidget asks
/// for the largest of all its pages, so the kinds' panels that are not shown (the 3-P̲RR's legs
/// editor in Serbian, the four-bar's lengths one to a line) held the window's side panel
/// wider than the four-bar needed, and on a 1024×768 projector the docks beside it had too
/// little room for their tabs' titles. A page brought in sight asks again.

#include <QStackedWidget>

namespace pkm {

class PageStack : public QStackedWidget
{
public:
    explicit PageStack(QWidget *parent = nullptr);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
};

} // namespace pkm
