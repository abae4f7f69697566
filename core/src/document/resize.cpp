#include "octaclay/core/document/resize.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core {
namespace {

// The Catmull-Rom kernel (a = -1/2): 1 at 0, 0 at the other integers, support (-2, 2).
double catmullRom(double x) {
  x = std::abs(x);
  if (x < 1) return (1.5 * x - 2.5) * x * x + 1;
  if (x < 2) return ((-0.5 * x + 2.5) * x - 4) * x + 2;
  return 0;
}

// One axis's taps: the old sample offsets from a base position and their weights.
struct Taps {
  int base = 0;
  std::vector<double> weights; // for base, base + 1, …
};

// The taps for new sample k of an m grid from an n grid along one axis.
Taps tapsFor(int k, int n, int m) {
  Taps t;
  if (m >= n) { // interpolate at k·n/m
    const int r = m / n;
    const int whole = k / r;
    const double frac = double(k % r) / double(r);
    t.base = whole - 1;
    for (int a = -1; a <= 2; ++a)
      t.weights.push_back(catmullRom(double(a) - frac));
  } else { // filter around k·r with the kernel widened r times
    const int r = n / m;
    t.base = k * r - (2 * r - 1);
    double sum = 0;
    for (int d = -(2 * r - 1); d <= 2 * r - 1; ++d) {
      t.weights.push_back(catmullRom(double(d) / double(r)));
      sum += t.weights.back();
    }
    for (double& w : t.weights)
      w /= sum;
  }
  return t;
}

// Resamples a field of `channels` floats per sample of an n grid, read by value(sample, out),
// into (m+1)² × channels floats; clamp: each channel kept within the values of the taps that
// carry weight (no overshoot).
template <class Value>
std::vector<float> resampleField(int n, int m, int channels, bool clamp, const Value& value) {
  const std::size_t side = static_cast<std::size_t>(m + 1), ch = static_cast<std::size_t>(channels);
  std::vector<Taps> taps;
  for (int k = 0; k <= m; ++k)
    taps.push_back(tapsFor(k, n, m));
  std::vector<float> out(side * side * ch);
  detail::parallelRows(m + 1, [&](int rowBegin, int rowEnd) {
    std::array<float, 4> v{};
    std::array<double, 4> sum{}, lo{}, hi{};
    for (int j = rowBegin; j < rowEnd; ++j) {
      const Taps& ty = taps[static_cast<std::size_t>(j)];
      // Only the samples on the grid's canonical positions matter; the rest are copied below.
      for (int i = 0; i <= m; ++i) {
        const Taps& tx = taps[static_cast<std::size_t>(i)];
        sum.fill(0);
        lo.fill(1e300);
        hi.fill(-1e300);
        for (std::size_t b = 0; b < ty.weights.size(); ++b) {
          if (ty.weights[b] == 0) continue;
          for (std::size_t a = 0; a < tx.weights.size(); ++a) {
            const double w = tx.weights[a] * ty.weights[b];
            if (w == 0) continue;
            value(wrap(n, {tx.base + int(a), ty.base + int(b)}), v.data());
            for (std::size_t c = 0; c < ch; ++c) {
              sum[c] += w * double(v[c]);
              lo[c] = std::min(lo[c], double(v[c]));
              hi[c] = std::max(hi[c], double(v[c]));
            }
          }
        }
        float* o = &out[(static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)) * ch];
        for (std::size_t c = 0; c < ch; ++c)
          o[c] = static_cast<float>(clamp ? std::clamp(sum[c], lo[c], hi[c]) : sum[c]);
      }
    }
  });
  // Identified samples: the canonical one's bits.
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) {
      const Sample c = canonical(m, {i, j});
      if (c == Sample{i, j}) continue;
      std::copy_n(&out[(static_cast<std::size_t>(c.j) * side + static_cast<std::size_t>(c.i)) * ch],
                  ch,
                  &out[(static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)) * ch]);
    }
  return out;
}

void resizeLayer(const Layer& from, Layer& to, int n, int m) {
  to = from;
  if (from.uniform()) return;
  const std::size_t side = static_cast<std::size_t>(n + 1),
                    ch = static_cast<std::size_t>(from.channels);
  to.texels = resampleField(n, m, from.channels, true, [&](Sample s, float* v) {
    const float* t =
        &from.texels[(static_cast<std::size_t>(s.j) * side + static_cast<std::size_t>(s.i)) * ch];
    std::copy_n(t, ch, v);
  });
}

} // namespace

Document resizeDocument(const Document& document, int m) {
  requireValidSize(m);
  if (const auto problem = positionsProblem(document.positions))
    throw Error(ErrorKind::InvalidInput,
                *problem + "; the document is damaged and cannot be resized");
  const int n = document.size();
  if (m == n) return document;
  Document out = document;
  out.positions = GeometryImage(m);
  const std::vector<float> positions = resampleField(n, m, 4, false, [&](Sample s, float* v) {
    const Vec4f& p = document.positions.at(s);
    v[0] = p.x, v[1] = p.y, v[2] = p.z, v[3] = p.w;
  });
  std::span<Vec4f> texels = out.positions.texels();
  for (std::size_t t = 0; t < texels.size(); ++t)
    texels[t] = {positions[4 * t], positions[4 * t + 1], positions[4 * t + 2],
                 positions[4 * t + 3]};
  resizeLayer(document.diffuse, out.diffuse, n, m);
  resizeLayer(document.feature, out.feature, n, m);
  resizeLayer(document.mask, out.mask, n, m);
  return out;
}

} // namespace octaclay::core
