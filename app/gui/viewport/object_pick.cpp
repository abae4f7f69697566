#include "object_pick.h"

#include "modeller.h"
#include "object_placement.h"

#include "octaclay/core/geometry/tile_bounds.h"

namespace octaclay::app {

std::optional<int> pickObject(const Modeller& modeller, const core::Ray& worldRay) {
  std::optional<int> nearest;
  float nearestDistance = 0;
  for (int k = 0; k < modeller.objectCount(); ++k) {
    const core::SceneObject& object = modeller.objectAt(k);
    if (!object.visible) continue;
    const ObjectPlacement placement(object.transform);
    const core::Ray ray = placement.rayToLocal(worldRay);
    std::optional<core::PickHit> hit;
    if (k == modeller.activeObject()) {
      if (!modeller.session().hasDocument()) continue;
      const gpu::GpuDocument& document = modeller.session().gpuDocument();
      hit = core::pickRay(document.document().positions, document.bounds(), ray);
    } else {
      if (object.document.size() < 2) continue;
      const core::GeometryImage& positions = object.document.positions;
      hit = core::pickRay(positions, core::TileBounds(positions), ray);
    }
    if (!hit) continue;
    // Distances compare in world units: each object's own are scaled.
    const float distance = core::length(placement.toWorld(hit->position) - worldRay.origin);
    if (!nearest || distance < nearestDistance) {
      nearest = k;
      nearestDistance = distance;
    }
  }
  return nearest;
}

} // namespace octaclay::app
