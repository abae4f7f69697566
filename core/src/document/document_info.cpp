#include "octaclay/core/document/document_info.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/geometry/seaming.h"

#include <atomic>
#include <cmath>

namespace octaclay::core {

DocumentInfo describeDocument(const Document& document) {
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

  for (const Vec4f& t : image.texels()) {
    const Vec3f p = t.xyz();
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
      info.bbox.extend(p);
    else
      ++info.nonFinite;
  }
  info.seamGap = maxSeamGap(image);

  std::atomic<std::uint64_t> degenerate{0};
  detail::parallelRows(n, [&](int rowBegin, int rowEnd) {
    std::uint64_t count = 0;
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& tri : cellTriangles(n, i, j)) {
          const Vec3f a = image.at(tri[0]).xyz();
          if (length(cross(image.at(tri[1]).xyz() - a, image.at(tri[2]).xyz() - a)) == 0.0f)
            ++count;
        }
    degenerate += count;
  });
  info.degenerateTriangles = degenerate;

  info.closed = info.seamGap == 0.0f && info.nonFinite == 0;
  info.manifold = info.closed && info.degenerateTriangles == 0;
  info.layers = {"positions", document.diffuse.name, document.feature.name};
  if (document.hasMask) info.layers.push_back(document.mask.name);
  return info;
}

} // namespace octaclay::core
