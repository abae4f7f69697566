#include "octaclay/core/measure/brush_sampling.h"

#include <algorithm>
#include <cmath>

namespace octaclay::core {

BrushSampling brushSampling(const GeometryImage& image, Vec2f uv, double radius) {
  constexpr int kRing = 2;
  const int n = image.size();
  const auto nearest = [n](float t) {
    return std::clamp(static_cast<int>(std::lround(std::clamp(t, 0.0f, 1.0f) * float(n))), 0, n);
  };
  const Sample centre{nearest(uv.x), nearest(uv.y)};
  BrushSampling out;
  for (int dj = -kRing; dj <= kRing; ++dj)
    for (int di = -kRing; di <= kRing; ++di) {
      const Sample s{centre.i + di, centre.j + dj};
      const Vec3f p = image.positionWrapped(s);
      for (const Sample d : {Sample{1, 0}, Sample{0, 1}}) {
        const double edge = double(length(image.positionWrapped({s.i + d.i, s.j + d.j}) - p));
        if (std::isfinite(edge)) out.longestEdge = std::max(out.longestEdge, edge);
      }
    }
  if (out.longestEdge > 0) out.samplesAcross = std::max(0.0, radius) / out.longestEdge;
  return out;
}

} // namespace octaclay::core
