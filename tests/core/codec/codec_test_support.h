// Images and checks the codec and container tests share.
#pragma once

#include "octaclay/core/codec/codec.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/octahedral.h"

#include <QtTest>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core::testing {

/// Sample (i, j)'s point on a bumpy octahedron-unfolded surface, from + − × ÷ only (no libm),
/// so golden streams do not depend on the C library; `channels` values per sample (the 4th
/// is a ramp, the 1st of a 1-channel image is x).
inline FloatImage bumpyImage(int n, int channels = 3) {
  FloatImage image{n, channels, std::vector<float>(std::size_t(n + 1) * (n + 1) * channels)};
  const auto value = [&](int i, int j, int c) {
    const Sample s = canonical(n, {i, j});
    const float u = 2.0f * float(s.i) / float(n) - 1.0f, v = 2.0f * float(s.j) / float(n) - 1.0f;
    float x = u, y = v, z = 1.0f - std::abs(u) - std::abs(v);
    if (z < 0) {
      x = (1.0f - std::abs(v)) * (u < 0 ? -1.0f : 1.0f);
      y = (1.0f - std::abs(u)) * (v < 0 ? -1.0f : 1.0f);
    }
    const float bump = 1.0f + x * y / 3.0f - z * z * x / 7.0f; // full mantissas
    const float p[4] = {x * bump, y * bump, z * bump, 0.5f + u * v / 5.0f};
    return p[c];
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      for (int c = 0; c < channels; ++c)
        image.texels[(std::size_t(j) * (n + 1) + i) * channels + c] = value(i, j, c);
  return image;
}

inline std::uint64_t fnv1a(std::span<const std::uint8_t> bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::uint8_t b : bytes)
    h = (h ^ b) * 1099511628211ull;
  return h;
}

inline std::uint64_t fnv1a(const FloatImage& image) {
  return fnv1a({reinterpret_cast<const std::uint8_t*>(image.texels.data()),
                image.texels.size() * sizeof(float)});
}

inline double maxAbsError(const FloatImage& a, const FloatImage& b) {
  double e = 0;
  for (std::size_t k = 0; k < a.texels.size(); ++k)
    e = std::max(e, double(std::abs(a.texels[k] - b.texels[k])));
  return e;
}

inline bool bitEqual(const FloatImage& a, const FloatImage& b) {
  return a.n == b.n && a.channels == b.channels && a.texels.size() == b.texels.size() &&
         std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(float)) == 0;
}

/// The first three channels as a geometry image, to measure seams with maxSeamGap.
inline GeometryImage asGeometry(const FloatImage& image) {
  GeometryImage g(image.n);
  for (std::size_t t = 0; t < g.texelCount(); ++t) {
    const float* p = &image.texels[t * image.channels];
    g.texels()[t] = {p[0], image.channels > 1 ? p[1] : 0.0f, image.channels > 2 ? p[2] : 0.0f,
                     0.0f};
  }
  return g;
}

/// True when every set of identified samples holds bit-identical values in all channels.
inline bool seamsBitExactForTest(const FloatImage& image) {
  const int n = image.n;
  const std::size_t c = std::size_t(image.channels);
  std::array<Sample, 4> same;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int count = identifiedSamples(n, {i, j}, same);
      for (int k = 1; k < count; ++k)
        if (std::memcmp(&image.texels[(std::size_t(same[0].j) * (n + 1) + same[0].i) * c],
                        &image.texels[(std::size_t(same[k].j) * (n + 1) + same[k].i) * c],
                        c * sizeof(float)) != 0)
          return false;
    }
  return true;
}

/// "" when decode threw Error(InvalidInput), else what happened instead.
template <class F> std::string refusal(F&& decode) {
  try {
    decode();
    return "accepted";
  } catch (const Error& e) {
    return e.kind() == ErrorKind::InvalidInput ? "" : std::string("wrong kind: ") + e.what();
  } catch (const std::exception& e) {
    return std::string("foreign exception: ") + e.what();
  }
}

/// Every proper prefix of a valid stream is refused with Error(InvalidInput); every stream
/// with one bit flipped (every byte, one bit each, rotating) either is refused so or decodes
/// to an image of the right shape.
inline void checkDamagedStreams(const Codec& codec, const std::vector<std::uint8_t>& stream, int n,
                                int channels) {
  for (std::size_t length = 0; length < stream.size(); ++length) {
    const std::string why =
        refusal([&] { codec.decode(std::span(stream).first(length), n, channels); });
    if (!why.empty())
      QFAIL(qPrintable(QString("%1: prefix of %2 of %3 bytes: %4")
                           .arg(QString::fromUtf8(codec.info.id.data(), int(codec.info.id.size())))
                           .arg(length)
                           .arg(stream.size())
                           .arg(QString::fromStdString(why))));
  }
  std::vector<std::uint8_t> damaged = stream;
  for (std::size_t at = 0; at < stream.size(); ++at) {
    damaged[at] ^= std::uint8_t(1u << (at % 8));
    try {
      const FloatImage image = codec.decode(damaged, n, channels);
      QCOMPARE(image.texels.size(), std::size_t(n + 1) * (n + 1) * channels);
    } catch (const Error& e) {
      QCOMPARE(int(e.kind()), int(ErrorKind::InvalidInput));
    }
    damaged[at] = stream[at];
  }
}

inline std::string hexOf(std::span<const std::uint8_t> bytes) {
  static const char* digits = "0123456789abcdef";
  std::string s;
  for (std::uint8_t b : bytes) {
    s += digits[b >> 4];
    s += digits[b & 15];
  }
  return s;
}

inline std::vector<std::uint8_t> bytesOfHex(std::string_view hex) {
  std::vector<std::uint8_t> bytes;
  const auto nibble = [](char c) { return c <= '9' ? c - '0' : c - 'a' + 10; };
  for (std::size_t k = 0; k + 1 < hex.size(); k += 2)
    bytes.push_back(std::uint8_t(nibble(hex[k]) * 16 + nibble(hex[k + 1])));
  return bytes;
}

} // namespace octaclay::core::testing
