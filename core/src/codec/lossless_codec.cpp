// `lossless`: exact float32. Each channel is walked in raster order; a sample is predicted from
// its decoded neighbours, in float, by the rule its 32 × 32 block chose (the encoder tries
// each): the parallelogram (Lorenzo) rule left + up − up-left, exact on planes and best on
// scanned detail; the second-order Lorenzo rule over the 3 × 3 corner, exact on biquadratic
// patches and twice as good on smooth surfaces; or their mean. Both value and prediction are
// mapped to integers in float order, and their difference is coded as a bit
// width (entropy-coded by zstd in 33 streams chosen by the neighbours' widths, an order-1
// context) plus its raw low bits. Low mantissa bits that are zero in every sample (half-float
// layers) are dropped first. Samples identified with a canonical one are copies when the input's
// seams are bit-exact, so they cost nothing.

#include "codec/bit_stream.h"
#include "codec/byte_io.h"
#include "codec/codec_list.h"
#include "codec/grid.h"
#include "codec/zstd_blocks.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace octaclay::core {
namespace {

using namespace detail;

constexpr CodecInfo kInfo{"lossless", 5, 1, false, "ignored: the decoded floats are bit-exact", 0};
constexpr int kWidths = 33; // bit widths 0 … 32, also the contexts
constexpr int kZstdLevel = 9;
constexpr std::uint8_t kCanonicalOnly = 1;

std::uint32_t toOrdered(float f) {
  const std::uint32_t b = std::bit_cast<std::uint32_t>(f);
  return (b & 0x80000000u) ? ~b : (b | 0x80000000u);
}

float fromOrdered(std::uint32_t o) {
  return std::bit_cast<float>((o & 0x80000000u) ? (o & 0x7fffffffu) : ~o);
}

// Values whose low `drop` bits are zero map to ordered integers whose low bits are all equal
// (zeros for positives, ones for negatives), so shifting them out is exact.
std::uint32_t restoreDropped(std::uint32_t reduced, int drop) {
  const std::uint32_t o = reduced << drop;
  return (o & 0x80000000u) ? o : (o | ((1u << drop) - 1u));
}

enum Predictor : std::uint8_t { Parallelogram = 0, Quadratic = 1, Mean = 2 };
constexpr int kPredictors = 3;
constexpr int kBlock = 32;

float predict(const float* plane, int side, int i, int j, int predictor) {
  const auto at = [&](int di, int dj) {
    return plane[static_cast<std::size_t>(j - dj) * side + (i - di)];
  };
  float p;
  if (j == 0)
    p = i == 0 ? 0.0f : at(1, 0);
  else if (i == 0)
    p = at(0, 1);
  else {
    p = (at(1, 0) + at(0, 1)) - at(1, 1);
    if (predictor != Parallelogram && i >= 2 && j >= 2) {
      // −Σ c(a)c(b)·f(i−a, j−b) over (a, b) ≠ (0, 0) with c = (1, −2, 1); power-of-two
      // weights keep every product exact, so the sum is the same on every IEEE machine.
      const float q = ((2.0f * at(1, 0) - at(2, 0)) + (2.0f * at(0, 1) - at(0, 2))) +
                      ((2.0f * at(2, 1) + 2.0f * at(1, 2)) - (4.0f * at(1, 1) + at(2, 2)));
      p = predictor == Quadratic ? q : 0.5f * (p + q);
    }
  }
  return std::isfinite(p) ? p : 0.0f;
}

int context(const std::uint8_t* widths, int side, int i, int j) {
  const std::size_t at = static_cast<std::size_t>(j) * side + i;
  if (i == 0 && j == 0) return 0;
  const int left = i > 0 ? widths[at - 1] : widths[at - side];
  const int up = j > 0 ? widths[at - side] : left;
  return (left + up + 1) >> 1;
}

// Walks the grid in raster order: code(i, j, at) for coded samples, the rest copied from their
// canonical sample (already visited) when only canonical samples are coded.
template <class Code, class Copy> void walk(int n, bool canonicalOnly, Code&& code, Copy&& copy) {
  const int side = n + 1;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const std::size_t at = static_cast<std::size_t>(j) * side + i;
      const bool border = i == 0 || j == 0 || i == n || j == n;
      if (canonicalOnly && border) {
        const Sample c = canonical(n, {i, j});
        if (c != Sample{i, j}) {
          copy(at, static_cast<std::size_t>(c.j) * side + c.i);
          continue;
        }
      }
      code(i, j, at);
    }
}

int droppableBits(const std::vector<float>& plane) {
  std::uint32_t used = 0;
  for (float v : plane)
    used |= std::bit_cast<std::uint32_t>(v);
  used &= 0x7fffffu;
  return used == 0 ? 23 : std::countr_zero(used);
}

int blocksPerSide(int n) {
  return (n + 1 + kBlock - 1) / kBlock;
}

