#include "viewport_focus.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QDialog>
#include <QKeyEvent>
#include <QLineEdit>
#include <QWidget>

namespace octaclay::app {

ViewportFocusReturn::ViewportFocusReturn(QWidget* viewport, QObject* parent)
    : QObject(parent), viewport_(viewport) {
  // Qt gives the viewport the focus before it delivers the press, so the box that had the keys
  // is known only here.
  connect(qApp, &QApplication::focusChanged, this, [this](QWidget* old, QWidget* now) {
    swallowPress_ = now && now == viewport_ && old &&
                    (qobject_cast<QAbstractSpinBox*>(old) || qobject_cast<QLineEdit*>(old)) &&
                    (QGuiApplication::mouseButtons() & Qt::LeftButton);
  });
}

bool ViewportFocusReturn::eventFilter(QObject* watched, QEvent* event) {
  if (!viewport_) return false;
  if (event->type() == QEvent::MouseButtonPress && watched == viewport_ && swallowPress_) {
    swallowPress_ = false;
    return true;
  }
  if (event->type() != QEvent::KeyPress) return false;
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
