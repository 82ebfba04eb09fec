// Output files written completely or not at all, for every writer of the program: the command
// line's outputs, the exports and the pictures.

#include "document/savefile.h"

#include <QSaveFile>
#include <QString>

namespace pkm::files {

std::optional<std::string> saveFile(const std::string &path, const std::function<bool(const ChunkWriter &)> &produce)
{
    QSaveFile file(QString::fromStdString(path));
    const auto failure = [&](const QString &why) {
        std::string reason = why.toStdString();
        while (!reason.empty() && (reason.back() == '.' || reason.back() == ' '))
            reason.pop_back();
        return std::optional<std::string>(
            "Cannot write '" + path + "': " + (reason.empty() ? "unknown error" : reason) + ".");
    };
    if (!file.open(QIODevice::WriteOnly))
        return failure(file.errorString());
    const bool written = produce([&](std::string_view chunk) {
        return file.write(chunk.data(), static_cast<qint64>(chunk.size())) == static_cast<qint64>(chunk.size());
    });
    if (!written) {
        const QString why = file.errorString();
        file.cancelWriting();
        return failure(why);
    }
    if (!file.commit())
        return failure(file.errorString());
    return std::nullopt;
}

std::optional<std::string> saveBytes(const std::string &path, const QByteArray &bytes)
{
    return saveFile(path, [&](const ChunkWriter &write) {
        return write(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    });
}

} // namespace pkm::files
