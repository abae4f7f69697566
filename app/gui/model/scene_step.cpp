#include "scene_step.h"

#include <algorithm>

namespace octaclay::app {
namespace {

std::size_t documentBytes(const core::Document& d) {
  std::size_t total = d.positions.byteSize();
  for (const core::Layer* l : {&d.diffuse, &d.feature, &d.mask})
    total += l->texels.capacity() * sizeof(float) + l->name.capacity();
  return total;
}

bool holds(const std::vector<ObjectId>& ids, ObjectId id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

} // namespace

ObjectLook lookOf(const core::SceneObject& object) {
  return {object.name, object.transform, object.visible, object.locked};
}

void setLook(core::SceneObject& object, const ObjectLook& look) {
  object.name = look.name;
  object.transform = look.transform;
  object.visible = look.visible;
  object.locked = look.locked;
}

std::size_t SceneStep::bytes() const {
  std::size_t total = sizeof(SceneStep) + label.capacity() +
                      (orderBefore.capacity() + orderAfter.capacity()) * sizeof(ObjectId) +
                      changes.capacity() * sizeof(Change) +
                      held.capacity() * sizeof(std::pair<ObjectId, core::SceneObject>);
  for (const Change& c : changes)
    total += c.before.name.capacity() + c.after.name.capacity();
  for (const auto& [id, object] : held)
    total += object.name.capacity() + documentBytes(object.document);
  return total;
}

bool showSide(SceneStep& step, bool before, core::Scene& scene, std::vector<ObjectId>& ids) {
  if (ids.size() != scene.objects.size()) return false;
  const std::vector<ObjectId>& order = before ? step.orderBefore : step.orderAfter;
  const auto heldAt = [&](ObjectId id) {
    return std::find_if(step.held.begin(), step.held.end(),
                        [id](const auto& h) { return h.first == id; });
  };
  // Checked first: nothing moves unless every object of the side can be found.
  for (const ObjectId id : order)
    if (!holds(ids, id) && heldAt(id) == step.held.end()) return false;
  for (const SceneStep::Change& c : step.changes)
    if (!holds(order.empty() ? ids : order, c.id)) return false;
  if (!order.empty()) {
    std::vector<core::SceneObject> objects;
    objects.reserve(order.size());
    for (const ObjectId id : order) {
      const auto in = std::find(ids.begin(), ids.end(), id);
      if (in != ids.end()) {
        objects.push_back(std::move(scene.objects[std::size_t(in - ids.begin())]));
        continue;
      }
      const auto h = heldAt(id);
      objects.push_back(std::move(h->second));
      step.held.erase(h);
    }
    for (std::size_t k = 0; k < ids.size(); ++k)
      if (!holds(order, ids[k])) step.held.emplace_back(ids[k], std::move(scene.objects[k]));
    scene.objects = std::move(objects);
    ids = order;
  }
  for (const SceneStep::Change& c : step.changes) {
    const auto in = std::find(ids.begin(), ids.end(), c.id);
    setLook(scene.objects[std::size_t(in - ids.begin())], before ? c.before : c.after);
  }
  return true;
}

std::string transformLabel(const core::ObjectTransform& before, const core::ObjectTransform& after,
                           const std::string& name) {
  const bool moved = !(before.translation == after.translation);
  const bool turned = !(before.rotationDegrees == after.rotationDegrees);
  const bool scaled = !(before.scale == after.scale);
  const int kinds = int(moved) + int(turned) + int(scaled);
  const char* verb = kinds != 1 ? "Transform" : moved ? "Move" : turned ? "Rotate" : "Scale";
  return std::string(verb) + " " + name;
}

} // namespace octaclay::app
