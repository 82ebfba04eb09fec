// The design panel's note (a preset's title and description) and its rows' layout: a
// panel narrower than a label's longest word, a field and its unit side by side puts each
// field under its label rather than cut the lines at the panel's edge.
#include "designpanel.h"

#include "quantityformat.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLayout>
#include <QTextDocument>

#include <algorithm>

namespace pkm {

void DesignPanel::setNote(const QString &title, const QString &note)
{
    m_noteTitle = title;
    m_noteText = note;
    m_noteExpanded = false;
    showNote();
    fitNote();
}

QString DesignPanel::firstSentence() const
{
    // The first full stop that ends a sentence: one followed by a capital letter, so that
    // abbreviations before a number ("fig. 3a", "рис. 3a", "сл. 3a", "табл. 1") do not split.
    qsizetype end = m_noteText.indexOf(QStringLiteral(". "));
    while (end > 0 && (end + 2 >= m_noteText.size() || !m_noteText.at(end + 2).isUpper()))
        end = m_noteText.indexOf(QStringLiteral(". "), end + 2);
    return end > 0 && end + 2 < m_noteText.size() ? m_noteText.left(end + 1) : m_noteText;
}

void DesignPanel::showNote()
{
    if (m_noteText.isEmpty()) {
        m_note->clear();
        m_note->hide();
        return;
    }
    // The first sentence says what the design is (and whether it is interpreted); the rest
    // opens on request, so the fields stay in sight. On a short panel the title alone.
    const QString first = firstSentence();
    const bool longer = first.size() < m_noteText.size() || m_noteCompact;
    const QString link = QStringLiteral("<a href=\"#toggle\">%1</a>").arg(m_noteExpanded ? tr("less") : tr("more…"));
    QString text;
    if (m_noteExpanded || !longer)
        text = QStringLiteral("<br>") + m_noteText.toHtmlEscaped();
    else if (!m_noteCompact)
        text = QStringLiteral("<br>") + first.toHtmlEscaped();
    if (longer)
        text += QLatin1Char(' ') + link;
    m_note->setText(QStringLiteral("<b>%1</b>%2").arg(unbreakable(m_noteTitle).toHtmlEscaped(), text));
    m_note->setToolTip(m_noteText);
    m_note->show();
}

void DesignPanel::fitNote()
{
    // At 720 lines the panel has some 220 px, and a first sentence of six lines (the Russian
    // П-joint's) would hide the fields: past 40 % of the panel in sight, the title alone.
    bool compact = false;
    if (m_viewport && !m_noteText.isEmpty()) {
        QTextDocument document;
        document.setDefaultFont(m_note->font());
        const int frame = 2 * (m_note->frameWidth() + 5) + layout()->contentsMargins().left() + layout()->contentsMargins().right();
        document.setTextWidth(std::max(40, m_viewport->width() - frame));
        document.setHtml(QStringLiteral("<b>%1</b><br>%2").arg(m_noteTitle.toHtmlEscaped(), firstSentence().toHtmlEscaped()));
        compact = document.size().height() > 0.4 * m_viewport->height();
    }
    if (compact != m_noteCompact) {
        m_noteCompact = compact;
        showNote();
    }
}

void DesignPanel::alignUnits()
{
    // The units line up at the width of the widest one this design shows ("mm/корак" whole):
    // the width of "mm/step" for every design left a Russian or Serbian label beside "мм" too
    // little room, and the panel scrolled sideways with the ends of its lines out of sight.
    int widest = 0;
    for (const Row &row : std::as_const(m_rows))
        widest = std::max(widest, row.unit->fontMetrics().horizontalAdvance(row.unit->text()));
    // A field without a unit (a ratio, a list of named values) has no unit beside it: a
    // unit's empty room beside the 3-RP̲R's "постоянная ориентация" made the panel too wide.
    for (const Row &row : std::as_const(m_rows)) {
        row.unit->setMinimumWidth(widest);
        row.unit->setHidden(row.unit->text().isEmpty());
    }
}

void DesignPanel::placeRows(bool stacked)
{
    m_stacked = stacked;
    QHash<QGridLayout *, int> lines;
    for (const Row &row : std::as_const(m_rows)) {
        row.form->removeWidget(row.label);
        row.form->removeWidget(row.field);
    }
    for (const Row &row : std::as_const(m_rows)) {
        int &line = lines[row.form];
        if (stacked || row.ownLine) {
            row.form->addWidget(row.label, line, 0, 1, 2);
            row.form->addWidget(row.field, line + 1, 1);
            line += 2;
        } else {
            row.form->addWidget(row.label, line, 0);
            row.form->addWidget(row.field, line, 1);
            line += 1;
        }
    }
}

int DesignPanel::sideBySideWidth() const
{
    // The narrowest the panel could be with each label beside its field, as its grids lay the
    // rows out: a group's labels share one column and its fields the next, so the group is as
    // wide as its widest label plus its widest field, even where they are on different rows
    // (taking the widest row instead left a Serbian П-joint's panel 8 px short, every line
    // cut). A long label on its own line spans both columns; its field is in the second. The
    // note wraps to any width.
    struct Columns
    {
        int label = 0, field = 0, spanning = 0;
    };
    QHash<QGridLayout *, Columns> forms;
    for (const Row &row : std::as_const(m_rows)) {
        if (row.label->isHidden())
            continue;
        Columns &columns = forms[row.form];
        const int label = row.label->minimumSizeHint().width();
        (row.ownLine ? columns.spanning : columns.label) = std::max(row.ownLine ? columns.spanning : columns.label, label);
        columns.field = std::max(columns.field, row.field->minimumSizeHint().width());
    }
    int widest = 0;
    for (auto it = forms.cbegin(); it != forms.cend(); ++it) {
        const Columns &columns = it.value();
        const int beside = columns.label > 0 ? columns.label + it.key()->horizontalSpacing() : 0;
        const QMargins frame = it.key()->contentsMargins() + it.key()->parentWidget()->contentsMargins();
        widest = std::max(widest, std::max(beside + columns.field, columns.spanning) + frame.left() + frame.right());
    }
    const QMargins margins = layout()->contentsMargins();
    return widest + margins.left() + margins.right();
}

void DesignPanel::fitRows()
{
    if (m_rows.isEmpty() || !m_viewport)
        return;
    const bool stacked = m_viewport->width() < sideBySideWidth();
    if (stacked != m_stacked)
        placeRows(stacked);
}

} // namespace pkm
