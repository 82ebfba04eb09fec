// The main window's Play and pose bookmarks: the Play toolbar (playbar.h) driving the player
// (player.h), and the Bookmarks menu a teacher steps through with Page Up / Page Down — the keys
// a presenter's clicker sends.

#include "gui/mainwindow.h"
#include "gui/mainwindowinternal.h"

#include "document/document.h"
#include "gui/player.h"
#include "playbar.h"
#include "quantityformat.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QMenuBar>
#include <QToolBar>

namespace pkm {

namespace {
using mainwindow::failureText;
/// How long Play's "turned back: …" stays while it plays on: long enough to read it aloud.
constexpr int turnedMessageMs = 5000;
} // namespace

void MainWindow::createPlayControls(QMenu *viewMenu)
{
    m_player = new Player(m_document, this);
    m_playBar = new PlayBar(this);
    m_playBar->setObjectName(QStringLiteral("playBar"));
    // Below the linkage and its sliders, near the hand that would otherwise drag them.
    m_playToolBar = new QToolBar(this);
    m_playToolBar->setObjectName(QStringLiteral("playToolBar"));
    addToolBar(Qt::BottomToolBarArea, m_playToolBar);
    m_playToolBar->addWidget(m_playBar);
    translated(m_playToolBar->toggleViewAction(), QT_TR_NOOP("Play Toolbar"));
    viewMenu->addAction(m_playToolBar->toggleViewAction());

    m_playAction = translated(new QAction(this), QT_TR_NOOP("Play / &Pause"),
                              QT_TR_NOOP("Move the chosen joint variable by itself, or stop it"));
    m_playAction->setObjectName(QStringLiteral("playAction"));
    m_playAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Space));
    viewMenu->insertAction(viewMenu->actions().value(0), m_playAction);
    connect(m_playAction, &QAction::triggered, this, [this] { setPlaying(!m_player->isPlaying()); });
    connect(m_playBar, &PlayBar::playRequested, this, &MainWindow::setPlaying);
    connect(m_player, &Player::stopped, this, [this](const QString &reason) {
        m_playBar->setPlaying(false);
        showStatus(reason);
    });
    connect(m_player, &Player::turned, this, [this](const QString &reason) {
        showStatus(reason);
        m_statusHeldUntil = QDeadlineTimer(turnedMessageMs);
    });

    m_bookmarksMenu = menuBar()->insertMenu(m_languageMenu ? m_languageMenu->menuAction() : nullptr, new QMenu(this))->menu();
    m_bookmarksMenu->setObjectName(QStringLiteral("bookmarksMenu"));
    translated(m_bookmarksMenu->menuAction(), QT_TR_NOOP("&Bookmarks"));
    m_addBookmarkAction = translated(new QAction(this), QT_TR_NOOP("&Add Bookmark"),
                                     QT_TR_NOOP("Keep this pose to come back to it (saved with the design)"));
    m_addBookmarkAction->setObjectName(QStringLiteral("addBookmarkAction"));
    m_addBookmarkAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    connect(m_addBookmarkAction, &QAction::triggered, this, &MainWindow::addBookmark);
    m_previousBookmarkAction = translated(new QAction(this), QT_TR_NOOP("&Previous Bookmark"));
    m_previousBookmarkAction->setObjectName(QStringLiteral("previousBookmarkAction"));
    m_previousBookmarkAction->setShortcut(QKeySequence(Qt::Key_PageUp));
    connect(m_previousBookmarkAction, &QAction::triggered, this, [this] { stepBookmark(-1); });
    m_nextBookmarkAction = translated(new QAction(this), QT_TR_NOOP("&Next Bookmark"));
    m_nextBookmarkAction->setObjectName(QStringLiteral("nextBookmarkAction"));
    m_nextBookmarkAction->setShortcut(QKeySequence(Qt::Key_PageDown));
    connect(m_nextBookmarkAction, &QAction::triggered, this, [this] { stepBookmark(+1); });
    m_removeBookmarkAction = translated(new QAction(this), QT_TR_NOOP("&Remove Current Bookmark"));
    m_removeBookmarkAction->setObjectName(QStringLiteral("removeBookmarkAction"));
    connect(m_removeBookmarkAction, &QAction::triggered, this, [this] {
        if (auto removed = m_document->removeBookmark(m_currentBookmark); !removed)
            showStatus(failureText(removed.failure()), true);
    });
    // The clicker's keys work wherever the focus is in the window, a slider's included.
    for (QAction *action : {m_previousBookmarkAction, m_nextBookmarkAction})
        action->setShortcutContext(Qt::WindowShortcut);
    // On the bar, symbols that need no room (the whole name is the button's tooltip), so that
    // the bar fits a projector at a large text size; the menu keeps the words.
    m_previousBookmarkAction->setIconText(QStringLiteral("◀ ★"));
    m_addBookmarkAction->setIconText(QStringLiteral("+ ★"));
    m_nextBookmarkAction->setIconText(QStringLiteral("★ ▶"));
    m_playToolBar->addSeparator();
    m_playToolBar->addAction(m_previousBookmarkAction);
    m_playToolBar->addAction(m_addBookmarkAction);
    m_playToolBar->addAction(m_nextBookmarkAction);
    connect(m_document, &Document::bookmarksChanged, this, &MainWindow::updateBookmarksMenu);
    updateBookmarksMenu();
}

