#include "octaclay/core/document/scene.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <cstdio>
#include <set>

namespace octaclay::core {

namespace {

std::string listOfNames(const Scene& scene) {
  std::string list;
  for (const SceneObject& object : scene.objects)
    list += (list.empty() ? "" : ", ") + object.name;
  return list.empty() ? "none" : list;
}

// "Sphere.001" → "Sphere"; "Sphere" and "Sphere.01" stay.
std::string_view stemOf(std::string_view name) {
  const std::size_t dot = name.rfind('.');
  if (dot == std::string_view::npos || dot == 0 || name.size() - dot != 4) return name;
  for (std::size_t k = dot + 1; k < name.size(); ++k)
    if (name[k] < '0' || name[k] > '9') return name;
  return name.substr(0, dot);
}

} // namespace

SceneObject* Scene::find(std::string_view name) {
  for (SceneObject& object : objects)
    if (object.name == name) return &object;
  return nullptr;
}

const SceneObject* Scene::find(std::string_view name) const {
  return const_cast<Scene*>(this)->find(name);
}

SceneObject& Scene::require(std::string_view name) {
  if (SceneObject* object = find(name)) return *object;
  throw Error(ErrorKind::InvalidArgument,
              "no object '" + std::string(name) +
                  "' in the document (the objects: " + listOfNames(*this) + ")");
}

const SceneObject& Scene::require(std::string_view name) const {
  return const_cast<Scene*>(this)->require(name);
}

std::vector<std::string> Scene::names() const {
  std::vector<std::string> result;
  result.reserve(objects.size());
  for (const SceneObject& object : objects)
    result.push_back(object.name);
  return result;
}

std::string Scene::uniqueName(std::string_view wanted) const {
  if (!find(wanted)) return std::string(wanted);
  const std::string stem(stemOf(wanted));
  for (int k = 1;; ++k) {
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, ".%03d", k);
    std::string name = stem + suffix;
    if (!find(name)) return name;
  }
}

std::optional<std::string> objectNameProblem(std::string_view name) {
  if (name.empty()) return "an object's name is empty";
  if (name.size() > kMaxObjectNameBytes)
    return "an object's name is " + std::to_string(name.size()) + " bytes long (at most " +
           std::to_string(kMaxObjectNameBytes) + ")";
  for (const char c : name) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      return "the object name '" + std::string(name) + "' holds a control character";
    if (c == ',')
      return "the object name '" + std::string(name) +
             "' holds a comma (lists of objects are split on commas)";
  }
  return std::nullopt;
}

std::optional<std::string> sceneProblem(const Scene& scene) {
  if (scene.objects.empty()) return "the scene holds no object";
  if (scene.objects.size() > kMaxSceneObjects)
    return "the scene holds " + std::to_string(scene.objects.size()) + " objects (at most " +
           std::to_string(kMaxSceneObjects) + ")";
  std::set<std::string_view> seen;
  for (const SceneObject& object : scene.objects) {
    if (auto problem = objectNameProblem(object.name)) return problem;
    if (!seen.insert(object.name).second)
      return "two objects are named '" + object.name + "' (names are unique)";
    if (auto problem = transformProblem(object.transform))
      return "object '" + object.name + "': " + *problem;
  }
  return std::nullopt;
}

std::vector<Vec3f> worldPositions(const SceneObject& object) {
  const auto texels = object.document.positions.texels();
  std::vector<Vec3f> result(texels.size());
  std::transform(texels.begin(), texels.end(), result.begin(),
                 [&](const Vec4f& p) { return applyTransform(object.transform, p.xyz()); });
  return result;
}

BoundingBox worldBounds(const SceneObject& object) {
  BoundingBox box;
  for (const Vec4f& p : object.document.positions.texels())
    box.extend(applyTransform(object.transform, p.xyz()));
  return box;
}

BoundingBox sceneBounds(const Scene& scene, bool visibleOnly) {
  BoundingBox box;
  for (const SceneObject& object : scene.objects) {
    if (visibleOnly && !object.visible) continue;
    const BoundingBox part = worldBounds(object);
    if (part.empty()) continue;
    box.extend(part.min);
    box.extend(part.max);
  }
  return box;
}

Scene sceneOf(Document document, std::string name) {
  Scene scene;
  scene.objects.push_back({std::move(name), std::move(document), {}, true, false});
  return scene;
}

} // namespace octaclay::core
