#pragma once

#include "octaclay/core/geometry/octahedral.h"

#include <cstdint>
#include <vector>

namespace octaclay::core {

/// Unique-vertex numbering of a (possibly subsampled) geometry image: every sample of the
/// (M+1)² grid with M = N/step gets the index of the vertex it is, in [0, M²+2). Canonical
/// samples are numbered in row-major order.
class VertexIndex {
public:
  /// Throws Error(InvalidArgument) unless n is valid and step a power of two with n/step ≥ 2.
  VertexIndex(int n, int step = 1);

  int size() const { return m_; } ///< M, the grid size after subsampling
  int step() const { return step_; }
  std::uint32_t vertexCount() const { return vertexCount_; }
  /// Index of the vertex at subsampled grid position (i, j), 0 ≤ i, j ≤ M.
  std::uint32_t at(int i, int j) const {
    return indices_[static_cast<std::size_t>(j) * static_cast<std::size_t>(m_ + 1) +
                    static_cast<std::size_t>(i)];
  }
  /// For each vertex, its canonical subsampled grid position (row-major order).
  std::vector<Sample> canonicalSamples() const;

private:
  int m_ = 0, step_ = 1;
  std::uint32_t vertexCount_ = 0;
  std::vector<std::uint32_t> indices_;
};

} // namespace octaclay::core
