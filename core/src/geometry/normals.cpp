#include "octaclay/core/geometry/normals.h"

namespace octaclay::core {

Vec3f vertexNormal(const GeometryImage& image, Sample s) {
  std::array<std::array<Sample, 3>, 6> tris;
  const int count = incidentTriangles(image.grid(), s, tris);
  const Vec3f p = image.positionWrapped(s);
  Vec3f sum{};
  // Cross products are twice the triangle areas: an area-weighted average.
  for (int k = 0; k < count; ++k)
    sum += cross(image.positionWrapped(tris[k][1]) - p, image.positionWrapped(tris[k][2]) - p);
  return normalize(sum);
}

Vec3f gridNormal(const GeometryImage& image, Sample s) {
  const Vec3f du = image.positionWrapped({s.i + 1, s.j}) - image.positionWrapped({s.i - 1, s.j});
  const Vec3f dv = image.positionWrapped({s.i, s.j + 1}) - image.positionWrapped({s.i, s.j - 1});
  // normalize works at every scale; a grid normal of no length falls back to the triangles'.
  const Vec3f n = normalize(cross(du, dv));
  return dot(n, n) > 0.5f ? n : vertexNormal(image, s);
}

std::vector<Vec3f> computeNormals(const GeometryImage& image) {
  const int side = image.side();
  std::vector<Vec3f> normals(image.texelCount());
  for (int j = 0; j < image.rows(); ++j)
    for (int i = 0; i < side; ++i)
      normals[static_cast<std::size_t>(j) * side + i] = vertexNormal(image, {i, j});
  return normals;
}

} // namespace octaclay::core
