#pragma once
/// What every fuzz target checks of what the program produced, beyond "did not crash": a
/// message is one printable sentence, and JSON is valid and holds no NaN or infinity (the
/// program writes null for those). A violation aborts, so libFuzzer keeps the input.

#include <QByteArray>

#include <string_view>

namespace pkm::fuzz {

/// Aborts with `what` and the offending text (escaped) on stderr.
[[noreturn]] void fail(const char *what, std::string_view text);

/// `message` is non-empty and holds no control character but a final newline (a file's own
/// text must reach a terminal escaped: core/text.h).
void checkMessage(std::string_view message);

/// `json` parses as one JSON object or array, and no number in it is NaN or infinite.
void checkJson(const QByteArray &json);

} // namespace pkm::fuzz
