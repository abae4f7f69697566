#include "brush_toolbar.h"

#include "brush_icons.h"
#include "brush_shortcuts.h"

#include <QAction>
#include <QActionGroup>

#include <array>
#include <set>
#include <string>

namespace octaclay::app {

BrushToolBar::BrushToolBar(QWidget* actionHost, QWidget* parent)
    : QToolBar(tr("Brushes"), parent), actionHost_(actionHost), group_(new QActionGroup(this)) {
  setObjectName(QStringLiteral("BrushToolBar"));
  setIconSize(QSize(28, 28));
  group_->setExclusive(true);
}

void BrushToolBar::setBrushes(const std::vector<gpu::BrushManifest>& brushes) {
  for (const QPointer<QAction>& a : actions_)
    delete a.data(); // removes it from this bar, the host and the group
  actions_.clear();
  std::set<std::string> seen;
  for (const gpu::Category category :
       {gpu::Category::Sculpt, gpu::Category::Paint, gpu::Category::Splat}) {
    bool first = true;
    for (const gpu::BrushManifest& brush : brushes) {
      if (brush.category != category || !seen.insert(brush.id).second) continue;
      if (first && !actions_.empty()) actions_.emplace_back(addSeparator());
      first = false;
      const QString id = QString::fromStdString(brush.id);
      const QString name = QString::fromStdString(brush.name);
      auto* action = new QAction(brushIcon(brush), name, actionHost_);
      action->setObjectName(QStringLiteral("actionBrush_") + id);
      action->setData(id);
      action->setCheckable(true);
      const QKeySequence key = brushShortcut(id);
      action->setShortcut(key);
      QString tip =
          key.isEmpty() ? name : tr("%1 (%2)").arg(name, key.toString(QKeySequence::NativeText));
      if (!brush.description.empty()) tip += u'\n' + QString::fromStdString(brush.description);
      action->setToolTip(tip);
      action->setStatusTip(tip.section(u'\n', 0, 0));
      action->setChecked(id == currentId_);
      group_->addAction(action);
      actionHost_->addAction(action);
      addAction(action);
      connect(action, &QAction::triggered, this, [this, id] {
        currentId_ = id;
        emit brushChosen(id);
      });
      actions_.emplace_back(action);
    }
  }
}

void BrushToolBar::setCurrentBrush(const QString& id) {
  currentId_ = id;
  for (const QPointer<QAction>& a : actions_)
    if (a && !a->isSeparator()) a->setChecked(a->data().toString() == id);
}

QAction* BrushToolBar::brushAction(const QString& id) const {
  for (const QPointer<QAction>& a : actions_)
    if (a && !a->isSeparator() && a->data().toString() == id) return a;
  return nullptr;
}

QStringList BrushToolBar::brushIds() const {
  QStringList ids;
  for (const QPointer<QAction>& a : actions_)
    if (a && !a->isSeparator()) ids.append(a->data().toString());
  return ids;
}

} // namespace octaclay::app
