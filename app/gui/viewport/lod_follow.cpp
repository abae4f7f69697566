// The live LOD between regenerations: vertices follow their source samples.
#include "lod_follow.h"

#include <algorithm>
#include <cmath>

namespace octaclay::app {

LodFollower::LodFollower(core::LodMesh lod, const core::GeometryImage& source)
    : lod_(std::move(lod)), grid_(source.grid()) {
  const std::size_t vertices = lod_.mesh.positions.size();
  sources_.assign(vertices, core::Sample{});
  sourcePositions_.resize(vertices);
  // Image coordinates are (x / W, y / H) of a full-resolution sample; a seam vertex's copies
  // are identified samples, all at the same position, so any corner names it.
  const auto toSample = [](float c, int cells) {
    return std::clamp(static_cast<int>(std::lround(c * static_cast<float>(cells))), 0, cells);
  };
  for (std::size_t t = 0; t < lod_.mesh.triangles.size() && t < lod_.cornerUv.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) {
      const core::Vec2f uv = lod_.cornerUv[t][k];
      sources_[lod_.mesh.triangles[t][k]] = {toSample(uv.x, grid_.width),
                                             toSample(uv.y, grid_.height)};
    }
  for (std::size_t v = 0; v < vertices; ++v)
    sourcePositions_[v] = source.at(sources_[v]).xyz();
}

core::LodMesh LodFollower::follow(const core::GeometryImage& now) const {
  core::LodMesh moved = lod_;
  if (now.grid() != grid_) return moved;
  for (std::size_t v = 0; v < moved.mesh.positions.size(); ++v)
    moved.mesh.positions[v] += now.at(sources_[v]).xyz() - sourcePositions_[v];
  return moved;
}

} // namespace octaclay::app
