#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/sample_grid.h"
#include "octaclay/core/geometry/tile_bounds.h"
#include "octaclay/core/geometry/vec.h"

#include <cstdint>
#include <span>
#include <vector>

namespace octaclay::gpu::detail {

// The displayed level cut into square chunks of cells, each with a bounding sphere and a cone
// bounding its triangles' normals, so whole chunks facing away from the eye are skipped before
// the rasterizer sets their triangles up (based on: Shirman & Abi-Ezzi 1993, normal cones; the
// sphere-cone test as in meshoptimizer's meshopt_computeClusterBounds).
class ModelChunks {
public:
  static constexpr int kCells = 16; // chunk side, in displayed cells

  // The level of an N-image every step samples: m = N/step cells a side.
  void reset(int n, int step);
  // The level of a W × H image every step samples: W/step × H/step cells, split as the grid's
  // topology splits them (the ball along its octahedron's faces, a torus or plane along every
  // cell's anti-diagonal). A plane is seen from both sides: its chunks are never culled.
  void reset(const core::SampleGrid& grid, int step);
  // Triangle indices in chunk order (chunk k's triangles are [first(k), first(k) + count(k))).
  std::vector<std::uint32_t> indices() const;
  // Recomputes the cones of chunks overlapping rects (texel rectangles), or all when empty.
  void update(const core::GeometryImage& image, std::span<const core::TexelRect> rects = {});
  // Index ranges (offset, count in indices) of the chunks not wholly facing away from eye,
  // consecutive chunks merged.
  void visibleRanges(core::Vec3f eye, std::vector<std::intptr_t>& offsets,
                     std::vector<int>& counts) const;
  int chunkCount() const { return chunksX_ * chunksY_; }

private:
  struct Chunk {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0; // cells [x0, x1) × [y0, y1)
    core::Vec3f centre, axis;
    float radius = 0;
    float cutoff = 2; // sin of the normals' spread; > 1 never culls
    int first = 0, count = 0;
  };
  void computeCone(const core::GeometryImage& image, Chunk& chunk) const;

  // The ball's split (along the octahedron's faces), else every cell's anti-diagonal.
  bool antiDiagonal(int i, int j) const;

  int m_ = 0, mh_ = 0, step_ = 1, chunksX_ = 0, chunksY_ = 0;
  core::Topology topology_ = core::Topology::Octahedral;
  std::vector<Chunk> chunks_;
};

} // namespace octaclay::gpu::detail
