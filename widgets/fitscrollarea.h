#pragma once
/// A column of texts that takes the height its words need at the width it is given, and
/// scrolls (up and down only) where the window has less: the four-bar's class and range in
/// words, beside the transmission gauge and above the plots, needed 180 px in Russian at
/// 1024×768 and had 80, cut off in the middle of a sentence. A scroll area's own size hint
/// guesses its content's height at another width; this one asks the content at its own.

#include <QScrollArea>

namespace pkm {

class FitScrollArea : public QScrollArea
{
public:
    /// `content` becomes the area's widget; the area draws no frame of its own.
    explicit FitScrollArea(QWidget *content, QWidget *parent = nullptr);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    /// The content's least width.
    int contentWidth() const;
    /// The content's height at the viewport's width (its whole text, wrapped there).
    int contentHeight() const;
};

} // namespace pkm
