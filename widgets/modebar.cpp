#include "modebar.h"

#include "wraplabel.h"

#include "flowlayout.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>
#include <QRegularExpression>

#include <algorithm>
#include <optional>

namespace pkm {

namespace {
const char *indexProperty = "pkmModeIndex"; ///< a button's alternative

/// The short form of a mode's label, for its button: "other assembly mode" of "other assembly
/// mode (same inputs)".
QString brief(const QString &label)
{
    return label.section(QStringLiteral(" ("), 0, 0);
}

/// A mode told apart from its neighbours by a number only: "assembly mode 3" (a 3-RP̲R's six
/// assembly modes) or "leg 2: other working mode" (one per leg). Modes with the same `key`
/// share one caption, and their buttons show the numbers.
struct Numbered {
    QString key;
    QString prefix; ///< "assembly mode"; "leg"
    QString what;   ///< empty; "other working mode"
    QString number;
};

std::optional<Numbered> numbered(const QString &label)
{
    static const QRegularExpression trailing(QStringLiteral("^(.*\\S)\\s+(\\d+)$"));
    static const QRegularExpression leading(QStringLiteral("^(\\S+)\\s+(\\d+):\\s+(.*\\S)$"));
    const QString text = brief(label);
    if (const QRegularExpressionMatch match = trailing.match(text); match.hasMatch())
        return Numbered {match.captured(1), match.captured(1), {}, match.captured(2)};
    if (const QRegularExpressionMatch match = leading.match(text); match.hasMatch())
        return Numbered {match.captured(1) + QLatin1Char('|') + match.captured(3), match.captured(1), match.captured(3),
            match.captured(2)};
    return std::nullopt;
}

/// Whether the labels at `i` and `j` are numbered modes of one group.
bool sameGroup(const QStringList &labels, qsizetype i, qsizetype j)
{
    if (j < 0 || j >= labels.size())
        return false;
    const std::optional<Numbered> a = numbered(labels[i]), b = numbered(labels[j]);
    return a && b && a->key == b->key;
}
/// A word-wrapped label that would rather be one line: QLabel's own hint for a wrapped text
/// is a guess that took two lines where one fitted, and the sliders under it lost a line.
class OneLineLabel : public QLabel
{
public:
    using QLabel::QLabel;
    QSize sizeHint() const override
    {
        const int width = WrapLabel::widthForLines(this, 1);
        return {width, heightForWidth(width)};
    }
};
} // namespace

ModeBar::ModeBar(QWidget *parent)
    : QWidget(parent)
{
    // The label and the buttons in rows that wrap: in a longer language they take a second
    // row rather than widen the window's middle and squeeze the docks.
    m_layout = new FlowLayout(this);
    m_layout->setContentsMargins(6, 2, 6, 2);
    m_current = new OneLineLabel(this);
    m_current->setTextFormat(Qt::PlainText);
    // "Режимы: β₁ = впереди, β₂ = впереди, σ = справа" on two lines in a narrow window
    // rather than widen it past a 1024×768 projector; on one where there is room
    m_current->setWordWrap(true);
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
        keepRowHeight(labels.isEmpty());
        m_labels = labels;
        emit hovered(-1); // the buttons go, the one under the pointer too
        // Later, not now: this runs inside the clicked() of one of these buttons (a switch
        // changes the modes), and a button deleted in its own signal is used after it is freed.
        for (QWidget *old : std::as_const(m_buttonList))
            retire(old);
        m_buttonList.clear();
        for (QWidget *old : std::as_const(m_groups))
            retire(old);
        m_groups.clear();
        m_currentButtons.clear(); // in the groups, which go
        m_groupLabels.clear();
        m_groupOf.clear();
        for (int i = 0; i < labels.size(); ++i) {
            // Modes that differ only by a number (a 3-RP̲R's six assembly modes, a leg's working
            // mode) share one caption, "→ assembly mode:", and their buttons show the numbers:
            // one short row instead of several long ones, which a projector at a large text
            // size and the five-bar's view at 1280×720 need.
            const bool inGroup = sameGroup(labels, i, i - 1) || sameGroup(labels, i, i + 1);
            const bool opens = inGroup && !sameGroup(labels, i, i - 1);
            if (opens) {
                // The caption and its numbers wrap as one: "1 2" alone on a third row named
                // nothing (the Russian five-bar in presentation mode).
                auto *group = new QWidget(this);
                auto *row = new QHBoxLayout(group);
                row->setContentsMargins(0, 0, 0, 0);
                auto *caption = new QLabel(group);
                caption->setTextFormat(Qt::PlainText);
                row->addWidget(caption);
                m_layout->addWidget(group);
                m_groups.append(group);
                m_groupLabels.append(caption);
            }
            m_groupOf.append(inGroup ? int(m_groupLabels.size()) - 1 : -1);
            // a number on a tool button, as wide as it needs: a push button is never narrower
            // than about 80 px, and five of them took two rows at 1280×720
            QAbstractButton *button = inGroup ? static_cast<QAbstractButton *>(new QToolButton(m_groups.last()))
                                              : new QPushButton(this);
            button->setObjectName(QStringLiteral("modeButton%1").arg(i));
            connect(button, &QAbstractButton::clicked, this, [this, i] { emit switchRequested(i); });
            button->setProperty(indexProperty, i);
            button->installEventFilter(this);
            if (inGroup)
                m_groups.last()->layout()->addWidget(button);
            else
                m_layout->addWidget(button);
            m_buttonList.append(button);
        }
        showCurrentNumbers();
    }
    retranslate();
}

