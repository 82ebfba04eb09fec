// pkm-draw: the drawing half of the headless command, to which `pkm` hands the commands that
// draw (clidrawing.h): render, sheet, dxf and the pictures of workspace and map. It runs the
// whole command line (runCli) with the drawing commands registered.
//
// Every command runs in a QCoreApplication, without a display, except `pkm render`, `pkm sheet`
// and `pkm dxf`, which draw with QPainter and OpenGL or measure text, and so need a
// QGuiApplication: the command
// line is looked at first (clirender.h: prepareRenderPlatform) to choose the Qt platform
// before the application object exists.

#include "cli/cli.h"
#include "cli/clirender.h"
#include "cli/drawingcommands.h"

#include <QCoreApplication>
#include <QGuiApplication>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

QtMessageHandler qtDefaultHandler = nullptr;

/// Keeps Qt's own chatter (platform plugins, fonts, GL drivers) off stderr, where `pkm` writes
/// one sentence per error; critical and fatal messages still get through, and PKM_QT_MESSAGES=1
/// lets all of them through.
void quietMessageHandler(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    if ((type == QtCriticalMsg || type == QtFatalMsg) && qtDefaultHandler)
        qtDefaultHandler(type, context, message);
}

} // namespace

int main(int argc, char *argv[])
{
    std::vector<std::string> peek;
    for (int i = 1; i < argc; ++i)
        peek.emplace_back(argv[i]);
    const pkm::cli::RenderSetup setup = pkm::cli::prepareRenderPlatform(peek);
    if (setup.quietQt && qEnvironmentVariableIsEmpty("PKM_QT_MESSAGES"))
        qtDefaultHandler = qInstallMessageHandler(quietMessageHandler);

    std::unique_ptr<QCoreApplication> application;
    if (setup.guiApplication)
        application = std::make_unique<QGuiApplication>(argc, argv);
    else
        application = std::make_unique<QCoreApplication>(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("pkm"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PKM_VERSION));
    QStringList arguments = QCoreApplication::arguments();
    arguments.removeFirst(); // the program name
    if (setup.xvfbRerun)
        pkm::cli::enableXvfbRerun(QCoreApplication::applicationFilePath(), arguments);
    pkm::cli::registerDrawingCommands();
    return pkm::runCli(arguments, stdout, stderr);
}
