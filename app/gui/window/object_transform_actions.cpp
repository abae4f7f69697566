#include "object_transform_actions.h"

#include "brush_state.h"
#include "brush_toolbar.h"
#include "main_window.h"
#include "modeller.h"
#include "object_transform_mode.h"
#include "transform_gizmo.h"
#include "viewport_widget.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

namespace octaclay::app {
namespace {

// The brush actions' own letters while Object Mode holds G, R and S (restored after it).
constexpr const char* kObjectModeKey = "objectModeKey";

bool takenInObjectMode(const QKeySequence& key) {
  return key == QKeySequence(Qt::Key_G) || key == QKeySequence(Qt::Key_R) ||
         key == QKeySequence(Qt::Key_S);
}

// Object Mode on: the brushes' G, R and S stand aside (their actions keep their letters in a
// property) and Move, Rotate and Scale answer them in the whole window. Off: the reverse; the
// three keep their letters (the menu and the shortcut sheet show them) but answer only inside
// their menu, so no key has two owners.
void giveKeys(MainWindow& window, bool objectMode, const std::vector<QAction*>& gestures) {
  for (QAction* a : window.findChildren<QAction*>()) {
    if (!a->objectName().startsWith(QStringLiteral("actionBrush_"))) continue;
    if (objectMode && takenInObjectMode(a->shortcut())) {
      a->setProperty(kObjectModeKey, a->shortcut());
      a->setShortcut({});
    } else if (!objectMode && a->property(kObjectModeKey).isValid()) {
      a->setShortcut(a->property(kObjectModeKey).value<QKeySequence>());
      a->setProperty(kObjectModeKey, {});
    }
  }
  for (QAction* a : gestures)
    a->setShortcutContext(objectMode ? Qt::WindowShortcut : Qt::WidgetShortcut);
}

} // namespace

void addObjectTransformActions(MainWindow& window) {
  ViewportWidget* viewport = window.viewport();
  auto* mode = new ObjectTransformMode(viewport, &window);
  mode->setObjectName(QStringLiteral("objectTransformMode"));
  auto* gizmo = new TransformGizmo(viewport, mode, &window);
  gizmo->setObjectName(QStringLiteral("transformGizmo"));

  QMenu* menu = window.findChild<QMenu*>(QStringLiteral("menuObjects"));
  if (!menu) menu = window.menuBar()->addMenu(MainWindow::tr("&Object"));
  menu->addSeparator();

  auto* objectMode = new QAction(MainWindow::tr("&Object Mode"), &window);
  objectMode->setObjectName(QStringLiteral("actionObjectMode"));
  objectMode->setCheckable(true);
  objectMode->setIconText(MainWindow::tr("Move Objects"));
  objectMode->setShortcut(QKeySequence(Qt::Key_Tab));
  objectMode->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  objectMode->setToolTip(MainWindow::tr("Move Objects (Tab): arrows on the edited object to drag "
                                        "it; G moves, R rotates, S scales"));
  objectMode->setStatusTip(objectMode->toolTip());
  viewport->addAction(objectMode); // Tab where the viewport has the focus
  menu->addAction(objectMode);

  std::vector<QAction*> gestures;
  const auto addGesture = [&](const QString& text, const QString& name, Qt::Key key,
                              ObjectTransformMode::Kind kind, const QString& tip) {
    auto* a = new QAction(text, &window);
    a->setObjectName(name);
    a->setShortcut(QKeySequence(key));
    a->setAutoRepeat(false); // holding the key must not restart the gesture
    a->setStatusTip(tip);
    QObject::connect(a, &QAction::triggered, mode, [mode, objectMode, kind] {
      objectMode->setChecked(true);
      mode->begin(kind);
    });
    window.addAction(a);
    menu->addAction(a);
    gestures.push_back(a);
  };
  addGesture(MainWindow::tr("&Move"), QStringLiteral("actionMoveObject"), Qt::Key_G,
             ObjectTransformMode::Kind::Move,
             MainWindow::tr("Moves the edited object with the pointer; X, Y, Z keep it on an axis, "
                            "a typed number moves it exactly, Enter or a click keeps it, Esc "
                            "cancels"));
  addGesture(MainWindow::tr("&Rotate"), QStringLiteral("actionRotateObject"), Qt::Key_R,
             ObjectTransformMode::Kind::Rotate,
             MainWindow::tr("Turns the edited object about the view's axis (X, Y, Z: about that "
                            "axis; a typed number: degrees)"));
  addGesture(MainWindow::tr("&Scale"), QStringLiteral("actionScaleObject"), Qt::Key_S,
             ObjectTransformMode::Kind::Scale,
             MainWindow::tr("Scales the edited object by the pointer's distance to its centre (a "
                            "typed number: the factor)"));

  auto* bar = new QToolBar(MainWindow::tr("Objects"), &window);
  bar->setObjectName(QStringLiteral("objectsToolBar"));
  bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
  bar->addAction(objectMode);
  window.addToolBar(Qt::TopToolBarArea, bar);

  const auto apply = [&window, gizmo, gestures](bool on) {
    gizmo->setShown(on);
    giveKeys(window, on, gestures);
  };
  QObject::connect(objectMode, &QAction::toggled, &window, apply);
  apply(false);
  // A brush list reloaded in Object Mode brings its letters back: they stand aside again.
  QObject::connect(&window.modeller()->brushState(), &BrushState::brushesChanged, &window,
                   [&window, objectMode, gestures] {
                     QTimer::singleShot(0, &window, [&window, objectMode, gestures] {
                       if (objectMode->isChecked()) giveKeys(window, true, gestures);
                     });
                   });
  // A brush picked (its icon or its key) means sculpting again: Object Mode goes off.
  if (auto* brushes = window.findChild<BrushToolBar*>())
    QObject::connect(brushes, &BrushToolBar::brushChosen, objectMode,
                     [objectMode] { objectMode->setChecked(false); });
  // A new object shows its arrows: Add ▸ <shape> turns Object Mode on.
  if (auto* add = window.findChild<QMenu*>(QStringLiteral("menuAdd")))
    for (QAction* a : add->actions())
      if (a->objectName().startsWith(QStringLiteral("actionAdd")))
        QObject::connect(a, &QAction::triggered, objectMode,
                         [objectMode] { objectMode->setChecked(true); });

  QStatusBar* status = window.statusBar();
  QObject::connect(mode, &ObjectTransformMode::textChanged, status, [status](const QString& text) {
    if (text.isEmpty())
      status->clearMessage();
    else
      status->showMessage(text);
  });
}

} // namespace octaclay::app
