#include "codec/wavelet_bands.h"

#include "codec/wavelet_range_coder.h"
#include "codec/wavelet_transform.h"

#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>

namespace octaclay::core::detail {
namespace {

constexpr int kBuckets = 24;
constexpr int kOtherClasses = 4;
constexpr int kExponents = 32;
// Exponent contexts: the bit width of the neighbourhood magnitude sum, so coarse bands (large
// sums) keep classes apart instead of sharing the top one.
constexpr int kExponentClasses = 20;
constexpr int kMaxCodedChannels = 4;
constexpr std::int64_t kMaxContext = std::int64_t{1} << 30;

// Context bucket of a weighted neighbourhood magnitude sum: exact below 8, then two per octave.
int bucket(int m) {
  if (m < 8) return m;
  const int width = std::bit_width(static_cast<unsigned>(m));
  return std::min(2 * (width - 4) + 8 + ((m >> (width - 2)) & 1), kBuckets - 1);
}

struct ChannelModels {
  std::array<BitModel, kBuckets * kOtherClasses> zero;
  std::array<BitModel, 27> sign;
  std::array<BitModel, kBuckets * kOtherClasses> above1;
  std::array<BitModel, kBuckets> above2;
  std::array<BitModel, kExponents * kExponentClasses> exponent;
  std::array<BitModel, kExponents> mantissa;
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
std::int32_t codeValue(Coder& coder, ChannelModels& m, std::int32_t value, int context,
                       int exponentClass, int other, int signContext, bool knownNonzero) {
  const int zeroCtx = context * kOtherClasses + other;
  if (!knownNonzero && coder.bit(m.zero[static_cast<std::size_t>(zeroCtx)], value != 0) == 0)
    return 0;
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
      const auto exponents = static_cast<std::size_t>(exponentClass) * kExponents;
      while (decoded < kExponents - 1 &&
             coder.bit(m.exponent[exponents + static_cast<std::size_t>(decoded)], decoded < e) != 0)
        ++decoded;
      std::uint32_t mantissa = 1;
      for (int b = decoded - 1; b >= 0; --b) {
        const int bit = static_cast<int>((v >> b) & 1u);
        mantissa =
            (mantissa << 1) |
            static_cast<std::uint32_t>(
                b == decoded - 1 ? coder.bit(m.mantissa[static_cast<std::size_t>(decoded)], bit)
                                 : coder.raw(bit));
      }
      result = std::min<std::uint32_t>(mantissa + 2, kMaxMagnitude);
    }
  }
  const auto signedResult = static_cast<std::int32_t>(result);
  return negative ? -signedResult : signedResult;
}

} // namespace

struct BandModels::State {
  std::vector<ChannelModels> channels;
  std::array<BitModel, kBuckets> vectorZero;
};
BandModels::BandModels() : state(std::make_unique<State>()) {}
BandModels::~BandModels() = default;
BandModels::BandModels(BandModels&&) noexcept = default;
BandModels& BandModels::operator=(BandModels&&) noexcept = default;

