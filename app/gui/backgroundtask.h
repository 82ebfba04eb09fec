#pragma once
/// Long exports (an animation, a parameter sheet with its workspace maps) run off the GUI
/// thread: a progress dialog appears after half a second and offers to cancel, and the result
/// comes back on the GUI thread.

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

} // namespace pkm
