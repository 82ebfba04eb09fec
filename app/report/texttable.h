#pragma once
/// Aligned columns for the human-readable outputs of `pkm` (list, show, eval), and the texts
/// of their number cells.

#include <string>
#include <vector>

namespace pkm::report {

/// Heading and text rows do not take part in the column widths, so one long warning does not
/// stretch a table. Widths count terminal columns, not bytes: Greek and Cyrillic symbols and
/// combining dots (θ̇) keep the columns aligned.
class TextTable
{
public:
    explicit TextTable(std::vector<bool> rightAligned, std::string indent = "  ");

    /// A title line, preceded by an empty line unless it is the first row.
    void heading(std::string text);
    /// An indented line of free text.
    void text(std::string text);
    void cells(std::vector<std::string> cells);

    void render(std::string &out) const;

private:
    enum class Kind { Heading, Text, Cells };
    struct Row {
        Kind kind;
        std::vector<std::string> cells;
    };
    std::vector<bool> m_rightAligned;
    std::string m_indent;
    std::vector<Row> m_rows;
};

/// Fixed decimals for the text tables (aligned decimal points); "undefined" when not finite.
std::string fixedText(double value, int decimals);

/// "[-60, 60]", "(0, ∞)": '(' and ')' exclude the bound; ∞ for an unbounded side, else the
/// bounds with up to `decimals` decimals.
std::string rangeText(double displayMin, double displayMax, bool openMin, bool openMax, int decimals = 6);

} // namespace pkm::report
