#include "background_task.h"

#include <QEventLoop>
#include <QFutureWatcher>
#include <QObject>
#include <QProgressDialog>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

namespace octaclay::app {

QString BackgroundTaskRunner::run(const QString& label, const std::function<void()>& work,
                                  std::shared_ptr<TaskControl> control) {
  if (busy_) return QObject::tr("Another file operation is still running");
  busy_ = true;
  auto error = std::make_shared<QString>();
  QFutureWatcher<void> watcher;
  QEventLoop loop;
  QObject::connect(&watcher, &QFutureWatcher<void>::finished, &loop, &QEventLoop::quit);
  QProgressDialog progress(label, control ? QObject::tr("Cancel") : QString(), 0, control ? 100 : 0,
                           parent_);
  progress.setWindowModality(Qt::WindowModal); // no edits while the document is in flight
  progress.setMinimumDuration(0);
  progress.cancel(); // QProgressDialog shows itself at construction otherwise: wait as below
  QTimer poll;
  if (control) {
    QObject::connect(&progress, &QProgressDialog::canceled, &progress,
                     [control] { control->cancel = true; });
    QObject::connect(&poll, &QTimer::timeout, &progress, [&progress, control] {
      progress.setValue(static_cast<int>(control->fraction.load() * 100));
    });
    poll.start(100);
  }
  watcher.setFuture(QtConcurrent::run([work, error] {
    try {
      work();
    } catch (const std::exception& e) {
      *error = QString::fromUtf8(e.what());
    }
  }));
  // Work a person would notice (over 100 ms) gets the dialog; quick work never flashes it.
  QTimer::singleShot(100, &progress, [&progress, &watcher] {
    if (!watcher.isFinished()) progress.show();
  });
  if (!watcher.isFinished()) loop.exec();
  busy_ = false;
  return *error;
}

} // namespace octaclay::app
