#pragma once
/// A row under the joint sliders that names the current working/assembly modes and offers the
/// other modes reachable at this pose as buttons. The mechanism changes mode only through a
/// click here or on a ghost in the linkage view — never by itself.

#include <QStringList>
#include <QWidget>

class QAbstractButton;
class QLabel;

namespace pkm {

class FlowLayout;

class ModeBar : public QWidget
{
    Q_OBJECT

public:
    explicit ModeBar(QWidget *parent = nullptr);

    /// `current` describes the modes the design is in ("β₁ = −1, β₂ = −1, σ = −1"); `labels`
    /// the alternatives at this pose. Buttons are rebuilt only when the labels change.
    void setModes(const QString &current, const QStringList &labels);
    QStringList labels() const { return m_labels; }
    QAbstractButton *button(int index) const;

signals:
    void switchRequested(int index);
    /// The pointer came onto the button of alternative `index`, or left it (−1): the linkage
    /// view shows that mode's ghost in front of the others.
    void hovered(int index);

protected:
    void changeEvent(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    /// "Modes: …" and the buttons' texts in the current language.
    void retranslate();
    /// Takes a button or caption out of the bar and deletes it once control is back in the
    /// event loop.
    void retire(QWidget *widget);
    /// In a group of numbered modes, the mode the mechanism is in, pressed among the others.
    void showCurrentNumbers();
    /// Before the buttons change: whether they all go.
    void keepRowHeight(bool buttonsGo);

    QLabel *m_current = nullptr;
    QString m_currentText;
    FlowLayout *m_layout = nullptr;
    QStringList m_labels;
    QList<QAbstractButton *> m_buttonList;
    QList<QWidget *> m_groups;     ///< the groups of numbered modes: a caption and its buttons
    QList<QLabel *> m_groupLabels; ///< the captions of the groups of numbered modes
    QList<int> m_groupOf;          ///< per button, its group's caption (−1: none)
    QList<QAbstractButton *> m_currentButtons; ///< showCurrentNumbers()
};

} // namespace pkm
