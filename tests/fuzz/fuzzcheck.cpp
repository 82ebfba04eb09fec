#include "fuzzcheck.h"

#include "text.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace pkm::fuzz {

namespace {

/// Qt reads a number too large for a double as ±inf; the program must never write one.
void checkNumbers(const QJsonValue &value, const QByteArray &json)
{
    if (value.isDouble() && !std::isfinite(value.toDouble()))
        fail("a number in JSON output is not finite", std::string_view(json.constData(), json.size()));
    if (value.isArray())
        for (const QJsonValue &item : value.toArray())
            checkNumbers(item, json);
    if (value.isObject())
        for (const QJsonValue &item : value.toObject())
            checkNumbers(item, json);
}

} // namespace

void fail(const char *what, std::string_view text)
{
    std::fprintf(stderr, "FUZZ CHECK FAILED: %s\n%s\n", what, text::printable(text, 4000).c_str());
    std::abort();
}

void checkMessage(std::string_view message)
{
    if (message.empty())
        fail("a failure without a message", message);
    std::string_view body = message;
    if (body.back() == '\n')
        body.remove_suffix(1);
    for (const char c : body) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f)
            fail("a message holds a control character", message);
    }
}

void checkJson(const QByteArray &json)
{
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError)
        fail("the JSON output does not parse", std::string_view(json.constData(), json.size()));
    checkNumbers(document.isArray() ? QJsonValue(document.array()) : QJsonValue(document.object()), json);
}

} // namespace pkm::fuzz
