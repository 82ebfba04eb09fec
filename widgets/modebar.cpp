#include "modebar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace pkm {

ModeBar::ModeBar(QWidget *parent)
    : QWidget(parent)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 2, 6, 2);
    m_current = new QLabel(this);
    m_current->setTextFormat(Qt::PlainText);
    layout->addWidget(m_current);
    m_buttons = new QHBoxLayout;
    layout->addLayout(m_buttons);
    layout->addStretch(1);
    setVisible(false);
}

void ModeBar::setModes(const QString &current, const QStringList &labels)
{
    setVisible(!current.isEmpty() || !labels.isEmpty());
    m_current->setText(current.isEmpty() ? QString() : tr("Modes: %1").arg(current));
    if (labels == m_labels)
        return;
    m_labels = labels;
    qDeleteAll(m_buttonList);
    m_buttonList.clear();
    for (int i = 0; i < labels.size(); ++i) {
        // the short form on the button ("other assembly mode"), the whole label in the tooltip
        const QString brief = labels[i].section(QStringLiteral(" ("), 0, 0);
        auto *button = new QPushButton(tr("→ %1").arg(brief), this);
        button->setObjectName(QStringLiteral("modeButton%1").arg(i));
        button->setToolTip(tr("Switch to %1. The mechanism stays in its mode until you click here or on "
                              "its ghost in the view.")
                               .arg(labels[i]));
        connect(button, &QPushButton::clicked, this, [this, i] { emit switchRequested(i); });
        m_buttons->addWidget(button);
        m_buttonList.append(button);
    }
}

QPushButton *ModeBar::button(int index) const
{
    return index >= 0 && index < m_buttonList.size() ? m_buttonList[index] : nullptr;
}

} // namespace pkm
