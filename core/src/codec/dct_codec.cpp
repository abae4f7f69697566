// `dct`: the thesis's floating-point JPEG (5.3). Each channel, less its minimum, is cut into
// 8 × 8 blocks (the (N+1)² grid padded by repeating its last row and column), transformed by
// OpenCV (the DCT matrix from cv::dct, applied to bands of blocks by cv::gemm), and each
// coefficient divided by JPEG's luminance table scaled by the quality (libjpeg's rule) times a unit
// of the channel's range / 2^14, then rounded. The integers go frequency by frequency (DC
// differenced across blocks) as varints into a zstd block per channel.

#include "codec/byte_io.h"
#include "codec/channel_stats.h"
#include "codec/codec_list.h"
#include "codec/grid.h"
#include "codec/zstd_blocks.h"

#include "octaclay/core/error.h"

#include <opencv2/core.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace octaclay::core {
namespace {

using namespace detail;

constexpr CodecInfo kInfo{
    "dct",
    2,
    1,
    true,
    "JPEG quality 1 … 100 (default 75): libjpeg's scaling of the luminance table, in units of "
    "the channel's range / 16384; 100 quantizes every coefficient by one unit",
    75};
constexpr int kZstdLevel = 9;
constexpr double kUnitsPerRange = 16384;

constexpr std::array<int, 64> kLuminance{
    16, 11, 10, 16, 24,  40,  51,  61,  12, 12, 14, 19, 26,  58,  60,  55,
    14, 13, 16, 24, 40,  57,  69,  56,  14, 17, 22, 29, 51,  87,  80,  62,
    18, 22, 37, 56, 68,  109, 103, 77,  24, 35, 55, 64, 81,  104, 113, 92,
    49, 64, 78, 87, 103, 121, 120, 101, 72, 92, 95, 98, 112, 100, 103, 99};

constexpr std::array<int, 64> kZigzag{
    0,  1,  8,  16, 9,  2,  3,  10, 17, 24, 32, 25, 18, 11, 4,  5,  12, 19, 26, 33, 40, 48,
    41, 34, 27, 20, 13, 6,  7,  14, 21, 28, 35, 42, 49, 56, 57, 50, 43, 36, 29, 22, 15, 23,
    30, 37, 44, 51, 58, 59, 52, 45, 38, 31, 39, 46, 53, 60, 61, 54, 47, 55, 62, 63};

int qualityOf(const CodecParams& params) {
  const double q = params.quality > 0 ? params.quality : kInfo.defaultQuality;
  if (q < 1 || q > 100 || q != std::floor(q))
    throw Error(ErrorKind::InvalidArgument,
                "dct: quality must be a whole number from 1 to 100, not " + std::to_string(q));
  return static_cast<int>(q);
}

// The table in units, as libjpeg scales it for a quality.
std::array<int, 64> quantTable(int quality) {
  const int scale = quality < 50 ? 5000 / quality : 200 - 2 * quality;
  std::array<int, 64> table{};
  for (int k = 0; k < 64; ++k)
    table[k] = std::clamp((kLuminance[k] * scale + 50) / 100, 1, 32767);
  return table;
}

// A channel's quantizer unit; 1 for a flat or denormal-thin channel, whose coefficients all
// round to zero either way.
float unitOf(const ChannelRange& range) {
  const float unit = static_cast<float>(range.span() / kUnitsPerRange);
  return unit >= std::numeric_limits<float>::min() ? unit : 1.0f;
}

struct Blocks {
  int perRow = 0, perColumn = 0;
  int count() const { return perRow * perColumn; }
};

Blocks blocksFor(int n) {
  const int b = (n + 1 + 7) / 8;
  return {b, b};
}

// The orthonormal 8-point DCT-II matrix C, from OpenCV's DCT of the unit vectors.
const cv::Mat& dctMatrix() {
  static const cv::Mat c = [] {
    cv::Mat transposed;
    cv::dct(cv::Mat::eye(8, 8, CV_32F), transposed, cv::DCT_ROWS);
    return cv::Mat(transposed.t());
  }();
  return c;
}

// A band of 8 image rows (8 × W, W = 8·blocks) holds a row of blocks side by side; C·band
// transforms every block's columns at once, and the same memory viewed as W rows of 8 holds
// one block row per row, so ·Cᵀ transforms the rows. Coefficient (u, v) of block b ends at
// band(u, 8b + v). The inverse runs the steps backwards with the transposes.
cv::Mat transformBand(const cv::Mat& band, bool inverse) {
  const cv::Mat& c = dctMatrix();
  cv::Mat first, second;
  if (!inverse) {
    cv::gemm(c, band, 1, cv::noArray(), 0, first);
    cv::gemm(first.reshape(1, band.cols), c, 1, cv::noArray(), 0, second, cv::GEMM_2_T);
    return second.reshape(1, 8);
  }
  cv::gemm(band.reshape(1, band.cols), c, 1, cv::noArray(), 0, first);
  cv::gemm(c, first.reshape(1, 8), 1, cv::noArray(), 0, second, cv::GEMM_1_T);
  return second;
}

// Band `by` of a plane (side²), less offset, padded by repeating the last row and column.
cv::Mat gatherBand(const std::vector<float>& plane, int side, const Blocks& blocks, int by,
                   float offset) {
  cv::Mat band(8, blocks.perRow * 8, CV_32F);
  for (int y = 0; y < 8; ++y) {
    const int j = std::min(by * 8 + y, side - 1);
    float* row = band.ptr<float>(y);
    for (int x = 0; x < band.cols; ++x)
      row[x] = plane[static_cast<std::size_t>(j) * side + std::min(x, side - 1)] - offset;
  }
  return band;
}

void putVarint(std::vector<std::uint8_t>& out, std::uint32_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<std::uint8_t>(v));
}

