#include "viewport_focus.h"

#include <QAbstractSlider>
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

bool ViewportFocusReturn::ours(QWidget* widget) const {
  if (!widget || widget == viewport_ || viewport_->isAncestorOf(widget)) return false;
  // Only the viewport's own window and its floating docks: Esc in a dialog still closes it.
  QWidget* top = widget->window();
  if (qobject_cast<QDialog*>(top)) return false;
  for (QObject* o = top; o; o = o->parent())
    if (o == viewport_->window()) return true;
  return false;
}

bool ViewportFocusReturn::eventFilter(QObject* watched, QEvent* event) {
  if (!viewport_) return false;
  if (event->type() == QEvent::MouseButtonPress && watched == viewport_ && swallowPress_) {
    swallowPress_ = false;
    return true;
  }
  // A slider let go: the keys go back to the model ([ and ] after setting the strength).
  if (event->type() == QEvent::MouseButtonRelease) {
    auto* slider = qobject_cast<QAbstractSlider*>(watched);
    if (slider && slider->hasFocus() && ours(slider) &&
        QGuiApplication::mouseButtons() == Qt::NoButton)
      viewport_->setFocus(Qt::OtherFocusReason);
    return false;
  }
  if (event->type() != QEvent::KeyPress) return false;
  const auto* key = static_cast<QKeyEvent*>(event);
  if (key->key() != Qt::Key_Escape || key->modifiers() != Qt::NoModifier) return false;
  if (!ours(qobject_cast<QWidget*>(watched))) return false;
  viewport_->setFocus(Qt::ShortcutFocusReason);
  return true;
}

} // namespace octaclay::app