void ModeBar::showCurrentNumbers()
{
    // "→ assembly mode: 1 2 3 4 6" read as if mode 5 were missing: the group's numbers are the
    // other modes of 1 … n + 1, so the one left out is the mode the mechanism is in, shown
    // pressed among them. Only where the number names the mode ("assembly mode 5"), not a leg
    // ("leg 2: other working mode", where a strut's leg has none).
    for (int g = 0; g < m_groups.size(); ++g) {
        QList<int> numbers;
        for (int i = 0; i < m_labels.size(); ++i) {
            const std::optional<Numbered> mode = m_groupOf[i] == g ? numbered(m_labels[i]) : std::nullopt;
            if (mode && mode->what.isEmpty())
                numbers << mode->number.toInt();
        }
        QList<int> missing;
        for (int n = 1; n <= numbers.size() + 1; ++n) {
            if (!numbers.contains(n))
                missing << n;
        }
        if (numbers.isEmpty() || missing.size() != 1)
            continue;
        auto *current = new QToolButton(m_groups[g]);
        current->setObjectName(QStringLiteral("currentModeButton"));
        current->setText(QString::number(missing.front()));
        current->setCheckable(true);
        current->setChecked(true);
        current->setFocusPolicy(Qt::NoFocus);
        connect(current, &QAbstractButton::toggled, current, [current] { current->setChecked(true); }); // stays in
        const int before = int(std::count_if(numbers.begin(), numbers.end(), [&](int n) { return n < missing.front(); }));
        static_cast<QHBoxLayout *>(m_groups[g]->layout())->insertWidget(1 + before, current); // after the caption
        m_currentButtons.append(current);
    }
}

void ModeBar::retranslate()
{
    for (QAbstractButton *current : std::as_const(m_currentButtons))
        current->setToolTip(tr("The mode the mechanism is in."));
    m_current->setText(m_currentText.isEmpty() ? QString() : tr("Modes: %1").arg(m_currentText));
    for (int i = 0; i < m_buttonList.size(); ++i) {
        // the short form on the button ("other assembly mode"), the whole label in the tooltip;
        // in a group, the number on the button and the rest on the group's caption
        const std::optional<Numbered> mode = m_groupOf[i] >= 0 ? numbered(m_labels[i]) : std::nullopt;
        if (mode) {
            //: groups of mode buttons named by numbers: "→ assembly mode:" [1] [2] …, "→ other working mode, leg:" [1] [2]
            m_groupLabels[m_groupOf[i]]->setText(
                mode->what.isEmpty() ? tr("→ %1:").arg(mode->prefix) : tr("→ %1, %2:").arg(mode->what, mode->prefix));
            m_buttonList[i]->setText(mode->number);
        } else {
            m_buttonList[i]->setText(tr("→ %1").arg(brief(m_labels[i])));
        }
        m_buttonList[i]->setToolTip(tr("Switch to %1. The mechanism stays in its mode until you click here or on "
                                       "its ghost in the view.")
                                        .arg(m_labels[i]));
    }
}

void ModeBar::keepRowHeight(bool buttonsGo)
{
    // When Play passes a pose with no other mode (the 3-R̲RR), the button beside "Modes: …"
    // went, and everything below moved up 8 px and back: the line alone keeps the height of
    // the row it shared. With buttons it needs none (on a row of its own above them, the
    // 3-P̲RR's sliders at 1280×720 have no pixel to spare).
    if (!buttonsGo) {
        m_current->setMinimumHeight(0);
        return;
    }
    QLayoutItem *next = m_layout->count() > 1 ? m_layout->itemAt(1) : nullptr;
    if (next && next->geometry().top() < m_current->geometry().bottom())
        m_current->setMinimumHeight(std::max(m_current->height(), next->geometry().height()));
}

void ModeBar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

bool ModeBar::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Enter || event->type() == QEvent::Leave) {
        const QVariant index = watched->property(indexProperty);
        if (index.isValid())
            emit hovered(event->type() == QEvent::Enter ? index.toInt() : -1);
    }
    return QWidget::eventFilter(watched, event);
}

QAbstractButton *ModeBar::button(int index) const
{
    return index >= 0 && index < m_buttonList.size() ? m_buttonList[index] : nullptr;
}

} // namespace pkm
