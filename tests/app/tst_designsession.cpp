// The file side of a session, through the main window as a user meets it: save and reopen,
// the unsaved-changes question, recent files, autosave and recovery after a crash.
#include "designpanel.h"
#include "document/designsession.h"
#include "document/document.h"
#include "document/language.h"
#include "gui/mainwindow.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>

#include <memory>

using namespace pkm;

namespace {
/// Answers the window's questions with `answer` and counts them.
struct Answers {
    QMessageBox::StandardButton answer = QMessageBox::Cancel;
    int asked = 0;
    QString lastText;
};

void answerWith(MainWindow &window, const std::shared_ptr<Answers> &answers)
{
    window.setQuestion([answers](const QString &, const QString &text, QMessageBox::StandardButtons) {
        ++answers->asked;
        answers->lastText = text;
        return answers->answer;
    });
}

double parameter(const MainWindow &window, const char *name)
{
    return window.document()->mechanism()->parameters().at(name);
}
} // namespace

class TestDesignSession : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("PKM Studio tests"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_designsession"));
    }

    void init()
    {
        QSettings().clear();
        QDir(DesignSession::autosaveDirectory()).removeRecursively();
    }

    void saveReopenUndo()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("mine.pkm.json"));
        {
            MainWindow window;
            auto answers = std::make_shared<Answers>();
            answerWith(window, answers);
            QVERIFY(!window.session()->isModified());
            QVERIFY(window.document()->setParameter(QStringLiteral("a"), 190.0).ok());
            QVERIFY(window.session()->isModified());
            QVERIFY(window.isWindowModified());
            // The toolbar keeps a short label and names the step in its tooltip.
            auto *toolbar = window.findChild<QToolBar *>(QStringLiteral("mainToolBar"));
            QVERIFY(toolbar);
            QAction *undoButton = nullptr;
            for (QAction *action : toolbar->actions()) {
                if (action->text() == QStringLiteral("Undo"))
                    undoButton = action;
            }
            QVERIFY(undoButton && undoButton->isEnabled());
            QVERIFY2(undoButton->toolTip().startsWith(QStringLiteral("Undo ")), qPrintable(undoButton->toolTip()));
            QVERIFY(window.session()->saveAs(path).ok());
            QVERIFY(!window.session()->isModified());
            QCOMPARE(window.session()->filePath(), QFileInfo(path).absoluteFilePath());
            QVERIFY(window.windowTitle().startsWith(QStringLiteral("mine.pkm.json")));
            QCOMPARE(window.session()->recentFiles(), QStringList{QFileInfo(path).absoluteFilePath()});
            // Undoing after the save is a change again; redoing returns to the saved state.
            window.document()->undoStack()->undo();
            QVERIFY(window.session()->isModified());
            window.document()->undoStack()->redo();
            QVERIFY(!window.session()->isModified());
        }
        MainWindow window;
        QVERIFY(window.openDesign(path));
        QCOMPARE(parameter(window, "a"), 190.0);
        QVERIFY(!window.session()->isModified());
        // The recent files menu offers it.
        auto *recent = window.findChild<QMenu *>(QStringLiteral("recentMenu"));
        QVERIFY(recent);
        QCOMPARE(recent->actions().size(), 1);
        QCOMPARE(recent->actions().first()->data().toString(), QFileInfo(path).absoluteFilePath());
    }

    void unsavedChangesAreAskedAbout()
    {
        QTemporaryDir dir;
        MainWindow window;
        auto answers = std::make_shared<Answers>();
        answerWith(window, answers);
        QVERIFY(window.maybeSave()); // nothing to save: no question
        QCOMPARE(answers->asked, 0);

        QVERIFY(window.document()->setParameter(QStringLiteral("a"), 185.0).ok());
        answers->answer = QMessageBox::Cancel;
        QVERIFY(!window.close()); // cancelled: the window stays, the change too
        QCOMPARE(answers->asked, 1);
        QVERIFY(answers->lastText.contains(QStringLiteral("not saved")));
        QCOMPARE(parameter(window, "a"), 185.0);

        // Save with a file: written, then the window may go on.
        const QString path = dir.filePath(QStringLiteral("kept.pkm.json"));
        QVERIFY(window.session()->saveAs(path).ok());
        QVERIFY(window.document()->setParameter(QStringLiteral("a"), 186.0).ok());
        answers->answer = QMessageBox::Save;
        QVERIFY(window.maybeSave());
        QVERIFY(!window.session()->isModified());
        QCOMPARE(designfile::load(path)->mechanism->parameters().at("a"), 186.0);

        // Discard: goes on without writing.
        QVERIFY(window.document()->setParameter(QStringLiteral("a"), 187.0).ok());
        answers->answer = QMessageBox::Discard;
        QVERIFY(window.close());
        QCOMPARE(designfile::load(path)->mechanism->parameters().at("a"), 186.0);
    }

    void autosaveAndRecovery()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("work.pkm.json"));
        QString autosave;
        {
            MainWindow window;
            QVERIFY(window.session()->saveAs(path).ok());
            QVERIFY(window.document()->setParameter(QStringLiteral("a"), 177.0).ok());
            QVERIFY(window.session()->autosaveNow().ok());
            autosave = window.session()->autosavePath();
            QVERIFY(QFile::exists(autosave));
            // A running session's autosave is not offered to another one.
            QVERIFY(DesignSession::pendingRecoveries().isEmpty());
            // A normal end removes it.
        }
        QVERIFY(!QFile::exists(autosave));
        QVERIFY(DesignSession::pendingRecoveries().isEmpty());
    }

    void recoveryAfterACrash()
    {
        // A child process makes changes, autosaves and is killed: its autosave stays behind.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("work.pkm.json"));
        QProcess child;
        child.setProcessChannelMode(QProcess::ForwardedChannels);
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("PKM_TEST_CRASH_AFTER_AUTOSAVE"), path);
        environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        child.setProcessEnvironment(environment);
        child.start(QCoreApplication::applicationFilePath(), {QStringLiteral("crashingSession")});
        QVERIFY(child.waitForFinished(60000));
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);

        const auto pending = DesignSession::pendingRecoveries();
        QCOMPARE(pending.size(), 1);
        QCOMPARE(pending.first().originalPath, QFileInfo(path).absoluteFilePath());

        MainWindow window;
        auto answers = std::make_shared<Answers>();
        answers->answer = QMessageBox::Yes;
        answerWith(window, answers);
        window.offerRecovery();
        QCOMPARE(answers->asked, 1);
        QCOMPARE(parameter(window, "a"), 175.5);
        QVERIFY(window.session()->isModified()); // not in the file yet
        QCOMPARE(window.session()->filePath(), QFileInfo(path).absoluteFilePath());
        QCOMPARE(designfile::load(path)->mechanism->parameters().at("a"), 170.0);
        // Recovered once: the next start does not offer it again.
        QVERIFY(DesignSession::pendingRecoveries().isEmpty());
        QVERIFY(window.saveFile());
        QCOMPARE(designfile::load(path)->mechanism->parameters().at("a"), 175.5);
    }

    /// A session killed before its first autosave leaves only its lock; the next look for
    /// recoveries removes it (it stayed for ever).
    void lockOfAKilledSessionIsRemoved()
    {
        const QDir directory(DesignSession::autosaveDirectory());
        const auto locks = [&] { return directory.entryList({QStringLiteral("*.lock")}, QDir::Files); };
        const QStringList before = locks();
        QProcess child;
        child.setProcessChannelMode(QProcess::ForwardedChannels);
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        child.setProcessEnvironment(environment);
        child.start(QCoreApplication::applicationFilePath(), {QStringLiteral("crashingBeforeAutosave")});
        QVERIFY(child.waitForFinished(60000));
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);
        QCOMPARE(locks().size(), before.size() + 1);
        QVERIFY(DesignSession::pendingRecoveries().isEmpty());
        QCOMPARE(locks(), before);
    }

    void declinedRecoveryIsDeleted()
    {
        QDir().mkpath(DesignSession::autosaveDirectory());
        const QString orphan = QDir(DesignSession::autosaveDirectory()).filePath(QStringLiteral("orphan.pkm.json"));
        QVERIFY(designfile::save(*designfile::load(QStringLiteral("moma-3a")), orphan).ok());
        QCOMPARE(DesignSession::pendingRecoveries().size(), 1);
        // the prompt names an unsaved preset in the language chosen, as the Design dock does
        QVERIFY(language::apply(QStringLiteral("ru")));
        MainWindow window;
        auto answers = std::make_shared<Answers>();
        answers->answer = QMessageBox::No;
        answerWith(window, answers);
        window.offerRecovery();
        language::apply(QStringLiteral("en"));
        QCOMPARE(answers->asked, 1);
        QVERIFY2(answers->lastText.contains(QStringLiteral("MOMA, конфигурация 3a")), qPrintable(answers->lastText));
        QCOMPARE(window.document()->mechanism()->kind(), std::string_view("pjoint"));
        QVERIFY(!QFile::exists(orphan));
    }

    void vanishedRecentFileIsRemoved()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("gone.pkm.json"));
        MainWindow window;
        QVERIFY(window.session()->saveAs(path).ok());
        QFile::remove(path);
        auto *recent = window.findChild<QMenu *>(QStringLiteral("recentMenu"));
        QCOMPARE(recent->actions().size(), 1);
        recent->actions().first()->trigger();
        QVERIFY(window.lastStatus().contains(QStringLiteral("no longer exists")));
        QVERIFY(window.session()->recentFiles().isEmpty());
        QCOMPARE(recent->actions().size(), 0);
    }
};

/// The child of recoveryAfterACrash: change the design, autosave, crash.
static int crashingSession(int argc, char **argv)
{
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("PKM Studio tests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_designsession"));
    const QString path = qEnvironmentVariable("PKM_TEST_CRASH_AFTER_AUTOSAVE");
    MainWindow window;
    if (!window.session()->saveAs(path).ok() || !window.document()->setParameter(QStringLiteral("a"), 175.5).ok()
        || !window.session()->autosaveNow().ok())
        return 1;
    std::abort();
}

/// The child of lockOfAKilledSessionIsRemoved: a session that ends before any autosave.
static int crashingBeforeAutosave(int argc, char **argv)
{
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("PKM Studio tests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_designsession"));
    MainWindow window;
    std::abort();
}

int main(int argc, char **argv)
{
    if (argc == 2 && qstrcmp(argv[1], "crashingSession") == 0)
        return crashingSession(argc, argv);
    if (argc == 2 && qstrcmp(argv[1], "crashingBeforeAutosave") == 0)
        return crashingBeforeAutosave(argc, argv);
    QApplication app(argc, argv);
    TestDesignSession test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_designsession.moc"
