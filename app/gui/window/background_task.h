#pragma once

#include <QString>

#include <atomic>
#include <functional>
#include <memory>

class QWidget;

namespace octaclay::app {

/// What a cancellable task shares with the GUI thread.
struct TaskControl {
  std::atomic<float> fraction{0};  ///< done so far, [0, 1]; the worker writes it
  std::atomic<bool> cancel{false}; ///< the user asked to stop; the worker polls it
};

/// Runs long file work (loads, saves, imports, exports) off the GUI thread, one task at a time,
/// while the event loop keeps the window responsive: a window-modal progress dialog appears
/// after 100 ms (so quick work never flashes it) and, for a task with a TaskControl, shows its
/// fraction and a Cancel button. GUI thread.
class BackgroundTaskRunner {
public:
  /// parent: the window the progress dialog is modal to; it must outlive the runner's tasks.
  explicit BackgroundTaskRunner(QWidget* parent) : parent_(parent) {}

  /// Runs work on a worker thread and returns once it is done: its error message (what it
  /// threw), empty on success; refuses (says so) while another task runs.
  QString run(const QString& label, const std::function<void()>& work,
              std::shared_ptr<TaskControl> control = nullptr);
  bool busy() const { return busy_; }

private:
  QWidget* parent_;
  bool busy_ = false;
};

} // namespace octaclay::app
