#include "octaclay/core/document/document_info.h"

#include "detail/finite_rows.h"
#include "detail/parallel_rows.h"

#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <algorithm>
#include <array>
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

// A row's box over its finite samples, in the order BoundingBox::extend takes them, and how many
// are not finite. Four lanes (x, y, z, w) per sample and four samples a step in vector code when
// every sample is finite. Between 0 and -0 the first one met stays: a zero bound is the axis's
// first zero in the row (the lanes meet their values in another order).
struct RowBox {
  Vec3f lo{}, hi{};
  bool any = false;
  std::uint64_t nonFinite = 0;
};

RowBox rowBoxInOrder(const Vec4f* row, int count) {
  RowBox box;
  for (int i = 0; i < count; ++i) {
    const Vec3f p = row[i].xyz();
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) {
      ++box.nonFinite;
    } else if (!box.any) {
      box.lo = box.hi = p;
      box.any = true;
    } else {
      box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y), std::min(box.lo.z, p.z)};
      box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y), std::max(box.hi.z, p.z)};
    }
  }
  return box;
}

__attribute__((target_clones("avx2", "default"))) RowBox rowBox(const Vec4f* row, int count) {
  const float* v = &row[0].x;
  if (count == 0 || detail::nonFiniteSamples(row, count) > 0) return rowBoxInOrder(row, count);
  std::array<std::array<float, 4>, 4> lo, hi;
  for (auto& l : lo)
    std::copy(v, v + 4, l.begin());
  hi = lo;
  int i = 1;
  for (; i + 4 <= count; i += 4)
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 4; ++c) {
        const float x = v[4 * (i + k) + c];
        lo[k][c] = x < lo[k][c] ? x : lo[k][c];
        hi[k][c] = hi[k][c] < x ? x : hi[k][c];
      }
  for (; i < count; ++i)
    for (int c = 0; c < 4; ++c) {
      const float x = v[4 * i + c];
      lo[0][c] = x < lo[0][c] ? x : lo[0][c];
      hi[0][c] = hi[0][c] < x ? x : hi[0][c];
    }
  RowBox box;
  box.any = true;
  box.lo = {lo[0][0], lo[0][1], lo[0][2]};
  box.hi = {hi[0][0], hi[0][1], hi[0][2]};
  for (int k = 1; k < 4; ++k) {
    box.lo = {std::min(box.lo.x, lo[k][0]), std::min(box.lo.y, lo[k][1]),
              std::min(box.lo.z, lo[k][2])};
    box.hi = {std::max(box.hi.x, hi[k][0]), std::max(box.hi.y, hi[k][1]),
              std::max(box.hi.z, hi[k][2])};
  }
  // A zero bound: the first ±0 of that axis met in order (every value before it lay beyond).
  const auto firstZero = [&](int c) {
    for (int k = 0; k < count; ++k)
      if (v[4 * k + c] == 0.0f) return v[4 * k + c];
    return 0.0f;
  };
  for (int c = 0; c < 3; ++c) {
    float& low = c == 0 ? box.lo.x : c == 1 ? box.lo.y : box.lo.z;
    float& high = c == 0 ? box.hi.x : c == 1 ? box.hi.y : box.hi.z;
    if (low == 0.0f) low = firstZero(c);
    if (high == 0.0f) high = firstZero(c);
  }
  return box;
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
      const Vec4f* row = &image.at(0, j);
      const RowBox rowBounds = rowBox(row, n + 1);
      band.nonFinite += rowBounds.nonFinite;
      if (rowBounds.any) {
        band.box.extend(rowBounds.lo);
        band.box.extend(rowBounds.hi);
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
