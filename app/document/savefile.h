#pragma once
/// Output files written completely or not at all: the command line's outputs, the exports and
/// the pictures all go through saveFile(), so a full disk or a killed process never leaves half
/// a file in place of the old one.

#include <QByteArray>

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace pkm::files {

/// Hands one chunk of a file to saveFile(): false when it could not be written.
using ChunkWriter = std::function<bool(std::string_view)>;
/// Writes `path` atomically: the chunks `produce` gives its ChunkWriter go to a temporary file
/// (QSaveFile) that replaces `path` only once all of them were written and `produce` returned
/// true; otherwise `path` is left as it was. The failure is one sentence naming the file.
std::optional<std::string> saveFile(const std::string &path, const std::function<bool(const ChunkWriter &)> &produce);
/// saveFile() with the whole content at once.
std::optional<std::string> saveBytes(const std::string &path, const QByteArray &bytes);

} // namespace pkm::files
