#include "gui/backgroundtask.h"

#include <QCoreApplication>
#include <QFutureWatcher>
#include <QPointer>
#include <QProgressDialog>
#include <QtConcurrent/QtConcurrentRun>

#include <memory>

namespace pkm {

void runInBackground(QWidget *parent, const QString &title, const QString &label,
                     std::function<TaskFailure(const std::atomic<bool> &cancel)> work,
                     std::function<void(const TaskFailure &failure, bool cancelled)> done)
{
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    QPointer<QProgressDialog> progress = new QProgressDialog(label, QCoreApplication::translate("pkm::BackgroundTask", "Cancel"), 0, 0, parent);
    progress->setWindowTitle(title);
    progress->setMinimumDuration(500);
    progress->setAttribute(Qt::WA_DeleteOnClose);
    QObject::connect(progress, &QProgressDialog::canceled, progress, [cancel] { *cancel = true; });

    auto *watcher = new QFutureWatcher<TaskFailure>(parent);
    QObject::connect(watcher, &QFutureWatcher<TaskFailure>::finished, parent, [watcher, progress, cancel, done] {
        const TaskFailure failure = watcher->result();
        watcher->deleteLater();
        const bool cancelled = *cancel;
        if (progress) {
            QObject::disconnect(progress, &QProgressDialog::canceled, progress, nullptr);
            progress->close(); // (closing a progress dialog says "canceled")
        }
        done(failure, cancelled);
    });
    watcher->setFuture(QtConcurrent::run([work = std::move(work), cancel] { return work(*cancel); }));
}

} // namespace pkm
