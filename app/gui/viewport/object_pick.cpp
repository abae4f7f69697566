#include "object_pick.h"

#include "modeller.h"
#include "object_placement.h"

#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/tile_bounds.h"

namespace octaclay::app {

std::optional<SurfacePick> pickSurface(const Modeller& modeller, const core::Ray& worldRay) {
  std::optional<SurfacePick> nearest;
  float nearestDistance = 0;
  for (int k = 0; k < modeller.objectCount(); ++k) {
    const core::SceneObject& object = modeller.objectAt(k);
    if (!object.visible) continue;
    const ObjectPlacement placement(object.transform);
    const core::Ray ray = placement.rayToLocal(worldRay);
    std::optional<core::PickHit> hit;
    const core::GeometryImage* positions = nullptr;
    if (k == modeller.activeObject()) {
      if (!modeller.session().hasDocument()) continue;
      const gpu::GpuDocument& document = modeller.session().gpuDocument();
      positions = &document.document().positions;
      hit = core::pickRay(*positions, document.bounds(), ray);
    } else {
      if (object.document.size() < 2) continue;
      positions = &object.document.positions;
      hit = core::pickRay(*positions, core::TileBounds(*positions), ray);
    }
    if (!hit) continue;
    // Distances compare in world units: each object's own are scaled.
    const core::Vec3f world = placement.toWorld(hit->position);
    const float distance = core::length(world - worldRay.origin);
    if (!nearest || distance < nearestDistance) {
      nearest =
          SurfacePick{k, world, placement.normalToWorld(core::gridNormal(*positions, hit->sample))};
      nearestDistance = distance;
    }
  }
  return nearest;
}

std::optional<int> pickObject(const Modeller& modeller, const core::Ray& worldRay) {
  const std::optional<SurfacePick> pick = pickSurface(modeller, worldRay);
  if (!pick) return std::nullopt;
  return pick->object;
}

} // namespace octaclay::app
