#include "user_messages.h"

#include <QFileInfo>
#include <QFontMetrics>
#include <QStatusBar>

#include <algorithm>

namespace octaclay::app {
namespace {

// reason without a leading "<prefix>: ".
bool dropPrefix(QString& reason, const QString& prefix) {
  if (prefix.isEmpty() || !reason.startsWith(prefix + QStringLiteral(": "))) return false;
  reason.remove(0, prefix.size() + 2);
  return true;
}

} // namespace

QString failureMessage(const QString& failed, const QString& path, const QString& reason) {
  QString why = reason;
  const QFileInfo info(path);
  dropPrefix(why, path) || dropPrefix(why, info.absoluteFilePath()) ||
      dropPrefix(why, info.fileName());
  return QStringLiteral("%1 %2: %3").arg(failed, path, why);
}

void showStatusMessage(QStatusBar& bar, const QString& message, int timeoutMs) {
  const QString firstLine = message.section(QLatin1Char('\n'), 0, 0);
  // The permanent widgets (frames/s, triangles…) keep their room on the right.
  int room = bar.width() - 16;
  for (QWidget* w : bar.findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly))
    if (w->isVisible()) room -= w->width();
  room = std::max(room, 120);
  const QString shown = bar.fontMetrics().elidedText(firstLine, Qt::ElideMiddle, room);
  bar.showMessage(shown, timeoutMs);
  bar.setToolTip(message);
  // The tooltip goes with the message (cleared, or replaced by another).
  QObject::connect(
      &bar, &QStatusBar::messageChanged, &bar,
      [&bar, shown](const QString& now) {
        if (now != shown) bar.setToolTip({});
      },
      Qt::SingleShotConnection);
}

bool isImportableMesh(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  return suffix == QLatin1String("obj") || suffix == QLatin1String("ply") ||
         suffix == QLatin1String("stl") || suffix == QLatin1String("off");
}

} // namespace octaclay::app
