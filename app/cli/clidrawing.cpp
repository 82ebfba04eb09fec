#include "cli/clidrawing.h"

#include "cli/cliworkspace.h"

namespace pkm::cli {

namespace {
DrawingCommands &commands()
{
    static DrawingCommands set;
    return set;
}
} // namespace

void setDrawingCommands(const DrawingCommands &drawing)
{
    commands() = drawing;
}

const DrawingCommands &drawingCommands()
{
    return commands();
}

bool isDxfCommand(const std::vector<std::string> &arguments)
{
    if (arguments.empty())
        return false;
    return arguments.front() == "dxf" || (arguments.front() == "help" && arguments.size() > 1 && arguments[1] == "dxf");
}

bool drawsPictures(const std::vector<std::string> &arguments)
{
    if (isDxfCommand(arguments))
        return true;
    const auto parsed = parseArguments(arguments);
    if (!parsed || parsed->help || parsed->version || !parsed->command)
        return false;
    switch (*parsed->command) {
    case Command::Render:
    case Command::Sheet:
        return true;
    case Command::Workspace:
    case Command::Map:
        return writesPicture(*parsed);
    default:
        return false;
    }
}

std::string cannotDrawMessage(std::string_view command)
{
    return "'pkm " + std::string(command) + "' draws, and this program cannot: its drawing half, pkm-draw, was not "
           "found beside it.";
}

} // namespace pkm::cli
