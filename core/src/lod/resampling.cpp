// Resampling the position image to an (M+1)² grid (lod.h). Each LOD sample (a, b) stands for
// the full-resolution footprint centred on (a·s, b·s), s = N/M, half-width s/2, read through
// wrap(). The tiling's half-turns map LOD grid points to LOD grid points and footprints onto
// footprints, so identified LOD samples have the same footprint; each vertex is computed once
// at its canonical sample and copied to the others, then seam() is run as the thesis does.
#include "lod/resampling.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/seaming.h"

#include <algorithm>
#include <string>

namespace octaclay::core::detail {
namespace {

bool isCone(int m, Sample s) {
  return s == Sample{0, 0} || s == Sample{m / 2, 0} || s == Sample{0, m / 2} ||
         s == Sample{m, m / 2} || s == Sample{m / 2, m};
}

struct Choice {
  Vec4f texel;
  Sample source; // full-resolution grid sample (point methods) or footprint centre
};

// Box filter over the closed footprint: weight 1 inside, 1/2 on its rim rows and columns,
// so neighbouring footprints' weights sum to one everywhere.
Choice averageFootprint(const GeometryImage& image, Sample centre, int half, bool salient) {
  const int n = image.size();
  const bool inside =
      centre.i - half >= 0 && centre.i + half <= n && centre.j - half >= 0 && centre.j + half <= n;
  return {footprintMean(centre, half, half, salient,
                        [&](Sample s) -> const Vec4f& {
                          return inside ? image.at(s) : image.at(wrap(n, s));
                        }),
          centre};
}

// The most salient sample within s/4 of the centre (ties keep the one nearest the
// centre, then the first in row order). The reach of s/4 keeps every LOD triangle positively
// oriented in the image whatever its corners choose (a corner would have to move more than s/4
// towards the opposite diagonal to fold it), where the whole footprint (s/2) could fold them.
// LOD samples on a seam choose along the seam only, so that the vertex stays on the seam; the
// octahedron's cone points keep their own sample.
Choice salientFootprint(const GeometryImage& image, int m, Sample lod, Sample centre, int step) {
  Choice best{image.at(centre), centre};
  if (isCone(m, lod)) return best;
  const int reach = step / 4;
  const bool onSeamI = lod.i == 0 || lod.i == m; // a vertical seam: move along j
  const bool onSeamJ = lod.j == 0 || lod.j == m;
  int bestDistance = 0;
  for (int dj = -reach; dj <= reach; ++dj)
    for (int di = -reach; di <= reach; ++di) {
      if ((onSeamI && di != 0) || (onSeamJ && dj != 0)) continue;
      const Sample s{centre.i + di, centre.j + dj};
      const Vec4f& t = image.at(s); // open footprints of non-cone samples stay in the grid
      const int distance = di * di + dj * dj;
      if (t.w > best.texel.w || (t.w == best.texel.w && distance < bestDistance)) {
        best = {t, s};
        bestDistance = distance;
      }
    }
  return best;
}

// The copy of full-resolution sample `source` that lies nearest to `target` in the image.
Sample nearestCopy(int n, Sample source, Sample target) {
  std::array<Sample, 4> copies;
  const int count = identifiedSamples(n, source, copies);
  Sample best = copies[0];
  long long bestDistance = -1;
  for (int k = 0; k < count; ++k) {
    const long long di = copies[k].i - target.i, dj = copies[k].j - target.j;
    const long long d = di * di + dj * dj;
    if (bestDistance < 0 || d < bestDistance) {
      bestDistance = d;
      best = copies[k];
    }
  }
  return best;
}

} // namespace

void requireLodSize(int n, int m) {
  if (m < kMinSize || (m & (m - 1)) != 0)
    throw Error(ErrorKind::InvalidArgument, "LOD size " + std::to_string(m) +
                                                " is not a power of two of at least 2; use e.g. " +
                                                std::to_string(std::max(2, n / 4)));
  if (m >= n)
    throw Error(ErrorKind::InvalidArgument,
                "LOD size " + std::to_string(m) + " must be smaller than the image size " +
                    std::to_string(n) + "; use at most " + std::to_string(n / 2));
}

ResampledImage resampleWithSources(const GeometryImage& image, int m, ResampleMethod method) {
  const int n = image.size();
  requireLodSize(n, m);
  const int step = n / m, half = step / 2;
  ResampledImage out{GeometryImage(m), {}};
  const int side = m + 1;
  out.source.resize(static_cast<std::size_t>(side) * side);
  const bool salient = method == ResampleMethod::SalientAverage;

  parallelRows(
      side,
      [&](int rowBegin, int rowEnd) {
        for (int b = rowBegin; b < rowEnd; ++b)
          for (int a = 0; a < side; ++a) {
            const Sample lod{a, b};
            if (canonical(m, lod) != lod) continue;
            const Sample centre{a * step, b * step};
            Choice c;
            switch (method) {
            case ResampleMethod::Point:
              c = {image.at(centre), centre};
              break;
            case ResampleMethod::Average:
            case ResampleMethod::SalientAverage:
              c = averageFootprint(image, centre, half, salient);
              break;
            case ResampleMethod::SalientPoint:
            case ResampleMethod::Adaptive: // never here: generateLod and resampleImage divert them
            case ResampleMethod::Collapse:
            case ResampleMethod::Auto:
              c = salientFootprint(image, m, lod, centre, step);
              break;
            }
            out.image.at(lod) = c.texel;
            out.source[static_cast<std::size_t>(b) * side + a] =
                Vec2f{float(c.source.i), float(c.source.j)};
          }
      },
      32);

  // Identified LOD samples: the canonical one's texel; the source copy on their side.
  for (int k = 0; k <= m; ++k)
    for (const Sample s : {Sample{k, 0}, Sample{k, m}, Sample{0, k}, Sample{m, k}}) {
      const Sample c = canonical(m, s);
      if (c == s) continue;
      out.image.at(s) = out.image.at(c);
      const Vec2f src = out.source[static_cast<std::size_t>(c.j) * side + c.i];
      const Sample copy = nearestCopy(n, {int(src.x), int(src.y)}, {s.i * step, s.j * step});
      out.source[static_cast<std::size_t>(s.j) * side + s.i] = {float(copy.i), float(copy.j)};
    }
  seam(out.image);
  return out;
}

} // namespace octaclay::core::detail
