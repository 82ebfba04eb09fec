#include "cli/drawingcommands.h"

#include "cli/clidrawing.h"
#include "cli/clidxf.h"
#include "cli/clirender.h"
#include "cli/clisheet.h"
#include "cli/cliworkspace.h"
#include "export/workspacepictures.h"

#include <QString>

namespace pkm::cli {

namespace {

std::optional<std::string> savePicture(const std::string &path, QImage image, const std::string &title)
{
    image.setText(QStringLiteral("Title"), QString::fromStdString(title));
    return pictures::savePng(path, image);
}

std::optional<std::string> workspacePicture(const std::string &path, const MapGrid &grid, std::span<const float> values,
    std::span<const SingularCurve> curves, const std::string &title)
{
    return savePicture(path, pictures::workspaceImage(grid, values, curves), title);
}

std::optional<std::string> regionsPicture(
    const std::string &path, const report::ModeRegions &regions, const std::string &title)
{
    return savePicture(path, pictures::modeRegionsImage(regions), title);
}

std::optional<std::string> mapPicture(const std::string &path, const MapGrid &grid, std::span<const float> values,
    MapQuantity quantity, double limit, std::span<const SingularCurve> curves, const std::string &title)
{
    return savePicture(path, pictures::mapImage(grid, values, quantity, limit, curves), title);
}

} // namespace

void registerDrawingCommands()
{
    setDrawingCommands({&runDxfCommand, &runRenderCommand, &runSheetCommand});
    setWorkspacePictureWriters({&workspacePicture, &regionsPicture, &mapPicture});
}

} // namespace pkm::cli
