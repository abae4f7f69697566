#include "merge/part_locator.h"

namespace octaclay::core::detail {
namespace {

double boxDistanceSquared(const BoundingBox& box, Vec3d p) {
  const auto gap = [](double v, double lo, double hi) {
    return v < lo ? lo - v : v > hi ? v - hi : 0.0;
  };
  const double x = gap(p.x, box.min.x, box.max.x), y = gap(p.y, box.min.y, box.max.y),
               z = gap(p.z, box.min.z, box.max.z);
  return x * x + y * y + z * z;
}

} // namespace

PartLocator::PartLocator(std::span<const PlacedSurface> parts) {
  for (const PlacedSurface& p : parts)
    parts_.push_back({&p, std::make_unique<AabbTree>(p.mesh), boundingBox(p.mesh)});
}

PartLocator::Found PartLocator::nearest(Vec3d p, Cursor& cursor) const {
  std::size_t winner = cursor.winner;
  AabbTree::Hit best = parts_[winner].tree->closest(p, cursor.hints[winner]);
  cursor.hints[winner] = best.triangle;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    if (k == cursor.winner || boxDistanceSquared(parts_[k].box, p) >= best.distanceSquared)
      continue;
    const AabbTree::Hit hit = parts_[k].tree->closest(p, cursor.hints[k]);
    cursor.hints[k] = hit.triangle;
    if (hit.distanceSquared < best.distanceSquared) best = hit, winner = k;
  }
  cursor.winner = winner;
  const Part& part = parts_[winner];
  const AabbTree::Triangle& t = part.tree->triangles()[best.triangle];
  return {winner, part.tree->triangleIds()[best.triangle],
          closestPointOnTriangle(p, Vec3d(t.a), Vec3d(t.b), Vec3d(t.c))};
}

bool PartLocator::otherWithin(Vec3d p, std::size_t except, double bound, Cursor& cursor) const {
  const double bound2 = bound * bound;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    if (k == except || boxDistanceSquared(parts_[k].box, p) >= bound2) continue;
    const AabbTree::Hit hit = parts_[k].tree->closest(p, cursor.hints[k]);
    cursor.hints[k] = hit.triangle;
    if (hit.distanceSquared < bound2) return true;
  }
  return false;
}

} // namespace octaclay::core::detail
