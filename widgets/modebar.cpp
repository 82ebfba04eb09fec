#include "modebar.h"

#include "flowlayout.h"

#include <QEvent>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>
#include <QRegularExpression>

namespace pkm {

namespace {
/// The short form of a mode's label, for its button: "other assembly mode" of "other assembly
/// mode (same inputs)".
QString brief(const QString &label)
{
    return label.section(QStringLiteral(" ("), 0, 0);
}

/// "assembly mode" and "3" of "assembly mode 3": modes told apart by a number only.
bool numbered(const QString &label, QString *prefix = nullptr, QString *number = nullptr)
{
    static const QRegularExpression pattern(QStringLiteral("^(.*\\S)\\s+(\\d+)$"));
    const QRegularExpressionMatch match = pattern.match(brief(label));
    if (prefix)
        *prefix = match.captured(1);
    if (number)
        *number = match.captured(2);
    return match.hasMatch();
}
} // namespace

ModeBar::ModeBar(QWidget *parent)
    : QWidget(parent)
{
    // The label and the buttons in rows that wrap: in a longer language they take a second
    // row rather than widen the window's middle and squeeze the docks.
    m_layout = new FlowLayout(this);
    m_layout->setContentsMargins(6, 2, 6, 2);
    m_current = new QLabel(this);
    m_current->setTextFormat(Qt::PlainText);
    m_layout->addWidget(m_current);
    setVisible(false);
}

void ModeBar::retire(QWidget *widget)
{
    m_layout->removeWidget(widget);
    widget->hide();
    widget->deleteLater();
}

void ModeBar::setModes(const QString &current, const QStringList &labels)
{
    setVisible(!current.isEmpty() || !labels.isEmpty());
    m_currentText = current;
    if (labels != m_labels) {
        m_labels = labels;
        // Later, not now: this runs inside the clicked() of one of these buttons (a switch
        // changes the modes), and a button deleted in its own signal is used after it is freed.
        for (QWidget *old : std::as_const(m_buttonList))
            retire(old);
        m_buttonList.clear();
        for (QWidget *old : std::as_const(m_groupLabels))
            retire(old);
        m_groupLabels.clear();
        m_groupOf.clear();
        for (int i = 0; i < labels.size(); ++i) {
            // Modes that differ only by a number (a 3-RP̲R's six assembly modes) share one
            // caption, "→ assembly mode:", and their buttons show the numbers: one short row
            // instead of two long ones, which a projector at a large text size needs.
            QString prefix, next;
            const bool inGroup = numbered(labels[i], &prefix)
                && ((i > 0 && numbered(labels[i - 1], &next) && next == prefix)
                    || (i + 1 < labels.size() && numbered(labels[i + 1], &next) && next == prefix));
            const bool opens = inGroup && (m_groupOf.isEmpty() || m_groupOf.last() < 0 || !numbered(labels[i - 1], &next) || next != prefix);
            if (opens) {
                auto *caption = new QLabel(this);
                caption->setTextFormat(Qt::PlainText);
                m_layout->addWidget(caption);
                m_groupLabels.append(caption);
            }
            m_groupOf.append(inGroup ? int(m_groupLabels.size()) - 1 : -1);
            // a number on a tool button, as wide as it needs: a push button is never narrower
            // than about 80 px, and five of them took two rows at 1280×720
            QAbstractButton *button = inGroup ? static_cast<QAbstractButton *>(new QToolButton(this)) : new QPushButton(this);
            button->setObjectName(QStringLiteral("modeButton%1").arg(i));
            connect(button, &QAbstractButton::clicked, this, [this, i] { emit switchRequested(i); });
            m_layout->addWidget(button);
            m_buttonList.append(button);
        }
    }
    retranslate();
}

void ModeBar::retranslate()
{
    m_current->setText(m_currentText.isEmpty() ? QString() : tr("Modes: %1").arg(m_currentText));
    for (int i = 0; i < m_buttonList.size(); ++i) {
        // the short form on the button ("other assembly mode"), the whole label in the tooltip;
        // in a group, the number on the button and the rest on the group's caption
        QString prefix, number;
        if (m_groupOf[i] >= 0 && numbered(m_labels[i], &prefix, &number)) {
            m_groupLabels[m_groupOf[i]]->setText(tr("→ %1:").arg(prefix));
            m_buttonList[i]->setText(number);
        } else {
            m_buttonList[i]->setText(tr("→ %1").arg(brief(m_labels[i])));
        }
        m_buttonList[i]->setToolTip(tr("Switch to %1. The mechanism stays in its mode until you click here or on "
                                       "its ghost in the view.")
                                        .arg(m_labels[i]));
    }
}

void ModeBar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

QAbstractButton *ModeBar::button(int index) const
{
    return index >= 0 && index < m_buttonList.size() ? m_buttonList[index] : nullptr;
}

} // namespace pkm
