// pkm: the headless command. All the work is in cli.cpp (runCli), which the tests also call.

#include "cli.h"

#include <QCoreApplication>

#include <cstdio>

int main(int argc, char *argv[])
{
    QCoreApplication application(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("pkm"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PKM_VERSION));
    QStringList arguments = QCoreApplication::arguments();
    arguments.removeFirst(); // the program name
    return pkm::runCli(arguments, stdout, stderr);
}
