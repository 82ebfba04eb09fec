#include "gui/backgroundtask.h"

#include <QCoreApplication>
#include <QFutureWatcher>
#include <QPointer>
#include <QProgressDialog>
#include <QThreadPool>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <memory>

namespace pkm {

namespace {
/// How far the work is, written by its thread and read by the GUI's timer.
struct Progress {
    std::atomic<int> done {0};
    std::atomic<int> total {0}; ///< 0: not known (a busy bar)
};
/// The pool long jobs run in. Its threads leave as soon as their job is done: a thread keeps
/// caches of its own (the glyphs an animation's frames were drawn with, its malloc arena)
/// until it exits, and in the shared pool an idle thread lives 30 s, so the memory of one
/// export could stay with the window that long (CI measured 29.5 s).
QThreadPool *jobPool()
{
    static QPointer<QThreadPool> pool;
    if (!pool) {
        // The application's child: it waits for a running job as the application closes,
        // as the shared pool would.
        pool = new QThreadPool(QCoreApplication::instance());
        pool->setExpiryTimeout(0);
    }
    return pool;
}
} // namespace

void runWithProgress(QWidget *parent, const QString &title, const QString &label,
                     std::function<TaskFailure(const std::atomic<bool> &cancel, const TaskProgress &progress)> work,
                     std::function<void(const TaskFailure &failure, bool cancelled)> done)
{
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    auto state = std::make_shared<Progress>();
    QPointer<QProgressDialog> progress = new QProgressDialog(label, QCoreApplication::translate("pkm::BackgroundTask", "Cancel"), 0, 0, parent);
    progress->setWindowTitle(title);
    progress->setMinimumDuration(500);
    progress->setAttribute(Qt::WA_DeleteOnClose);
    // The bar stays full while the last step finishes (a video's index): closed by the end only.
    progress->setAutoClose(false);
    progress->setAutoReset(false);
    QObject::connect(progress, &QProgressDialog::canceled, progress, [cancel] { *cancel = true; });
    auto *timer = new QTimer(progress);
    QObject::connect(timer, &QTimer::timeout, progress, [progress, state] {
        const int total = state->total;
        if (total > 0 && progress) {
            progress->setMaximum(total);
            progress->setValue(std::min(state->done.load(), total));
        }
    });
    timer->start(100);

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
    const TaskProgress report = [state](int doneSteps, int total) {
        state->done = doneSteps;
        state->total = total;
    };
    watcher->setFuture(QtConcurrent::run(jobPool(), [work = std::move(work), cancel, report] { return work(*cancel, report); }));
}

void runInBackground(QWidget *parent, const QString &title, const QString &label,
                     std::function<TaskFailure(const std::atomic<bool> &cancel)> work,
                     std::function<void(const TaskFailure &failure, bool cancelled)> done)
{
    runWithProgress(
        parent, title, label,
        [work = std::move(work)](const std::atomic<bool> &cancel, const TaskProgress &) { return work(cancel); },
        std::move(done));
}

} // namespace pkm
