#include "detail/unit_scale.h"

#include <cmath>

namespace octaclay::core::detail {

int unitScaleExponent(const GeometryImage& image) {
  return unitScaleExponent(static_cast<double>(boundingBox(image).diagonal()));
}

int unitScaleExponent(double diagonal) {
  if (!(diagonal > 0) || !std::isfinite(diagonal) || (diagonal >= 1.0 / 256 && diagonal <= 256))
    return 0;
  int exponent = 0;
  std::frexp(diagonal, &exponent); // diagonal = f × 2^exponent, f in [0.5, 1)
  return 1 - exponent;
}

GeometryImage scaledPositions(const GeometryImage& image, int exponent) {
  GeometryImage scaled = image;
  for (Vec4f& t : scaled.texels()) {
    t.x = std::ldexp(t.x, exponent);
    t.y = std::ldexp(t.y, exponent);
    t.z = std::ldexp(t.z, exponent);
  }
  return scaled;
}

void scaleMesh(TriangleMesh& mesh, int exponent) {
  for (Vec3f& p : mesh.positions)
    p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
}

} // namespace octaclay::core::detail