std::uint32_t zigzag(std::int32_t v) {
  return (static_cast<std::uint32_t>(v) << 1) ^ static_cast<std::uint32_t>(v >> 31);
}

std::int32_t unzigzag(std::uint32_t v) {
  return static_cast<std::int32_t>(v >> 1) ^ -static_cast<std::int32_t>(v & 1);
}

std::vector<std::uint8_t> encodeChannel(const FloatImage& image, int c, const ChannelRange& range,
                                        const std::array<int, 64>& table) {
  const int side = image.n + 1;
  const Blocks blocks = blocksFor(image.n);
  const std::vector<float> plane = channelPlane(image, c);
  const float unit = unitOf(range);
  // coefficients[k][block], k in zigzag order
  std::vector<std::int32_t> coefficients(static_cast<std::size_t>(blocks.count()) * 64);
  for (int by = 0; by < blocks.perColumn; ++by) {
    const cv::Mat band = transformBand(gatherBand(plane, side, blocks, by, range.min), false);
    for (int bx = 0; bx < blocks.perRow; ++bx) {
      const std::size_t b = static_cast<std::size_t>(by) * blocks.perRow + bx;
      for (int k = 0; k < 64; ++k) {
        const int at = kZigzag[k];
        const float coefficient = band.at<float>(at / 8, bx * 8 + at % 8);
        coefficients[k * blocks.count() + b] = static_cast<std::int32_t>(
            std::lround(coefficient / (static_cast<float>(table[at]) * unit)));
      }
    }
  }
  std::vector<std::uint8_t> varints;
  std::int32_t previousDc = 0;
  for (std::size_t k = 0; k < coefficients.size(); ++k) {
    std::int32_t v = coefficients[k];
    if (k < static_cast<std::size_t>(blocks.count())) {
      v -= previousDc;
      previousDc = coefficients[k];
    }
    putVarint(varints, zigzag(v));
  }
  ByteWriter out;
  out.f32(range.min);
  out.f32(unit);
  out.u32(static_cast<std::uint32_t>(varints.size()));
  writeZstdBlock(out, varints, kZstdLevel);
  return out.take();
}

std::vector<std::uint8_t> encode(const FloatImage& image, const CodecParams& params) {
  requireCodableImage(image, kInfo.id);
  const int quality = qualityOf(params);
  const auto table = quantTable(quality);
  const auto ranges = channelRanges(image);
  for (const ChannelRange& r : ranges)
    if (!std::isfinite(r.span()))
      throw Error(ErrorKind::InvalidArgument, "dct: the image holds non-finite values");
  std::vector<std::vector<std::uint8_t>> chunks(image.channels);
  parallelTasks(image.channels,
                [&](int c) { chunks[c] = encodeChannel(image, c, ranges[c], table); });
  ByteWriter out;
  writeStreamHeader(out, kInfo, image.n, image.channels);
  out.u8(static_cast<std::uint8_t>(quality));
  for (const auto& chunk : chunks)
    out.append(chunk);
  return out.take();
}

struct DecodedChannel {
  float offset = 0, unit = 1;
  std::vector<std::int32_t> coefficients;
};

