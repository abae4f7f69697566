#include "octaclay/core/geometry/vertex_index.h"

#include "geometry/subsampling.h"

namespace octaclay::core {

VertexIndex::VertexIndex(int n, int step) : m_(detail::subsampledSize(n, step)), step_(step) {
  const std::size_t side = static_cast<std::size_t>(m_) + 1;
  indices_.resize(side * side);
  std::uint32_t next = 0;
  forEachCanonicalRun(m_, [&](int j, int iBegin, int iEnd) {
    std::uint32_t* row = indices_.data() + j * side;
    for (int i = iBegin; i < iEnd; ++i)
      row[i] = next++;
  });
  vertexCount_ = next;
  // The other samples take their canonical sample's index; those all lie on the border.
  for (int k = 0; k <= m_; ++k)
    for (const Sample s : {Sample{k, 0}, Sample{k, m_}, Sample{0, k}, Sample{m_, k}}) {
      const Sample c = canonical(m_, s);
      indices_[s.j * side + s.i] = indices_[c.j * side + c.i];
    }
}

std::vector<Sample> VertexIndex::canonicalSamples() const {
  std::vector<Sample> samples;
  samples.reserve(vertexCount_);
  forEachCanonicalRun(m_, [&](int j, int iBegin, int iEnd) {
    for (int i = iBegin; i < iEnd; ++i)
      samples.push_back({i, j});
  });
  return samples;
}

} // namespace octaclay::core
