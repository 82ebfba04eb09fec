#include "report/texttable.h"

#include "mechanism.h"
#include "report/numberformat.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

namespace pkm::report {

namespace {

/// Columns a UTF-8 string occupies in a terminal: one per code point except combining marks
/// (the dot of θ̇ is U+0307).
int displayWidth(std::string_view text)
{
    int width = 0;
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const std::size_t length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
        char32_t code = lead;
        if (length == 2 && i + 1 < text.size())
            code = ((lead & 0x1Fu) << 6) | (static_cast<unsigned char>(text[i + 1]) & 0x3Fu);
        else if (length == 3 && i + 2 < text.size())
            code = ((lead & 0x0Fu) << 12) | ((static_cast<unsigned char>(text[i + 1]) & 0x3Fu) << 6)
                | (static_cast<unsigned char>(text[i + 2]) & 0x3Fu);
        const bool combining = (code >= 0x0300 && code <= 0x036F) || (code >= 0x20D0 && code <= 0x20FF);
        width += combining ? 0 : 1;
        i += length;
    }
    return width;
}

/// A bound for range texts: ∞ for an unbounded side, else up to `decimals` decimals.
std::string boundText(double displayValue, int decimals)
{
    if (std::isinf(displayValue))
        return displayValue > 0 ? "∞" : "-∞";
    return formatNumber(displayValue, decimals);
}

} // namespace

TextTable::TextTable(std::vector<bool> rightAligned, std::string indent)
    : m_rightAligned(std::move(rightAligned))
    , m_indent(std::move(indent))
{
}

void TextTable::heading(std::string text)
{
    m_rows.push_back({Kind::Heading, {std::move(text)}});
}

void TextTable::text(std::string text)
{
    m_rows.push_back({Kind::Text, {std::move(text)}});
}

void TextTable::cells(std::vector<std::string> cells)
{
    m_rows.push_back({Kind::Cells, std::move(cells)});
}

void TextTable::render(std::string &out) const
{
    std::vector<int> widths(m_rightAligned.size(), 0);
    for (const Row &row : m_rows) {
        if (row.kind != Kind::Cells)
            continue;
        for (std::size_t c = 0; c < row.cells.size() && c < widths.size(); ++c)
            widths[c] = std::max(widths[c], displayWidth(row.cells[c]));
    }
    bool first = true;
    for (const Row &row : m_rows) {
        if (row.kind == Kind::Heading) {
            out += first ? "" : "\n";
            out += row.cells.front();
            out += '\n';
        } else if (row.kind == Kind::Text) {
            out += m_indent + row.cells.front() + '\n';
        } else {
            std::string line = m_indent;
            for (std::size_t c = 0; c < row.cells.size() && c < widths.size(); ++c) {
                const std::string &cell = row.cells[c];
                const std::string padding(static_cast<std::size_t>(widths[c] - displayWidth(cell)), ' ');
                if (c > 0)
                    line += "  ";
                line += m_rightAligned[c] ? padding + cell : cell + padding;
            }
            line.erase(line.find_last_not_of(' ') + 1);
            out += line + '\n';
        }
        first = false;
    }
}

std::string fixedText(double value, int decimals)
{
    if (std::isinf(value))
        return "∞"; // unbounded at a singular pose: its sign depends on the side it is neared from
    if (!std::isfinite(value))
        return "undefined";
    if (std::abs(value) >= 1e15)
        return numberText(value);
    char buffer[64];
    const auto result
        = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, std::clamp(decimals, 0, 17));
    std::string text(buffer, result.ptr);
    if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos)
        text.erase(0, 1); // "-0.00" → "0.00"
    return text;
}

std::string rangeText(double displayMin, double displayMax, bool openMin, bool openMax, int decimals)
{
    // Built by appending, which also keeps GCC 12 from a false -Wrestrict on `"[" + std::string`.
    std::string text(openMin || std::isinf(displayMin) ? "(" : "["); // ∞ is never a member
    text.append(boundText(displayMin, decimals)).append(", ").append(boundText(displayMax, decimals));
    text.append(openMax || std::isinf(displayMax) ? ")" : "]");
    return text;
}

} // namespace pkm::report
