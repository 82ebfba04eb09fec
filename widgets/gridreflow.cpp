#include "gridreflow.h"

#include <QEvent>
#include <QGridLayout>
#include <QTimer>
#include <QWidget>

namespace pkm {

GridReflow::GridReflow(QWidget *box, QGridLayout *grid, std::vector<std::vector<QWidget *>> rows, int stretchColumn, int gap,
    std::vector<int> weights)
    : QObject(box)
    , m_box(box)
    , m_grid(grid)
    , m_rows(std::move(rows))
    , m_stretchColumn(stretchColumn)
    , m_gap(gap)
    , m_weights(std::move(weights))
{
    box->installEventFilter(this);
    refit();
}

void GridReflow::place(int perLine)
{
    if (perLine == m_perLine)
        return;
    m_perLine = perLine;
    for (const auto &row : m_rows) {
        for (QWidget *widget : row)
            m_grid->removeWidget(widget);
    }
    const int width = m_rows.empty() ? 0 : int(m_rows.front().size()) + 1; // a row and the gap after it
    for (int column = 0; column < 2 * width; ++column) {
        m_grid->setColumnStretch(column, 0);
        m_grid->setColumnMinimumWidth(column, 0);
    }
    for (std::size_t r = 0; r < m_rows.size(); ++r) {
        const int line = int(r) / perLine, first = (int(r) % perLine) * width;
        for (std::size_t c = 0; c < m_rows[r].size(); ++c)
            m_grid->addWidget(m_rows[r][c], line, first + int(c));
        m_grid->setColumnStretch(first + m_stretchColumn, r < m_weights.size() ? m_weights[r] : 1);
        if (int(r) % perLine + 1 < perLine)
            m_grid->setColumnMinimumWidth(first + width - 1, m_gap);
    }
    m_grid->invalidate();
}

void GridReflow::refit()
{
    // Nothing to do where no row asks for another width than at the last fit (a four-bar's
    // words change with every length while a slider is dragged, their longest word seldom).
    std::vector<int> widths;
    for (const auto &row : m_rows) {
        for (const QWidget *widget : row)
            widths.push_back(widget->isHidden() ? -1 : widget->minimumSizeHint().width());
    }
    if (widths == m_fittedWidths && m_twoWide > 0)
        return;
    m_fittedWidths = std::move(widths);
    // The grid keeps what each row asked for until told: a text just set (a box of words) is
    // measured now, not at its next layout (the fit took the four-bar's words as empty)
    for (const auto &row : m_rows) {
        for (QWidget *widget : row)
            widget->updateGeometry();
    }
    // The box's least width each way, from its own layout; it then asks only for the
    // narrower, and takes two to a line once it is given the wider.
    m_box->setMinimumWidth(0);
    place(2);
    m_twoWide = m_box->minimumSizeHint().width();
    place(1);
    m_box->setMinimumWidth(m_box->minimumSizeHint().width());
    follow();
}

void GridReflow::follow()
{
    // Out of sight, two to a line: a page unseen counts in a QStackedWidget's least height,
    // and the four-bar's lengths one to a line there made the window 34 px taller than a
    // 1280×720 screen before anything was laid out (the window's own stack is a PageStack now).
    place(!m_box->isVisible() || m_box->width() >= m_twoWide ? 2 : 1);
}

bool GridReflow::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_box && (event->type() == QEvent::Resize || event->type() == QEvent::Show))
        follow();
    // Hidden, later: a box being destroyed hides itself, half gone already (its grid too)
    if (watched == m_box && event->type() == QEvent::Hide)
        QTimer::singleShot(0, this, &GridReflow::follow);
    return QObject::eventFilter(watched, event);
}

} // namespace pkm
