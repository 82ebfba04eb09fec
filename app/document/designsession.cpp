#include "document/designsession.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <QUuid>

namespace pkm {

namespace {
constexpr const char *recentFilesKey = "files/recent";
/// The key an autosave adds to the design file: {"file": original path, "saved": ISO time}.
constexpr const char *autosaveKey = "autosave";
constexpr int defaultAutosaveMilliseconds = 60 * 1000;

QString lockPathFor(const QString &autosavePath)
{
    QString path = autosavePath;
    path.chop(int(qstrlen(".pkm.json")));
    return path + QStringLiteral(".lock");
}

Failure writeFailure(const QString &path, const QString &why)
{
    return Failure{FailureKind::InvalidParameter, path.toStdString(),
                   DesignSession::tr("Cannot write %1: %2.").arg(path, why).toStdString()};
}
} // namespace

DesignSession::DesignSession(Document *document, QObject *parent)
    : QObject(parent)
    , m_document(document)
{
    const QString directory = autosaveDirectory();
    QDir().mkpath(directory);
    const QString id = QUuid::createUuid().toString(QUuid::WithoutBraces);
    m_autosavePath = QDir(directory).filePath(id + QStringLiteral(".pkm.json"));
    m_lock = std::make_unique<QLockFile>(lockPathFor(m_autosavePath));
    m_lock->setStaleLockTime(0); // stale only when its process is gone, however long it runs
    m_lock->tryLock(0);

    m_timer.setInterval(defaultAutosaveMilliseconds);
    connect(&m_timer, &QTimer::timeout, this, [this] { autosaveNow(); });
    m_timer.start();
    connect(m_document->undoStack(), &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

DesignSession::~DesignSession()
{
    // Ending normally: nothing to recover.
    removeAutosave();
}

bool DesignSession::isModified() const
{
    return !m_document->undoStack()->isClean();
}

QString DesignSession::displayName() const
{
    if (!m_filePath.isEmpty())
        return QFileInfo(m_filePath).fileName();
    const QString title = designfile::presetText(m_document->design().title);
    return title.isEmpty() ? tr("Untitled design") : title;
}

Result<bool> DesignSession::open(const QString &presetOrPath)
{
    auto opened = m_document->open(presetOrPath);
    if (!opened)
        return opened;
    if (designfile::isPresetId(presetOrPath)) {
        setFilePath(QString());
    } else {
        const QString path = QFileInfo(presetOrPath).absoluteFilePath();
        setFilePath(path);
        addRecentFile(path);
    }
    markClean();
    return true;
}

Result<bool> DesignSession::openTemplate(const QString &presetId)
{
    auto opened = m_document->openTemplate(presetId);
    if (!opened)
        return opened;
    setFilePath(QString()); // the undo stack is past its clean state: modified
    return true;
}

Result<bool> DesignSession::save()
{
    Q_ASSERT(!m_filePath.isEmpty());
    return saveAs(m_filePath);
}

Result<bool> DesignSession::saveAs(const QString &path)
{
    Design design = m_document->design();
    if (QFileInfo(path).absoluteFilePath() != m_filePath)
        design.id.clear(); // a saved copy is the user's design, not the preset
    auto saved = designfile::save(design, path);
    if (!saved)
        return saved;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    setFilePath(absolute);
    addRecentFile(absolute);
    markClean();
    removeAutosave();
    return true;
}

void DesignSession::markClean()
{
    m_document->undoStack()->setClean();
    emit modifiedChanged(false);
}

void DesignSession::setFilePath(const QString &path)
{
    if (path == m_filePath)
        return;
    m_filePath = path;
    emit filePathChanged(path);
}

QStringList DesignSession::recentFiles() const
{
    return QSettings().value(QLatin1String(recentFilesKey)).toStringList();
}

void DesignSession::addRecentFile(const QString &path)
{
    QStringList files = recentFiles();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > maxRecentFiles)
        files.removeLast();
    QSettings().setValue(QLatin1String(recentFilesKey), files);
    emit recentFilesChanged();
}

void DesignSession::removeRecentFile(const QString &path)
{
    QStringList files = recentFiles();
    if (files.removeAll(path) == 0)
        return;
    QSettings().setValue(QLatin1String(recentFilesKey), files);
    emit recentFilesChanged();
}

QString DesignSession::autosaveDirectory()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(QStringLiteral("autosave"));
}

Result<bool> DesignSession::autosaveNow()
{
    if (!isModified()) {
        removeAutosave();
        return true;
    }
    QJsonObject root = QJsonDocument::fromJson(designfile::serialize(m_document->design())).object();
    root.insert(QLatin1String(autosaveKey),
                QJsonObject{{QStringLiteral("file"), m_filePath},
                            {QStringLiteral("saved"), QDateTime::currentDateTime().toString(Qt::ISODate)}});
    QSaveFile file(m_autosavePath);
    if (!file.open(QIODevice::WriteOnly))
        return writeFailure(m_autosavePath, file.errorString());
    file.write(QJsonDocument(root).toJson(QJsonDocument::Indented));
    if (!file.commit())
        return writeFailure(m_autosavePath, file.errorString());
    return true;
}

void DesignSession::removeAutosave()
{
    QFile::remove(m_autosavePath);
}

QList<DesignSession::Recovery> DesignSession::pendingRecoveries()
{
    QList<Recovery> list;
    const QDir directory(autosaveDirectory());
    // A session killed before its first autosave leaves only its lock: taken over once its
    // process is gone (stale), it is removed as the QLockFile goes.
    for (const QFileInfo &info : directory.entryInfoList({QStringLiteral("*.lock")}, QDir::Files)) {
        QString design = info.absoluteFilePath();
        design.chop(int(qstrlen(".lock")));
        if (QFile::exists(design + QStringLiteral(".pkm.json")))
            continue; // its autosave is looked at below
        QLockFile lock(info.absoluteFilePath());
        lock.setStaleLockTime(0);
        lock.tryLock(0);
    }
    const QFileInfoList files =
        directory.entryInfoList({QStringLiteral("*.pkm.json")}, QDir::Files, QDir::Time | QDir::Reversed);
    for (const QFileInfo &info : files) {
        QLockFile lock(lockPathFor(info.absoluteFilePath()));
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0))
            continue; // a running session's
        const auto bytes = designfile::readFile(info.absoluteFilePath(), info.fileName());
        if (!bytes)
            continue; // unreadable or too large: not a copy this program wrote
        const QJsonObject root = QJsonDocument::fromJson(*bytes).object();
        const QJsonObject autosave = root.value(QLatin1String(autosaveKey)).toObject();
        Recovery recovery;
        recovery.autosavePath = info.absoluteFilePath();
        recovery.originalPath = autosave.value(QStringLiteral("file")).toString();
        recovery.title = root.value(QStringLiteral("title")).toString();
        recovery.saved = QDateTime::fromString(autosave.value(QStringLiteral("saved")).toString(), Qt::ISODate);
        if (!recovery.saved.isValid())
            recovery.saved = info.lastModified();
        list.append(recovery);
    }
    return list;
}

Result<bool> DesignSession::recover(const Recovery &recovery)
{
    auto opened = m_document->open(recovery.autosavePath);
    if (!opened)
        return opened;
    // Not clean: the recovered changes are not in any file yet.
    setFilePath(recovery.originalPath);
    emit modifiedChanged(isModified());
    if (autosaveNow())
        discardRecovery(recovery); // this session's autosave holds it now
    return true;
}

void DesignSession::discardRecovery(const Recovery &recovery)
{
    QFile::remove(recovery.autosavePath);
    QFile::remove(lockPathFor(recovery.autosavePath));
}

} // namespace pkm
