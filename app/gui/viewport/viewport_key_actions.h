#pragma once

#include <QAction>
#include <QEvent>
#include <QKeyEvent>
#include <QObject>
#include <QWidget>

#include <functional>
#include <utility>

namespace octaclay::app {

/// Keys the viewport takes before the window's shortcuts: lookup names the action a key event
/// stands for (or null), which is then triggered on the press. Used where a window shortcut
/// cannot say the key: the keypad's keys arrive with KeypadModifier and, with NumLock off, as
/// other keys (End, Delete) that other shortcuts own; Alt+letters are menu mnemonics.
class ViewportKeyActions : public QObject {
public:
  using Lookup = std::function<QAction*(const QKeyEvent&)>;
  ViewportKeyActions(QWidget* viewport, Lookup lookup)
      : QObject(viewport), lookup_(std::move(lookup)) {
    viewport->installEventFilter(this);
  }

protected:
  bool eventFilter(QObject*, QEvent* event) override {
    if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
      return false;
    QAction* action = lookup_(*static_cast<QKeyEvent*>(event));
    if (!action) return false;
    // Accepting the override keeps the window's shortcuts from taking the key.
    event->accept();
    if (event->type() == QEvent::KeyPress && action->isEnabled()) action->trigger();
    return true;
  }

private:
  Lookup lookup_;
};

} // namespace octaclay::app
