#pragma once
/// The languages PKM Studio speaks: English (the source), Serbian in Cyrillic and in Latin
/// script, and Russian. Applying one installs its catalogue (and Qt's own, where Debian has
/// it), makes its locale the default for numbers, and lets core/ translate its sentences
/// (text.h). Qt then sends QEvent::LanguageChange to every widget, which re-translates itself.

#include <QLocale>
#include <QString>
#include <QStringList>

#include <functional>

namespace pkm::language {

struct Language {
    QString code;       ///< "en", "sr", "sr_Latn", "ru": the catalogue's suffix
    QString nativeName; ///< as its speakers write it: "Српски (ћирилица)"
    QLocale locale;     ///< numbers and dates
};

/// All languages, English first.
const QList<Language> &all();
/// The language of `code`, or nullptr.
const Language *find(const QString &code);
/// The language that best fits `locale` (the system's by default): Russian for ru_*, Serbian
/// Latin for sr_Latn_* (and the Latin-script Serbo-Croatian locales), Serbian Cyrillic for
/// other sr_*, else English.
QString bestFor(const QLocale &locale = QLocale::system());
/// The language remembered in the settings, else bestFor().
QString preferred();
/// Remembers `code` for the next start.
void remember(const QString &code);

/// Switches the running program to `code` (QCoreApplication must exist). Returns false, and
/// changes nothing, for an unknown code or a missing catalogue.
bool apply(const QString &code);
/// Called by apply() with the new locale before the catalogues are installed: the GUI gives it
/// to the windows open, whose widgets keep the locale they were made with.
using LocaleHook = std::function<void(const QLocale &)>;
void setLocaleHook(LocaleHook hook);
/// The code applied last ("en" before any).
QString current();

} // namespace pkm::language
