#include "octaclay/core/vertex_index.h"

#include "detail/subsampling.h"

namespace octaclay::core {

// Canonical samples come before the samples identified with them in row-major order (see
// canonical()), so one pass numbers every sample.
VertexIndex::VertexIndex(int n, int step) : m_(detail::subsampledSize(n, step)), step_(step) {
  const std::size_t side = static_cast<std::size_t>(m_) + 1;
  indices_.resize(side * side);
  std::uint32_t next = 0;
  for (int j = 0; j <= m_; ++j)
    for (int i = 0; i <= m_; ++i) {
      const Sample c = canonical(m_, {i, j});
      indices_[j * side + i] = c == Sample{i, j} ? next++ : at(c.i, c.j);
    }
  vertexCount_ = next;
}

std::vector<Sample> VertexIndex::canonicalSamples() const {
  std::vector<Sample> samples;
  samples.reserve(vertexCount_);
  for (int j = 0; j <= m_; ++j)
    for (int i = 0; i <= m_; ++i)
      if (canonical(m_, {i, j}) == Sample{i, j}) samples.push_back({i, j});
  return samples;
}

} // namespace octaclay::core
