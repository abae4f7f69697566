#include "octaclay/core/geometry/mesh_extraction.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/geometry/vertex_index.h"

namespace octaclay::core {
namespace {

// Writes the triangles of cell rows [rowBegin, rowEnd). Within a row the split changes only at
// the middle column, so the per-cell test of cellSplit() is hoisted out of the loop.
void writeTriangleRows(const VertexIndex& index, int rowBegin, int rowEnd,
                       std::array<std::uint32_t, 3>* out) {
  const int m = index.size();
  const int half = m / 2;
  for (int j = rowBegin; j < rowEnd; ++j) {
    std::array<std::uint32_t, 3>* row = out + static_cast<std::size_t>(j) * 2 * m;
    const bool lowerHalf = j < half;
    for (int i = 0; i < m; ++i) {
      const std::uint32_t a = index.at(i, j), b = index.at(i + 1, j);
      const std::uint32_t c = index.at(i + 1, j + 1), d = index.at(i, j + 1);
      const bool anti = (i < half) == lowerHalf;
      if (anti) {
        row[2 * i] = {a, b, d};
        row[2 * i + 1] = {b, c, d};
      } else {
        row[2 * i] = {a, b, c};
        row[2 * i + 1] = {a, c, d};
      }
    }
  }
}

} // namespace

TriangleMesh extractMesh(const GeometryImage& image, int step) {
  const VertexIndex index(image.size(), step);
  const int m = index.size();
  TriangleMesh mesh;
  mesh.positions.resize(index.vertexCount());
  mesh.triangles.resize(2 * static_cast<std::size_t>(m) * static_cast<std::size_t>(m));

  // Canonical runs are exactly the vertex order of VertexIndex.
  std::size_t v = 0;
  forEachCanonicalRun(m, [&](int j, int iBegin, int iEnd) {
    const Vec4f* row = &image.at(0, j * step);
    for (int i = iBegin; i < iEnd; ++i)
      mesh.positions[v++] = row[i * step].xyz();
  });

  detail::parallelRows(
      m,
      [&](int rowBegin, int rowEnd) {
        writeTriangleRows(index, rowBegin, rowEnd, mesh.triangles.data());
      },
      128);
  return mesh;
}

} // namespace octaclay::core
