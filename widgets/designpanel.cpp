#include "designpanel.h"

#include "parameterchoices.h"
#include "quantityformat.h"
#include "symboltext.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QKeyEvent>
#include <QLabel>
#include <QKeySequence>
#include <QLineEdit>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pkm {

namespace {
constexpr qsizetype longLabel = 40; ///< characters of the English label, past which it has a line
QString groupTitle(ParameterGroup group)
{
    switch (group) {
    case ParameterGroup::Geometry: return DesignPanel::tr("Geometry");
    case ParameterGroup::Range: return DesignPanel::tr("Motion range");
    case ParameterGroup::Actuator: return DesignPanel::tr("Actuator");
    case ParameterGroup::Drawing: return DesignPanel::tr("Motor body (drawing)");
    case ParameterGroup::Mode: return DesignPanel::tr("Modes");
    }
    return {};
}

/// The English label shown: a list of named values needs no list of their codes.
const std::string &labelSource(const ParameterInfo &info) { return info.listLabel.empty() ? info.label : info.listLabel; }

const ParameterInfo *parameterNamed(const MechanismPtr &mechanism, const QString &name)
{
    if (!mechanism)
        return nullptr;
    for (const ParameterInfo &info : mechanism->parameterInfo()) {
        if (toQString(info.name) == name)
            return &info;
    }
    return nullptr;
}

QString notNumberMessage(const QString &name, const QString &label, const QString &text)
{
    return DesignPanel::tr("%1 (%2): '%3' is not a number.").arg(name, label, text);
}

const char *nameProperty = "pkmParameter";
const char *helpProperty = "pkmHelp"; ///< the field's tooltip while it is valid
} // namespace

DesignPanel::DesignPanel(QWidget *parent)
    : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    // The message goes above the fields, where it is seen without scrolling the panel.
    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("QLabel { color: #b3261e; font-weight: bold; background: #fde7e5;"
                                            " border: 1px solid #b3261e; padding: 4px; }"));
    m_message->hide();
    layout->addWidget(m_message);
    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("designNote"));
    m_note->setWordWrap(true);
    m_note->setTextFormat(Qt::RichText);
    m_note->setStyleSheet(QStringLiteral("QLabel { background: #eef3f8; border: 1px solid #c5d3e0; padding: 4px; }"));
    m_note->hide();
    connect(m_note, &QLabel::linkActivated, this, [this] {
        m_noteExpanded = !m_noteExpanded;
        showNote();
    });
    layout->addWidget(m_note);
    m_groups = new QVBoxLayout;
    layout->addLayout(m_groups);
    m_warnings = new QLabel(this);
    m_warnings->setWordWrap(true);
    m_warnings->setStyleSheet(QStringLiteral("color: #8a5a00;"));
    m_warnings->hide();
    layout->addWidget(m_warnings);
    layout->addStretch(1);
}

void DesignPanel::setMechanism(const MechanismPtr &mechanism)
{
    const bool rebuildNeeded = !m_mechanism || m_mechanism->kind() != mechanism->kind();
    m_mechanism = mechanism;
    if (rebuildNeeded)
        rebuild();
    showValues();
}

