// libFuzzer target: the design-file reader (designfile::parse), the kinds' parameter checks
// behind it (every kind, the leg library's legs included) and what is done with a design that
// reads: it saves and reads back to the same file, and its pose evaluates to valid JSON.
//
// Seeds: the presets (resources/presets), then the saved corpus (tests/fuzz/corpus/designfile).
#include "fuzzcheck.h"

#include "cli/cli.h"
#include "document/designfile.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

#include <cstddef>
#include <cstdint>
#include <string>

// Messages are translated through QCoreApplication, as the programs set it up.
extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static QCoreApplication application(*argc, *argv);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    using namespace pkm;
    // the reader refuses larger files before parsing (designfile::readFile)
    if (size > std::size_t(designfile::maxFileBytes))
        return 0;
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    const Result<Design> design = designfile::parse(bytes, QStringLiteral("fuzz.pkm.json"));
    if (!design) {
        // the message goes to a dialog or stderr as it is: one printable, bounded sentence
        const std::string &message = design.failure().message;
        fuzz::checkMessage(message);
        if (message.size() > 4000)
            fuzz::fail("a failure message longer than 4000 bytes", message);
        return 0;
    }
    // What reads must save, and what is saved must read back as the same design.
    const QByteArray saved = designfile::serialize(*design);
    fuzz::checkJson(saved);
    const Result<Design> again = designfile::parse(saved, QStringLiteral("saved.pkm.json"));
    if (!again)
        fuzz::fail("a saved design does not read back", again.failure().message);
    if (const QByteArray resaved = designfile::serialize(*again); resaved != saved)
        fuzz::fail("a saved design reads back different",
                   std::string(saved.constData(), std::size_t(saved.size())) + "\nread back and saved again:\n" +
                       std::string(resaved.constData(), std::size_t(resaved.size())));
    const std::string report = cli::evalJson(*design->mechanism, design->pose, false, false);
    fuzz::checkJson(QByteArray::fromStdString(report));
    return 0;
}
