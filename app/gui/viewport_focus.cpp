#include "viewport_focus.h"

#include <QDialog>
#include <QKeyEvent>
#include <QWidget>

namespace octaclay::app {

ViewportFocusReturn::ViewportFocusReturn(QWidget* viewport, QObject* parent)
    : QObject(parent), viewport_(viewport) {}

bool ViewportFocusReturn::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::KeyPress || !viewport_) return false;
  const auto* key = static_cast<QKeyEvent*>(event);
  if (key->key() != Qt::Key_Escape || key->modifiers() != Qt::NoModifier) return false;
  auto* widget = qobject_cast<QWidget*>(watched);
  if (!widget || widget == viewport_ || viewport_->isAncestorOf(widget)) return false;
  // Only the viewport's own window and its floating docks: Esc in a dialog still closes it.
  QWidget* top = widget->window();
  if (qobject_cast<QDialog*>(top)) return false;
  bool ours = false;
  for (QObject* o = top; o && !ours; o = o->parent())
    ours = o == viewport_->window();
  if (!ours) return false;
  viewport_->setFocus(Qt::ShortcutFocusReason);
  return true;
}

} // namespace octaclay::app
