#include "octaclay/core/document/document_info.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace octaclay::core {
namespace {

// A torus or plane: counts from its extracted mesh (it is as large as the image, and these
// documents are new; the ball's counts follow from its grid below).
DocumentInfo describeGridDocument(const GeometryImage& image) {
  DocumentInfo info;
  info.size = image.size();
  const MeshTopology topology = analyzeTopology(extractMesh(image));
  info.vertices = topology.vertices;
  info.triangles = topology.triangles;
  info.edges = topology.edges;
  info.euler = topology.euler;
  info.degenerateTriangles = topology.degenerateTriangles;
  for (const Vec4f& t : image.texels()) {
    const Vec3f p = t.xyz();
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
      info.bbox.extend(p);
    else
      ++info.nonFinite;
  }
  info.seamGap = maxSeamGap(image);
  const bool whole = info.seamGap == 0.0f && info.nonFinite == 0;
  info.closed = whole && topology.closed();
  info.manifold = whole && topology.manifold() && info.degenerateTriangles == 0;
  return info;
}

// Degenerate triangles among cells [iBegin, iEnd) of the row between here (row j) and next
// (row j+1): a cell's two triangles as cellTriangles() gives them, corners in its order, zero
// area when the cross product's squared length is 0 (length 0, without its square root).
std::uint64_t degenerateInRow(const Vec4f* here, const Vec4f* next, int iBegin, int iEnd,
                              bool antiDiagonal) {
  const auto zeroArea = [](Vec3f a, Vec3f b, Vec3f c) {
    const Vec3f normal = cross(b - a, c - a);
    return std::uint64_t(dot(normal, normal) == 0.0f);
  };
  std::uint64_t count = 0;
  if (antiDiagonal) // CellSplit::AntiDiagonal: {a, b, d}, {b, c, d}
    for (int i = iBegin; i < iEnd; ++i) {
      const Vec3f a = here[i].xyz(), b = here[i + 1].xyz(), c = next[i + 1].xyz(),
                  d = next[i].xyz();
      count += zeroArea(a, b, d) + zeroArea(b, c, d);
    }
  else // {a, b, c}, {a, c, d}
    for (int i = iBegin; i < iEnd; ++i) {
      const Vec3f a = here[i].xyz(), b = here[i + 1].xyz(), c = next[i + 1].xyz(),
                  d = next[i].xyz();
      count += zeroArea(a, b, c) + zeroArea(a, c, d);
    }
  return count;
}

} // namespace

DocumentInfo describeDocument(const Document& document) {
  if (document.positions.topology() != Topology::Octahedral) {
    DocumentInfo info = describeGridDocument(document.positions);
    info.layers = {"positions", document.diffuse.name, document.feature.name};
    if (document.hasMask) info.layers.push_back(document.mask.name);
    return info;
  }
  const GeometryImage& image = document.positions;
  const int n = image.size();
  DocumentInfo info;
  info.size = n;
  const std::uint64_t nn = static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(n);
  info.vertices = nn + 2;
  info.triangles = 2 * nn;
  info.edges = 3 * nn; // every triangle has three edges, each shared by two triangles
  info.euler = static_cast<long long>(info.vertices) - static_cast<long long>(info.edges) +
               static_cast<long long>(info.triangles);

  // One pass on every core: each band's box, non-finite samples and degenerate triangles (a
  // cell's two triangles as cellTriangles() gives them, corners in its order), then merged.
  struct Band {
    BoundingBox box;
    std::uint64_t nonFinite = 0, degenerate = 0;
  };
  std::vector<Band> bands(static_cast<std::size_t>(n + 1));
  detail::parallelRows(n + 1, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j) {
      Band& band = bands[static_cast<std::size_t>(j)];
      // BoundingBox::extend inline, in the same order (signed zeros land as they did).
      const Vec4f* row = &image.at(0, j);
      Vec3f lo{}, hi{};
      bool any = false;
      for (int i = 0; i <= n; ++i) {
        const Vec3f p = row[i].xyz();
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) {
          ++band.nonFinite;
        } else if (!any) {
          lo = hi = p;
          any = true;
        } else {
          lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
          hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        }
      }
      if (any) {
        band.box.extend(lo);
        band.box.extend(hi);
      }
      if (j == n) continue;
      // Row j's cells in two runs, each of one split, so the loop has no branch per cell.
      const Vec4f* next = &image.at(0, j + 1);
      const int half = (n + 1) / 2; // 2i >= n from here on
      const bool lowerHalf = 2 * j >= n;
      band.degenerate += degenerateInRow(row, next, 0, half, !lowerHalf);
      band.degenerate += degenerateInRow(row, next, half, n, lowerHalf);
    }
  });
  std::uint64_t degenerate = 0;
  for (const Band& band : bands) {
    if (!band.box.empty()) {
      info.bbox.extend(band.box.min);
      info.bbox.extend(band.box.max);
    }
    info.nonFinite += band.nonFinite;
    degenerate += band.degenerate;
  }
  info.seamGap = maxSeamGap(image);
  info.degenerateTriangles = degenerate;

  info.closed = info.seamGap == 0.0f && info.nonFinite == 0;
  info.manifold = info.closed && info.degenerateTriangles == 0;
  info.layers = {"positions", document.diffuse.name, document.feature.name};
  if (document.hasMask) info.layers.push_back(document.mask.name);
  return info;
}

} // namespace octaclay::core