void MainWindow::setPlaying(bool play)
{
    if (!play) {
        m_player->stop();
        m_playBar->setPlaying(false);
        return;
    }
    m_playBar->setPlaying(m_player->start(m_playBar->settings()));
}

QString MainWindow::poseSummary() const
{
    const MechanismPtr &mechanism = m_document->mechanism();
    const Pose &pose = m_document->pose();
    QStringList summary;
    const auto &variables = mechanism->variableInfo();
    for (int i = 0; i < static_cast<int>(variables.size()); ++i) {
        summary << QStringLiteral("%1 = %2").arg(toQString(variables[i].symbol),
                                                 formatQuantity(mechanism->variableValue(pose, i), variables[i].unit,
                                                                variables[i].decimals));
    }
    return summary.join(QStringLiteral("   "));
}

void MainWindow::addBookmark()
{
    // Named after the pose it keeps: a teacher adds bookmarks with one key during the lesson
    // plan and reads in the menu where each one goes.
    const QString name = poseSummary();
    if (auto added = m_document->addBookmark(name); !added) {
        showStatus(failureText(added.failure()), true);
        return;
    }
    m_currentBookmark = static_cast<int>(m_document->bookmarks().size()) - 1;
    updateBookmarksMenu();
    showStatus(tr("Bookmark %1 kept: %2").arg(m_currentBookmark + 1).arg(name));
}

void MainWindow::goToBookmark(int index)
{
    const int count = static_cast<int>(m_document->bookmarks().size());
    if (index < 0 || index >= count)
        return;
    setPlaying(false);
    m_currentBookmark = index;
    auto moved = m_document->goToBookmark(index);
    updateBookmarksMenu();
    if (!moved) {
        showStatus(failureText(moved.failure()), true);
        return;
    }
    showStatus(tr("Bookmark %1 of %2: %3").arg(index + 1).arg(count).arg(m_document->bookmarks()[index].name));
}

void MainWindow::stepBookmark(int step)
{
    const int count = static_cast<int>(m_document->bookmarks().size());
    if (count == 0) {
        showStatus(tr("No bookmarks yet: Bookmarks ▸ Add Bookmark (Ctrl+B) keeps the pose shown."));
        return;
    }
    // From none: Page Down starts at the first, Page Up at the last.
    const int from = m_currentBookmark < 0 || m_currentBookmark >= count ? (step > 0 ? -1 : 0) : m_currentBookmark;
    goToBookmark(((from + step) % count + count) % count);
}

void MainWindow::updateBookmarksMenu()
{
    const QList<Bookmark> &bookmarks = m_document->bookmarks();
    if (m_currentBookmark >= bookmarks.size())
        m_currentBookmark = static_cast<int>(bookmarks.size()) - 1;
    m_bookmarksMenu->clear();
    m_bookmarksMenu->addAction(m_addBookmarkAction);
    m_bookmarksMenu->addAction(m_previousBookmarkAction);
    m_bookmarksMenu->addAction(m_nextBookmarkAction);
    m_bookmarksMenu->addAction(m_removeBookmarkAction);
    m_removeBookmarkAction->setEnabled(m_currentBookmark >= 0);
    if (bookmarks.isEmpty())
        return;
    m_bookmarksMenu->addSeparator();
    auto *group = new QActionGroup(m_bookmarksMenu);
    for (int i = 0; i < bookmarks.size(); ++i) {
        QAction *action = m_bookmarksMenu->addAction(QStringLiteral("%1. %2").arg(i + 1).arg(bookmarks[i].name));
        action->setObjectName(QStringLiteral("bookmark_%1").arg(i + 1));
        action->setCheckable(true);
        action->setChecked(i == m_currentBookmark);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, i] { goToBookmark(i); });
    }
}

} // namespace pkm
