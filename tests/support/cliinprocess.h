#pragma once
/// Running `pkm` inside the test's own process through runCli(), drawing commands included
/// (`pkm render`, as pkm-draw registers them): faster than starting the program, and what the
/// tests of the pictures, animations and videos use. Call cli::registerDrawingCommands() once
/// first (initTestCase) when the test runs `render`.

#include <QString>
#include <QStringList>

namespace pkm::test {

/// What runCli() returned and printed.
struct CliRun {
    int status = 0;
    QString out; ///< standard output, UTF-8
    QString err; ///< standard error, UTF-8
};

/// Runs `pkm ARGUMENTS...` in this process.
CliRun runCliInProcess(const QStringList &arguments);

} // namespace pkm::test
