// The scene's one history without a window (app/gui/model/scene_history, scene_step): a scene
// step's two sides shown on a scene, documents moved and never lost, a scene that does not
// match refused untouched; document steps of several objects in one order, each object's
// history parked while another is edited, one budget and one redo across them.
#include "scene_history.h"
#include "scene_step.h"

#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/document/edit_steps.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QtTest>

#include <cstring>
#include <string>
#include <vector>

using namespace octaclay;
using app::ObjectId;
using app::SceneHistory;
using app::SceneStep;

namespace {

core::Document ball(int n = 16) {
  return core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n));
}

bool sameBits(const core::Document& a, const core::Document& b) {
  const auto x = a.positions.texels(), y = b.positions.texels();
  return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size_bytes()) == 0;
}

// doc with sample (i, 3) moved by dx, and the step from the document before.
core::EditStep moveSample(core::Document& doc, int i, float dx, const std::string& label) {
  const core::Document before = doc;
  doc.positions.at(i, 3).x += dx;
  return core::recordDifference(before, doc, label);
}

std::vector<std::string> names(const core::Scene& scene) {
  return scene.names();
}

} // namespace

class SceneHistoryTest : public QObject {
  Q_OBJECT

private slots:
  void sidesMoveDocumentsAndLooks();
  void aSceneThatDoesNotMatchIsLeftAlone();
  void documentStepsOfSeveralObjectsInOneOrder();
  void budgetAndRedoSpanParkedHistories();
  void transformLabels();
};

void SceneHistoryTest::sidesMoveDocumentsAndLooks() {
  core::Scene scene;
  for (const char* name : {"A", "B", "C"})
    scene.objects.push_back({name, ball(), {}, true, false});
  scene.objects[1].document.positions.at(2, 2).y = 7.5f; // B's own bits
  const core::Document b = scene.objects[1].document;
  std::vector<ObjectId> ids{1, 2, 3};
  // Delete B, rename C, as one step.
  SceneStep step;
  step.orderBefore = ids;
  step.orderAfter = {1, 3};
  step.changes.push_back({3, app::lookOf(scene.objects[2]), {"D", {}, false, true}});
  QVERIFY(app::showSide(step, false, scene, ids));
  QCOMPARE(names(scene), std::vector<std::string>({"A", "D"}));
  QCOMPARE(ids, std::vector<ObjectId>({1, 3}));
  QVERIFY(!scene.objects[1].visible && scene.objects[1].locked);
  QCOMPARE(step.held.size(), std::size_t(1));
  QCOMPARE(step.held[0].first, ObjectId(2));
  QVERIFY(sameBits(step.held[0].second.document, b));
  // The held document counts in the step's bytes, and goes when it is shown again.
  const std::size_t heldBytes = step.bytes();
  QVERIFY(heldBytes >= b.positions.byteSize());
  QVERIFY(app::showSide(step, true, scene, ids));
  QCOMPARE(names(scene), std::vector<std::string>({"A", "B", "C"}));
  QCOMPARE(ids, std::vector<ObjectId>({1, 2, 3}));
  QVERIFY(scene.objects[2].visible && !scene.objects[2].locked);
  QVERIFY(sameBits(scene.objects[1].document, b));
  QVERIFY(step.held.empty());
  QVERIFY(step.bytes() + b.positions.byteSize() <= heldBytes);
  // A move holds two looks: a few hundred bytes, whatever the document's size.
  SceneStep move;
  move.label = "Move C";
  move.changes.push_back({3, app::lookOf(scene.objects[2]), app::lookOf(scene.objects[2])});
  move.changes[0].after.transform.translation.x = 1;
  QVERIFY(move.bytes() < 1024);
  qInfo("a move step holds %zu bytes; a delete of an N = 16 ball %zu (its positions %zu)",
        move.bytes(), heldBytes, b.positions.byteSize());
  // A reorder: the same objects, another order.
  SceneStep reorder;
  reorder.orderBefore = ids;
  reorder.orderAfter = {3, 1, 2};
  QVERIFY(app::showSide(reorder, false, scene, ids));
  QCOMPARE(names(scene), std::vector<std::string>({"C", "A", "B"}));
  QVERIFY(sameBits(scene.objects[2].document, b));
  QVERIFY(reorder.held.empty());
}

void SceneHistoryTest::aSceneThatDoesNotMatchIsLeftAlone() {
  core::Scene scene;
  for (const char* name : {"A", "B"})
    scene.objects.push_back({name, ball(), {}, true, false});
  std::vector<ObjectId> ids{1, 2};
  SceneStep add; // adds object 3, which it does not hold
  add.orderBefore = ids;
  add.orderAfter = {1, 2, 3};
  QVERIFY(!app::showSide(add, false, scene, ids));
  QCOMPARE(names(scene), std::vector<std::string>({"A", "B"}));
  QCOMPARE(ids, std::vector<ObjectId>({1, 2}));
  SceneStep look; // a look for an object not in the scene
  look.changes.push_back({7, {}, {"X", {}, true, false}});
  QVERIFY(!app::showSide(look, false, scene, ids));
  QCOMPARE(names(scene), std::vector<std::string>({"A", "B"}));
  std::vector<ObjectId> short_{1};
  QVERIFY(!app::showSide(add, true, scene, short_));
}

