#include "document/language.h"

#include "text.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

#include <memory>

namespace pkm::language {

namespace {
LocaleHook &localeHook()
{
    static LocaleHook hook;
    return hook;
}
} // namespace

void setLocaleHook(LocaleHook hook)
{
    localeHook() = std::move(hook);
}

namespace {

const QString settingsKey = QStringLiteral("language");

struct Installed {
    QString code = QStringLiteral("en");
    std::unique_ptr<QTranslator> own;
    std::unique_ptr<QTranslator> qt;
};

Installed &installed()
{
    static Installed state;
    return state;
}

std::string translateHook(const char *context, const char *source, const char *disambiguation, int n)
{
    return QCoreApplication::translate(context, source, disambiguation, n).toStdString();
}

} // namespace

const QList<Language> &all()
{
    static const QList<Language> languages = {
        {QStringLiteral("en"), QStringLiteral("English"), QLocale(QLocale::English, QLocale::UnitedStates)},
        {QStringLiteral("sr"), QStringLiteral("Српски (ћирилица)"),
         QLocale(QLocale::Serbian, QLocale::CyrillicScript, QLocale::Serbia)},
        {QStringLiteral("sr_Latn"), QStringLiteral("Srpski (latinica)"),
         QLocale(QLocale::Serbian, QLocale::LatinScript, QLocale::Serbia)},
        {QStringLiteral("ru"), QStringLiteral("Русский"), QLocale(QLocale::Russian, QLocale::Russia)},
    };
    return languages;
}

const Language *find(const QString &code)
{
    for (const Language &language : all()) {
        if (language.code == code)
            return &language;
    }
    return nullptr;
}

QString bestFor(const QLocale &locale)
{
    switch (locale.language()) {
    case QLocale::Russian:
        return QStringLiteral("ru");
    case QLocale::Serbian:
        return locale.script() == QLocale::LatinScript ? QStringLiteral("sr_Latn") : QStringLiteral("sr");
    case QLocale::Bosnian:
    case QLocale::Croatian:
        return locale.script() == QLocale::CyrillicScript ? QStringLiteral("sr") : QStringLiteral("sr_Latn");
    default:
        return QStringLiteral("en");
    }
}

QString preferred()
{
    const QString stored = QSettings().value(settingsKey).toString();
    return find(stored) ? stored : bestFor();
}

void remember(const QString &code)
{
    if (find(code))
        QSettings().setValue(settingsKey, code);
}

bool apply(const QString &code)
{
    const Language *language = find(code);
    if (!language || !QCoreApplication::instance())
        return false;
    // English has a catalogue too: the plural forms ("1 loop", "2 loops").
    // An installed catalogue (share/pkm-studio/translations beside the program's bin folder,
    // where `cmake --install` puts them) comes before the built-in one, so that a translator
    // can try a new .qm file without building the program again.
    auto own = std::make_unique<QTranslator>();
    const QString file = QStringLiteral("pkm_studio_") + code;
    const QString shared = QCoreApplication::applicationDirPath() + QStringLiteral("/../share/pkm-studio/translations");
    if (!own->load(file, shared) && !own->load(QStringLiteral(":/i18n/") + file))
        return false;
    // Qt's own words (standard buttons, file dialogs) where Debian ships them (Russian).
    auto qt = std::make_unique<QTranslator>();
    if (!qt->load(language->locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                  QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        qt.reset();

    Installed &state = installed();
    if (state.own)
        QCoreApplication::removeTranslator(state.own.get());
    if (state.qt)
        QCoreApplication::removeTranslator(state.qt.get());
    state.own = std::move(own);
    state.qt = std::move(qt);
    state.code = code;

    // No group separators anywhere: "a = 1000 mm" in a plot's subtitle as in the values panel
    // and the fields ("1,000" reads as one in Russian and Serbian, where ',' is the decimal point).
    QLocale locale = language->locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    QLocale::setDefault(locale);
    // Widgets keep the locale they were made with: the GUI's hook gives the windows open now
    // the new one (their children inherit it), so spin boxes and fields read and write numbers
    // the new way.
    if (localeHook())
        localeHook()(locale);
    text::Hooks hooks;
    hooks.translate = translateHook;
    hooks.decimalPoint = language->locale.decimalPoint().toStdString();
    // The minus sign of typography (U+2212) in every language, as the plots' tick labels and
    // the titles write it: in drawings and sentences "−5°" reads better than "-5°".
    hooks.minusSign = "\u2212";
    text::install(std::move(hooks));
    // Last: installing sends LanguageChange, and the widgets re-translate with the new locale.
    if (state.qt)
        QCoreApplication::installTranslator(state.qt.get());
    QCoreApplication::installTranslator(state.own.get());
    return true;
}

QString current()
{
    return installed().code;
}

} // namespace pkm::language
