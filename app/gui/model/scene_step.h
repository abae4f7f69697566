#pragma once

// A step of the scene's one history that is not a document's (issue 33): objects added,
// deleted, merged, reordered, renamed, moved, hidden or locked. Qt-free; the Modeller applies
// it (SceneHistory holds it).

#include "octaclay/core/document/object_transform.h"
#include "octaclay/core/document/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace octaclay::app {

/// An object's identity for this session: names change and indices move, this does not. 0 is
/// no object. Never saved.
using ObjectId = std::uint64_t;

/// What an object is apart from its document: its name, transform, visibility and lock.
struct ObjectLook {
  std::string name;
  core::ObjectTransform transform;
  bool visible = true;
  bool locked = false;
  friend bool operator==(const ObjectLook&, const ObjectLook&) = default;
};
ObjectLook lookOf(const core::SceneObject& object);
void setLook(core::SceneObject& object, const ObjectLook& look);

/// One change of the scene's objects as its two sides. Small: a move holds two looks, a
/// delete the removed object (its document), an add nothing while done (the added object's
/// document while undone).
struct SceneStep {
  std::string label; ///< "Add Sphere", "Delete Cube", "Move Head", …
  /// The scene's objects in order before and after the step; both empty when it keeps them (a
  /// rename, a move, a hide or a lock).
  std::vector<ObjectId> orderBefore, orderAfter;
  /// An object's look before and after the step.
  struct Change {
    ObjectId id = 0;
    ObjectLook before, after;
  };
  std::vector<Change> changes;
  /// The objects the side shown now lacks, documents and all: the removed ones while the step
  /// is done, the added ones while it is undone.
  std::vector<std::pair<ObjectId, core::SceneObject>> held;
  /// The edited object before and after (equal when the step does not change which is edited).
  ObjectId activeBefore = 0, activeAfter = 0;

  /// Memory held: the struct, the orders, the looks' names and every held document's texels.
  std::size_t bytes() const;
};

/// Shows one side of step (before: its orderBefore and the changes' before looks) on scene,
/// whose objects are ids in order (the edited object's slot may hold no document): objects the
/// side lacks move into step.held, objects it holds that the scene lacks move out of it, the
/// changed objects take their looks. Documents are moved, never copied. Returns false, with
/// nothing changed, when the scene is not at the step's other side (an object of the side
/// neither in the scene nor held, or ids and scene of different lengths).
bool showSide(SceneStep& step, bool before, core::Scene& scene, std::vector<ObjectId>& ids);

/// A transform step's label: "Move", "Rotate", "Scale" or "Transform" (several at once) and the
/// object's name.
std::string transformLabel(const core::ObjectTransform& before, const core::ObjectTransform& after,
                           const std::string& name);

} // namespace octaclay::app
