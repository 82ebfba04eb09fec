#include "report/jsonwriter.h"

#include "report/numberformat.h"

#include <charconv>
#include <cmath>

namespace pkm::report {

JsonWriter &JsonWriter::key(std::string_view name)
{
    separate();
    appendString(name);
    m_out.append(m_pretty ? ": " : ":");
    m_afterKey = true;
    return *this;
}

void JsonWriter::number(double value)
{
    beforeValue();
    if (std::isfinite(value))
        appendNumber(m_out, value);
    else
        m_out.append("null");
}

void JsonWriter::integer(std::int64_t value)
{
    beforeValue();
    char buffer[24];
    m_out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

void JsonWriter::string(std::string_view text)
{
    beforeValue();
    appendString(text);
}

void JsonWriter::boolean(bool value)
{
    beforeValue();
    m_out.append(value ? "true" : "false");
}

void JsonWriter::null()
{
    beforeValue();
    m_out.append("null");
}

void JsonWriter::beforeValue()
{
    if (m_afterKey)
        m_afterKey = false;
    else
        separate();
}

void JsonWriter::separate()
{
    if (m_depth == 0)
        return;
    Level &level = m_levels[m_depth - 1];
    if (!level.first)
        m_out.push_back(',');
    if (m_pretty) {
        if (!level.inlined)
            newline(m_depth);
        else if (!level.first)
            m_out.push_back(' ');
    }
    level.first = false;
}

void JsonWriter::open(char bracket, bool inlined)
{
    beforeValue();
    m_out.push_back(bracket);
    const bool parentInlined = m_depth > 0 && m_levels[m_depth - 1].inlined;
    m_levels.at(m_depth++) = Level {true, inlined || parentInlined};
}

void JsonWriter::close(char bracket)
{
    const Level level = m_levels[--m_depth];
    if (m_pretty && !level.inlined && !level.first)
        newline(m_depth);
    m_out.push_back(bracket);
}

void JsonWriter::newline(std::size_t depth)
{
    m_out.push_back('\n');
    m_out.append(2 * depth, ' ');
}

void JsonWriter::appendString(std::string_view text)
{
    static constexpr char hex[] = "0123456789abcdef";
    m_out.push_back('"');
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (ch == '"' || ch == '\\') {
            m_out.push_back('\\');
            m_out.push_back(ch);
        } else if (ch == '\n') {
            m_out.append("\\n");
        } else if (c < 0x20) {
            m_out.append("\\u00");
            m_out.push_back(hex[c >> 4]);
            m_out.push_back(hex[c & 0xF]);
        } else {
            m_out.push_back(ch); // UTF-8 passes through
        }
    }
    m_out.push_back('"');
}

} // namespace pkm::report
