// `bytepack`: the thesis's custom byte packing (5.5). A float32 mip-map of R × R regions holds
// each region's mean; per region the smallest and largest delta from that mean are kept as
// float32, and every sample becomes an 8-bit offset between them. The offsets are filtered with
// the gradient predictor (like PNG's filters; the thesis stored them as an 8-bit image) and
// all streams are entropy-coded by zstd.

#include "codec/byte_io.h"
#include "codec/channel_stats.h"
#include "codec/codec_list.h"
#include "codec/grid.h"
#include "codec/zstd_blocks.h"

#include "octaclay/core/error.h"

#include <cmath>
#include <cstring>

namespace octaclay::core {
namespace {

using namespace detail;

constexpr CodecInfo kInfo{
    "bytepack",
    1,
    1,
    true,
    "regions per side R of the mip-map, a power of two 1 … N (default 16, or N when smaller; the "
    "thesis used 4, "
    "16 and 64); each sample is within (region's delta range)/510 of the original",
    16};
constexpr int kZstdLevel = 9;

int regionsPerSide(const CodecParams& params, int n) {
  const double q = params.quality > 0 ? params.quality : std::min<double>(kInfo.defaultQuality, n);
  const int r = static_cast<int>(q);
  if (r != q || r < 1 || r > n || (r & (r - 1)) != 0)
    throw Error(ErrorKind::InvalidArgument,
                "bytepack: regions per side must be a power of two from 1 to N = " +
                    std::to_string(n) + ", not " + std::to_string(q));
  return r;
}

// The region of grid index i (0 … N): blocks of N/R samples, the last one also holding N.
int regionOf(int i, int n, int r) {
  return std::min(i / (n / r), r - 1);
}

std::uint8_t gradientPrediction(const std::uint8_t* plane, int side, int i, int j) {
  const std::size_t at = static_cast<std::size_t>(j) * side + i;
  if (j == 0) return i == 0 ? 0 : plane[at - 1];
  if (i == 0) return plane[at - side];
  const int p = plane[at - 1] + plane[at - side] - plane[at - side - 1];
  return static_cast<std::uint8_t>(std::clamp(p, 0, 255));
}

struct Regions {
  std::vector<float> mean, lo, hi; // [c][region]
};

float decodedValue(const Regions& regions, std::size_t region, std::uint8_t offset) {
  const float step = (regions.hi[region] - regions.lo[region]) / 255.0f;
  return regions.mean[region] + (regions.lo[region] + static_cast<float>(offset) * step);
}

std::vector<std::uint8_t> encode(const FloatImage& image, const CodecParams& params) {
  requireCodableImage(image, kInfo.id);
  const int n = image.n, side = n + 1, channels = image.channels;
  const int r = regionsPerSide(params, n);
  for (const ChannelRange& range : channelRanges(image))
    if (!std::isfinite(range.span()))
      throw Error(ErrorKind::InvalidArgument,
                  "bytepack: the image holds non-finite values or a range beyond float's");
  const std::size_t regionCount = static_cast<std::size_t>(r) * r;
  Regions regions{std::vector<float>(regionCount * channels),
                  std::vector<float>(regionCount * channels, INFINITY),
                  std::vector<float>(regionCount * channels, -INFINITY)};
  std::vector<double> sums(regionCount * channels, 0.0);
  std::vector<std::size_t> counts(regionCount, 0);
  const auto regionIndex = [&](int i, int j) {
    return static_cast<std::size_t>(regionOf(j, n, r)) * r + regionOf(i, n, r);
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const std::size_t g = regionIndex(i, j);
      ++counts[g];
      for (int c = 0; c < channels; ++c)
        sums[c * regionCount + g] +=
            image.texels[(static_cast<std::size_t>(j) * side + i) * channels + c];
    }
  for (std::size_t k = 0; k < sums.size(); ++k)
    regions.mean[k] = static_cast<float>(sums[k] / static_cast<double>(counts[k % regionCount]));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      for (int c = 0; c < channels; ++c) {
        const std::size_t g = c * regionCount + regionIndex(i, j);
        const float d =
            image.texels[(static_cast<std::size_t>(j) * side + i) * channels + c] - regions.mean[g];
        regions.lo[g] = std::min(regions.lo[g], d);
        regions.hi[g] = std::max(regions.hi[g], d);
      }

  const std::size_t count = sampleCount(n);
  std::vector<std::uint8_t> offsets(count * channels), filtered(count * channels);
  for (int c = 0; c < channels; ++c) {
    std::uint8_t* plane = offsets.data() + c * count;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const std::size_t at = static_cast<std::size_t>(j) * side + i;
        const std::size_t g = c * regionCount + regionIndex(i, j);
        const float span = regions.hi[g] - regions.lo[g];
        const float d = image.texels[at * channels + c] - regions.mean[g];
        const float t = span > 0 ? (d - regions.lo[g]) / span * 255.0f : 0.0f;
        plane[at] = static_cast<std::uint8_t>(std::clamp(std::lround(t), 0L, 255L));
        filtered[c * count + at] =
            static_cast<std::uint8_t>(plane[at] - gradientPrediction(plane, side, i, j));
      }
  }

