#pragma once
/// The design panel: one field per design parameter, built from the mechanism's
/// ParameterInfo, grouped (geometry, range, actuator, drawing). It shows a design and emits
/// edits; whether an edit is valid is the document's answer, shown back with markInvalid().

#include "mechanism.h"

#include <QHash>
#include <QWidget>

class QLabel;
class QLineEdit;
class QVBoxLayout;

namespace pkm {

class DesignPanel : public QWidget
{
    Q_OBJECT

public:
    explicit DesignPanel(QWidget *parent = nullptr);

    /// Shows the design's values (rebuilding the fields when the kind changes) and clears marks.
    void setMechanism(const MechanismPtr &mechanism);
    /// A note about the design shown above the fields (a preset's description: where its
    /// numbers come from, what is interpreted); empty hides it.
    void setNote(const QString &title, const QString &note);
    QString note() const;
    /// Marks a field invalid with the reason; the field keeps the text the user typed.
    void markInvalid(const QString &name, const QString &message);

    QLineEdit *field(const QString &name) const { return m_fields.value(name); }
    QString message() const;

signals:
    /// A number was entered (display units). `continuous`: a step with arrow keys or wheel.
    void parameterEdited(const QString &name, double displayValue, bool continuous);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void rebuild();
    void commit(const QString &name, bool continuous);
    void step(const QString &name, int steps);
    void showValues();
    void setMark(QLineEdit *field, bool invalid);
    void showNote();

    MechanismPtr m_mechanism;
    QVBoxLayout *m_groups = nullptr;
    QHash<QString, QLineEdit *> m_fields;
    QLabel *m_message = nullptr;
    QLabel *m_note = nullptr;
    QString m_noteTitle;
    QString m_noteText;
    bool m_noteExpanded = false;
    QLabel *m_warnings = nullptr;
};

/// Parses a number typed by a person: the locale's form or the C form ("0,4" and "0.4" in a
/// comma locale), with an optional trailing unit symbol. Returns false for anything else.
bool parseNumber(const QString &text, const QString &unitSymbol, double *value);

} // namespace pkm
