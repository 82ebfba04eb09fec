#pragma once
/// The file side of a working session: which file the document belongs to, whether it has
/// unsaved changes, the recent files, and the autosave that lets a design survive a crash.
///
/// Modified means "a design change the file does not have": the undo stack is not at its clean
/// index. Moving the pose is exploring, not editing (document.h), so it does not ask to be
/// saved; a save writes the current pose all the same.
///
/// Autosave: while the design is modified, it is written every autosaveInterval() to
/// <app data>/autosave/<session>.pkm.json (atomically), next to a lock file held for the
/// session's lifetime. A session that ends normally removes both. At the next start an autosave
/// whose lock is stale (its process is gone) is a design to recover.

#include "document/document.h"

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <memory>

namespace pkm {

class DesignSession : public QObject
{
    Q_OBJECT

public:
    /// A design left behind by a session that did not end normally.
    struct Recovery {
        QString autosavePath;
        QString originalPath; ///< the file it belonged to, or empty
        QString title;
        QDateTime saved;
    };

    explicit DesignSession(Document *document, QObject *parent = nullptr);
    ~DesignSession() override;

    /// The design file the document was opened from or saved to; empty for a preset.
    QString filePath() const { return m_filePath; }
    bool isModified() const;
    /// The title for the window: the file's name, or the design's title.
    QString displayName() const;

    /// Opens a preset or a file as an undoable replacement; a file joins the recent files.
    Result<bool> open(const QString &presetOrPath);
    /// Starts a new design from a preset (Document::openTemplate): no file yet, and modified
    /// until it is saved, so that closing asks about it.
    Result<bool> openTemplate(const QString &presetId);
    /// Saves to filePath() (which must not be empty), atomically.
    Result<bool> save();
    /// Saves to `path` and makes it the document's file.
    Result<bool> saveAs(const QString &path);
    /// Marks the current state as saved (after the start-up design is opened).
    void markClean();

    QStringList recentFiles() const;
    void removeRecentFile(const QString &path);
    static constexpr int maxRecentFiles = 8;

    // -- autosave and recovery ----------------------------------------------------------------
    QString autosavePath() const { return m_autosavePath; }
    int autosaveInterval() const { return m_timer.interval(); }
    void setAutosaveInterval(int milliseconds) { m_timer.setInterval(milliseconds); }
    /// Writes the autosave now if the design is modified (else removes a stale one).
    Result<bool> autosaveNow();
    /// The autosaves of sessions that ended without closing.
    static QList<Recovery> pendingRecoveries();
    /// Opens a recovered design: modified, belonging to its original file (not saved there
    /// until the user saves). The recovered autosave is removed once this session holds it.
    Result<bool> recover(const Recovery &recovery);
    /// Deletes a recovery the user does not want.
    static void discardRecovery(const Recovery &recovery);
    /// The directory of the autosaves.
    static QString autosaveDirectory();

signals:
    void modifiedChanged(bool modified);
    void filePathChanged(const QString &path);
    void recentFilesChanged();

private:
    void setFilePath(const QString &path);
    void addRecentFile(const QString &path);
    void removeAutosave();

    Document *m_document;
    QString m_filePath;
    QString m_autosavePath;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
};

} // namespace pkm
