#pragma once
/// Long exports (an animation, a parameter sheet with its workspace maps) run off the GUI
/// thread: a progress dialog appears after half a second and offers to cancel, and the result
/// comes back on the GUI thread. Work that knows how far it is (a video's frames) fills the
/// dialog's bar.

#include <QString>

#include <atomic>
#include <functional>
#include <optional>

class QWidget;

namespace pkm {

/// What the work reports: nothing on success, else one sentence for the user.
using TaskFailure = std::optional<QString>;

/// Runs `work` on a pool thread. It must touch only its own data and should return soon after
/// its cancel flag becomes true. `done` runs on the GUI thread with the outcome and whether the
/// user cancelled; it is dropped if `parent` is gone by then.
void runInBackground(QWidget *parent, const QString &title, const QString &label,
                     std::function<TaskFailure(const std::atomic<bool> &cancel)> work,
                     std::function<void(const TaskFailure &failure, bool cancelled)> done);

/// Tells the progress dialog that `done` of `total` steps are done; callable from the work's
/// thread at any rate (the dialog looks ten times a second).
using TaskProgress = std::function<void(int done, int total)>;

/// runInBackground() with a progress bar: `work` reports through its TaskProgress.
void runWithProgress(QWidget *parent, const QString &title, const QString &label,
                     std::function<TaskFailure(const std::atomic<bool> &cancel, const TaskProgress &progress)> work,
                     std::function<void(const TaskFailure &failure, bool cancelled)> done);

} // namespace pkm
