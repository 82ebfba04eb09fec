// pkm-studio: the desktop application. Usage: pkm-studio [--3d] [--presentation] [PRESET-ID | DESIGN.pkm.json]
#include "document/designsession.h"
#include "document/document.h"
#include "document/language.h"
#include "gui/mainwindow.h"
#include "linkageview.h"
#include "textscale.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QScreen>
#include <QTabWidget>
#include <QTimer>

#include <cstdio>

namespace {
QElapsedTimer started;

/// Quits the application after the first paint of the object it watches (the linkage view:
/// the window is up and drawn), saying how long it took.
class FirstPaint : public QObject
{
public:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::Paint && !m_seen) {
            m_seen = true;
            QTimer::singleShot(0, qApp, [] {
                std::printf("first paint after %.1f ms from main()\n", started.nsecsElapsed() * 1e-6);
                QApplication::quit();
            });
        }
        return QObject::eventFilter(watched, event);
    }

private:
    bool m_seen = false;
};
} // namespace

int main(int argc, char *argv[])
{
    started.start();
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("PKM Studio"));
    QApplication::setApplicationName(QStringLiteral("pkm-studio"));
    QApplication::setApplicationDisplayName(QStringLiteral("PKM Studio"));
    QApplication::setApplicationVersion(QStringLiteral(PKM_VERSION));
    QApplication::setDesktopFileName(QStringLiteral("org.pkmstudio.PKMStudio"));
    pkm::textscale::applyBaseFont(); // a classroom projects this

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Design, analyse and teach parallel-kinematic mechanisms."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("design"),
                                 QStringLiteral("Preset id (see 'pkm list') or design file to open; "
                                                "default: pjoint-prototype."));
    const QCommandLineOption show3d(QStringLiteral("3d"), QStringLiteral("Start with the 3D view of the linkage."));
    parser.addOption(show3d);
    const QCommandLineOption presentation(QStringLiteral("presentation"),
                                          QStringLiteral("Start in presentation mode (full screen, large text; Esc leaves it)."));
    parser.addOption(presentation);
    const QCommandLineOption languageOption(
        QStringLiteral("lang"),
        QStringLiteral("Language for this run: en, sr (Serbian, Cyrillic), sr_Latn (Serbian, Latin) or ru; "
                       "default: the one chosen in the Language menu, else the system's."),
        QStringLiteral("code"));
    parser.addOption(languageOption);
    // For the start-up benchmark (bench/startup.cmake): quit once the window has been painted,
    // printing how long that took from main().
    QCommandLineOption quitAfterPaint(QStringLiteral("quit-after-first-paint"),
                                      QStringLiteral("Quit as soon as the window is painted (benchmarks)."));
    quitAfterPaint.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(quitAfterPaint);
    parser.process(app);

    // The language first, so that every widget is made in it. --lang is for this run only.
    const QString code = parser.isSet(languageOption) ? parser.value(languageOption) : pkm::language::preferred();
    if (!pkm::language::apply(code)) {
        std::fprintf(stderr, "pkm-studio: unknown language '%s' (use en, sr, sr_Latn or ru)\n", qPrintable(code));
        return 2;
    }

    pkm::MainWindow window;
    const QStringList designs = parser.positionalArguments();
    if (!designs.isEmpty() && !window.openDesign(designs.first())) {
        std::fprintf(stderr, "pkm-studio: %s\n", qPrintable(window.lastStatus()));
    } else {
        // Opening at start is not an edit the user should be able to undo.
        window.document()->undoStack()->clear();
        window.session()->markClean();
    }
    if (parser.isSet(show3d))
        window.viewTabs()->setCurrentIndex(1);
    // First start: fill the screen (also where no window manager honours "maximized");
    // later starts restore the remembered geometry, maximized or not.
    if (!window.restoredGeometry()) {
        if (QScreen *screen = QGuiApplication::primaryScreen())
            window.setGeometry(screen->availableGeometry());
        window.showMaximized();
    } else {
        window.show();
    }
    // After the window's own first steps (queued before this one: the Design and the values
    // raised in front of their tabs, the docks sized to the screen), so that leaving the
    // presentation returns to that layout, not to Mobility and Tolerances in front.
    if (parser.isSet(presentation))
        QTimer::singleShot(0, &window, [&window] { window.setPresentationMode(true); });
    FirstPaint firstPaint;
    if (parser.isSet(quitAfterPaint))
        window.linkageView()->installEventFilter(&firstPaint);
    else // after the window is up, so that the question has a parent to sit on
        QTimer::singleShot(0, &window, [&window] { window.offerRecovery(); });
    return app.exec();
}