namespace {

template <class Coder>
void codeBand(Coder& coder, CoefficientPlanes& planes, int level, Orientation orientation,
              BandModels::State& state) {
  const BandGeometry g = geometryOf(planes.n, level, orientation);
  const int n = g.n, s = g.s, d = 2 * s;
  const std::size_t w = static_cast<std::size_t>(n) + 1;
  state.channels.resize(static_cast<std::size_t>(planes.channels));
  std::vector<ChannelModels>& models = state.channels;
  std::array<BitModel, kBuckets>& vectorZero = state.vectorZero;
  const int vectorChannels = planes.channels >= 3 ? 3 : 0;
  if (vectorChannels > 0) planes.magnitude.resize(planes.q[0].size());
  const auto index = [w](int i, int j) {
    return static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i);
  };
  for (int j = g.jFirst; j <= n; j += d) {
    const int pj = g.hasParent ? parentCoordinate(j, s, n) : 0;
    for (int i = g.iFirst; i <= n; i += d) {
      const bool border = i == 0 || i == n || j == 0 || j == n;
      if (border && !isCanonicalSample(n, i, j)) continue;
      const std::size_t at = index(i, j);
      const int pi = g.hasParent ? parentCoordinate(i, s, n) : 0;
      // Weighted magnitudes of the coded neighbours in the band, the parent and its band
      // neighbours; the signs of the nearest three.
      struct Neighbourhood {
        int m;
        std::int32_t left, up, parent;
      };
      const auto neighbourhood = [&](const std::int32_t* q) {
        const auto value = [&](int ii, int jj) -> std::int32_t {
          return ii < 0 || jj < 0 || ii > n || jj > n ? 0 : q[index(ii, jj)];
        };
        Neighbourhood h{0, value(i - d, j), value(i, j - d), 0};
        // In 64 bits and capped: a damaged stream may hold magnitudes up to kMaxMagnitude
        // (three times that in the vector plane), whose weighted sum overflows an int.
        const auto magnitude = [](std::int32_t v) { return std::abs(std::int64_t{v}); };
        std::int64_t parents = 0;
        if (g.hasParent) {
          const int pd = 4 * s;
          h.parent = q[index(pi, pj)];
          parents = 2 * magnitude(h.parent) +
                    (magnitude(value(pi - pd, pj)) + magnitude(value(pi + pd, pj)) +
                     magnitude(value(pi, pj - pd)) + magnitude(value(pi, pj + pd)) + 1) /
                        2;
        }
        // The parent's band is coarser, its coefficients several times larger: a quarter of
        // its weight (measured on armadillo: 1 % fewer bits than full weight).
        const std::int64_t m = 3 * (magnitude(h.left) + magnitude(h.up)) +
                               magnitude(value(i - d, j - d)) + magnitude(value(i + d, j - d)) +
                               magnitude(value(i - 2 * d, j)) + magnitude(value(i, j - 2 * d)) +
                               (parents + 2) / 4;
        h.m = static_cast<int>(std::min<std::int64_t>(m, kMaxContext));
        return h;
      };
      int first = 0;
      if (vectorChannels > 0) {
        // One decision for the whole position vector (most of a fine band is zero), its
        // context from the vector magnitudes so that a zero costs one neighbourhood, not three.
        bool any = false;
        for (int c = 0; c < vectorChannels; ++c)
          any = any || planes.q[static_cast<std::size_t>(c)][at] != 0;
        const int vectorContext = neighbourhood(planes.magnitude.data()).m;
        if (coder.bit(vectorZero[static_cast<std::size_t>(bucket(vectorContext))], any) == 0) {
          for (int c = 0; c < vectorChannels; ++c)
            planes.q[static_cast<std::size_t>(c)][at] = 0;
          first = vectorChannels;
        }
      }
      std::array<int, kMaxCodedChannels> contexts{}, signContexts{};
      for (int c = first; c < planes.channels; ++c) {
        const Neighbourhood h = neighbourhood(planes.q[static_cast<std::size_t>(c)].data());
        contexts[static_cast<std::size_t>(c)] = h.m;
        signContexts[static_cast<std::size_t>(c)] =
            signClass(h.left) * 9 + signClass(h.up) * 3 + signClass(h.parent);
      }
      int otherSum = 0;
      for (int c = first; c < planes.channels; ++c) {
        std::int32_t* q = planes.q[static_cast<std::size_t>(c)].data();
        const auto cc = static_cast<std::size_t>(c);
        const int other = c == 0 || c == vectorChannels ? 0 : 1 + std::min(otherSum, 2);
        // The last component of a non-zero vector whose others are zero is not zero.
        const bool knownNonzero = c == vectorChannels - 1 && otherSum == 0;
        const int exponentClass =
            std::min(static_cast<int>(std::bit_width(static_cast<unsigned>(contexts[cc]))),
                     kExponentClasses - 1);
        const std::int32_t coded = codeValue(coder, models[cc], q[at], bucket(contexts[cc]),
                                             exponentClass, other, signContexts[cc], knownNonzero);
        q[at] = coded;
        otherSum = c == vectorChannels - 1 ? 0 : otherSum + std::abs(coded);
      }
      int magnitude = 0;
      for (int c = 0; c < vectorChannels; ++c)
        magnitude += std::min(std::abs(planes.q[static_cast<std::size_t>(c)][at]), kMaxMagnitude);
      if (vectorChannels > 0) planes.magnitude[at] = magnitude;
      if (border) {
        std::array<Sample, 4> copies;
        const int count = identifiedSamples(n, {i, j}, copies);
        for (int k = 1; k < count; ++k) {
          const std::size_t copy =
              index(copies[static_cast<std::size_t>(k)].i, copies[static_cast<std::size_t>(k)].j);
          for (auto& q : planes.q)
            q[copy] = q[at];
          if (vectorChannels > 0) planes.magnitude[copy] = planes.magnitude[at];
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

void setVectorMagnitudes(CoefficientPlanes& planes) {
  if (planes.channels < 3) return;
  planes.magnitude.assign(planes.q[0].size(), 0);
  for (std::size_t k = 0; k < planes.magnitude.size(); ++k)
    planes.magnitude[k] =
        std::abs(planes.q[0][k]) + std::abs(planes.q[1][k]) + std::abs(planes.q[2][k]);
}

std::vector<std::uint8_t> encodeBand(const CoefficientPlanes& planes, int level,
                                     Orientation orientation, BandModels& models) {
  RangeEncoder coder;
  // codeBand writes each value back unchanged when encoding.
  codeBand(coder, const_cast<CoefficientPlanes&>(planes), level, orientation, *models.state);
  return coder.finish();
}

bool decodeBand(std::span<const std::uint8_t> bytes, CoefficientPlanes& planes, int level,
                Orientation orientation, BandModels& models) {
  RangeDecoder coder(bytes);
  codeBand(coder, planes, level, orientation, *models.state);
  return coder.intact();
}

std::size_t maxBandBytes(std::size_t samples, int channels) {
  // Per coefficient: zero, sign, > 1, > 2 and up to 31 exponent decisions, 31 raw bits.
  constexpr std::size_t bitsPerValue = (5 + kExponents) * kMaxBitsPerDecision + kExponents;
  return samples * static_cast<std::size_t>(channels) * bitsPerValue / 8 + 16;
}

} // namespace octaclay::core::detail
