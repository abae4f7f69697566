#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/object_transform.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core {

/// One object of a scene (DESIGN.md, "Objects and topologies"): its geometry image and layers
/// (the Document, which carries the topology), where it sits, whether it is drawn and whether it
/// may be edited.
struct SceneObject {
  std::string name;
  Document document;
  ObjectTransform transform;
  bool visible = true;
  bool locked = false;
};

/// The most objects a scene holds: a file declaring more is refused before it is read.
inline constexpr std::size_t kMaxSceneObjects = 1024;
/// The longest object name, in bytes.
inline constexpr std::size_t kMaxObjectNameBytes = 255;

/// A document of one or more objects, in order (the Objects list's order, the file's parts).
/// Names are unique.
struct Scene {
  std::vector<SceneObject> objects;

  /// The object named so, or nullptr.
  SceneObject* find(std::string_view name);
  const SceneObject* find(std::string_view name) const;
  /// The object named so; throws Error(InvalidArgument) "no object 'X' (the objects: A, B)".
  SceneObject& require(std::string_view name);
  const SceneObject& require(std::string_view name) const;
  /// Every name, in order.
  std::vector<std::string> names() const;
  /// wanted when no object has it, else Blender's way: its stem (wanted less a ".NNN" suffix)
  /// with the first free ".001", ".002", … ("Sphere" → "Sphere.001", "Sphere.001" → "Sphere.002").
  std::string uniqueName(std::string_view wanted) const;
};

/// What is wrong with an object's name (empty, longer than kMaxObjectNameBytes, a control
/// character, a comma: `merge --objects A,B` splits on commas), or nothing.
std::optional<std::string> objectNameProblem(std::string_view name);

/// What is wrong with a scene: no objects, more than kMaxSceneObjects, a bad or repeated name, a
/// bad transform; nothing when it may be written.
std::optional<std::string> sceneProblem(const Scene& scene);

/// The object's sample positions in world space (its transform applied), row-major like its
/// position image's texels.
std::vector<Vec3f> worldPositions(const SceneObject& object);

/// The world-space bounding box of the object's samples.
BoundingBox worldBounds(const SceneObject& object);

/// The world-space bounding box of the scene's objects (only the visible ones when
/// visibleOnly); empty when there are none.
BoundingBox sceneBounds(const Scene& scene, bool visibleOnly = false);

/// A one-object scene holding document, named name, at the identity transform.
Scene sceneOf(Document document, std::string name = "Model");

} // namespace octaclay::core
