#include "codecs/wavelet_bands.h"

#include "codecs/wavelet_range_coder.h"
#include "codecs/wavelet_transform.h"
#include "octaclay/core/octahedral.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>

namespace octaclay::core::detail {
namespace {

constexpr int kBuckets = 12;
constexpr int kLevelClasses = 3;
constexpr int kOtherClasses = 4;
constexpr int kExponents = 32;

// Context bucket of a weighted neighbourhood magnitude sum, roughly logarithmic.
int bucket(int m) {
  static constexpr std::array<std::uint8_t, 40> table = {
      0, 1, 2, 3, 4, 5, 5, 6, 6, 7, 7, 7, 7,  8,  8,  8,  8,  8,  8,  8,
      9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 10, 10, 10, 10, 10, 10, 10, 10};
  return m < static_cast<int>(table.size()) ? table[static_cast<std::size_t>(m)] : kBuckets - 1;
}

struct ChannelModels {
  std::array<BitModel, kBuckets * kOtherClasses> zero;
  std::array<BitModel, 27> sign;
  std::array<BitModel, kBuckets * kOtherClasses> above1;
  std::array<BitModel, kBuckets> above2;
  std::array<BitModel, kExponents> exponent;
};

struct BandGeometry {
  int n, s, iFirst, jFirst, levels, level;
  bool hasParent;
};

BandGeometry geometryOf(int n, int level, Orientation orientation) {
  const int s = 1 << level;
  const bool oddI = orientation != Orientation::AlongJ;
  const bool oddJ = orientation != Orientation::AlongI;
  const int levels = waveletLevels(n);
  return {n, s, oddI ? s : 0, oddJ ? s : 0, levels, level, level + 1 < levels};
}

bool isCanonicalSample(int n, int i, int j) {
  if (i != 0 && i != n && j != 0 && j != n) return true;
  return canonical(n, {i, j}) == Sample{i, j};
}

// The sample of the next coarser band (same orientation) that covers (i, j).
int parentCoordinate(int x, int s, int n) {
  const int k = x / (2 * s);
  if ((x / s) % 2 == 1) return (2 * (k >> 1) + 1) * 2 * s; // odd multiple of s
  return std::min(4 * s * ((k + 1) >> 1), n);
}

int signClass(std::int32_t v) {
  return v > 0 ? 2 : (v < 0 ? 0 : 1);
}

template <class Coder>
std::int32_t codeValue(Coder& coder, ChannelModels& m, std::int32_t value, int context, int other,
                       int signContext) {
  const int zeroCtx = context * kOtherClasses + other;
  if (coder.bit(m.zero[static_cast<std::size_t>(zeroCtx)], value != 0) == 0) return 0;
  const bool negative = coder.bit(m.sign[static_cast<std::size_t>(signContext)], value < 0) != 0;
  const std::uint32_t magnitude =
      value < 0 ? static_cast<std::uint32_t>(-static_cast<std::int64_t>(value))
                : static_cast<std::uint32_t>(value);
  std::uint32_t result = 1;
  if (coder.bit(m.above1[static_cast<std::size_t>(zeroCtx)], magnitude > 1) != 0) {
    result = 2;
    if (coder.bit(m.above2[static_cast<std::size_t>(context)], magnitude > 2) != 0) {
      // Exp-Golomb of magnitude − 3: the exponent in unary (adaptive), the mantissa raw.
      const std::uint32_t v = magnitude - 2; // ≥ 1 when encoding
      const int e = v == 0 ? 0 : std::bit_width(v) - 1;
      int decoded = 0;
      while (decoded < kExponents - 1 &&
             coder.bit(m.exponent[static_cast<std::size_t>(decoded)], decoded < e) != 0)
        ++decoded;
      std::uint32_t mantissa = 1;
      for (int b = decoded - 1; b >= 0; --b)
        mantissa = (mantissa << 1) | static_cast<std::uint32_t>(coder.raw((v >> b) & 1u));
      result = std::min<std::uint32_t>(mantissa + 2, kMaxMagnitude);
    }
  }
  const auto signedResult = static_cast<std::int32_t>(result);
  return negative ? -signedResult : signedResult;
}

template <class Coder>
void codeBand(Coder& coder, CoefficientPlanes& planes, int level, Orientation orientation) {
  const BandGeometry g = geometryOf(planes.n, level, orientation);
  const int n = g.n, s = g.s, d = 2 * s;
  const std::size_t w = static_cast<std::size_t>(n) + 1;
  const int levelClass = std::min(level, kLevelClasses - 1);
  (void)levelClass;
  std::vector<ChannelModels> models(static_cast<std::size_t>(planes.channels));
  const auto index = [w](int i, int j) {
    return static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i);
  };
  for (int j = g.jFirst; j <= n; j += d) {
    const int pj = g.hasParent ? parentCoordinate(j, s, n) : 0;
    for (int i = g.iFirst; i <= n; i += d) {
      const bool border = i == 0 || i == n || j == 0 || j == n;
      if (border && !isCanonicalSample(n, i, j)) continue;
      const std::size_t at = index(i, j);
      int otherSum = 0;
      for (int c = 0; c < planes.channels; ++c) {
        std::int32_t* q = planes.q[static_cast<std::size_t>(c)].data();
        const auto value = [&](int ii, int jj) -> std::int32_t {
          return ii < 0 || jj < 0 || ii > n ? 0 : q[index(ii, jj)];
        };
        const std::int32_t left = value(i - d, j), up = value(i, j - d);
        const std::int32_t parent = g.hasParent ? q[index(parentCoordinate(i, s, n), pj)] : 0;
        const int m = 2 * (std::abs(left) + std::abs(up)) + std::abs(value(i - d, j - d)) +
                      std::abs(value(i + d, j - d)) + std::abs(value(i - 2 * d, j)) +
                      std::abs(value(i, j - 2 * d)) + 2 * std::abs(parent);
        const int context = bucket(m);
        const int other = c == 0 ? 0 : 1 + std::min(otherSum, 2);
        const int signContext = signClass(left) * 9 + signClass(up) * 3 + signClass(parent);
        const std::int32_t coded = codeValue(coder, models[static_cast<std::size_t>(c)], q[at],
                                             context, other, signContext);
        q[at] = coded;
        otherSum += std::abs(coded);
      }
      if (border) {
        std::array<Sample, 4> copies;
        const int count = identifiedSamples(n, {i, j}, copies);
        for (int k = 1; k < count; ++k)
          for (int c = 0; c < planes.channels; ++c) {
            auto& q = planes.q[static_cast<std::size_t>(c)];
            q[index(copies[static_cast<std::size_t>(k)].i, copies[static_cast<std::size_t>(k)].j)] =
                q[at];
          }
      }
    }
  }
}

} // namespace

