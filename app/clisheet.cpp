#include "clisheet.h"

#include "cli.h"

#include <QFileInfo>
#include <QString>

namespace pkm::cli {

sheet::Source sheetSource(const PreparedDesign &prepared)
{
    const QString origin = QString::fromStdString(prepared.origin);
    sheet::Source source;
    // a design file by its name, without the directories of this machine
    source.design = prepared.design.id.isEmpty() ? QFileInfo(origin).fileName().toStdString() : prepared.origin;
    source.title = prepared.design.title;
    source.description = prepared.design.description;
    return source;
}

int runSheetCommand(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err)
{
    const std::string &path = *invocation.output; // parseArguments() requires it, with a known extension
    const std::optional<sheet::Format> format = sheet::formatOf(path);
    if (!format) {
        printError(err, "-o " + path + ": 'pkm sheet' writes a .pdf, .json or .csv file.");
        return CliUsageError;
    }
    const sheet::Sheet built = sheet::build(*prepared.mechanism, prepared.pose, sheetSource(prepared));
    if (const auto failure = sheet::save(built, path)) {
        printError(err, *failure);
        return CliOutputError;
    }
    std::string kind = *format == sheet::Format::Pdf ? "PDF, A4 portrait"
        : *format == sheet::Format::Json              ? "JSON"
                                                      : "CSV";
    std::string line = "Wrote " + path + " (parameter sheet of " + built.design + ", " + kind + ", "
        + std::to_string(built.sections.size()) + " sections)\n";
    return printOutput(out, err, line);
}

} // namespace pkm::cli
