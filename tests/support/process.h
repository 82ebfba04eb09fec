#pragma once
/// Running programs from a test: the `pkm` command built with the tests, the tools that read its
/// files back (poppler's pdfinfo and pdftotext, python), and reading what they print. The tests
/// of the CLI, of the sheet and DXF files and of the windows (which compare the GUI's numbers
/// with the command's) all ran `pkm` through QProcess with a copy of the same few lines.

#include <QByteArray>
#include <QJsonObject>
#include <QProcessEnvironment>
#include <QSizeF>
#include <QString>
#include <QStringList>

#include <initializer_list>

namespace pkm::test {

/// What a program did: its exit status and both of its output streams.
struct Run {
    int exitCode = -1; ///< -1: it did not start or did not finish in time; -2: it crashed
    QByteArray out;
    QByteArray err;
};

/// How long a program may run. Generous: the suite runs on slow, busy machines (an Asan build,
/// two test jobs at once), and a program that hangs still fails the test in the end.
inline constexpr int programTimeoutMs = 120000;

/// Runs `program` with `arguments` in `environment` and waits for it.
Run runProgram(const QString &program, const QStringList &arguments,
    const QProcessEnvironment &environment = QProcessEnvironment::systemEnvironment());

/// The `pkm` binary of this build.
QString pkmProgram();

/// Runs `pkm ARGUMENTS...`.
Run runPkm(
    const QStringList &arguments, const QProcessEnvironment &environment = QProcessEnvironment::systemEnvironment());

/// Bytes as one JSON object; an empty object when they are not one.
QJsonObject jsonObject(const QByteArray &bytes);

/// Runs `pkm ARGUMENTS...` (the arguments as given: add "--json" where the command needs it)
/// and reads its standard output as a JSON object. The exit status goes to `exitCode`; a
/// failing run usually prints no JSON and so gives an empty object.
QJsonObject pkmJson(const QStringList &arguments, int *exitCode = nullptr);

/// `pkm eval pjoint-prototype --json` with `--set` for each of `sets` ("theta=20"): the
/// published prototype, which several tests compare with.
QJsonObject prototypeEval(const QStringList &sets = {}, int *exitCode = nullptr);

/// UTF-8 arguments as a list: args({"eval", "moma-3a", "--set", "x=10"}).
QStringList args(std::initializer_list<const char *> arguments);

/// A file's bytes; empty when it cannot be read.
QByteArray fileBytes(const QString &path);

/// A JSON file's top-level object; empty when it cannot be read or is not one.
QJsonObject readJson(const QString &path);

/// Runs a poppler tool (pdfinfo, pdftotext) and gives its output; a null string when the tool
/// is not installed (poppler-utils is optional: the tests that need it skip without it).
QString poppler(const QString &tool, const QStringList &arguments);

/// The page size from pdfinfo's "Page size:      460.8 x 259.2 pts"; empty when not there.
QSizeF pdfPageSize(const QString &info);

} // namespace pkm::test
