#pragma once

#include "octaclay/gpu/brush_manifest.h"

#include <QPointer>
#include <QToolBar>

#include <map>
#include <vector>

class QAction;
class QActionGroup;

namespace octaclay::app {

/// The brush tool bar: one checkable icon per brush, grouped by category (sculpt, paint, splat,
/// separated), the brush's name, shortcut (brush_shortcuts.h) and description in its tooltip.
/// Each icon is a QAction parented to and added to actionHost (the main window), so its shortcut
/// works while the bar is hidden and the shortcut sheet finds it; object name
/// "actionBrush_<id>". GUI thread.
class BrushToolBar : public QToolBar {
  Q_OBJECT
public:
  explicit BrushToolBar(QWidget* actionHost, QWidget* parent = nullptr);

  /// Replaces the actions by one per brush (duplicate ids: the first), in category order then
  /// the order given; the current brush stays checked if it is still there.
  void setBrushes(const std::vector<gpu::BrushManifest>& brushes);
  /// Checks the action of brush id (none when no brush has it). Emits nothing.
  void setCurrentBrush(const QString& id);
  /// The action picking brush id, or nullptr.
  QAction* brushAction(const QString& id) const;
  /// The listed brush ids in display order.
  QStringList brushIds() const;

signals:
  /// The user picked brush id (clicked its icon or pressed its shortcut).
  void brushChosen(const QString& id);

private:
  QWidget* actionHost_;
  QActionGroup* group_;
  std::vector<QPointer<QAction>> actions_; // brush actions and separators, in bar order
  QString currentId_;
};

} // namespace octaclay::app
