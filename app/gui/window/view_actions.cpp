#include "view_actions.h"

#include "looks_menu.h"
#include "viewport_key_actions.h"
#include "viewport_widget.h"

#include <QActionGroup>
#include <QDockWidget>
#include <QKeyEvent>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>

#include <array>

namespace octaclay::app {
namespace {

// The numeric keypad's view keys, taken from the viewport's own key events. A QAction bound to
// KeypadModifier | Key_1 never fires from a real keyboard through Qt 6.4's xcb key mapping (a
// synthesized QTest::keyClick bypasses that mapping, so only real input shows it). With NumLock
// off the keys arrive as End, PgDn, Home and Clear, still with KeypadModifier: that modifier
// tells keypad 7 (Top) from Home (Frame Model), which the shortcut map would otherwise match
// without it. Each key triggers its menu action, so the Orthographic check mark follows.
// Actions are Front, Back, Right, Left, Top, Bottom,
// Orthographic.
QAction* keypadViewAction(const QKeyEvent& key, const std::array<QAction*, 7>& actions) {
  const Qt::KeyboardModifiers mods = key.modifiers();
  if (!(mods & Qt::KeypadModifier) || (mods & ~(Qt::KeypadModifier | Qt::ControlModifier)))
    return nullptr;
  const int ctrl = (mods & Qt::ControlModifier) ? 1 : 0;
  switch (key.key()) {
  case Qt::Key_1:
  case Qt::Key_End:
    return actions[0 + ctrl];
  case Qt::Key_3:
  case Qt::Key_PageDown:
    return actions[2 + ctrl];
  case Qt::Key_7:
  case Qt::Key_Home:
    return actions[4 + ctrl];
  case Qt::Key_5:
  case Qt::Key_Clear:
    return ctrl ? nullptr : actions[6];
  default:
    return nullptr;
  }
}

} // namespace

void addViewActions(QMenu* view, ViewportWidget* viewport) {
  struct Standard {
    const char* text;
    const char* name;
    ViewDirection direction;
    QKeyCombination key;
  };
  const Qt::KeyboardModifiers pad = Qt::KeypadModifier;
  const Qt::KeyboardModifiers ctrlPad = Qt::KeypadModifier | Qt::ControlModifier;
  const Standard standards[] = {
      {QT_TR_NOOP("&Front"), "actionViewFront", ViewDirection::Front, pad | Qt::Key_1},
      {QT_TR_NOOP("&Back"), "actionViewBack", ViewDirection::Back, ctrlPad | Qt::Key_1},
      {QT_TR_NOOP("&Right"), "actionViewRight", ViewDirection::Right, pad | Qt::Key_3},
      {QT_TR_NOOP("&Left"), "actionViewLeft", ViewDirection::Left, ctrlPad | Qt::Key_3},
      {QT_TR_NOOP("&Top"), "actionViewTop", ViewDirection::Top, pad | Qt::Key_7},
      {QT_TR_NOOP("Bott&om"), "actionViewBottom", ViewDirection::Bottom, ctrlPad | Qt::Key_7},
  };
  QMenu* views = view->addMenu(QMenu::tr("&Views"));
  std::array<QAction*, 7> keypad{};
  int k = 0;
  for (const Standard& s : standards) {
    QAction* a = views->addAction(QMenu::tr(s.text));
    keypad[k++] = a;
    a->setObjectName(QString::fromLatin1(s.name));
    a->setShortcut(QKeySequence(s.key));
    QObject::connect(a, &QAction::triggered, viewport,
                     [viewport, d = s.direction] { viewport->setView(d); });
  }

  QAction* ortho = view->addAction(QMenu::tr("&Orthographic"));
  ortho->setObjectName("actionOrthographic");
  ortho->setCheckable(true);
  ortho->setShortcut(QKeySequence(Qt::KeypadModifier | Qt::Key_5));
  ortho->setToolTip(QMenu::tr("Parallel projection (no perspective), for checking proportions"));
  QObject::connect(ortho, &QAction::toggled, viewport, &ViewportWidget::setOrthographic);
  keypad[6] = ortho;
  new ViewportKeyActions(viewport,
                         [keypad](const QKeyEvent& key) { return keypadViewAction(key, keypad); });

  QMenu* orbit = view->addMenu(QMenu::tr("Or&bit"));
  auto* group = new QActionGroup(orbit);
  const auto addOrbit = [&](const QString& text, const char* name, OrbitMode mode,
                            const QString& tip) {
    QAction* a = orbit->addAction(text);
    a->setObjectName(QString::fromLatin1(name));
    a->setCheckable(true);
    a->setToolTip(tip);
    a->setStatusTip(tip);
    group->addAction(a);
    QObject::connect(a, &QAction::triggered, viewport, [viewport, mode] {
      viewport->setOrbitMode(mode);
      QSettings().setValue("view/orbit", mode == OrbitMode::Trackball ? "trackball" : "turntable");
    });
    return a;
  };
  QAction* turntable =
      addOrbit(QMenu::tr("&Turntable"), "actionOrbitTurntable", OrbitMode::Turntable,
               QMenu::tr("Dragging turns the model about its up axis; up stays up"));
  QAction* trackball =
      addOrbit(QMenu::tr("Free T&rackball"), "actionOrbitTrackball", OrbitMode::Trackball,
               QMenu::tr("Dragging turns the model freely, rolling it too"));
  orbit->setToolTipsVisible(true);
  const bool free = QSettings().value("view/orbit").toString() == "trackball";
  (free ? trackball : turntable)->setChecked(true);
  viewport->setOrbitMode(free ? OrbitMode::Trackball : OrbitMode::Turntable);
}

void addViewMenu(QMainWindow& window, ViewportWidget* viewport) {
  QMenu* view = window.menuBar()->addMenu(QMainWindow::tr("&View"));
  for (QDockWidget* dock : window.findChildren<QDockWidget*>())
    view->addAction(dock->toggleViewAction());
  view->addSeparator();
  QAction* frame = view->addAction(QMainWindow::tr("&Frame Model"));
  frame->setObjectName("actionFrameModel");
  frame->setShortcut(QKeySequence(QMainWindow::tr("Home")));
  QObject::connect(frame, &QAction::triggered, viewport, &ViewportWidget::frameModel);
  addViewActions(view, viewport);
  addLookActions(view, viewport);
}

} // namespace octaclay::app
