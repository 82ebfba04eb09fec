#include "support/cliinprocess.h"

#include "cli/cli.h"

#include <QByteArray>

#include <cstdio>

namespace pkm::test {

namespace {
/// All a temporary file holds, and the file closed.
QString readAndClose(std::FILE *file)
{
    std::fflush(file);
    std::rewind(file);
    QByteArray bytes;
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, file))
        bytes.append(buffer, static_cast<qsizetype>(n));
    std::fclose(file);
    return QString::fromUtf8(bytes);
}
} // namespace

CliRun runCliInProcess(const QStringList &arguments)
{
    std::FILE *out = std::tmpfile();
    std::FILE *err = std::tmpfile();
    CliRun run;
    run.status = runCli(arguments, out, err);
    run.out = readAndClose(out);
    run.err = readAndClose(err);
    return run;
}

} // namespace pkm::test