void SceneHistoryTest::documentStepsOfSeveralObjectsInOneOrder() {
  core::EditHistory live;
  SceneHistory history(live);
  history.restart(1);
  core::Document a = ball(), b = ball(32);
  // A stroke on object 1, then object 2 edited (another N) and stroked, then a scene step.
  live.record(moveSample(a, 4, 0.5f, "a1"));
  QVERIFY(history.noteLiveStep());
  QVERIFY(!history.noteLiveStep()); // nothing new
  history.leave();
  QCOMPARE(live.undoCount(), std::size_t(0));
  history.enter(2);
  live.record(moveSample(b, 5, 0.25f, "b1"));
  QVERIFY(history.noteLiveStep());
  SceneStep rename;
  rename.label = "Rename";
  history.record(std::move(rename));
  QCOMPARE(history.undoCount(), std::size_t(3));
  QCOMPARE(history.documentStepAt(0)->label, std::string("a1"));
  QCOMPARE(history.documentStepAt(1)->label, std::string("b1"));
  QVERIFY(!history.documentStepAt(2));
  QCOMPARE(history.entryAt(2)->scene->label, std::string("Rename"));
  QVERIFY(!history.nextUndo()); // a scene step
  const std::uint64_t atRename = history.position();
  history.stepped(true);
  QCOMPARE(history.nextUndo()->label, std::string("b1"));
  QCOMPARE(history.nextUndoEntry()->object, ObjectId(2));
  QVERIFY(history.position() != atRename);
  // Object 1 edited again: its own history (its N) comes back, object 2's is parked.
  history.leave();
  history.enter(1);
  QCOMPARE(live.undoCount(), std::size_t(1));
  QCOMPARE(live.nextUndo()->label, std::string("a1"));
  QCOMPARE(history.documentStepAt(1)->label, std::string("b1"));
  history.stepped(false);
  QCOMPARE(history.position(), atRename);
}

void SceneHistoryTest::budgetAndRedoSpanParkedHistories() {
  core::EditHistory live;
  SceneHistory history(live);
  history.restart(1);
  core::Document a = ball(), b = ball();
  live.record(moveSample(a, 4, 0.5f, "a1"));
  history.noteLiveStep();
  live.record(moveSample(a, 6, 0.5f, "a2"));
  history.noteLiveStep();
  history.leave();
  history.enter(2);
  live.record(moveSample(b, 5, 0.25f, "b1"));
  history.noteLiveStep();
  // Object 2's step undone (as the modeller does: its history, then the cursor).
  const core::EditStep* undone = live.undo(core::applierFor(b));
  QVERIFY(undone);
  history.stepped(true);
  QCOMPARE(history.redoCount(), std::size_t(1));
  // Back on object 1, a new step: object 2's redo step goes too.
  history.leave();
  history.enter(1);
  live.record(moveSample(a, 8, 0.5f, "a3"));
  QVERIFY(history.noteLiveStep());
  QCOMPARE(history.redoCount(), std::size_t(0));
  QCOMPARE(history.undoCount(), std::size_t(3));
  history.leave();
  history.enter(2);
  QCOMPARE(live.undoCount() + live.redoCount(), std::size_t(0));
  history.leave();
  history.enter(1);
  // A budget one byte short drops the oldest entry (a1), nothing else.
  const std::size_t bytes = history.bytes();
  history.setBudget(bytes - 1);
  QCOMPARE(history.dropped(), std::size_t(1));
  QCOMPARE(history.undoCount(), std::size_t(2));
  QCOMPARE(live.undoCount(), std::size_t(2));
  QCOMPARE(history.documentStepAt(0)->label, std::string("a2"));
  QVERIFY(history.bytes() < bytes);
  // Then a budget of nothing keeps the newest entry alone.
  history.setBudget(0);
  QCOMPARE(history.undoCount(), std::size_t(1));
  QCOMPARE(history.nextUndo()->label, std::string("a3"));
  QCOMPARE(history.position() == SceneHistory::kUnreachable, false);
  history.clear();
  QCOMPARE(history.undoCount() + history.redoCount(), std::size_t(0));
  QCOMPARE(history.position(), std::uint64_t(0));
  QCOMPARE(live.undoCount(), std::size_t(0));
}

void SceneHistoryTest::transformLabels() {
  const core::ObjectTransform still{};
  core::ObjectTransform moved = still, turned = still, both = still;
  moved.translation.x = 1;
  turned.rotationDegrees.z = 30;
  both.translation.y = 2;
  both.scale.x = 2;
  QCOMPARE(app::transformLabel(still, moved, "Head"), std::string("Move Head"));
  QCOMPARE(app::transformLabel(still, turned, "Head"), std::string("Rotate Head"));
  core::ObjectTransform scaled = still;
  scaled.scale = {2, 2, 2};
  QCOMPARE(app::transformLabel(still, scaled, "Head"), std::string("Scale Head"));
  QCOMPARE(app::transformLabel(still, both, "Head"), std::string("Transform Head"));
}

QTEST_MAIN(SceneHistoryTest)
#include "scene_history_test.moc"
