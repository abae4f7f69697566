#include "codec/wavelet_transform.h"

#include "detail/parallel_rows.h"

#include <bit>
#include <cstddef>

namespace octaclay::core::detail {
namespace {

// CDF 9/7 lifting coefficients (Daubechies & Sweldens); the scaling makes the low-pass DC gain
// √2, so the 2-D transform is close to orthonormal and one quantizer step suits every band.
constexpr float kAlpha = -1.586134342f;
constexpr float kBeta = -0.05298011854f;
constexpr float kGamma = 0.8829110762f;
constexpr float kDelta = 0.4435068522f;
constexpr float kScale = 1.149604398f;

struct Plane {
  float* data;
  int n;
  float* row(int j) const {
    return data + static_cast<std::size_t>(j) * static_cast<std::size_t>(n + 1);
  }
};

// One lifting step along row j at spacing s: targets (odd or even multiples of s) gain
// c·(left + right). Beyond the row's ends the tiling continues in row N − j, reversed:
// (−s, j) is (s, N − j) and (N + s, j) is (N − s, N − j). Sums are written left + right for
// both a sample and its mirror image, so identified samples stay bit-equal.
void liftRow(const Plane& p, int j, int s, float c, bool oddTargets) {
  float* row = p.row(j);
  const float* mirror = p.row(p.n - j);
  const int n = p.n;
  if (oddTargets) {
    for (int i = s; i < n; i += 2 * s)
      row[i] += c * (row[i - s] + row[i + s]);
    return;
  }
  row[0] += c * (mirror[s] + row[s]);
  for (int i = 2 * s; i < n; i += 2 * s)
    row[i] += c * (row[i - s] + row[i + s]);
  row[n] += c * (row[n - s] + mirror[n - s]);
}

void scaleRow(const Plane& p, int j, int s, float even, float odd) {
  float* row = p.row(j);
  for (int i = 0; i <= p.n; i += 2 * s)
    row[i] *= even;
  for (int i = s; i < p.n; i += 2 * s)
    row[i] *= odd;
}

// Rows j and N − j depend on each other at their ends: lift them together, step by step.
template <class Steps> void forEachRowPair(const Plane& p, int s, Steps&& steps) {
  const int rows = p.n / s + 1; // multiples of s
  const int pairs = (rows + 1) / 2;
  parallelRows(
      pairs,
      [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
          const int j = k * s;
          steps(j, p.n - j);
        }
      },
      std::max(1, 128 / s));
}

void rowPass(const Plane& p, int s, bool forward) {
  forEachRowPair(p, s, [&](int j, int mirror) {
    const auto step = [&](float c, bool odd) {
      liftRow(p, j, s, c, odd);
      if (mirror != j) liftRow(p, mirror, s, c, odd);
    };
    const auto scale = [&](float even, float odd) {
      scaleRow(p, j, s, even, odd);
      if (mirror != j) scaleRow(p, mirror, s, even, odd);
    };
    if (forward) {
      step(kAlpha, true);
      step(kBeta, false);
      step(kGamma, true);
      step(kDelta, false);
      scale(kScale, 1 / kScale);
    } else {
      scale(1 / kScale, kScale);
      step(-kDelta, false);
      step(-kGamma, true);
      step(-kBeta, false);
      step(-kAlpha, true);
    }
  });
}

// One lifting step down the columns at spacing s, done a row at a time: target rows (odd or
// even multiples of s) gain c·(row above + row below). Above row 0 lies row s reversed
// ((i, −s) is (N − i, s)); below row N lies row N − s reversed.
void columnStep(const Plane& p, int s, float c, bool oddTargets) {
  const int n = p.n;
  const int first = oddTargets ? s : 0;
  const int count = oddTargets ? n / (2 * s) : n / (2 * s) + 1;
  parallelRows(
      count,
      [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
          const int j = first + 2 * s * k;
          float* row = p.row(j);
          if (j == 0 || j == n) {
            const float* inner = p.row(j == 0 ? s : n - s);
            for (int i = 0; i <= n; i += s)
              row[i] += c * (inner[n - i] + inner[i]);
            continue;
          }
          const float* above = p.row(j - s);
          const float* below = p.row(j + s);
          if (s == 1) {
            for (int i = 0; i <= n; ++i)
              row[i] += c * (above[i] + below[i]);
          } else {
            for (int i = 0; i <= n; i += s)
              row[i] += c * (above[i] + below[i]);
          }
        }
      },
      std::max(1, 128 / s));
}

void columnScale(const Plane& p, int s, float even, float odd) {
  const int count = p.n / s + 1;
  parallelRows(
      count,
      [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
          float* row = p.row(k * s);
          const float factor = k % 2 == 0 ? even : odd;
          for (int i = 0; i <= p.n; i += s)
            row[i] *= factor;
        }
      },
      std::max(1, 128 / s));
}

void columnPass(const Plane& p, int s, bool forward) {
  if (forward) {
    columnStep(p, s, kAlpha, true);
    columnStep(p, s, kBeta, false);
    columnStep(p, s, kGamma, true);
    columnStep(p, s, kDelta, false);
    columnScale(p, s, kScale, 1 / kScale);
  } else {
    columnScale(p, s, 1 / kScale, kScale);
    columnStep(p, s, -kDelta, false);
    columnStep(p, s, -kGamma, true);
    columnStep(p, s, -kBeta, false);
    columnStep(p, s, -kAlpha, true);
  }
}

} // namespace

int waveletLevels(int n) {
  return std::countr_zero(static_cast<unsigned>(n));
}

void forwardWavelet(std::span<float> plane, int n) {
  const Plane p{plane.data(), n};
  for (int level = 0; level < waveletLevels(n); ++level) {
    rowPass(p, 1 << level, true);
    columnPass(p, 1 << level, true);
  }
}

void inverseWaveletLevel(std::span<float> plane, int n, int level) {
  const Plane p{plane.data(), n};
  columnPass(p, 1 << level, false);
  rowPass(p, 1 << level, false);
}

void inverseWavelet(std::span<float> plane, int n) {
  for (int level = waveletLevels(n) - 1; level >= 0; --level)
    inverseWaveletLevel(plane, n, level);
}

} // namespace octaclay::core::detail
