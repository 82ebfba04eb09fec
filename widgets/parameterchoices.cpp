#include "parameterchoices.h"

#include "quantityformat.h"
#include "symboltext.h"

#include <QComboBox>
#include <QLineEdit>
#include <QLocale>
#include <QSignalBlocker>
#include <QStyle>

#include <algorithm>
#include <cmath>

namespace pkm::choices {

QString text(const ParameterInfo &info, std::size_t index)
{
    if (index < info.choiceLabels.size())
        return coreLabel(info.choiceLabels[index]);
    return index < info.choices.size() ? coreLabel(info.choices[index].first) : QString();
}

QString textOf(const ParameterInfo &info, double value)
{
    for (std::size_t i = 0; i < info.choices.size(); ++i) {
        if (info.choices[i].second == value)
            return text(info, i);
    }
    return {};
}

std::optional<double> valueOf(const ParameterInfo &info, const QString &typed)
{
    const QString word = typed.trimmed();
    for (std::size_t i = 0; i < info.choices.size(); ++i) {
        if (word.compare(toQString(info.choices[i].first), Qt::CaseInsensitive) == 0
            || word.compare(text(info, i), Qt::CaseInsensitive) == 0)
            return info.choices[i].second;
    }
    return std::nullopt;
}

QString fieldText(const ParameterInfo &info, const ParameterSet &values)
{
    if (const QString choice = textOf(info, values.at(info.name)); !choice.isEmpty())
        return choice; // "RP̲R", not "2"
    const double display = info.unit.toDisplay(values.at(info.name));
    QString text = QLocale().toString(display, 'f', info.decimals + 2);
    const QChar point = QLocale().decimalPoint().at(0);
    if (text.contains(point)) {
        while (text.endsWith(QLatin1Char('0')))
            text.chop(1);
        if (text.endsWith(point))
            text.chop(1);
    }
    return typographicMinus(text);
}

namespace {
const char *leastWidthProperty = "pkmLeastWidth";

/// As wide as the widest choice with the box's arrow and frames, and at least its least width.
void fitWidth(QComboBox *box)
{
    int widest = 0;
    for (int i = 0; i < box->count(); ++i)
        widest = std::max(widest, box->fontMetrics().horizontalAdvance(box->itemText(i)));
    const QStyle *style = box->style();
    const int chrome = style->pixelMetric(QStyle::PM_ScrollBarExtent) + 2 * style->pixelMetric(QStyle::PM_ComboBoxFrameWidth)
        + 3 * box->fontMetrics().averageCharWidth();
    box->setFixedWidth(std::max(box->property(leastWidthProperty).toInt(), widest + chrome));
}
} // namespace

QComboBox *makeBox(const ParameterInfo &info, int width, QWidget *parent)
{
    auto *box = new QComboBox(parent);
    // Editable, so that the field is a line edit as every other: typed numbers and names,
    // Up/Down and the wheel, Ctrl+Z and the invalid mark work the same way.
    box->setEditable(true);
    box->setInsertPolicy(QComboBox::NoInsert);
    box->lineEdit()->setAlignment(Qt::AlignLeft); // a word, read from its start as in the list
    box->setProperty(leastWidthProperty, width);
    for (std::size_t i = 0; i < info.choices.size(); ++i)
        box->addItem(text(info, i), info.choices[i].second);
    fitWidth(box);
    return box;
}

void showInField(QLineEdit *field, const QString &text, double value)
{
    if (auto *box = qobject_cast<QComboBox *>(field->parentWidget())) {
        const QSignalBlocker blocker(box);
        box->setCurrentIndex(box->findData(value));
    }
    field->setText(text);
}

void retranslateBox(QComboBox *box, const ParameterInfo &info)
{
    const QSignalBlocker blocker(box);
    const QString shown = box->lineEdit()->text();
    for (int i = 0; i < box->count() && std::size_t(i) < info.choices.size(); ++i)
        box->setItemText(i, text(info, std::size_t(i)));
    box->lineEdit()->setText(shown);
    fitWidth(box);
}

} // namespace pkm::choices
