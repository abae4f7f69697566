// One history for the scene's objects (issue 33, item 1): strokes on several objects and every
// object change (add, rename, move, hide, lock, delete, merge, reorder) are steps of one linear
// history, undone and redone bit for bit; switching objects clears nothing; the saved state and
// the budget work across objects. Driven through the real window and VTK viewport (xcb under
// Xvfb, llvmpipe), strokes made with the mouse.
#include "history_list.h"
#include "main_window.h"
#include "modeller.h"
#include "scene_history.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QAction>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace octaclay;
using app::MainWindow;

namespace {

core::Document shape(core::BaseShape s) {
  return core::makeDocument(core::makeBaseShape(s, 64));
}

// Body (a unit sphere at the origin, edited), Box at x = 3 and Lump at x = -3, halved.
core::Scene threeObjects() {
  core::Scene scene = core::sceneOf(shape(core::BaseShape::Sphere), "Body");
  scene.objects.push_back({"Box",
                           shape(core::BaseShape::Cube),
                           {{3.0f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
                           true,
                           false});
  scene.objects.push_back({"Lump",
                           shape(core::BaseShape::Blob),
                           {{-3.0f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
                           true,
                           false});
  return scene;
}

// What an object is, bits and all, as the modeller holds it.
struct ObjectState {
  std::string name;
  core::ObjectTransform transform;
  bool visible = true, locked = false;
  std::vector<float> positions;
};
using SceneState = std::vector<ObjectState>;

SceneState stateOf(const app::Modeller& modeller) {
  SceneState state;
  for (const core::SceneObject& o : modeller.scene().objects) {
    const auto texels = o.document.positions.texels();
    std::vector<float> positions(texels.size() * 4);
    std::memcpy(positions.data(), texels.data(), texels.size_bytes());
    state.push_back({o.name, o.transform, o.visible, o.locked, std::move(positions)});
  }
  return state;
}

// Why two states differ (empty when every object's name, transform, visibility, lock and
// positions are the same, bit for bit, in the same order).
QString difference(const SceneState& got, const SceneState& want) {
  if (got.size() != want.size())
    return QString("%1 objects, expected %2").arg(got.size()).arg(want.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    const ObjectState &a = got[k], &b = want[k];
    const QString which = QString("object %1 (%2)").arg(k).arg(QString::fromStdString(b.name));
    if (a.name != b.name) return which + QString(": named %1").arg(QString::fromStdString(a.name));
    if (std::memcmp(&a.transform, &b.transform, sizeof(core::ObjectTransform)) != 0)
      return which + ": another transform";
    if (a.visible != b.visible || a.locked != b.locked) return which + ": visibility or lock";
    if (!app::testing::bitEqual(a.positions, b.positions)) return which + ": other positions";
  }
  return {};
}

// A push stroke across the view's centre with an undo tried half-way (refused: a stroke is
// being made).
bool strokeTryingUndo(MainWindow& w) {
  w.brushState()->selectBrush("push");
  w.brushState()->setRadius(0.05f);
  w.brushState()->setStrength(0.3f);
  QWidget* view = w.viewport();
  const QPoint from(view->width() / 2 - 30, view->height() / 2 + 10);
  const QPoint to(view->width() / 2 + 30, view->height() / 2 + 10);
  QTest::mousePress(view, Qt::LeftButton, {}, from);
  for (int k = 1; k <= 5; ++k)
    QTest::mouseMove(view, from + (to - from) * k / 10);
  const std::size_t steps = w.modeller()->history().undoCount();
  const bool refused = w.viewport()->stroking() && !w.modeller()->undoStroke() &&
                       !w.undoStack()->canUndo() && w.modeller()->history().undoCount() == steps;
  for (int k = 6; k <= 10; ++k)
    QTest::mouseMove(view, from + (to - from) * k / 10);
  QTest::mouseRelease(view, Qt::LeftButton, {}, to);
  return refused && QTest::qWaitFor([&] { return !w.viewport()->stroking(); }, 20000);
}

} // namespace

class SceneHistoryRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void cleanup();
  void everyObjectChangeUndoesAndRedoesBitExactly();
  void budgetAndRedoSpanEveryObject();
  void previewsRecordNothingAndUndoEndsThem();

private:
  bool open(const core::Scene& scene, const QString& name);

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void SceneHistoryRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("scene_history_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
}

void SceneHistoryRenderTest::cleanup() {
  window_.reset();
}

bool SceneHistoryRenderTest::open(const core::Scene& scene, const QString& name) {
  const QString path = dir_.filePath(name);
  core::writeScene(scene, path.toStdString());
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  return window_ && window_->openDocument(path);
}

void SceneHistoryRenderTest::everyObjectChangeUndoesAndRedoesBitExactly() {
  QVERIFY(open(threeObjects(), "three.exr"));
  app::Modeller& modeller = *window_->modeller();
  app::HistoryList& list = *window_->undoStack();
  std::vector<SceneState> states{stateOf(modeller)};
  QStringList labels;
  const auto stepped = [&](const QString& label) {
    states.push_back(stateOf(modeller));
    labels << label;
    return modeller.history().undoCount() == std::size_t(labels.size()) &&
           list.undoText() == label && !modeller.canRedo();
  };

  // 1. Add: a ball at the origin, inside the body, made the edited one.
  QVERIFY(modeller.addObject({"Ball",
                              shape(core::BaseShape::Sphere),
                              {{0.0f, 0.0f, 0.0f}, {}, {0.6f, 0.6f, 0.6f}},
                              true,
                              false}));
  QCOMPARE(modeller.activeObject(), 3);
  QVERIFY(stepped("Add Ball"));
  // 2. A stroke on the ball (an undo tried while it is made is refused).
  QVERIFY(strokeTryingUndo(*window_));
  QVERIFY(difference(stateOf(modeller), states.back()).contains("other positions"));
  QVERIFY(stepped("Stroke (push)"));
  // Switching is not a step and clears nothing.
  QVERIFY(modeller.setActiveObject(0));
  QCOMPARE(modeller.history().undoCount(), std::size_t(2));
  QCOMPARE(list.undoText(), QString("Stroke (push)"));
  // 3. A stroke on the body.
  app::testing::pushStrokeAcross(*window_, 0);
  QVERIFY(difference(stateOf(modeller), states.back()).contains("object 0"));
  QVERIFY(stepped("Stroke (push)"));
  // 4. Rename.
  QVERIFY(window_->isModified());
  QCOMPARE(modeller.renameObject(3, "Head"), QString());
  QVERIFY(stepped("Rename Ball → Head"));
  // 5. Move: previews record nothing; the confirmed move is one step from where they began.
  QVERIFY(modeller.previewObjectTransform(3, {{0.5f, 0.0f, 0.0f}, {0.0f, 20.0f, 0.0f}, {1, 1, 1}}));
  QVERIFY(modeller.previewObjectTransform(3, {{0.7f, 0.1f, 0.0f}, {}, {0.6f, 0.6f, 0.6f}}));
  QCOMPARE(modeller.history().undoCount(), std::size_t(4));
  QCOMPARE(modeller.setObjectTransform(3, {{0.25f, 0.5f, -0.125f}, {}, {0.6f, 0.6f, 0.6f}}),
           QString());
  QVERIFY(stepped("Move Head"));
  // 6. Hide, 7. lock: a stroke on the locked body is refused and records nothing.
  QVERIFY(modeller.setObjectVisible(1, false));
  QVERIFY(stepped("Hide Box"));
  QVERIFY(modeller.setObjectLocked(0, true));
  QVERIFY(stepped("Lock Body"));
  app::testing::pushStrokeAcross(*window_, 0);
  QCOMPARE(difference(stateOf(modeller), states.back()), QString());
  QCOMPARE(modeller.history().undoCount(), std::size_t(7));
  // 8. Delete the head (its own stroke goes with it, kept by the history).
  QVERIFY(modeller.setActiveObject(3));
  QCOMPARE(modeller.deleteActiveObject(), QString());
  QCOMPARE(modeller.activeObject(), 2);
  QVERIFY(stepped("Delete Head"));
  // 9. Merge: Box and Lump replaced by one object.
  core::SceneObject merged{"Merged", shape(core::BaseShape::Blob), {}, true, false};
  merged.document.positions.at(10, 20).x += 0.25f; // not any base shape's bits
  QCOMPARE(modeller.replaceObjects({1, 2}, std::move(merged), "Merge 2 Objects"), QString());
  QCOMPARE(modeller.objectCount(), 2);
  QCOMPARE(modeller.activeObject(), 1);
  QVERIFY(stepped("Merge 2 Objects"));
  // 10. Reorder: the edited object stays the edited one.
  QVERIFY(modeller.moveObject(1, 0));
  QCOMPARE(modeller.activeObject(), 0);
  QCOMPARE(modeller.objectAt(0).name, std::string("Merged"));
  QVERIFY(stepped("Reorder Objects"));

  // The saved state: saved, an object change makes the title's "*", undoing it clears it.
  QVERIFY(window_->saveDocument(dir_.filePath("saved.exr")));
  QVERIFY(!window_->isModified());
  QVERIFY(modeller.setObjectVisible(1, false));
  QVERIFY(window_->isModified());
  QVERIFY(stepped("Hide Body"));
  QCOMPARE(list.count(), 11);
  for (int k = 0; k < labels.size(); ++k)
    QCOMPARE(list.text(k), labels[k]);
  QCOMPARE(list.data(list.QAbstractListModel::index(0, 0), Qt::DisplayRole).toString(),
           QString("Model as opened or made"));
  QCOMPARE(list.rowCount(), 12);
  list.undo();
  QVERIFY(!window_->isModified());

  // Undo everything: each state as it was, bit for bit; a document step of an object that is
  // not edited makes it the edited one first.
  for (int k = int(labels.size()) - 1; k >= 1; --k) {
    QCOMPARE(list.redoText(), labels[k]);
    QCOMPARE(difference(stateOf(modeller), states[std::size_t(k)]), QString());
    // Edit ▸ Undo, as Ctrl+Z triggers it, names the step it takes.
    QAction* undo = window_->action("actionUndo");
    QCOMPARE(undo->text(), "&Undo " + labels[k - 1]);
    QVERIFY(undo->isEnabled());
    undo->trigger();
    QCOMPARE(list.index(), k - 1);
    QVERIFY(window_->isModified());
    if (k - 1 == 2) QCOMPARE(modeller.objectAt(modeller.activeObject()).name, std::string("Body"));
    if (k - 1 == 1) QCOMPARE(modeller.objectAt(modeller.activeObject()).name, std::string("Ball"));
  }
  QCOMPARE(difference(stateOf(modeller), states[0]), QString());
  QVERIFY(!modeller.canUndo());
  QCOMPARE(modeller.activeObject(), 0);
  QCOMPARE(list.index(), 0);

  // Redo everything: the states recorded on the way, the saved one clean again.
  for (int k = 1; k <= int(labels.size()); ++k) {
    QVERIFY2(modeller.redoStroke(), qPrintable(labels[k - 1]));
    QCOMPARE(difference(stateOf(modeller), states[std::size_t(k)]), QString());
    QCOMPARE(window_->isModified(), k != int(labels.size()) - 1);
  }
  QVERIFY(!modeller.canRedo());
  // The saved file holds the saved state.
  const core::Scene saved = core::readScene(dir_.filePath("saved.exr").toStdString());
  QCOMPARE(saved.names(), std::vector<std::string>({"Merged", "Body"}));
}

void SceneHistoryRenderTest::budgetAndRedoSpanEveryObject() {
  QVERIFY(open(threeObjects(), "budget.exr"));
  app::Modeller& modeller = *window_->modeller();
  app::SceneHistory& history = modeller.history();
  // Strokes on the body, then on the box brought under the view's centre.
  app::testing::pushStrokeAcross(*window_, 0);
  const SceneState afterFirst = stateOf(modeller);
  app::testing::pushStrokeAcross(*window_, 20);
  QCOMPARE(modeller.setObjectTransform(1, {{0.0f, 0.0f, 0.0f}, {}, {1.2f, 1.2f, 1.2f}}), QString());
  QVERIFY(modeller.setActiveObject(1));
  app::testing::pushStrokeAcross(*window_, 0);
  QCOMPARE(history.undoCount(), std::size_t(4));
  const SceneState newest = stateOf(modeller);

  // A delete holds the deleted object's document: its bytes are counted.
  const std::size_t beforeDelete = history.bytes();
  QCOMPARE(modeller.deleteActiveObject(), QString());
  const std::size_t documentBytes = modeller.document().positions.byteSize();
  QVERIFY2(history.bytes() >= beforeDelete + documentBytes,
           qPrintable(QString("%1 → %2").arg(beforeDelete).arg(history.bytes())));
  QVERIFY(modeller.undoStroke());
  QVERIFY(history.bytes() < beforeDelete + documentBytes);
  QCOMPARE(history.redoCount(), std::size_t(1));

  // A budget one byte short drops the oldest entry (the body's first stroke), whatever object
  // is edited; the redo entry stays.
  modeller.setHistoryBudget(history.bytes() - 1);
  QCOMPARE(history.dropped(), std::size_t(1));
  QCOMPARE(history.undoCount(), std::size_t(3));
  QCOMPARE(history.redoCount(), std::size_t(1));
  QVERIFY(history.bytes() <= history.budget());
  QCOMPARE(window_->undoStack()
               ->data(window_->undoStack()->QAbstractListModel::index(0, 0), Qt::DisplayRole)
               .toString(),
           QString("Oldest kept step"));
  // Undoing what is kept reaches the state after that stroke, on every object.
  while (modeller.canUndo())
    QVERIFY(modeller.undoStroke());
  QCOMPARE(difference(stateOf(modeller), afterFirst), QString());
  while (history.redoCount() > 1)
    QVERIFY(modeller.redoStroke());
  QCOMPARE(difference(stateOf(modeller), newest), QString());

  // A new step anywhere clears the redo entries, whichever object they belong to.
  QVERIFY(modeller.undoStroke()); // the box's stroke
  QVERIFY(modeller.undoStroke()); // the box's move
  QCOMPARE(history.redoCount(), std::size_t(3));
  QVERIFY(modeller.setActiveObject(0));
  QVERIFY(modeller.setObjectLocked(2, true));
  QVERIFY(!modeller.canRedo());
  QVERIFY(!window_->undoStack()->canRedo());
  modeller.setHistoryBudget(std::size_t(256) << 20);
}

// G/R/S previews (previewObjectTransform) record nothing; a confirmed transform is one step from
// where the preview began; another change while a preview runs keeps it; an undo ends it.
void SceneHistoryRenderTest::previewsRecordNothingAndUndoEndsThem() {
  QVERIFY(open(threeObjects(), "preview.exr"));
  app::Modeller& modeller = *window_->modeller();
  const core::ObjectTransform original = modeller.objectAt(1).transform;
  const core::ObjectTransform dragged{{2.0f, 1.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
      placed{{2.5f, 1.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
      turned{{3.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 45.0f}, {0.5f, 0.5f, 0.5f}};
  const auto same = [](const core::ObjectTransform& a, const core::ObjectTransform& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
  };
  // Dragged and put back (Esc): nothing recorded, nothing modified.
  QVERIFY(modeller.previewObjectTransform(1, dragged));
  QVERIFY(modeller.previewObjectTransform(1, original));
  QCOMPARE(modeller.setObjectTransform(1, original), QString());
  QVERIFY(!modeller.canUndo());
  QVERIFY(!window_->isModified());
  // Dragged, Lump hidden meanwhile (one step, the drag goes on), then placed: "Move Box" from
  // where it began.
  QVERIFY(modeller.previewObjectTransform(1, dragged));
  QVERIFY(modeller.setObjectVisible(2, false));
  QCOMPARE(modeller.history().undoCount(), std::size_t(1));
  QVERIFY(same(modeller.objectAt(1).transform, dragged));
  QCOMPARE(modeller.setObjectTransform(1, placed), QString());
  QCOMPARE(modeller.history().undoCount(), std::size_t(2));
  QCOMPARE(window_->undoStack()->undoText(), QString("Move Box"));
  QVERIFY(modeller.undoStroke());
  QVERIFY(same(modeller.objectAt(1).transform, original));
  QVERIFY(!modeller.objectAt(2).visible);
  QVERIFY(modeller.undoStroke());
  QVERIFY(modeller.objectAt(2).visible);
  QVERIFY(!window_->isModified());
  QVERIFY(modeller.redoStroke() && modeller.redoStroke());
  QVERIFY(same(modeller.objectAt(1).transform, placed));
  // A rotation previewed, then an undo: the preview ends, Box back where it was before "Move".
  QVERIFY(modeller.previewObjectTransform(1, turned));
  QVERIFY(modeller.undoStroke());
  QVERIFY(same(modeller.objectAt(1).transform, original));
  QCOMPARE(modeller.setObjectTransform(1, turned), QString());
  QCOMPARE(window_->undoStack()->undoText(), QString("Rotate Box"));
  QVERIFY(modeller.undoStroke());
  QVERIFY(same(modeller.objectAt(1).transform, original));
}

QTEST_MAIN(SceneHistoryRenderTest)
#include "scene_history_render_test.moc"
