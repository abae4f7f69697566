#include "detail/finite_rows.h"

#include <cmath>

namespace octaclay::core::detail {

__attribute__((target_clones("avx2", "default"))) int nonFiniteSamples(const Vec4f* row,
                                                                       int count) {
  const float* v = &row[0].x;
  int notFinite = 0;
  for (int i = 0; i < count; ++i)
    notFinite += int(!(std::fabs(v[4 * i]) <= 3.4028235e38f)) |
                 int(!(std::fabs(v[4 * i + 1]) <= 3.4028235e38f)) |
                 int(!(std::fabs(v[4 * i + 2]) <= 3.4028235e38f));
  return notFinite;
}

} // namespace octaclay::core::detail
