#include "merge/part_snap.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/geometry/seaming.h"

#include <atomic>
#include <cmath>

namespace octaclay::core::detail {

std::size_t snapToParts(const PartLocator& parts, GeometryImage& positions, double maxMove,
                        double clearance, LayerCarrier* layers) {
  if (layers && !layers->active()) layers = nullptr;
  const int n = positions.size();
  std::atomic<std::size_t> moved{0};
  const double maxMove2 = maxMove * maxMove;
  parallelRows(n + 1, [&](int rowBegin, int rowEnd) {
    PartLocator::Cursor cursor = parts.cursor();
    std::size_t count = 0;
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i <= n; ++i) {
        Vec4f& t = positions.at(i, j);
        const Vec3d p(t.xyz());
        const PartLocator::Found found = parts.nearest(p, cursor);
        const Vec3d d = found.point - p;
        if (layers) layers->carry(std::size_t(j) * std::size_t(n + 1) + std::size_t(i), found);
        if (dot(d, d) > maxMove2 || parts.otherWithin(found.point, found.part, clearance, cursor))
          continue;
        t.x = float(found.point.x), t.y = float(found.point.y), t.z = float(found.point.z);
        ++count;
      }
    moved += count;
  });
  seam(positions);
  return moved;
}

} // namespace octaclay::core::detail
