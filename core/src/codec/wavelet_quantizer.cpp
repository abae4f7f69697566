#include "codec/wavelet_quantizer.h"

#include "codec/wavelet_transform.h"
#include "detail/parallel_rows.h"

#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/vec.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace octaclay::core::detail {
namespace {

using Frame = std::array<std::array<float, 3>, 3>; // rows: normal, tangent, tangent

// A slightly wide zero bin (|c| < 0.56 step) and steps that shrink by 0.85 a level towards the
// coarse ones: together 1.5 % fewer bits at 95 dB on armadillo (measured by bench_codecs
// --wavelet-rate; wider zero bins, biased reconstruction and other level factors did worse).
constexpr float kZeroThreshold = 0.56f;
constexpr float kLevelStepFactor = 0.85f;

std::int32_t quantize(float c, float step) {
  const float magnitude = std::min(std::floor(std::abs(c) / step + (1.0f - kZeroThreshold)),
                                   static_cast<float>(kMaxMagnitude - 1));
  const auto m = static_cast<std::int32_t>(magnitude);
  return c < 0 ? -m : m;
}

float dequantize(std::int32_t q, float step) {
  return static_cast<float>(q) * step;
}

// The frame of sample (i, j) at level spacing d on the rebuilt surface: the unit normal of the
// coarse cell holding it (of the two cells it borders when it lies on a cell edge), and two
// tangents, the first across the cell's i direction, the second along it. Aligned with the
// grid, the tangential details (mostly the parameterization's uneven speed along the
// transform's direction) gather in the second; the axes when the cell is degenerate.
Frame frameAt(const std::vector<std::vector<float>>& planes, int n, int d, int i, int j) {
  const int i0 = std::min(i / d * d, n - d), j0 = std::min(j / d * d, n - d);
  const auto w = static_cast<std::size_t>(n) + 1;
  const auto point = [&](int ii, int jj) {
    const std::size_t k = static_cast<std::size_t>(jj) * w + static_cast<std::size_t>(ii);
    return Vec3f{planes[0][k], planes[1][k], planes[2][k]};
  };
  // A cell's normal from its diagonals, unnormalized (larger cells weigh more).
  const auto cellNormal = [&](Vec3f a, Vec3f b, Vec3f c, Vec3f e) { return cross(e - a, c - b); };
  const Vec3f a = point(i0, j0), b = point(i0 + d, j0), c = point(i0, j0 + d),
              e = point(i0 + d, j0 + d);
  Vec3f normal = cellNormal(a, b, c, e);
  // The other cell beside an edge sample (one coordinate a multiple of d, the other not).
  int ci = -1, cj = -1;
  if (i % d == 0 && j % d != 0) {
    ci = i0 == i ? i - d : i;
    cj = j0;
  } else if (j % d == 0 && i % d != 0) {
    ci = i0;
    cj = j0 == j ? j - d : j;
  }
  if (ci >= 0 && cj >= 0 && ci + d <= n && cj + d <= n)
    normal +=
        cellNormal(point(ci, cj), point(ci + d, cj), point(ci, cj + d), point(ci + d, cj + d));
  // Divides rather than core::normalize's multiply by 1/length: the stream's golden bytes depend
  // on the rounding.
  const auto unit = [](Vec3f& v) {
    // A model far from unit size (a cross product of edges 1e13 long) would square past float:
    // a power of two brings it near 1 first, which leaves v / |v| bit for bit as it was.
    const float largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (std::isfinite(largest) && largest > 0 && (largest > 1e15f || largest < 1e-15f)) {
      int exponent = 0;
      std::frexp(largest, &exponent);
      v = {std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent)};
    }
    const float l = length(v);
    if (!(l > 0) || !std::isfinite(l)) return false;
    v = {v.x / l, v.y / l, v.z / l};
    return true;
  };
  const Frame axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  if (!unit(normal)) return axes;
  Vec3f t = cross(normal, (b - a) + (e - c));
  if (!unit(t)) return axes;
  const Vec3f s = cross(normal, t);
  return {{{normal.x, normal.y, normal.z}, {t.x, t.y, t.z}, {s.x, s.y, s.z}}};
}

bool isCanonicalSample(int n, int i, int j) {
  if (i != 0 && i != n && j != 0 && j != n) return true;
  return canonical(n, {i, j}) == Sample{i, j};
}

void setCorners(std::vector<float>& plane, int n, float value) {
  const auto w = static_cast<std::size_t>(n) + 1;
  const auto last = static_cast<std::size_t>(n);
  plane[0] = plane[last] = plane[last * w] = plane[last * w + last] = value;
}

