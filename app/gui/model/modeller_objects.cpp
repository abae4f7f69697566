// The Modeller's scene edits that are not strokes: an object's visibility, lock, name and
// transform, adding and removing, replacing and reordering objects (issue 33). Each is one step
// of the scene's one history (SceneHistory, SceneStep), made by showing the step's after side,
// so that redo is the same code as the edit itself.
#include "modeller.h"

#include <algorithm>

namespace octaclay::app {

int Modeller::indexOf(ObjectId id) const {
  const auto at = std::find(ids_.begin(), ids_.end(), id);
  return at == ids_.end() ? -1 : static_cast<int>(at - ids_.begin());
}

QString Modeller::showStep(SceneStep& step, bool before) {
  const ObjectId now = ids_[std::size_t(active_)];
  const std::vector<ObjectId>& order = before ? step.orderBefore : step.orderAfter;
  const bool stays = order.empty() || std::find(order.begin(), order.end(), now) != order.end();
  const ObjectId wanted = step.activeBefore != step.activeAfter || !stays
                              ? (before ? step.activeBefore : step.activeAfter)
                              : now;
  if (!stays && wanted == now) return tr("The history does not match the scene");
  if (wanted == now) {
    if (!showSide(step, before, scene_, ids_)) return tr("The history does not match the scene");
    active_ = indexOf(now);
    emit objectsChanged();
    return {};
  }
  strokes_.settle();
  if (session_.stroking()) return tr("Finish the stroke first");
  emit activeObjectAboutToChange();
  // The edited document goes back into its slot: the step may hold it from now on.
  scene_.objects[std::size_t(active_)].document = document();
  if (!showSide(step, before, scene_, ids_)) {
    scene_.objects[std::size_t(active_)].document = {};
    return tr("The history does not match the scene");
  }
  const int k = indexOf(wanted);
  if (k < 0 || !enterObject(k)) {
    showSide(step, !before, scene_, ids_); // back as it was
    active_ = indexOf(now);
    scene_.objects[std::size_t(active_)].document = {};
    return error().isEmpty() ? tr("The history does not match the scene") : error();
  }
  emit objectsChanged();
  emit activeObjectChanged(k);
  return {};
}

QString Modeller::doStep(SceneStep step) {
  if (!hasDocument()) return tr("There is no model");
  if (const QString why = showStep(step, false); !why.isEmpty()) return why;
  history_.noteLiveStep(); // anything the session recorded comes first
  history_.record(std::move(step));
  emit historyChanged();
  return {};
}

QString Modeller::changeLook(int k, const ObjectLook& after, std::string label, bool placing) {
  const ObjectId id = ids_[std::size_t(k)];
  ObjectLook before = lookOf(scene_.objects[std::size_t(k)]);
  // A transform set while a preview runs is one step from where the preview began, and ends the
  // preview; another change (a hide while G runs) keeps the previewed transform on both sides.
  if (const auto preview = previewed_.find(id); placing && preview != previewed_.end()) {
    before.transform = preview->second;
    previewed_.erase(preview);
  }
  if (before == after) { // a preview put back where it began: no step
    if (!(lookOf(scene_.objects[std::size_t(k)]) == after)) {
      setLook(scene_.objects[std::size_t(k)], after);
      emit objectsChanged();
    }
    return {};
  }
  SceneStep step;
  step.label = std::move(label);
  step.changes.push_back({id, std::move(before), after});
  step.activeBefore = step.activeAfter = ids_[std::size_t(active_)];
  return doStep(std::move(step));
}

bool Modeller::setObjectVisible(int k, bool visible) {
  if (k < 0 || k >= objectCount()) return false;
  ObjectLook look = lookOf(scene_.objects[std::size_t(k)]);
  if (look.visible == visible) return true;
  look.visible = visible;
  return changeLook(k, look, (visible ? "Show " : "Hide ") + look.name).isEmpty();
}

bool Modeller::setObjectsVisible(const std::vector<int>& objects, bool visible,
                                 const std::string& label) {
  SceneStep step;
  step.label = label;
  for (int k : objects) {
    if (k < 0 || k >= objectCount()) return false;
    const ObjectLook before = lookOf(scene_.objects[std::size_t(k)]);
    if (before.visible == visible) continue;
    ObjectLook after = before;
    after.visible = visible;
    step.changes.push_back({ids_[std::size_t(k)], before, after});
  }
  if (step.changes.empty()) return true;
  step.activeBefore = step.activeAfter = ids_[std::size_t(active_)];
  return doStep(std::move(step)).isEmpty();
}

bool Modeller::setObjectLocked(int k, bool locked) {
  if (k < 0 || k >= objectCount()) return false;
  ObjectLook look = lookOf(scene_.objects[std::size_t(k)]);
  if (look.locked == locked) return true;
  look.locked = locked;
  return changeLook(k, look, (locked ? "Lock " : "Unlock ") + look.name).isEmpty();
}

QString Modeller::renameObject(int k, const QString& name) {
  if (k < 0 || k >= objectCount()) return tr("There is no object %1").arg(k + 1);
  const std::string wanted = name.toStdString();
  ObjectLook look = lookOf(scene_.objects[std::size_t(k)]);
  if (look.name == wanted) return {};
  if (const auto problem = core::objectNameProblem(wanted)) return QString::fromStdString(*problem);
  if (scene_.find(wanted)) return tr("Another object is already named %1").arg(name);
  const std::string label = "Rename " + look.name + " → " + wanted;
  look.name = wanted;
  return changeLook(k, look, label);
}

QString Modeller::setObjectTransform(int k, const core::ObjectTransform& transform) {
  if (k < 0 || k >= objectCount()) return tr("There is no object %1").arg(k + 1);
  if (const auto problem = core::transformProblem(transform))
    return QString::fromStdString(*problem);
  ObjectLook look = lookOf(scene_.objects[std::size_t(k)]);
  const auto preview = previewed_.find(ids_[std::size_t(k)]);
  const core::ObjectTransform& from =
      preview != previewed_.end() ? preview->second : look.transform;
  const std::string label = transformLabel(from, transform, look.name);
  look.transform = transform;
  return changeLook(k, look, label, true);
}

void Modeller::cancelPreviews() {
  for (const auto& [id, transform] : previewed_)
    if (const int k = indexOf(id); k >= 0) {
      scene_.objects[std::size_t(k)].transform = transform;
      emit objectMoved(k);
    }
  previewed_.clear();
}

bool Modeller::previewObjectTransform(int k, const core::ObjectTransform& transform) {
  if (k < 0 || k >= objectCount() || core::transformProblem(transform)) return false;
  core::SceneObject& object = scene_.objects[std::size_t(k)];
  // The first preview remembers where the object was: the step goes from there.
  const auto [at, first] = previewed_.try_emplace(ids_[std::size_t(k)], object.transform);
  if (!first && at->second == transform) previewed_.erase(at); // back where it was: cancelled
  object.transform = transform;
  emit objectMoved(k);
  return true;
}

QString Modeller::replaceObjects(const std::vector<int>& removed, core::SceneObject added,
                                 const QString& label) {
  if (removed.empty()) return tr("No objects were chosen");
  for (const int k : removed)
    if (k < 0 || k >= objectCount()) return tr("There is no object %1").arg(k + 1);
  if (!hasDocument()) return tr("There is no model");
  std::vector<bool> gone(std::size_t(objectCount()), false);
  for (const int k : removed)
    gone[std::size_t(k)] = true;
  const ObjectId id = newObjectId();
  // The merged object may keep a chosen object's name: only the objects that stay are in its way.
  bool taken = false;
  for (std::size_t k = 0; k < gone.size(); ++k)
    taken = taken || (!gone[k] && scene_.objects[k].name == added.name);
  if (taken || added.name.empty()) added.name = scene_.uniqueName(added.name);
  SceneStep step;
  step.label = label.isEmpty() ? std::string("Replace Objects") : label.toStdString();
  step.orderBefore = ids_;
  for (std::size_t k = 0; k < ids_.size(); ++k)
    if (!gone[k]) step.orderAfter.push_back(ids_[k]);
  step.orderAfter.push_back(id);
  step.held.emplace_back(id, std::move(added));
  step.activeBefore = ids_[std::size_t(active_)];
  step.activeAfter = id;
  return doStep(std::move(step));
}

bool Modeller::moveObject(int from, int to) {
  if (from < 0 || from >= objectCount() || to < 0 || to >= objectCount()) return false;
  if (from == to) return true;
  SceneStep step;
  step.label = "Reorder Objects";
  step.orderBefore = ids_;
  step.orderAfter = ids_;
  const ObjectId moving = step.orderAfter[std::size_t(from)];
  step.orderAfter.erase(step.orderAfter.begin() + from);
  step.orderAfter.insert(step.orderAfter.begin() + to, moving);
  // The edited object keeps being edited wherever it now sits.
  step.activeBefore = step.activeAfter = ids_[std::size_t(active_)];
  return doStep(std::move(step)).isEmpty();
}

bool Modeller::activeLocked() const {
  return active_ >= 0 && active_ < objectCount() && scene_.objects[std::size_t(active_)].locked;
}

bool Modeller::addObject(core::SceneObject object, const QString& label) {
  if (!hasDocument()) return false;
  object.name = scene_.uniqueName(object.name);
  const ObjectId id = newObjectId();
  SceneStep step;
  step.label = label.isEmpty() ? "Add " + object.name : label.toStdString();
  step.orderBefore = ids_;
  step.orderAfter = ids_;
  step.orderAfter.push_back(id);
  step.held.emplace_back(id, std::move(object));
  step.activeBefore = ids_[std::size_t(active_)];
  step.activeAfter = id;
  return doStep(std::move(step)).isEmpty();
}

QString Modeller::deleteActiveObject() {
  if (objectCount() <= 1) return tr("The last object cannot be deleted");
  const int gone = active_;
  SceneStep step;
  step.label = "Delete " + scene_.objects[std::size_t(gone)].name;
  step.orderBefore = ids_;
  step.orderAfter = ids_;
  step.orderAfter.erase(step.orderAfter.begin() + gone);
  step.activeBefore = ids_[std::size_t(gone)];
  step.activeAfter = ids_[std::size_t(gone > 0 ? gone - 1 : 1)];
  return doStep(std::move(step));
}

} // namespace octaclay::app
