#include "merge/part_layers.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/geometry/vertex_index.h"

#include <algorithm>
#include <array>

namespace octaclay::core::detail {
namespace {

Layer& layerOf(Document& d, int which) {
  return which == 0 ? d.diffuse : which == 1 ? d.feature : d.mask;
}
const Layer& layerOf(const Document& d, int which) {
  return which == 0 ? d.diffuse : which == 1 ? d.feature : d.mask;
}

// Barycentric weights of q (a point of triangle abc) for a, b, c.
std::array<double, 3> barycentric(Vec3d q, Vec3d a, Vec3d b, Vec3d c) {
  const Vec3d v0 = b - a, v1 = c - a, v2 = q - a;
  const double d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1), d20 = dot(v2, v0),
               d21 = dot(v2, v1);
  const double den = d00 * d11 - d01 * d01;
  if (!(den > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3}; // no area: any corner mix is on it
  const double v = std::clamp((d11 * d20 - d01 * d21) / den, 0.0, 1.0);
  const double w = std::clamp((d00 * d21 - d01 * d20) / den, 0.0, 1.0 - v);
  return {1.0 - v - w, v, w};
}

} // namespace

LayerCarrier::LayerCarrier(const PartLocator& parts, Document& merged,
                           std::vector<std::uint16_t>& sourcePart)
    : parts_(parts), merged_(merged), sourcePart_(sourcePart) {
  sourcePart_.clear();
  merged_.hasMask = false;
  for (std::size_t k = 0; k < parts_.size(); ++k)
    merged_.hasMask = merged_.hasMask || parts_.part(k).document->hasMask;
  for (int which = 0; which < 3; ++which) {
    const Layer& first = layerOf(*parts_.part(0).document, which);
    bool same = true;
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      const Layer& l = layerOf(*parts_.part(k).document, which);
      same = same && l.uniform() && l.fill == first.fill;
    }
    Layer& to = layerOf(merged_, which);
    to.texels.clear();
    if (same)
      to.fill = first.fill;
    else
      carried_.push_back(which);
  }
  if (carried_.empty()) return;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const int n = parts_.part(k).document->size();
    std::vector<std::size_t> texels;
    for (const Sample s : VertexIndex(n).canonicalSamples())
      texels.push_back(std::size_t(s.j) * std::size_t(n + 1) + std::size_t(s.i));
    vertexTexel_.push_back(std::move(texels));
  }
  const std::size_t texels = merged_.positions.texelCount();
  sourcePart_.assign(texels, 0);
  for (int which : carried_) {
    Layer& to = layerOf(merged_, which);
    to.texels.assign(texels * std::size_t(to.channels), 0.0f);
  }
}

void LayerCarrier::carry(std::size_t texel, const PartLocator::Found& found) {
  sourcePart_[texel] = std::uint16_t(found.part);
  const PlacedSurface& part = parts_.part(found.part);
  const auto& tri = part.mesh.triangles[found.triangle];
  const std::array<double, 3> w =
      barycentric(found.point, Vec3d(part.mesh.positions[tri[0]]),
                  Vec3d(part.mesh.positions[tri[1]]), Vec3d(part.mesh.positions[tri[2]]));
  for (int which : carried_) {
    const Layer& from = layerOf(*part.document, which);
    Layer& to = layerOf(merged_, which);
    const std::size_t channels = std::size_t(to.channels);
    for (std::size_t ch = 0; ch < channels; ++ch) {
      double value = 0;
      for (std::size_t corner = 0; corner < 3; ++corner)
        value += w[corner] *
                 (from.uniform()
                      ? double(from.fill[ch])
                      : double(from.texels[vertexTexel_[found.part][tri[corner]] * channels + ch]));
      to.texels[texel * channels + ch] = float(value);
    }
  }
}

void carryPartLayers(const PartLocator& parts, Document& merged,
                     std::vector<std::uint16_t>& sourcePart) {
  LayerCarrier carrier(parts, merged, sourcePart);
  if (!carrier.active()) return;
  const int m = merged.size();
  const std::size_t side = std::size_t(m + 1);
  parallelRows(m + 1, [&](int rowBegin, int rowEnd) {
    PartLocator::Cursor cursor = parts.cursor();
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i <= m; ++i)
        carrier.carry(std::size_t(j) * side + std::size_t(i),
                      parts.nearest(Vec3d(merged.positions.at(i, j).xyz()), cursor));
  });
}

} // namespace octaclay::core::detail
