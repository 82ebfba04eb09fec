#pragma once
/// A streaming JSON writer for the outputs of `pkm`: keeps the key order of the layouts
/// (QJsonObject would sort them), formats numbers with appendNumber and writes non-finite
/// numbers as null.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace pkm::report {

class JsonWriter
{
public:
    enum class Style { Pretty, Compact };
    JsonWriter(std::string &out, Style style)
        : m_out(out)
        , m_pretty(style == Style::Pretty)
    {
    }

    /// `inlined`: keep the container on one line (matrices, rows of a table).
    void beginObject(bool inlined = false) { open('{', inlined); }
    void endObject() { close('}'); }
    void beginArray(bool inlined = false) { open('[', inlined); }
    void endArray() { close(']'); }

    /// Starts a member of the open object; its value follows: `json.key("unit").string("mm")`.
    JsonWriter &key(std::string_view name);
    void number(double value);
    void integer(std::int64_t value);
    void string(std::string_view text);
    void boolean(bool value);
    void null();

private:
    struct Level {
        bool first = true;
        bool inlined = false;
    };

    void beforeValue();
    void separate();
    void open(char bracket, bool inlined);
    void close(char bracket);
    void newline(std::size_t depth);
    void appendString(std::string_view text);

    std::string &m_out;
    bool m_pretty;
    bool m_afterKey = false;
    std::size_t m_depth = 0;
    std::array<Level, 16> m_levels {};
};

} // namespace pkm::report
