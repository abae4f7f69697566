// The Modeller's scene edits that are not strokes: an object's visibility, lock and name, adding
// and removing, replacing and reordering objects (issue 33). Undo does not cover them yet.
#include "modeller.h"

namespace octaclay::app {

bool Modeller::setObjectVisible(int k, bool visible) {
  if (k < 0 || k >= objectCount()) return false;
  core::SceneObject& object = scene_.objects[std::size_t(k)];
  if (object.visible == visible) return true;
  object.visible = visible;
  emit objectsChanged();
  return true;
}

bool Modeller::setObjectLocked(int k, bool locked) {
  if (k < 0 || k >= objectCount()) return false;
  core::SceneObject& object = scene_.objects[std::size_t(k)];
  if (object.locked == locked) return true;
  object.locked = locked;
  emit objectsChanged();
  return true;
}

QString Modeller::renameObject(int k, const QString& name) {
  if (k < 0 || k >= objectCount()) return tr("There is no object %1").arg(k + 1);
  const std::string wanted = name.toStdString();
  core::SceneObject& object = scene_.objects[std::size_t(k)];
  if (object.name == wanted) return {};
  if (const auto problem = core::objectNameProblem(wanted)) return QString::fromStdString(*problem);
  if (scene_.find(wanted)) return tr("Another object is already named %1").arg(name);
  object.name = wanted;
  emit objectsChanged();
  return {};
}

QString Modeller::setObjectTransform(int k, const core::ObjectTransform& transform) {
  if (k < 0 || k >= objectCount()) return tr("There is no object %1").arg(k + 1);
  if (const auto problem = core::transformProblem(transform))
    return QString::fromStdString(*problem);
  scene_.objects[std::size_t(k)].transform = transform;
  emit objectsChanged();
  return {};
}

bool Modeller::previewObjectTransform(int k, const core::ObjectTransform& transform) {
  if (k < 0 || k >= objectCount() || core::transformProblem(transform)) return false;
  scene_.objects[std::size_t(k)].transform = transform;
  emit objectMoved(k);
  return true;
}

QString Modeller::replaceObjects(const std::vector<int>& removed, core::SceneObject added,
                                 const QString& label) {
  (void)label; // named for the history's step (issue 33: one history)
  if (removed.empty()) return tr("No objects were chosen");
  for (const int k : removed)
    if (k < 0 || k >= objectCount()) return tr("There is no object %1").arg(k + 1);
  std::vector<bool> gone(std::size_t(objectCount()), false);
  for (const int k : removed)
    gone[std::size_t(k)] = true;
  if (!addObject(std::move(added)))
    return error().isEmpty() ? tr("Finish the stroke first") : error();
  const int merged = active_;
  // The chosen objects go, newest first, so the indices left stay right; the added one is last.
  for (int k = merged - 1; k >= 0; --k)
    if (gone[std::size_t(k)]) scene_.objects.erase(scene_.objects.begin() + k);
  active_ = objectCount() - 1;
  emit objectsChanged();
  return {};
}

bool Modeller::moveObject(int from, int to) {
  if (from < 0 || from >= objectCount() || to < 0 || to >= objectCount()) return false;
  if (from == to) return true;
  const int edited = active_;
  core::SceneObject moving = std::move(scene_.objects[std::size_t(from)]);
  scene_.objects.erase(scene_.objects.begin() + from);
  scene_.objects.insert(scene_.objects.begin() + to, std::move(moving));
  // The edited object keeps being edited wherever it now sits.
  if (edited == from)
    active_ = to;
  else if (from < edited && to >= edited)
    --active_;
  else if (from > edited && to <= edited)
    ++active_;
  emit objectsChanged();
  return true;
}

bool Modeller::activeLocked() const {
  return active_ >= 0 && active_ < objectCount() && scene_.objects[std::size_t(active_)].locked;
}

bool Modeller::addObject(core::SceneObject object) {
  if (!hasDocument()) return false;
  object.name = scene_.uniqueName(object.name);
  scene_.objects.push_back(std::move(object));
  if (!setActiveObject(objectCount() - 1)) {
    scene_.objects.pop_back();
    return false;
  }
  emit objectsChanged();
  return true;
}

QString Modeller::deleteActiveObject() {
  if (objectCount() <= 1) return tr("The last object cannot be deleted");
  const int gone = active_;
  if (!setActiveObject(gone > 0 ? gone - 1 : 1)) return tr("Finish the stroke first");
  scene_.objects.erase(scene_.objects.begin() + gone);
  if (active_ > gone) --active_;
  emit objectsChanged();
  return {};
}

} // namespace octaclay::app