std::size_t bandSampleCount(int n, int level, Orientation orientation) {
  const BandGeometry g = geometryOf(n, level, orientation);
  std::size_t count = 0;
  for (int j = g.jFirst; j <= n; j += 2 * g.s)
    for (int i = g.iFirst; i <= n; i += 2 * g.s)
      count += isCanonicalSample(n, i, j) ? 1 : 0;
  return count;
}

std::vector<std::uint8_t> encodeBand(const CoefficientPlanes& planes, int level,
                                     Orientation orientation) {
  RangeEncoder coder;
  // codeBand writes each value back unchanged when encoding.
  codeBand(coder, const_cast<CoefficientPlanes&>(planes), level, orientation);
  return coder.finish();
}

bool decodeBand(std::span<const std::uint8_t> bytes, CoefficientPlanes& planes, int level,
                Orientation orientation) {
  RangeDecoder coder(bytes);
  codeBand(coder, planes, level, orientation);
  return coder.intact();
}

std::size_t maxBandBytes(std::size_t samples, int channels) {
  // Per coefficient: zero, sign, > 1, > 2 and up to 31 exponent decisions, 31 raw bits.
  constexpr std::size_t bitsPerValue = (4 + kExponents - 1) * kMaxBitsPerDecision + kExponents - 1;
  return samples * static_cast<std::size_t>(channels) * bitsPerValue / 8 + 16;
}

} // namespace octaclay::core::detail