  ByteWriter out;
  writeStreamHeader(out, kInfo, n, channels);
  out.u16(static_cast<std::uint16_t>(r));
  std::vector<std::uint8_t> floats(regions.mean.size() * 3 * sizeof(float));
  std::uint8_t* f = floats.data();
  for (const auto* v : {&regions.mean, &regions.lo, &regions.hi}) {
    std::memcpy(f, v->data(), v->size() * sizeof(float)); // little-endian hosts only (x86, ARM)
    f += v->size() * sizeof(float);
  }
  writeZstdBlock(out, floats, kZstdLevel);
  writeZstdBlock(out, filtered, kZstdLevel);
  return out.take();
}

FloatImage decode(std::span<const std::uint8_t> bytes, int n, int channels) {
  requireDecodableShape(n, channels, kInfo.id);
  ByteReader in(bytes, "bytepack stream");
  readStreamHeader(in, kInfo, n, channels);
  const int r = in.u16();
  if (r < 1 || r > n || (r & (r - 1)) != 0)
    in.fail("regions per side " + std::to_string(r) + " is not a power of two from 1 to N");
  const std::size_t regionCount = static_cast<std::size_t>(r) * r;
  const std::size_t count = sampleCount(n);
  const int side = n + 1;
  const auto floats = readZstdBlock(in, regionCount * channels * 3 * sizeof(float));
  auto offsets = readZstdBlock(in, count * channels);
  in.expectEnd();

  Regions regions;
  const std::uint8_t* f = floats.data();
  for (auto* v : {&regions.mean, &regions.lo, &regions.hi}) {
    v->resize(regionCount * channels);
    std::memcpy(v->data(), f, v->size() * sizeof(float));
    f += v->size() * sizeof(float);
  }
  FloatImage image{n, channels, std::vector<float>(count * channels)};
  parallelTasks(channels, [&](int c) {
    std::uint8_t* plane = offsets.data() + c * count;
    for (int j = 0; j <= n; ++j) {
      const std::size_t rowRegion = static_cast<std::size_t>(regionOf(j, n, r)) * r;
      for (int i = 0; i <= n; ++i) {
        const std::size_t at = static_cast<std::size_t>(j) * side + i;
        plane[at] = static_cast<std::uint8_t>(plane[at] + gradientPrediction(plane, side, i, j));
        image.texels[at * channels + c] =
            decodedValue(regions, c * regionCount + rowRegion + regionOf(i, n, r), plane[at]);
      }
    }
  });
  copySeams(image);
  return image;
}

std::size_t maxEncodedSize(int n, int channels, const CodecParams& params) {
  const std::size_t r = static_cast<std::size_t>(regionsPerSide(params, n));
  return kStreamHeaderSize + 2 + zstdBlockBound(r * r * channels * 3 * sizeof(float)) +
         zstdBlockBound(sampleCount(n) * channels);
}

// Each offset is within half a step, (hi − lo)/510, of the delta; the delta range of a region
// is at most the channel's range. Float rounding of the three operations adds a few ulps.
double errorBound(const FloatImage& image, const CodecParams& params) {
  regionsPerSide(params, image.n);
  double bound = 0;
  for (const ChannelRange& range : channelRanges(image))
    bound = std::max(bound, range.span() / 510.0 + 1e-6 * range.largestMagnitude());
  return bound;
}

} // namespace

Codec makeBytepackCodec() {
  return {kInfo, encode, decode, maxEncodedSize, errorBound};
}

} // namespace octaclay::core
