#include "support/process.h"

#include <QFile>
#include <QJsonDocument>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>

namespace pkm::test {

Run runProgram(const QString &program, const QStringList &arguments, const QProcessEnvironment &environment)
{
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(program, arguments);
    Run run;
    if (!process.waitForStarted(10000) || !process.waitForFinished(programTimeoutMs))
        return run;
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

QString pkmProgram()
{
    return QStringLiteral(PKM_BINARY_DIR "/pkm");
}

Run runPkm(const QStringList &arguments, const QProcessEnvironment &environment)
{
    return runProgram(pkmProgram(), arguments, environment);
}

QJsonObject jsonObject(const QByteArray &bytes)
{
    return QJsonDocument::fromJson(bytes).object();
}

QJsonObject pkmJson(const QStringList &arguments, int *exitCode)
{
    const Run run = runPkm(arguments);
    if (exitCode)
        *exitCode = run.exitCode;
    return jsonObject(run.out);
}

QJsonObject prototypeEval(const QStringList &sets, int *exitCode)
{
    QStringList arguments {QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--json")};
    for (const QString &set : sets)
        arguments << QStringLiteral("--set") << set;
    return pkmJson(arguments, exitCode);
}

QStringList args(std::initializer_list<const char *> arguments)
{
    QStringList list;
    for (const char *argument : arguments)
        list << QString::fromUtf8(argument);
    return list;
}

QByteArray fileBytes(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

QJsonObject readJson(const QString &path)
{
    return jsonObject(fileBytes(path));
}

QString poppler(const QString &tool, const QStringList &arguments)
{
    const QString program = QStandardPaths::findExecutable(tool);
    if (program.isEmpty())
        return {};
    QProcess process;
    process.start(program, arguments);
    if (!process.waitForFinished(30000))
        return {};
    return QString::fromUtf8(process.readAllStandardOutput());
}

QSizeF pdfPageSize(const QString &info)
{
    const QRegularExpressionMatch match
        = QRegularExpression(QStringLiteral("Page size:\\s*([0-9.]+) x ([0-9.]+) pts")).match(info);
    return match.hasMatch() ? QSizeF(match.captured(1).toDouble(), match.captured(2).toDouble()) : QSizeF();
}

} // namespace pkm::test
