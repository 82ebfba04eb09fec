// Output files written completely or not at all, for every writer of the program: the command
// line's outputs, the exports and the pictures.

#include "document/savefile.h"

#include <QSaveFile>
#include <QString>

#include <cerrno>
#include <cstring>
#include <QString>

namespace pkm::files {

std::optional<std::string> saveFile(const std::string &path, const std::function<bool(const ChunkWriter &)> &produce)
{
    QSaveFile file(QString::fromStdString(path));
    // Qt says "Unknown error" where the buffered write hit a full disk at commit; the system's
    // own reason (errno: "No space left on device") is the one to tell
    const auto failure = [&](const QString &why, int error) {
        std::string reason = why.toStdString();
        if ((reason.empty() || reason == "Unknown error") && error != 0)
            reason = std::strerror(error);
        while (!reason.empty() && (reason.back() == '.' || reason.back() == ' '))
            reason.pop_back();
        return std::optional<std::string>(
            "Cannot write '" + path + "': " + (reason.empty() ? "unknown error" : reason) + ".");
    };
    errno = 0;
    if (!file.open(QIODevice::WriteOnly))
        return failure(file.errorString(), errno);
    int error = 0;
    const bool written = produce([&](std::string_view chunk) {
        errno = 0;
        const bool whole = file.write(chunk.data(), static_cast<qint64>(chunk.size())) == static_cast<qint64>(chunk.size());
        error = whole ? 0 : errno;
        return whole;
    });
    if (!written) {
        const QString why = file.errorString();
        file.cancelWriting();
        return failure(why, error);
    }
    errno = 0;
    if (!file.commit())
        return failure(file.errorString(), errno);
    return std::nullopt;
}

std::optional<std::string> saveBytes(const std::string &path, const QByteArray &bytes)
{
    return saveFile(path, [&](const ChunkWriter &write) {
        return write(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    });
}

} // namespace pkm::files