DecodedChannel readChannel(ByteReader& in, const Blocks& blocks) {
  DecodedChannel channel;
  channel.offset = in.f32();
  channel.unit = in.f32();
  const std::uint32_t varintBytes = in.u32();
  const std::size_t count = static_cast<std::size_t>(blocks.count()) * 64;
  if (varintBytes < count || varintBytes > count * 5)
    in.fail("coefficient block of " + std::to_string(varintBytes) + " bytes cannot hold " +
            std::to_string(count) + " coefficients");
  const auto varints = readZstdBlock(in, varintBytes);
  channel.coefficients.resize(count);
  std::size_t at = 0;
  std::int32_t previousDc = 0;
  for (std::size_t k = 0; k < count; ++k) {
    std::uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      if (at >= varints.size()) in.fail("coefficients end early");
      if (shift > 28) in.fail("coefficient longer than 32 bits");
      const std::uint8_t byte = varints[at++];
      v |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
      if (!(byte & 0x80)) break;
    }
    if (v > 0xffffffffu) in.fail("coefficient longer than 32 bits");
    std::int32_t value = unzigzag(static_cast<std::uint32_t>(v));
    if (k < static_cast<std::size_t>(blocks.count())) {
      value = static_cast<std::int32_t>(static_cast<std::uint32_t>(value) +
                                        static_cast<std::uint32_t>(previousDc));
      previousDc = value;
    }
    channel.coefficients[k] = value;
  }
  if (at != varints.size()) in.fail("coefficient block longer than its blocks");
  return channel;
}

FloatImage decode(std::span<const std::uint8_t> bytes, int n, int channels) {
  requireDecodableShape(n, channels, kInfo.id);
  ByteReader in(bytes, "dct stream");
  readStreamHeader(in, kInfo, n, channels);
  const int quality = in.u8();
  if (quality < 1 || quality > 100) in.fail("quality " + std::to_string(quality) + " out of range");
  const auto table = quantTable(quality);
  const Blocks blocks = blocksFor(n);
  std::vector<DecodedChannel> decoded;
  for (int c = 0; c < channels; ++c)
    decoded.push_back(readChannel(in, blocks));
  in.expectEnd();

  const int side = n + 1;
  FloatImage image{n, channels, std::vector<float>(sampleCount(n) * channels)};
  parallelTasks(channels * blocks.perColumn, [&](int task) {
    const int c = task / blocks.perColumn, by = task % blocks.perColumn;
    const DecodedChannel& channel = decoded[c];
    cv::Mat coefficients(8, blocks.perRow * 8, CV_32F);
    for (int bx = 0; bx < blocks.perRow; ++bx) {
      const std::size_t b = static_cast<std::size_t>(by) * blocks.perRow + bx;
      for (int k = 0; k < 64; ++k) {
        const int at = kZigzag[k];
        coefficients.at<float>(at / 8, bx * 8 + at % 8) =
            static_cast<float>(channel.coefficients[k * blocks.count() + b]) *
            (static_cast<float>(table[at]) * channel.unit);
      }
    }
    const cv::Mat band = transformBand(coefficients, true);
    for (int y = 0; y < 8 && by * 8 + y < side; ++y) {
      const float* row = band.ptr<float>(y);
      const std::size_t j = static_cast<std::size_t>(by * 8 + y);
      for (int x = 0; x < side; ++x)
        image.texels[(j * side + x) * channels + c] = row[x] + channel.offset;
    }
  });
  copySeams(image);
  return image;
}

std::size_t maxEncodedSize(int n, int channels, const CodecParams& params) {
  qualityOf(params);
  const std::size_t count = static_cast<std::size_t>(blocksFor(n).count()) * 64;
  // Coefficients are below 2^21 in magnitude (8 × range over one unit), so ≤ 4 varint bytes.
  return kStreamHeaderSize + 1 + channels * (12 + zstdBlockBound(count * 4));
}

// Each coefficient is off by at most half its step; basis function (u, v) of the orthonormal
// 8 × 8 DCT is at most C(u)·C(v)/4 in magnitude (C(0) = 1/√2, else 1), so a sample is off by
// at most Σ step·C(u)·C(v)/8, plus float rounding.
double errorBound(const FloatImage& image, const CodecParams& params) {
  const auto table = quantTable(qualityOf(params));
  double weighted = 0;
  for (int u = 0; u < 8; ++u)
    for (int v = 0; v < 8; ++v)
      weighted += table[u * 8 + v] * (u == 0 ? M_SQRT1_2 : 1.0) * (v == 0 ? M_SQRT1_2 : 1.0) / 8;
  double bound = 0;
  for (const ChannelRange& r : channelRanges(image))
    bound = std::max(bound, weighted * unitOf(r) + 1e-5 * (r.span() + r.largestMagnitude()));
  return bound;
}

} // namespace

Codec makeDctCodec() {
  return {kInfo, encode, decode, maxEncodedSize, errorBound};
}

} // namespace octaclay::core