void DesignPanel::rebuild()
{
    while (QLayoutItem *item = m_groups->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_fields.clear();
    m_rows.clear();
    m_boxes.clear();
    // A grid rather than a form: the label column takes all the width the fields leave, so
    // long labels (Russian, Serbian) wrap into as few lines as the dock allows.
    QHash<int, QGridLayout *> forms;
    const std::vector<ParameterInfo> &infos = m_mechanism->parameterInfo();
    for (int i = 0; i < static_cast<int>(infos.size()); ++i) {
        const ParameterInfo &info = infos[std::size_t(i)];
        const int group = static_cast<int>(info.group);
        if (!forms.contains(group)) {
            auto *box = new QGroupBox(groupTitle(info.group), this);
            auto *form = new QGridLayout(box);
            form->setColumnStretch(0, 1);
            m_groups->addWidget(box);
            forms.insert(group, form);
            m_boxes.insert(group, box);
        }
        const QString name = toQString(info.name);
        auto *rowWidget = new QWidget;
        auto *rowLayout = new QHBoxLayout(rowWidget);
        rowLayout->setContentsMargins(0, 0, 0, 0);
        Row row;
        row.parameter = i;
        // The values are short; a narrow field leaves the width to the label, which wraps less.
        const int width = fontMetrics().horizontalAdvance(QStringLiteral("−0000.0000")) + 2 * fontMetrics().averageCharWidth();
        if (info.choices.empty()) {
            row.edit = new QLineEdit(rowWidget);
            row.edit->setAlignment(Qt::AlignRight);
            row.edit->setFixedWidth(width);
            rowLayout->addWidget(row.edit);
        } else { // a list of the named values, whose field is its line edit
            QComboBox *box = choices::makeBox(info, width, rowWidget);
            row.edit = box->lineEdit();
            connect(box, &QComboBox::activated, this, [this, name] { commit(name, false); });
            rowLayout->addWidget(box);
        }
        row.edit->setObjectName(QStringLiteral("parameter_") + name);
        row.edit->setProperty(nameProperty, name);
        row.edit->installEventFilter(this);
        connect(row.edit, &QLineEdit::editingFinished, this, [this, name] { commit(name, false); });
        row.unit = new QLabel(rowWidget);
        rowLayout->addWidget(row.unit);
        rowLayout->addStretch(1); // a field without a unit (hidden) starts where the others do
        row.label = new QLabel;
        row.label->setWordWrap(true); // long labels wrap rather than push the fields out of the dock
        row.label->setBuddy(row.edit);
        describe(row);
        row.field = rowWidget;
        row.form = forms.value(group);
        // A label that explains a mode's values ("platform: 0 a point (2 DOF), 1 constant
        // orientation (2 DOF), 2 free (3 DOF)") took six lines of a word or two beside its
        // field: it has the whole width, and its field the line below.
        row.ownLine = toQString(labelSource(info)).size() > longLabel;
        m_fields.insert(name, row.edit);
        m_rows.append(row);
    }
    alignUnits();
    placeRows(false);
}

void DesignPanel::describe(const Row &row)
{
    const ParameterInfo &info = m_mechanism->parameterInfo()[std::size_t(row.parameter)];
    const QString name = toQString(info.name);
    const QString label = coreLabel(labelSource(info));
    const QString unit = unitText(info.unit);
    const QString range = info.domain.max == std::numeric_limits<double>::infinity()
                            ? tr("greater than %1").arg(QLocale().toString(info.unit.toDisplay(info.domain.min)))
                            : tr("between %1 and %2")
                                  .arg(QLocale().toString(info.unit.toDisplay(info.domain.min)),
                                       QLocale().toString(info.unit.toDisplay(info.domain.max)));
    // The name is the key of design files and of "pkm … --set NAME=VALUE", the same in every
    // language, so it comes on a line of its own.
    const QString help = tr("%1: %2. Up/Down or the mouse wheel step by %3.")
                             .arg(label, unit.isEmpty() ? range : range + QLatin1Char(' ') + unit,
                                  QLocale().toString(info.displayStep))
        + QLatin1Char('\n') + tr("Name in design files and on the command line: %1").arg(name);
    row.edit->setProperty(helpProperty, help);
    if (row.edit->styleSheet().isEmpty()) // an invalid field's tooltip says why
        row.edit->setToolTip(help);
    row.unit->setText(unit);
    // A symbol is the same in every language, unless it is a word ("form"), which core marks.
    row.label->setText(
        QStringLiteral("<b>%1</b>&nbsp; %2").arg(symbolHtml(coreLabel(info.symbol)), unbreakable(label).toHtmlEscaped()));
    row.label->setToolTip(help);
}

void DesignPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void DesignPanel::retranslate()
{
    showNote();
    fitNote();
    if (!m_mechanism)
        return;
    for (auto it = m_boxes.cbegin(); it != m_boxes.cend(); ++it)
        it.value()->setTitle(groupTitle(static_cast<ParameterGroup>(it.key())));
    const ParameterSet values = m_mechanism->parameters();
    for (const Row &row : std::as_const(m_rows)) {
        describe(row);
        if (auto *box = qobject_cast<QComboBox *>(row.edit->parentWidget()))
            choices::retranslateBox(box, m_mechanism->parameterInfo()[std::size_t(row.parameter)]);
        // The value in the new locale's form, unless the field holds what the user typed.
        const bool typing = row.edit->hasFocus() && row.edit->isModified();
        if (row.edit->styleSheet().isEmpty() && !typing)
            row.edit->setText(choices::fieldText(m_mechanism->parameterInfo()[std::size_t(row.parameter)], values));
    }
    alignUnits();
    fitRows();
    showWarnings();
    if (!m_message->isHidden())
        showMessage();
}

void DesignPanel::showApplicable()
{
    // Only what the design uses (a two-legged platform has no third leg): the rest stays in
    // the design, unseen, and comes back when it applies again.
    QHash<int, bool> used;
    for (const Row &row : std::as_const(m_rows)) {
        const ParameterInfo &info = m_mechanism->parameterInfo()[std::size_t(row.parameter)];
        const bool applies = m_mechanism->parameterApplies(info.name);
        row.label->setVisible(applies);
        row.edit->parentWidget()->setVisible(applies);
        used[int(info.group)] = used.value(int(info.group)) || applies;
    }
    for (auto it = m_boxes.cbegin(); it != m_boxes.cend(); ++it)
        it.value()->setVisible(used.value(it.key()));
    fitRows();
}

void DesignPanel::showValues()
{
    showApplicable();
    const ParameterSet values = m_mechanism->parameters();
    for (const ParameterInfo &info : m_mechanism->parameterInfo()) {
        QLineEdit *edit = m_fields.value(toQString(info.name));
        if (!edit)
            continue;
        choices::showInField(edit, choices::fieldText(info, values), values.at(info.name));
        setMark(edit, false);
    }
    m_message->hide();
    m_messageReason.clear();
    m_notNumberField.clear();
    m_notNumberText.clear();
    showWarnings();
}

void DesignPanel::showWarnings()
{
    // Core says them in the language of the moment (text::translate).
    QStringList warnings;
    for (const std::string &w : m_mechanism->designWarnings())
        warnings << QString::fromStdString(w);
    m_warnings->setText(warnings.join(QLatin1Char('\n')));
    m_warnings->setVisible(!warnings.isEmpty());
}

void DesignPanel::markInvalid(const QString &name, const QString &message)
{
    if (QLineEdit *edit = m_fields.value(name)) {
        setMark(edit, true);
        edit->setToolTip(message);
    }
    m_messageReason = message;
    m_notNumberField.clear();
    m_notNumberText.clear();
    showMessage();
}

void DesignPanel::showMessage()
{
    QString reason = m_messageReason;
    if (!m_notNumberField.isEmpty()) {
        // Said here, so it can be said again in another language.
        const ParameterInfo *info = parameterNamed(m_mechanism, m_notNumberField);
        reason = notNumberMessage(m_notNumberField, info ? coreLabel(info->label) : QString(), m_notNumberText);
        if (QLineEdit *edit = m_fields.value(m_notNumberField); edit && !edit->styleSheet().isEmpty())
            edit->setToolTip(reason);
    }
    m_message->setText(reason + QLatin1Char(' ') + tr("The last valid design is kept."));
    m_message->show();
}

QString DesignPanel::message() const
{
    return m_message->isVisible() ? m_message->text() : QString();
}

void DesignPanel::setMark(QLineEdit *field, bool invalid)
{
    field->setStyleSheet(invalid ? QStringLiteral("QLineEdit { background: #fde7e5; border: 2px solid #b3261e; }")
                                 : QString());
    if (!invalid)
        field->setToolTip(field->property(helpProperty).toString());
}

void DesignPanel::commit(const QString &name, bool continuous)
{
    QLineEdit *edit = m_fields.value(name);
    if (!edit || !m_mechanism)
        return;
    const ParameterSet values = m_mechanism->parameters();
    for (const ParameterInfo &info : m_mechanism->parameterInfo()) {
        if (toQString(info.name) != name)
            continue;
        double value = 0;
        // a mode may be typed or picked by its name ("X", "RP̲R"); else the unit as shown
        // ("мм") or its English symbol ("mm")
        const std::optional<double> named = choices::valueOf(info, edit->text());
        if (named)
            value = *named;
        else if (!parseNumber(edit->text(), QStringList {unitText(info.unit), toQString(info.unit.symbol)}, &value)) {
            const QString text = edit->text();
            markInvalid(name, notNumberMessage(name, coreLabel(info.label), text));
            m_notNumberField = name;
            m_notNumberText = text;
            return;
        }
        // An unchanged field (focus left without an edit) is not an edit.
        const double current = info.unit.toDisplay(values.at(info.name));
        if (!continuous && std::abs(value - current) <= 1e-12 * std::max(1.0, std::abs(current))
            && edit->styleSheet().isEmpty()) {
            if (!info.choices.empty()) // "free body", not the "2" typed or the "Free" of a file
                choices::showInField(edit, choices::fieldText(info, values), values.at(info.name));
            return;
        }
        emit parameterEdited(name, value, continuous);
        return;
    }
}

void DesignPanel::step(const QString &name, int steps)
{
    QLineEdit *edit = m_fields.value(name);
    for (const ParameterInfo &info : m_mechanism->parameterInfo()) {
        if (toQString(info.name) != name)
            continue;
        double value = info.unit.toDisplay(m_mechanism->parameters().at(info.name));
        // Step from the value itself (Up then Down comes back), rounded only to hide binary noise.
        const double scale = std::pow(10.0, info.decimals + 2);
        value = std::round((value + steps * info.displayStep) * scale) / scale;
        edit->setText(QLocale().toString(value, 'f', info.decimals + 2));
        commit(name, true);
        return;
    }
}

bool DesignPanel::event(QEvent *event)
{
    // New texts, a new design or a new font change how wide the rows need to be side by side:
    // the panel's layout asks again, and so do the rows (the viewport may not resize).
    if (event->type() == QEvent::LayoutRequest)
        fitRows();
    if (event->type() == QEvent::ParentChange) {
        if (m_viewport) // in a scroll area, the viewport shows the panel
            m_viewport->removeEventFilter(this);
        m_viewport = parentWidget();
        if (m_viewport)
            m_viewport->installEventFilter(this);
    }
    return QWidget::event(event);
}

bool DesignPanel::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_viewport) {
        if (event->type() == QEvent::Resize) {
            fitNote();
            fitRows();
        }
        return QWidget::eventFilter(watched, event);
    }
    auto *edit = qobject_cast<QLineEdit *>(watched);
    if (!edit)
        return QWidget::eventFilter(watched, event);
    const QString name = edit->property(nameProperty).toString();
    if (event->type() == QEvent::ShortcutOverride) {
        // Ctrl+Z in a field that shows the design's value (an edit just committed) is the
        // document's undo, not the field's own text undo, which would only bring back what was
        // typed; while the user types (the text modified), the field keeps it.
        const auto *key = static_cast<QKeyEvent *>(event);
        if (!edit->isModified() && (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo))) {
            event->ignore(); // not the field's: the window's Undo and Redo actions take it
            return true;
        }
    } else if (event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent *>(event)->key();
        if (key == Qt::Key_Up || key == Qt::Key_Down) {
            step(name, key == Qt::Key_Up ? 1 : -1);
            return true;
        }
        if (key == Qt::Key_Escape) {
            showValues();
            return true;
        }
    } else if (event->type() == QEvent::Wheel && edit->hasFocus()) {
        const int delta = static_cast<QWheelEvent *>(event)->angleDelta().y();
        if (delta != 0)
            step(name, delta > 0 ? 1 : -1);
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace pkm
