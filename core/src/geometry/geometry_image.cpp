#include "octaclay/core/geometry/geometry_image.h"

namespace octaclay::core {

GeometryImage::GeometryImage(int n) : grid_{Topology::Octahedral, n, n} {
  requireValidSize(n);
  texels_.resize(static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1));
}

GeometryImage::GeometryImage(Topology topology, int width, int height)
    : grid_{topology, width, height} {
  requireValidGrid(grid_);
  texels_.resize(static_cast<std::size_t>(width + 1) * static_cast<std::size_t>(height + 1));
}

BoundingBox boundingBox(const GeometryImage& image) {
  BoundingBox box;
  for (const Vec4f& t : image.texels())
    box.extend(t.xyz());
  return box;
}

} // namespace octaclay::core