// Copies each canonical sample onto the samples identified with it.
void seamPlane(std::vector<float>& plane, int n) {
  const auto w = static_cast<std::size_t>(n) + 1;
  const auto copyFrom = [&](int i, int j) {
    std::array<Sample, 4> copies;
    const int count = identifiedSamples(n, {i, j}, copies);
    const float value = plane[static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i)];
    for (int k = 1; k < count; ++k) {
      const Sample c = copies[static_cast<std::size_t>(k)];
      plane[static_cast<std::size_t>(c.j) * w + static_cast<std::size_t>(c.i)] = value;
    }
  };
  copyFrom(0, 0);
  for (int t = 1; t < n / 2; ++t) {
    copyFrom(t, 0);
    copyFrom(t, n);
    copyFrom(0, t);
    copyFrom(n, t);
  }
}

} // namespace

void rebuild(CoefficientPlanes& q, std::span<const ChannelCoding> coding,
             std::vector<std::vector<float>>& planes,
             const std::vector<std::vector<float>>* exact) {
  const int n = q.n, channels = q.channels;
  const auto w = static_cast<std::size_t>(n) + 1;
  planes.assign(static_cast<std::size_t>(channels), std::vector<float>(w * w, 0.0f));
  for (int c = 0; c < channels; ++c)
    setCorners(planes[static_cast<std::size_t>(c)], n, coding[static_cast<std::size_t>(c)].dc);
  const bool vector = channels >= kVectorChannels;
  for (int level = waveletLevels(n) - 1; level >= 0; --level) {
    const int s = 1 << level, d = 2 * s;
    const float levelScale = std::pow(kLevelStepFactor, static_cast<float>(level));
    parallelRows(
        n / s + 1,
        [&](int begin, int end) {
          for (int row = begin; row < end; ++row) {
            const int j = row * s;
            const bool oddRow = row % 2 == 1;
            for (int i = oddRow ? 0 : s; i <= n; i += oddRow ? s : d) {
              const bool border = i == 0 || i == n || j == 0 || j == n;
              if (border && !isCanonicalSample(n, i, j)) continue;
              const std::size_t k = static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i);
              std::array<float, 4> values{};
              int c = 0;
              if (vector && exact == nullptr && q.q[0][k] == 0 && q.q[1][k] == 0 &&
                  q.q[2][k] == 0) {
                // A zero vector in any frame; the planes hold zero there already.
                if (channels == kVectorChannels) continue;
                c = 3;
              } else if (vector) {
                const Frame f = frameAt(planes, n, d, i, j);
                std::array<float, 3> rebuilt{0, 0, 0};
                for (int r = 0; r < 3; ++r) {
                  const auto rr = static_cast<std::size_t>(r);
                  std::int32_t& qr = q.q[rr][k];
                  if (exact != nullptr)
                    qr = quantize(f[rr][0] * (*exact)[0][k] + f[rr][1] * (*exact)[1][k] +
                                      f[rr][2] * (*exact)[2][k],
                                  coding[rr].step * levelScale);
                  const float component = dequantize(qr, coding[rr].step * levelScale);
                  for (std::size_t x = 0; x < 3; ++x)
                    rebuilt[x] += component * f[rr][x];
                }
                for (std::size_t x = 0; x < 3; ++x)
                  values[x] = rebuilt[x];
                c = 3;
              }
              for (; c < channels; ++c) {
                const auto cc = static_cast<std::size_t>(c);
                if (exact != nullptr)
                  q.q[cc][k] = quantize((*exact)[cc][k], coding[cc].step * levelScale);
                values[cc] = dequantize(q.q[cc][k], coding[cc].step * levelScale);
              }
              std::array<Sample, 4> copies{Sample{i, j}};
              const int count = border ? identifiedSamples(n, {i, j}, copies) : 1;
              for (int m = 0; m < count; ++m) {
                const Sample at = copies[static_cast<std::size_t>(m)];
                const std::size_t km =
                    static_cast<std::size_t>(at.j) * w + static_cast<std::size_t>(at.i);
                for (int cc = 0; cc < channels; ++cc) {
                  planes[static_cast<std::size_t>(cc)][km] = values[static_cast<std::size_t>(cc)];
                  q.q[static_cast<std::size_t>(cc)][km] = q.q[static_cast<std::size_t>(cc)][k];
                }
              }
            }
          }
        },
        std::max(1, 64 / s));
    for (auto& plane : planes)
      inverseWaveletLevel(plane, n, level);
  }
  for (int c = 0; c < channels; ++c) {
    auto& plane = planes[static_cast<std::size_t>(c)];
    const float centre = coding[static_cast<std::size_t>(c)].centre;
    for (float& v : plane)
      v += centre;
    seamPlane(plane, n);
  }
}

} // namespace octaclay::core::detail
