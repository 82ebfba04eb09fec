#pragma once
/// The design panel: one field per design parameter, built from the mechanism's
/// ParameterInfo, grouped (geometry, range, actuator, drawing). It shows a design and emits
/// edits; whether an edit is valid is the document's answer, shown back with markInvalid().

#include "mechanism.h"

#include <QHash>
#include <QStringList>
#include <QVector>
#include <QWidget>

class QGridLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QVBoxLayout;

namespace pkm {

class DesignPanel : public QWidget
{
    Q_OBJECT

public:
    explicit DesignPanel(QWidget *parent = nullptr);

    /// Shows the design's values (rebuilding the fields when the kind changes) and clears marks;
    /// only the parameters that apply to the design have a visible field.
    void setMechanism(const MechanismPtr &mechanism);
    /// A note about the design shown above the fields (a preset's description: where its
    /// numbers come from, what is interpreted); empty hides it.
    void setNote(const QString &title, const QString &note);
    QString note() const { return m_noteText; }
    /// Marks a field invalid with the reason; the field keeps the text the user typed.
    void markInvalid(const QString &name, const QString &message);

    QLineEdit *field(const QString &name) const { return m_fields.value(name); }
    QString message() const;

signals:
    /// A number was entered (display units). `continuous`: a step with arrow keys or wheel.
    void parameterEdited(const QString &name, double displayValue, bool continuous);

protected:
    bool event(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    /// One field: its parameter (index into parameterInfo()) and the widgets that show it.
    struct Row {
        int parameter = 0;
        QLabel *label = nullptr;
        QLineEdit *edit = nullptr;
        QLabel *unit = nullptr;
        QWidget *field = nullptr; ///< the field and its unit
        QGridLayout *form = nullptr; ///< its group's grid
        bool ownLine = false; ///< a long label, on a line of its own above its field
    };
    void rebuild();
    /// Sets every text again in the current language: group titles, labels, units, tooltips,
    /// the values in the locale's form (a field being typed into or marked invalid keeps its
    /// text), the warnings, the note's link and the message.
    void retranslate();
    /// Gives every unit the width of the widest one shown, so they line up.
    void alignUnits();
    /// Puts the rows into their groups' grids: each label beside its field, or (`stacked`, or
    /// a long label) on a line of its own above it.
    void placeRows(bool stacked);
    /// How wide the panel must be for every label beside its field.
    int sideBySideWidth() const;
    /// Stacks the rows when the panel in sight is narrower than that (designpanelnote.cpp).
    void fitRows();
    /// The label, unit and tooltip of one field.
    void describe(const Row &row);
    void showWarnings();
    void showMessage();
    void commit(const QString &name, bool continuous);
    void step(const QString &name, int steps);
    void showValues();
    /// Shows the fields of the parameters that apply to the design (parameterApplies) and hides
    /// the others, and a group with none.
    void showApplicable();
    void setMark(QLineEdit *field, bool invalid);
    void showNote();
    /// The note's first sentence (all of it when it has one sentence).
    QString firstSentence() const;
    /// The title alone where the first sentence would take much of the panel in sight.
    void fitNote();

    MechanismPtr m_mechanism;
    QVBoxLayout *m_groups = nullptr;
    QHash<QString, QLineEdit *> m_fields;
    QVector<Row> m_rows;
    QHash<int, QGroupBox *> m_boxes; ///< by ParameterGroup
    QLabel *m_message = nullptr;
    /// What the message says, without "The last valid design is kept.": the document's reason
    /// (kept as given) or, for a field that is not a number, that field (said again in the
    /// current language).
    QString m_messageReason;
    QString m_notNumberField;
    QString m_notNumberText;
    QLabel *m_note = nullptr;
    QString m_noteTitle;
    QString m_noteText;
    bool m_noteExpanded = false;
    bool m_noteCompact = false;
    QWidget *m_viewport = nullptr; ///< what shows the panel (a scroll area's viewport)
    bool m_stacked = false; ///< each field under its label (fitRows())
    QLabel *m_warnings = nullptr;
};

} // namespace pkm
