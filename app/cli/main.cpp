// pkm: the headless command. All the work is in cli.cpp (runCli), which the tests also call.
//
// `pkm` links only QtCore and the kinematics: `pkm eval`, `sweep`, `show`, `list`, `workspace`
// and `map` (without a picture) start without loading a GUI library. A command that draws is
// handed, with the same arguments, to pkm-draw beside this program (or in the libexec folder
// of an installation), which replaces this process (clidrawing.h).

#include "cli/cli.h"
#include "cli/clidrawing.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <climits>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

/// The folder of this program's own file.
std::string programFolder()
{
    char path[PATH_MAX];
    const ssize_t length = readlink("/proc/self/exe", path, sizeof path - 1);
    if (length <= 0)
        return {};
    std::string file(path, static_cast<std::size_t>(length));
    const auto slash = file.rfind('/');
    return slash == std::string::npos ? std::string() : file.substr(0, slash);
}

/// Replaces this process by pkm-draw with the same arguments; returns only if it cannot.
void runDrawingProgram(char *argv[])
{
    const std::string folder = programFolder();
    if (folder.empty())
        return;
    for (const std::string &candidate : {folder + "/pkm-draw", folder + "/../libexec/pkm-studio/pkm-draw"}) {
        if (access(candidate.c_str(), X_OK) == 0)
            execv(candidate.c_str(), argv);
    }
}

} // namespace

int main(int argc, char *argv[])
{
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    if (pkm::cli::drawsPictures(arguments))
        runDrawingProgram(argv); // if it returns, runCli() says that this program cannot draw

    QCoreApplication application(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("pkm"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PKM_VERSION));
    QStringList list = QCoreApplication::arguments();
    list.removeFirst(); // the program name
    return pkm::runCli(list, stdout, stderr);
}
