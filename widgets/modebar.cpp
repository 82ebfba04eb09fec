#include "modebar.h"

#include "flowlayout.h"

#include <QEvent>
#include <QLabel>
#include <QPushButton>

namespace pkm {

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

void ModeBar::setModes(const QString &current, const QStringList &labels)
{
    setVisible(!current.isEmpty() || !labels.isEmpty());
    m_currentText = current;
    if (labels != m_labels) {
        m_labels = labels;
        qDeleteAll(m_buttonList);
        m_buttonList.clear();
        for (int i = 0; i < labels.size(); ++i) {
            auto *button = new QPushButton(this);
            button->setObjectName(QStringLiteral("modeButton%1").arg(i));
            connect(button, &QPushButton::clicked, this, [this, i] { emit switchRequested(i); });
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
        // the short form on the button ("other assembly mode"), the whole label in the tooltip
        const QString brief = m_labels[i].section(QStringLiteral(" ("), 0, 0);
        m_buttonList[i]->setText(tr("→ %1").arg(brief));
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

QPushButton *ModeBar::button(int index) const
{
    return index >= 0 && index < m_buttonList.size() ? m_buttonList[index] : nullptr;
}

} // namespace pkm
