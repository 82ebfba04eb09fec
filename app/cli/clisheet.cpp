#include "cli/clisheet.h"

#include "kinds/kindmodule.h"

#include "cli/cli.h"
#include "document/language.h"
#include "text.h"

#include <QFileInfo>
#include <QLocale>
#include <QString>

namespace pkm::cli {

namespace {

/// The sheet's language while the command runs: its catalogue, the locale of its numbers and
/// core's texts (language::apply). What was there before comes back at the end, since runCli()
/// also runs inside other programs (the tests).
class LanguageScope
{
public:
    explicit LanguageScope(const QString &code)
        : m_previous(language::current())
        , m_hooks(text::installed())
        , m_locale(QLocale())
    {
        m_applied = language::apply(code);
        if (!m_applied && code == QLatin1String("en")) {
            // English is the source language: without its catalogue only the plural forms of
            // counts are missing. Numbers with '.' whatever the system's locale.
            QLocale english(QLocale::English, QLocale::UnitedStates);
            english.setNumberOptions(QLocale::OmitGroupSeparator);
            QLocale::setDefault(english);
            text::install({});
            m_applied = true;
        }
    }
    ~LanguageScope()
    {
        if (language::current() != m_previous)
            language::apply(m_previous);
        text::install(m_hooks);
        QLocale::setDefault(m_locale);
    }
    LanguageScope(const LanguageScope &) = delete;
    LanguageScope &operator=(const LanguageScope &) = delete;

    bool applied() const { return m_applied; }

private:
    QString m_previous;
    text::Hooks m_hooks;
    QLocale m_locale;
    bool m_applied = false;
};

/// "en, sr, sr_Latn or ru"
std::string languageCodes()
{
    std::string codes;
    const auto &languages = language::all();
    for (qsizetype i = 0; i < languages.size(); ++i) {
        if (i > 0)
            codes += i + 1 == languages.size() ? " or " : ", ";
        codes += languages[i].code.toStdString();
    }
    return codes;
}

} // namespace

sheet::Source sheetSource(const PreparedDesign &prepared)
{
    const QString origin = QString::fromStdString(prepared.origin);
    sheet::Source source;
    // a design file by its name, without the directories of this machine
    source.design = prepared.design.id.isEmpty() ? QFileInfo(origin).fileName().toStdString() : prepared.origin;
    source.title = prepared.design.title;
    source.description = prepared.design.description;
    source.requirements = prepared.design.requirements;
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
    // English unless --lang says otherwise, whatever the system's locale: scripts read the sheet.
    const std::string code = invocation.language.value_or("en");
    if (!language::find(QString::fromStdString(code))) {
        printError(err,
            "--lang " + code + ": unknown language '" + code + "': use " + languageCodes()
                + " (see 'pkm sheet --help').");
        return CliUsageError;
    }
    sheet::Sheet built;
    std::optional<std::string> failure;
    {
        const LanguageScope scope(QString::fromStdString(code));
        if (!scope.applied()) {
            printError(err, "--lang " + code + ": this build of pkm has no catalogue for '" + code + "'.");
            return CliUsageError;
        }
        built = kinds::buildSheet(*prepared.mechanism, prepared.pose, sheetSource(prepared));
        failure = sheet::save(built, path);
    }
    if (failure) {
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
