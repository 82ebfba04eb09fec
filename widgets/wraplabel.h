#pragma once
/// A word-wrapped label that never asks for more than a few lines: QLabel at its narrowest is
/// as wide as its longest word, and a slider's name "q₁ (улаз, са погоном)" took three lines
/// there, more than the six rows of a 3-P̲RR had room for at 1024×768; at the width of two
/// lines it fitted.

#include <QLabel>

namespace pkm {

class WrapLabel : public QLabel
{
public:
    /// `lines`: the most lines the text takes at the label's narrowest.
    explicit WrapLabel(int lines, QWidget *parent = nullptr);

    /// As narrow as `lines` lines of the text allow (QLabel's own where it does not wrap).
    QSize minimumSizeHint() const override;

    /// The least width at which `label`'s text, as the label lays it out, takes no more than
    /// `lines` lines.
    static int widthForLines(const QLabel *label, int lines);

private:
    int m_lines;
};

} // namespace pkm
