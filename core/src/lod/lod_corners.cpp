#include "lod/lod_corners.h"

#include <algorithm>
#include <utility>

namespace octaclay::core::detail {
namespace {

float squaredDistance(Vec2f a, Vec2f b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

} // namespace

std::array<Vec2f, 3> cornerCoordinates(const std::array<std::uint32_t, 3>& tri,
                                       const std::vector<VertexCopies>& copies) {
  const VertexCopies &a = copies[tri[0]], &b = copies[tri[1]], &c = copies[tri[2]];
  std::array<Vec2f, 3> best{a.uv[0], b.uv[0], c.uv[0]};
  if (a.count == 1 && b.count == 1 && c.count == 1) return best;
  float bestSpread = -1;
  for (int ia = 0; ia < a.count; ++ia)
    for (int ib = 0; ib < b.count; ++ib)
      for (int ic = 0; ic < c.count; ++ic) {
        const float spread = squaredDistance(a.uv[ia], b.uv[ib]) +
                             squaredDistance(b.uv[ib], c.uv[ic]) +
                             squaredDistance(c.uv[ic], a.uv[ia]);
        if (bestSpread < 0 || spread < bestSpread) {
          bestSpread = spread;
          best = {a.uv[ia], b.uv[ib], c.uv[ic]};
        }
      }
  return best;
}

VertexCollapseOptions collapseOptionsFor(const LodOptions& options,
                                         const std::vector<VertexCopies>& copies,
                                         bool normalTurnPerCollapse,
                                         std::vector<float> vertexWeights) {
  VertexCollapseOptions collapseOptions;
  collapseOptions.targetTriangles = options.targetTriangles;
  collapseOptions.maxError = options.maxError;
  collapseOptions.engine = options.collapseEngine;
  collapseOptions.maxNormalTurnDegrees = options.maxNormalTurnDegrees;
  collapseOptions.maxAspectRatio = options.maxAspectRatio;
  collapseOptions.normalTurnPerCollapse = normalTurnPerCollapse;
  collapseOptions.vertexWeights = std::move(vertexWeights);
  collapseOptions.cornerCoordinates = [&copies](const std::array<std::uint32_t, 3>& tri) {
    return cornerCoordinates(tri, copies);
  };
  return collapseOptions;
}

void takeCollapsed(LodMesh& lod, CollapsedMesh collapsed, const std::vector<VertexCopies>& copies) {
  lod.mesh = std::move(collapsed.mesh);
  std::vector<VertexCopies> kept(collapsed.inputVertex.size());
  for (std::size_t v = 0; v < kept.size(); ++v)
    kept[v] = copies[collapsed.inputVertex[v]];
  setCornerCoordinates(lod, kept);
}

void setCornerCoordinates(LodMesh& lod, const std::vector<VertexCopies>& copies) {
  lod.cornerUv.resize(lod.mesh.triangles.size());
  for (std::size_t t = 0; t < lod.mesh.triangles.size(); ++t)
    lod.cornerUv[t] = cornerCoordinates(lod.mesh.triangles[t], copies);
}

std::vector<float> saliencyWeights(const GeometryImage& image, const std::vector<Sample>& sampleOf,
                                   float weight) {
  if (weight == 0 || std::all_of(image.texels().begin(), image.texels().end(),
                                 [](const Vec4f& t) { return t.w == 0; }))
    return {};
  std::vector<float> weights(sampleOf.size());
  for (std::size_t v = 0; v < sampleOf.size(); ++v)
    weights[v] = 1 + weight * image.at(sampleOf[v].i, sampleOf[v].j).w;
  return weights;
}

// Two Jacobi steps: +4 dB over none at 1 % of 2N², a third adds under 0.2 dB. Where a triangle
// covers under 4 samples (over 25 % of 2N²) the second adds under 0.05 dB for a quarter of the
// LOD's time (the sculpted sphere at 25 %; bench_lod).
int refitIterations(double cells, std::size_t triangles) {
  return 2.0 * cells < 4.0 * double(triangles) ? 1 : 2;
}

// The refit reads every stride-th sample: about 16 per LOD triangle or more (the fit is a
// mean over each triangle, a few samples estimate it well).
int refitStride(double cells, std::size_t triangles) {
  int stride = 1;
  while (2.0 * cells / (4.0 * stride * stride) >= 16.0 * double(triangles))
    stride *= 2;
  return stride;
}

} // namespace octaclay::core::detail
