// The export's sample grid: positions and normals from each sample's canonical sample.

#include "export/sample_grid.h"

#include "geometry/subsampling.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"

#include <cmath>
#include <string>

namespace octaclay::core::detail {

void requireLayer(const Layer& layer, int n) {
  const std::size_t side = static_cast<std::size_t>(n) + 1;
  if (!layer.uniform() &&
      layer.texels.size() != side * side * static_cast<std::size_t>(layer.channels))
    throw Error(ErrorKind::InvalidArgument,
                "cannot export: the " + layer.name + " layer holds " +
                    std::to_string(layer.texels.size()) + " values, not (N+1)² × " +
                    std::to_string(layer.channels) + " for N = " + std::to_string(n));
}

namespace {

// Calls triangle(a, b, c) for the 2M² triangles, counter-clockwise seen from outside, split as
// extractMesh splits them (the anti-diagonal where (i < M/2) == (j < M/2)).
template <class Triangle> void forEachTriangle(int m, Triangle&& triangle) {
  const int half = m / 2;
  const auto index = [m](int i, int j) { return static_cast<std::uint32_t>(j * (m + 1) + i); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const std::uint32_t a = index(i, j), b = index(i + 1, j);
      const std::uint32_t c = index(i + 1, j + 1), d = index(i, j + 1);
      if ((i < half) == (j < half)) {
        triangle(a, b, d);
        triangle(b, c, d);
      } else {
        triangle(a, b, c);
        triangle(a, c, d);
      }
    }
}

} // namespace

SampleGrid makeGrid(const Document& doc, int step) {
  SampleGrid grid;
  grid.n = doc.size();
  grid.m = subsampledSize(grid.n, step);
  grid.step = step;
  requireLayer(doc.diffuse, grid.n);
  requireLayer(doc.feature, grid.n);

  const GeometryImage& image = doc.positions;
  std::vector<Vec3f> fullNormals;
  if (step == 1) fullNormals = computeNormals(image); // parallel; every sample is exported
  const std::size_t count = grid.vertexCount();
  grid.positions.resize(count);
  grid.normals.resize(count);
  for (int j = 0; j <= grid.m; ++j)
    for (int i = 0; i <= grid.m; ++i) {
      const Sample c = canonical(grid.n, {i * step, j * step});
      const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(grid.m + 1) +
                            static_cast<std::size_t>(i);
      grid.positions[k] = image.at(c).xyz();
      Vec3f normal =
          step == 1
              ? fullNormals[static_cast<std::size_t>(c.j) * static_cast<std::size_t>(grid.n + 1) +
                            static_cast<std::size_t>(c.i)]
              : vertexNormal(image, c);
      // A degenerate neighbourhood has no normal; glTF requires unit normals, so point it
      // outward from the origin (the base shapes are centred there).
      if (!(std::abs(length(normal) - 1.0f) < 1e-3f)) normal = normalize(image.at(c).xyz());
      if (!(std::abs(length(normal) - 1.0f) < 1e-3f)) normal = {0, 0, 1};
      grid.normals[k] = normal;
    }
  return grid;
}

std::vector<Vec2f> gridTexcoords(const SampleGrid& grid, bool vUp) {
  std::vector<Vec2f> texcoords;
  texcoords.reserve(grid.vertexCount());
  for (int j = 0; j <= grid.m; ++j)
    for (int i = 0; i <= grid.m; ++i)
      texcoords.push_back({grid.u(i), vUp ? 1.0f - grid.v(j) : grid.v(j)});
  return texcoords;
}

std::vector<std::array<std::uint32_t, 3>> gridTriangles(int m) {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(2 * static_cast<std::size_t>(m) * static_cast<std::size_t>(m));
  forEachTriangle(m, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    triangles.push_back({a, b, c});
  });
  return triangles;
}

} // namespace octaclay::core::detail
