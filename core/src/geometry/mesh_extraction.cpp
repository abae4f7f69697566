#include "octaclay/core/geometry/mesh_extraction.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/vertex_index.h"

#include <string>

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

// The torus's and plane's mesh: Mw × Mh cells each split along its anti-diagonal, vertex (i, j)
// numbered j · columns + i over the distinct samples (the torus's column Mw and row Mh are its
// column and row 0 again).
TriangleMesh extractGridMesh(const GeometryImage& image, int step) {
  if (step < 1 || (step & (step - 1)) != 0 || image.width() % step != 0 ||
      image.height() % step != 0)
    throw Error(ErrorKind::InvalidArgument,
                "mesh step " + std::to_string(step) + " is not a power of two dividing the image");
  const int mw = image.width() / step, mh = image.height() / step;
  const bool torus = image.topology() == Topology::Torus;
  const int minCells = torus ? kMinTorusSize : 1;
  if (mw < minCells || mh < minCells)
    throw Error(ErrorKind::InvalidArgument, "mesh step " + std::to_string(step) +
                                                " leaves fewer than " + std::to_string(minCells) +
                                                " cells across the image");
  const int columns = torus ? mw : mw + 1, rows = torus ? mh : mh + 1;
  TriangleMesh mesh;
  mesh.positions.resize(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i)
      mesh.positions[static_cast<std::size_t>(j) * columns + i] =
          image.at(i * step, j * step).xyz();
  const auto vertex = [&](int i, int j) {
    if (torus) i %= mw, j %= mh;
    return static_cast<std::uint32_t>(j * columns + i);
  };
  mesh.triangles.reserve(2 * static_cast<std::size_t>(mw) * static_cast<std::size_t>(mh));
  for (int j = 0; j < mh; ++j)
    for (int i = 0; i < mw; ++i) {
      const std::uint32_t a = vertex(i, j), b = vertex(i + 1, j);
      const std::uint32_t c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      mesh.triangles.push_back({a, b, d});
      mesh.triangles.push_back({b, c, d});
    }
  return mesh;
}

} // namespace

TriangleMesh extractMesh(const GeometryImage& image, int step) {
  if (image.topology() != Topology::Octahedral) return extractGridMesh(image, step);
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