std::uint32_t zigzagResidual(std::uint32_t actual, std::uint32_t predicted, int drop) {
  const std::int64_t modulus = std::int64_t{1} << (32 - drop);
  std::int64_t d = static_cast<std::int64_t>(actual) - predicted;
  if (d >= modulus / 2) d -= modulus;
  if (d < -modulus / 2) d += modulus;
  return static_cast<std::uint32_t>(d >= 0 ? 2 * d : -2 * d - 1);
}

// For each block, the predictor whose residuals have the fewest bits (the plane is exact, so
// the decoder will predict from the same values).
std::vector<std::uint8_t> choosePredictors(const std::vector<float>& plane, int n, int drop) {
  const int side = n + 1, blocks = blocksPerSide(n);
  std::vector<std::array<std::uint64_t, kPredictors>> cost(static_cast<std::size_t>(blocks) *
                                                           blocks);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const std::uint32_t actual = toOrdered(plane[static_cast<std::size_t>(j) * side + i]) >> drop;
      auto& c = cost[static_cast<std::size_t>(j / kBlock) * blocks + i / kBlock];
      for (int k = 0; k < kPredictors; ++k)
        c[k] += std::bit_width(
            zigzagResidual(actual, toOrdered(predict(plane.data(), side, i, j, k)) >> drop, drop));
    }
  std::vector<std::uint8_t> chosen(cost.size());
  for (std::size_t b = 0; b < cost.size(); ++b)
    chosen[b] = static_cast<std::uint8_t>(std::min_element(cost[b].begin(), cost[b].end()) -
                                          cost[b].begin());
  return chosen;
}

std::vector<std::uint8_t> encodeChannel(const std::vector<float>& plane, int n,
                                        bool canonicalOnly) {
  const int side = n + 1, blocks = blocksPerSide(n);
  const int drop = droppableBits(plane);
  const std::vector<std::uint8_t> predictors = choosePredictors(plane, n, drop);
  std::vector<std::uint8_t> widths(plane.size(), 0);
  std::array<std::vector<std::uint8_t>, kWidths> streams;
  BitWriter raw;
  walk(
      n, canonicalOnly,
      [&](int i, int j, std::size_t at) {
        const int predictor =
            predictors[static_cast<std::size_t>(j / kBlock) * blocks + i / kBlock];
        const std::uint32_t predicted =
            toOrdered(predict(plane.data(), side, i, j, predictor)) >> drop;
        const std::uint32_t zig = zigzagResidual(toOrdered(plane[at]) >> drop, predicted, drop);
        const int width = std::bit_width(zig);
        streams[context(widths.data(), side, i, j)].push_back(static_cast<std::uint8_t>(width));
        widths[at] = static_cast<std::uint8_t>(width);
        if (width > 1) raw.put(zig & ((1u << (width - 1)) - 1u), width - 1);
      },
      [&](std::size_t at, std::size_t from) { widths[at] = widths[from]; });

  ByteWriter out;
  out.u8(static_cast<std::uint8_t>(drop));
  writeZstdBlock(out, predictors, kZstdLevel);
  for (const auto& s : streams)
    out.varint(s.size());
  for (const auto& s : streams)
    if (!s.empty()) writeZstdBlock(out, s, kZstdLevel);
  const auto bits = raw.finish();
  out.varint(bits.size());
  out.append(bits);
  return out.take();
}

std::size_t codedSamples(int n, bool canonicalOnly) {
  return canonicalOnly ? static_cast<std::size_t>(n) * n + 2 : sampleCount(n);
}

