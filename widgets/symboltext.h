#pragma once
/// Symbols with their subscripts lowered (symbolHtml()) where Qt would draw a plain text:
/// an item view's cells and a combo box's field and list. The items keep the notation ("x_AB"),
/// so tooltips, copies and tests read what the program writes; only the drawing differs. A
/// number field shows a negative number with the typographic minus, as every panel does.

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QStyledItemDelegate>

#include <optional>

class QPainter;

namespace pkm {

/// symbolHtml() of `text`, ended with "…" where its laid-out width in `font` is more than
/// `width` pixels, as a plain text is elided in a narrow column.
QString symbolHtmlElided(const QString &text, const QFont &font, int width);

/// Draws `text` with its subscripts lowered, elided to `room`'s width and centred in its height.
void drawSymbolText(QPainter *painter, const QRect &room, const QString &text, const QFont &font, const QColor &colour);

/// An item delegate that draws a symbol or a meaning with its subscripts lowered: "J_q" as J
/// with a small q. A text without '_' is drawn by the style as usual.
class SymbolDelegate : public QStyledItemDelegate
{
public:
    using QStyledItemDelegate::QStyledItemDelegate;
    void paint(QPainter *painter, const QStyleOptionViewItem &option, const QModelIndex &index) const override;
    /// Tall enough for a mark over a tall letter (the dot of θ̇) and a lowered subscript.
    QSize sizeHint(const QStyleOptionViewItem &option, const QModelIndex &index) const override;
};

/// A combo box whose entries are symbols or start with one ("x_AB — rod joint C, D"): the field
/// and the list show them lowered, as the values panel and the equations do.
class SymbolComboBox : public QComboBox
{
    Q_OBJECT

public:
    explicit SymbolComboBox(QWidget *parent = nullptr);

protected:
    void paintEvent(QPaintEvent *event) override;
};

/// A spin box that shows "−261.50 mm" as the panels and plots do, and takes a typed "-" or "−".
class NumberSpinBox : public QDoubleSpinBox
{
public:
    using QDoubleSpinBox::QDoubleSpinBox;

    QString textFromValue(double value) const override;
    double valueFromText(const QString &text) const override;
    QValidator::State validate(QString &input, int &pos) const override;
    void fixup(QString &input) const override;

private:
    /// The end of the range nearest a number typed past it (`plain`: with "-" for a minus),
    /// or none for text that is no such number.
    std::optional<double> beyondRange(const QString &plain) const;
};

/// `text` with each hyphen-minus turned into the typographic minus "−" (U+2212).
QString typographicMinus(QString text);
/// `text` with each typographic minus turned into the hyphen-minus that number parsing reads.
QString plainMinus(QString text);

} // namespace pkm
