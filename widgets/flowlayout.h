#pragma once
/// A layout that places its items in a row, left to right, and starts a new row where the
/// width runs out — for rows of buttons whose texts are longer in some languages than in
/// others (the mode bar), so that they never widen the window or squeeze its docks. An item
/// whose height depends on its width (a word-wrapped label) wraps its text where a row is
/// narrower than its one line.

#include <QLayout>
#include <QList>

namespace pkm {

class FlowLayout : public QLayout
{
public:
    explicit FlowLayout(QWidget *parent = nullptr);
    ~FlowLayout() override;

    void addItem(QLayoutItem *item) override;
    int count() const override;
    QLayoutItem *itemAt(int index) const override;
    QLayoutItem *takeAt(int index) override;

    Qt::Orientations expandingDirections() const override;
    bool hasHeightForWidth() const override;
    int heightForWidth(int width) const override;
    QSize minimumSize() const override;
    QSize sizeHint() const override;
    void setGeometry(const QRect &rect) override;

private:
    /// Lays the items out in `rect` (moves them if `apply`); returns the height needed.
    int arrange(const QRect &rect, bool apply) const;
    int gap() const;

    QList<QLayoutItem *> m_items;
};

} // namespace pkm
