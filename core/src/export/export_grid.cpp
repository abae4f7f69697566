// The export's grid: positions and normals from each sample's canonical sample, on the ball,
// the torus and the plane.

#include "export/export_grid.h"

#include "geometry/subsampling.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/vertex_index.h"

#include <cmath>
#include <string>

namespace octaclay::core::detail {

void requireLayer(const Layer& layer, const SampleGrid& image) {
  const std::size_t texels =
      static_cast<std::size_t>(image.width + 1) * static_cast<std::size_t>(image.height + 1);
  if (!layer.uniform() && layer.texels.size() != texels * static_cast<std::size_t>(layer.channels))
    throw Error(ErrorKind::InvalidArgument,
                "cannot export: the " + layer.name + " layer holds " +
                    std::to_string(layer.texels.size()) + " values, not (W+1)(H+1) × " +
                    std::to_string(layer.channels) + " for a " + std::to_string(image.width) +
                    " × " + std::to_string(image.height) + " image");
}

namespace {

// The cells a step leaves across the image; the ball's own rule (subsampledSize) on the ball.
void subsample(const SampleGrid& image, int step, int& mw, int& mh) {
  if (image.topology == Topology::Octahedral) {
    mw = mh = subsampledSize(image.width, step);
    return;
  }
  const int least = image.topology == Topology::Torus ? kMinTorusSize : 1;
  if (step < 1 || (step & (step - 1)) != 0 || image.width % step != 0 || image.height % step != 0 ||
      image.width / step < least || image.height / step < least)
    throw Error(
        ErrorKind::InvalidArgument,
        "export step " + std::to_string(step) + " is invalid for a " + std::to_string(image.width) +
            " × " + std::to_string(image.height) + " " + std::string(topologyName(image.topology)) +
            ": use a power of two leaving at least " + std::to_string(least) + " cells each way");
  mw = image.width / step;
  mh = image.height / step;
}

// The sample whose position and normal every copy of s carries.
Sample canonicalOf(const SampleGrid& image, Sample s) {
  return image.topology == Topology::Octahedral ? canonical(image.width, s) : wrap(image, s);
}

// Calls triangle(a, b, c) for the 2·Mw·Mh triangles, counter-clockwise seen from outside, split
// as extractMesh splits them: the ball on the anti-diagonal where (i < M/2) == (j < M/2), the
// torus and plane on every cell's anti-diagonal.
template <class Triangle> void forEachTriangle(const ExportGrid& grid, Triangle&& triangle) {
  const bool ball = grid.image.topology == Topology::Octahedral;
  const int half = grid.mw / 2;
  const auto index = [&](int i, int j) {
    return static_cast<std::uint32_t>(j * (grid.mw + 1) + i);
  };
  for (int j = 0; j < grid.mh; ++j)
    for (int i = 0; i < grid.mw; ++i) {
      const std::uint32_t a = index(i, j), b = index(i + 1, j);
      const std::uint32_t c = index(i + 1, j + 1), d = index(i, j + 1);
      if (!ball || (i < half) == (j < half)) {
        triangle(a, b, d);
        triangle(b, c, d);
      } else {
        triangle(a, b, c);
        triangle(a, c, d);
      }
    }
}

} // namespace

ExportGrid makeExportGrid(const Document& doc, int step) {
  ExportGrid grid;
  grid.image = doc.positions.grid();
  grid.step = step;
  subsample(grid.image, step, grid.mw, grid.mh);
  requireLayer(doc.diffuse, grid.image);
  requireLayer(doc.feature, grid.image);

  const GeometryImage& image = doc.positions;
  std::vector<Vec3f> fullNormals;
  if (step == 1) fullNormals = computeNormals(image); // every sample is exported
  const std::size_t count = grid.vertexCount();
  grid.positions.resize(count);
  grid.normals.resize(count);
  const auto side = static_cast<std::size_t>(image.side());
  for (int j = 0; j <= grid.mh; ++j)
    for (int i = 0; i <= grid.mw; ++i) {
      const Sample c = canonicalOf(grid.image, {i * step, j * step});
      const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(grid.mw + 1) +
                            static_cast<std::size_t>(i);
      grid.positions[k] = image.at(c).xyz();
      Vec3f normal =
          step == 1
              ? fullNormals[static_cast<std::size_t>(c.j) * side + static_cast<std::size_t>(c.i)]
              : vertexNormal(image, c);
      // A degenerate neighbourhood has no normal; glTF requires unit normals, so point it
      // outward from the origin (the base shapes are centred there).
      if (!(std::abs(length(normal) - 1.0f) < 1e-3f)) normal = normalize(image.at(c).xyz());
      if (!(std::abs(length(normal) - 1.0f) < 1e-3f)) normal = {0, 0, 1};
      grid.normals[k] = normal;
    }
  return grid;
}

std::vector<Vec2f> gridTexcoords(const ExportGrid& grid, bool vUp) {
  std::vector<Vec2f> texcoords;
  texcoords.reserve(grid.vertexCount());
  for (int j = 0; j <= grid.mh; ++j)
    for (int i = 0; i <= grid.mw; ++i)
      texcoords.push_back({grid.u(i), vUp ? 1.0f - grid.v(j) : grid.v(j)});
  return texcoords;
}

std::vector<std::array<std::uint32_t, 3>> gridTriangles(const ExportGrid& grid) {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(2 * static_cast<std::size_t>(grid.mw) * static_cast<std::size_t>(grid.mh));
  forEachTriangle(grid, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    triangles.push_back({a, b, c});
  });
  return triangles;
}

std::vector<std::uint32_t> weldedVertices(const ExportGrid& grid, std::uint32_t& weldedCount) {
  std::vector<std::uint32_t> welded(grid.vertexCount());
  const auto k = [&](int i, int j) { return static_cast<std::size_t>(j) * (grid.mw + 1) + i; };
  switch (grid.image.topology) {
  case Topology::Octahedral: {
    const VertexIndex index(grid.image.width, grid.step);
    for (int j = 0; j <= grid.mh; ++j)
      for (int i = 0; i <= grid.mw; ++i)
        welded[k(i, j)] = index.at(i, j);
    weldedCount = index.vertexCount();
    break;
  }
  case Topology::Torus: // extractMesh's numbering: column Mw is column 0, row Mh is row 0
    for (int j = 0; j <= grid.mh; ++j)
      for (int i = 0; i <= grid.mw; ++i)
        welded[k(i, j)] = static_cast<std::uint32_t>((j % grid.mh) * grid.mw + i % grid.mw);
    weldedCount = static_cast<std::uint32_t>(grid.mw * grid.mh);
    break;
  case Topology::Plane:
    for (std::size_t v = 0; v < welded.size(); ++v)
      welded[v] = static_cast<std::uint32_t>(v);
    weldedCount = grid.vertexCount();
    break;
  }
  return welded;
}

} // namespace octaclay::core::detail