void decodeChannel(std::span<const std::uint8_t> bytes, int n, bool canonicalOnly,
                   std::vector<float>& plane, const std::string& what) {
  ByteReader in(bytes, what);
  const int side = n + 1, blocks = blocksPerSide(n);
  const int drop = in.u8();
  if (drop > 23) in.fail("dropped-bit count " + std::to_string(drop) + " is over 23");
  const std::vector<std::uint8_t> predictors =
      readZstdBlock(in, static_cast<std::size_t>(blocks) * blocks);
  for (std::uint8_t p : predictors)
    if (p >= kPredictors) in.fail("unknown predictor " + std::to_string(p));
  const std::uint64_t modulus = std::uint64_t{1} << (32 - drop);
  const int maxWidth = 32 - drop;
  std::array<std::uint32_t, kWidths> counts{};
  std::uint64_t total = 0;
  for (auto& c : counts)
    total += c = in.varint32();
  if (total != codedSamples(n, canonicalOnly))
    in.fail("holds " + std::to_string(total) + " samples, expected " +
            std::to_string(codedSamples(n, canonicalOnly)));
  std::array<std::vector<std::uint8_t>, kWidths> streams;
  for (int k = 0; k < kWidths; ++k)
    if (counts[k] > 0) streams[k] = readZstdBlock(in, counts[k]);
  const std::uint32_t rawLength = in.varint32();
  BitReader raw(in.take(rawLength), in);
  in.expectEnd();

  std::array<std::size_t, kWidths> next{};
  std::vector<std::uint8_t> widths(sampleCount(n), 0);
  plane.assign(sampleCount(n), 0.0f);
  walk(
      n, canonicalOnly,
      [&](int i, int j, std::size_t at) {
        const int ctx = context(widths.data(), side, i, j);
        if (next[ctx] >= streams[ctx].size()) in.fail("context stream ends early");
        const int width = streams[ctx][next[ctx]++];
        if (width > maxWidth)
          in.fail("residual width " + std::to_string(width) + " is over " +
                  std::to_string(maxWidth));
        widths[at] = static_cast<std::uint8_t>(width);
        std::uint32_t zig = 0;
        if (width > 0)
          zig = (std::uint32_t{1} << (width - 1)) | (width > 1 ? raw.get(width - 1) : 0u);
        const std::int64_t d = (zig & 1u) ? -static_cast<std::int64_t>(zig >> 1) - 1
                                          : static_cast<std::int64_t>(zig >> 1);
        const int predictor =
            predictors[static_cast<std::size_t>(j / kBlock) * blocks + i / kBlock];
        const std::uint32_t predicted =
            toOrdered(predict(plane.data(), side, i, j, predictor)) >> drop;
        const std::uint64_t reduced =
            static_cast<std::uint64_t>(static_cast<std::int64_t>(predicted) + d) & (modulus - 1);
        plane[at] = fromOrdered(restoreDropped(static_cast<std::uint32_t>(reduced), drop));
      },
      [&](std::size_t at, std::size_t from) {
        plane[at] = plane[from];
        widths[at] = widths[from];
      });
  for (int k = 0; k < kWidths; ++k)
    if (next[k] != streams[k].size()) in.fail("context stream longer than its samples");
  raw.expectEnd();
}

std::vector<std::uint8_t> encode(const FloatImage& image, const CodecParams&) {
  requireCodableImage(image, kInfo.id);
  const bool canonicalOnly = seamsBitExact(image);
  const std::size_t count = sampleCount(image.n);
  std::vector<std::vector<std::uint8_t>> chunks(image.channels);
  parallelTasks(image.channels, [&](int c) {
    std::vector<float> plane(count);
    for (std::size_t k = 0; k < count; ++k)
      plane[k] = image.texels[k * image.channels + c];
    chunks[c] = encodeChannel(plane, image.n, canonicalOnly);
  });
  ByteWriter out;
  writeStreamHeader(out, kInfo, image.n, image.channels);
  out.u8(canonicalOnly ? kCanonicalOnly : 0);
  for (const auto& chunk : chunks)
    out.u32(static_cast<std::uint32_t>(chunk.size()));
  for (const auto& chunk : chunks)
    out.append(chunk);
  return out.take();
}

FloatImage decode(std::span<const std::uint8_t> bytes, int n, int channels) {
  requireDecodableShape(n, channels, kInfo.id);
  ByteReader in(bytes, "lossless stream");
  readStreamHeader(in, kInfo, n, channels);
  const std::uint8_t flags = in.u8();
  if (flags > kCanonicalOnly) in.fail("unknown flags " + std::to_string(flags));
  std::vector<std::uint32_t> lengths(channels);
  for (auto& l : lengths)
    l = in.u32();
  std::vector<std::span<const std::uint8_t>> chunks;
  for (auto l : lengths)
    chunks.push_back(in.take(l));
  in.expectEnd();

  std::vector<std::vector<float>> planes(channels);
  parallelTasks(channels, [&](int c) {
    decodeChannel(chunks[c], n, flags & kCanonicalOnly, planes[c],
                  "lossless stream, channel " + std::to_string(c));
  });
  FloatImage image{n, channels, std::vector<float>(sampleCount(n) * channels)};
  for (std::size_t k = 0; k < sampleCount(n); ++k)
    for (int c = 0; c < channels; ++c)
      image.texels[k * channels + c] = planes[c][k];
  return image;
}

std::size_t maxEncodedSize(int n, int channels, const CodecParams&) {
  const std::size_t count = sampleCount(n);
  // Per channel: widths (each context's block bounded by its own count; the bounds are
  // superadditive enough with one extra frame overhead per context), raw bits ≤ 31 per sample.
  const std::size_t blocks = static_cast<std::size_t>(blocksPerSide(n));
  const std::size_t perChannel = 1 + zstdBlockBound(blocks * blocks) + 5 * kWidths +
                                 kWidths * zstdBlockBound(0) + zstdBlockBound(count) + 5 +
                                 (count * 31 + 7) / 8;
  return kStreamHeaderSize + 1 + channels * (4 + perChannel);
}

} // namespace

Codec makeLosslessCodec() {
  return {kInfo, encode, decode, maxEncodedSize,
          [](const FloatImage&, const CodecParams&) { return 0.0; }};
}

} // namespace octaclay::core
