#pragma once
/// Rows of a grid (a label, a slider and a field each) two to a line where their box is wide
/// enough for that, one to a line where it is not: the four-bar's link lengths two to a line
/// asked 473 px of a Russian window, more than a 1024×768 projector leaves beside the docks.
/// The box asks only for the width of one to a line, so a narrow window can have it.

#include <QObject>

#include <vector>

class QGridLayout;
class QWidget;

namespace pkm {

class GridReflow : public QObject
{
public:
    /// `rows` in `grid` (the layout of `box`), each the widgets of one row in column order;
    /// `stretchColumn`: the column of a row that takes the spare width; `gap`: the room
    /// between two rows on one line; `weights`: how the spare width is shared between two rows
    /// on one line (each row's weight, 1 each when empty).
    GridReflow(QWidget *box, QGridLayout *grid, std::vector<std::vector<QWidget *>> rows, int stretchColumn, int gap,
        std::vector<int> weights = {});
    /// Works out again how wide the box must be for each arrangement, after a change of text
    /// (nothing is laid out again where no row's least width changed).
    void refit();
    int perLine() const { return m_perLine; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void place(int perLine);
    void follow();

    QWidget *m_box;
    QGridLayout *m_grid;
    std::vector<std::vector<QWidget *>> m_rows;
    int m_stretchColumn;
    int m_gap;
    std::vector<int> m_weights;
    int m_perLine = 0;
    int m_twoWide = 0; ///< the box's least width with two rows to a line
    std::vector<int> m_fittedWidths; ///< the rows' widgets' least widths at the last refit()
};

} // namespace pkm
