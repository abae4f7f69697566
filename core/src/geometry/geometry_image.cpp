#include "octaclay/core/geometry/geometry_image.h"

#include "detail/parallel_rows.h"

#include <algorithm>

namespace octaclay::core {

GeometryImage::GeometryImage(int n) : grid_{Topology::Octahedral, n, n} {
  requireValidSize(n);
  zeroTexels(static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1));
}

GeometryImage::GeometryImage(Topology topology, int width, int height)
    : grid_{topology, width, height} {
  requireValidGrid(grid_);
  zeroTexels(static_cast<std::size_t>(width + 1) * static_cast<std::size_t>(height + 1));
}

// The texels made unset, then zeroed a band of rows per core: the pages' first touch (the
// kernel's page faults and clearing) and the fill run on every core.
void GeometryImage::zeroTexels(std::size_t count) {
  texels_.resize(count);
  const int side = this->side();
  detail::parallelRows(rows(), [&](int rowBegin, int rowEnd) {
    std::fill(texels_.begin() + std::ptrdiff_t(rowBegin) * side,
              texels_.begin() + std::ptrdiff_t(rowEnd) * side, Vec4f{});
  });
}

BoundingBox boundingBox(const GeometryImage& image) {
  BoundingBox box;
  for (const Vec4f& t : image.texels())
    box.extend(t.xyz());
  return box;
}

} // namespace octaclay::core
