#include "objects_menu.h"

#include "main_window.h"
#include "modeller.h"
#include "object_merge.h"
#include "objects_panel.h"
#include "user_messages.h"
#include "viewport_key_actions.h"
#include "viewport_widget.h"

#include <QAction>
#include <QKeyEvent>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <vtkRenderer.h>

#include <array>

namespace octaclay::app {
namespace {

// Keys taken from the viewport's own key events before the shortcut map sees them (as
// view_actions' keypad views are): the keypad's "." (Frame Selected) arrives with
// KeypadModifier as Period (or Comma, by the layout) with NumLock on and as Delete with NumLock
// off, which the Delete Object shortcut would otherwise take; Alt+H (Show All) is also the Help
// menu's mnemonic, so as a window shortcut it would be ambiguous and do nothing.
// The action the key stands for on the viewport, or null.
QAction* objectKeyAction(const QKeyEvent& key, QAction* frameSelected, QAction* showAll) {
  const Qt::KeyboardModifiers mods = key.modifiers();
  if (mods == Qt::KeypadModifier &&
      (key.key() == Qt::Key_Period || key.key() == Qt::Key_Comma || key.key() == Qt::Key_Delete))
    return frameSelected;
  if (mods == Qt::AltModifier && key.key() == Qt::Key_H) return showAll;
  return nullptr;
}

QAction* addAction(QMenu* menu, const QString& text, const char* name, const QString& tip,
                   const QKeySequence& key = {}) {
  QAction* a = menu->addAction(text);
  a->setObjectName(QString::fromLatin1(name));
  a->setStatusTip(tip);
  a->setToolTip(key.isEmpty() ? tip : QStringLiteral("%1 (%2)").arg(tip, key.toString()));
  if (!key.isEmpty()) a->setShortcut(key);
  return a;
}

void frameSelected(MainWindow& window) {
  const core::BoundingBox box = window.modeller()->activeWorldBounds();
  if (box.empty()) return;
  std::array<double, 6> bounds{box.min.x, box.max.x, box.min.y, box.max.y, box.min.z, box.max.z};
  window.viewport()->renderer()->ResetCamera(bounds.data());
  window.viewport()->update();
}

void duplicate(MainWindow& window, int axis) {
  const QString why = window.modeller()->duplicateActiveObject(axis);
  if (!why.isEmpty()) showStatusMessage(*window.statusBar(), why, 8000);
}

// H, Shift+H and Alt+H through the one door for an object's eye (setObjectVisible).
// One step for all of them (Show All, Hide Others): one undo brings them back.
void showObjects(MainWindow& window, bool all, bool shown, const std::string& label) {
  Modeller& modeller = *window.modeller();
  std::vector<int> objects;
  for (int k = 0; k < modeller.objectCount(); ++k)
    if (all || k != modeller.activeObject()) objects.push_back(k);
  modeller.setObjectsVisible(objects, shown, label);
}

QMenu* viewMenuOf(MainWindow& window) {
  if (QAction* frame = window.action("actionFrameModel"))
    for (QObject* o : frame->associatedObjects())
      if (auto* menu = qobject_cast<QMenu*>(o)) return menu;
  return nullptr;
}

void addToolBar(MainWindow& window, QMenu* mirror) {
  auto* bar = new QToolBar(MainWindow::tr("Objects"), &window);
  bar->setObjectName(QStringLiteral("objectsToolBar"));
  if (auto* add = window.menuBar()->findChild<QMenu*>("menuAdd")) {
    auto* button = new QToolButton(bar);
    button->setObjectName(QStringLiteral("addObjectButton"));
    button->setText(MainWindow::tr("Add"));
    button->setToolTip(MainWindow::tr("Adds a new object at the view's centre and edits it"));
    button->setMenu(add);
    button->setPopupMode(QToolButton::InstantPopup);
    bar->addWidget(button);
  }
  bar->addAction(window.action("actionDuplicateObject"));
  auto* mirrorButton = new QToolButton(bar);
  mirrorButton->setObjectName(QStringLiteral("mirrorDuplicateButton"));
  QAction* mirrorX = window.action("actionMirrorDuplicateX");
  // What a tool button shows (and shows again whenever the action changes): "Across X" needs
  // its menu to be understood.
  mirrorX->setIconText(MainWindow::tr("Mirror X"));
  mirrorButton->setDefaultAction(mirrorX);
  mirrorButton->setMenu(mirror);
  mirrorButton->setPopupMode(QToolButton::MenuButtonPopup);
  bar->addWidget(mirrorButton);
  window.addToolBar(Qt::TopToolBarArea, bar);
}

} // namespace

void addObjectsMenu(MainWindow& window) {
  auto* menu = new QMenu(MainWindow::tr("&Objects"), &window);
  menu->setObjectName("menuObjects");
  QMenu* view = viewMenuOf(window);
  if (view)
    window.menuBar()->insertMenu(view->menuAction(), menu);
  else
    window.menuBar()->addMenu(menu);
  menu->setToolTipsVisible(true);
  Modeller& modeller = *window.modeller();

  QAction* dup = addAction(menu, MainWindow::tr("&Duplicate"), "actionDuplicateObject",
                           MainWindow::tr("A copy of the edited object in its place, edited next"),
                           QKeySequence(Qt::SHIFT | Qt::Key_D));
  QObject::connect(dup, &QAction::triggered, &window, [&window] { duplicate(window, -1); });
  QMenu* mirror = menu->addMenu(MainWindow::tr("&Mirror Duplicate"));
  mirror->setObjectName("menuMirrorDuplicate");
  mirror->setToolTipsVisible(true);
  const std::array<std::pair<const char*, const char*>, 3> axes{{{"X", "actionMirrorDuplicateX"},
                                                                 {"Y", "actionMirrorDuplicateY"},
                                                                 {"Z", "actionMirrorDuplicateZ"}}};
  for (int axis = 0; axis < 3; ++axis) {
    const QString letter = QString::fromLatin1(axes[std::size_t(axis)].first);
    QAction* a =
        addAction(mirror, MainWindow::tr("Across &%1").arg(letter), axes[std::size_t(axis)].second,
                  MainWindow::tr("A copy of the edited object mirrored across the scene's %1 plane "
                                 "(%2 → −%2): a pair of legs, ears or eyes")
                      .arg(letter, letter.toLower()));
    QObject::connect(a, &QAction::triggered, &window, [&window, axis] { duplicate(window, axis); });
  }
  if (QAction* remove = window.action("actionDeleteObject")) menu->addAction(remove);

  menu->addSeparator();
  QAction* hide = addAction(menu, MainWindow::tr("&Hide"), "actionHideObject",
                            MainWindow::tr("Hides the edited object: not drawn, not sculpted"),
                            QKeySequence(Qt::Key_H));
  QObject::connect(hide, &QAction::triggered, &window, [&window] {
    window.modeller()->setObjectVisible(window.modeller()->activeObject(), false);
  });
  QAction* others = addAction(menu, MainWindow::tr("Hide &Others"), "actionHideOthers",
                              MainWindow::tr("Hides every object but the edited one"),
                              QKeySequence(Qt::SHIFT | Qt::Key_H));
  QObject::connect(others, &QAction::triggered, &window,
                   [&window] { showObjects(window, false, false, "Hide Others"); });
  QAction* showAll =
      addAction(menu, MainWindow::tr("&Show All"), "actionShowAllObjects",
                MainWindow::tr("Shows every hidden object"), QKeySequence(Qt::ALT | Qt::Key_H));
  // Named in the menu; the key itself is taken on the viewport (objectKeyAction).
  showAll->setShortcutContext(Qt::WidgetShortcut);
  QObject::connect(showAll, &QAction::triggered, &window,
                   [&window] { showObjects(window, true, true, "Show All"); });

  menu->addSeparator();
  QAction* frame = addAction(menu, MainWindow::tr("&Frame Selected"), "actionFrameSelected",
                             MainWindow::tr("The view frames the edited object"),
                             QKeySequence(Qt::KeypadModifier | Qt::Key_Period));
  QObject::connect(frame, &QAction::triggered, &window, [&window] { frameSelected(window); });
  if (view) {
    // In View too, after Frame Model.
    QAction* frameModel = window.action("actionFrameModel");
    const QList<QAction*> items = view->actions();
    const qsizetype at = items.indexOf(frameModel);
    view->insertAction(at >= 0 && at + 1 < items.size() ? items[at + 1] : nullptr, frame);
  }
  new ViewportKeyActions(window.viewport(), [frame, showAll](const QKeyEvent& key) {
    return objectKeyAction(key, frame, showAll);
  });

  menu->addSeparator();
  auto* merger =
      new ObjectMerge({&window, window.statusBar(), window.modeller(), window.viewport()}, &window);
  QAction* merge = addAction(
      menu, MainWindow::tr("&Merge"), "actionMergeObjects",
      MainWindow::tr("Merges the objects selected in the Objects list (Ctrl+click to select "
                     "several) into one closed object; with one selected, every visible object"));
  QObject::connect(merge, &QAction::triggered, &window, [&window, merger] {
    merger->merge(merger->chosenObjects(window.objectsPanel()->selectedObjects()));
  });

  const auto update = [&modeller, dup, mirror, hide, others, showAll, frame, merge] {
    const bool any = modeller.hasDocument();
    for (QAction* a : {dup, hide, others, showAll, frame})
      a->setEnabled(any);
    mirror->setEnabled(any);
    merge->setEnabled(modeller.objectCount() >= 2);
  };
  QObject::connect(&modeller, &Modeller::sceneChanged, menu, update);
  QObject::connect(&modeller, &Modeller::objectsChanged, menu, update);
  QObject::connect(&modeller, &Modeller::activeObjectChanged, menu, update);
  update();
  addToolBar(window, mirror);
}

} // namespace octaclay::app
