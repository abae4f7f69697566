#include "model_chunks.h"

#include <algorithm>
#include <cmath>

namespace octaclay::gpu::detail {

bool ModelChunks::antiDiagonal(int i, int j) const {
  // core::extractMesh's split: on the ball diagonals follow the octahedron's faces.
  return topology_ != core::Topology::Octahedral || (i < m_ / 2) == (j < m_ / 2);
}

void ModelChunks::reset(int n, int step) {
  reset(core::SampleGrid{core::Topology::Octahedral, n, n}, step);
}

void ModelChunks::reset(const core::SampleGrid& grid, int step) {
  m_ = grid.width / step;
  mh_ = grid.height / step;
  step_ = step;
  topology_ = grid.topology;
  chunksX_ = (m_ + kCells - 1) / kCells;
  chunksY_ = (mh_ + kCells - 1) / kCells;
  chunks_.assign(static_cast<std::size_t>(chunksX_) * chunksY_, {});
  int first = 0;
  for (int cy = 0; cy < chunksY_; ++cy)
    for (int cx = 0; cx < chunksX_; ++cx) {
      Chunk& c = chunks_[static_cast<std::size_t>(cy * chunksX_ + cx)];
      c.x0 = cx * kCells;
      c.y0 = cy * kCells;
      c.x1 = std::min(m_, c.x0 + kCells);
      c.y1 = std::min(mh_, c.y0 + kCells);
      c.first = first;
      c.count = 6 * (c.x1 - c.x0) * (c.y1 - c.y0);
      first += c.count;
    }
}

std::vector<std::uint32_t> ModelChunks::indices() const {
  std::vector<std::uint32_t> out;
  out.reserve(6 * static_cast<std::size_t>(m_) * static_cast<std::size_t>(mh_));
  const int m = m_;
  auto at = [m](int i, int j) { return static_cast<std::uint32_t>(j * (m + 1) + i); };
  for (const Chunk& c : chunks_)
    for (int j = c.y0; j < c.y1; ++j)
      for (int i = c.x0; i < c.x1; ++i) {
        const std::uint32_t a = at(i, j), b = at(i + 1, j), cc = at(i + 1, j + 1), d = at(i, j + 1);
        if (antiDiagonal(i, j))
          out.insert(out.end(), {a, b, d, b, cc, d});
        else
          out.insert(out.end(), {a, b, cc, a, cc, d});
      }
  return out;
}

void ModelChunks::computeCone(const core::GeometryImage& image, Chunk& c) const {
  auto p = [&](int i, int j) { return image.at(i * step_, j * step_).xyz(); };
  core::BoundingBox box;
  for (int j = c.y0; j <= c.y1; ++j)
    for (int i = c.x0; i <= c.x1; ++i)
      box.extend(p(i, j));
  c.centre = (box.min + box.max) * 0.5f;
  c.radius = 0;
  for (int j = c.y0; j <= c.y1; ++j)
    for (int i = c.x0; i <= c.x1; ++i)
      c.radius = std::max(c.radius, core::length(p(i, j) - c.centre));

  std::vector<core::Vec3f> normals;
  normals.reserve(static_cast<std::size_t>(2 * (c.x1 - c.x0) * (c.y1 - c.y0)));
  core::Vec3f sum{};
  auto add = [&](core::Vec3f a, core::Vec3f b, core::Vec3f d) {
    const core::Vec3f n = core::cross(b - a, d - a);
    const float len = core::length(n);
    if (!(len > 0)) return; // degenerate: faces nowhere
    normals.push_back(n * (1 / len));
    sum = sum + normals.back();
  };
  for (int j = c.y0; j < c.y1; ++j)
    for (int i = c.x0; i < c.x1; ++i) {
      const core::Vec3f a = p(i, j), b = p(i + 1, j), cc = p(i + 1, j + 1), d = p(i, j + 1);
      if (antiDiagonal(i, j)) {
        add(a, b, d);
        add(b, cc, d);
      } else {
        add(a, b, cc);
        add(a, cc, d);
      }
    }
  c.cutoff = 2;
  if (topology_ == core::Topology::Plane) return; // an open sheet: both sides are seen
  const float sumLength = core::length(sum);
  if (normals.empty() || !(sumLength > 1e-12f)) return;
  c.axis = sum * (1 / sumLength);
  float minCos = 1;
  for (const core::Vec3f& n : normals)
    minCos = std::min(minCos, core::dot(n, c.axis));
  // Normals within angle α of the axis all face away from every eye direction within 90° - α.
  if (minCos > 0) c.cutoff = std::sqrt(std::max(0.0f, 1 - minCos * minCos));
}

void ModelChunks::update(const core::GeometryImage& image, std::span<const core::TexelRect> rects) {
  for (Chunk& c : chunks_) {
    bool touched = rects.empty();
    // A chunk's cells span texels [x0·step, x1·step]; a changed texel on its edge counts.
    for (const core::TexelRect& r : rects)
      touched = touched || (r.x <= c.x1 * step_ && r.x + r.width > c.x0 * step_ &&
                            r.y <= c.y1 * step_ && r.y + r.height > c.y0 * step_);
    if (touched) computeCone(image, c);
  }
}

void ModelChunks::visibleRanges(core::Vec3f eye, std::vector<std::intptr_t>& offsets,
                                std::vector<int>& counts) const {
  offsets.clear();
  counts.clear();
  int runStart = -1, runCount = 0;
  for (const Chunk& c : chunks_) {
    const core::Vec3f toChunk = c.centre - eye;
    const bool backFacing =
        c.cutoff <= 1 && core::dot(toChunk, c.axis) >= c.cutoff * core::length(toChunk) + c.radius;
    if (backFacing || c.count == 0) continue;
    if (runStart >= 0 && runStart + runCount == c.first) {
      runCount += c.count;
      continue;
    }
    if (runStart >= 0) {
      offsets.push_back(static_cast<std::intptr_t>(runStart) * 4);
      counts.push_back(runCount);
    }
    runStart = c.first;
    runCount = c.count;
  }
  if (runStart >= 0) {
    offsets.push_back(static_cast<std::intptr_t>(runStart) * 4);
    counts.push_back(runCount);
  }
}

} // namespace octaclay::gpu::detail
