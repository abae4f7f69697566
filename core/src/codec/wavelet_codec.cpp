#include "octaclay/core/codec/wavelet_codec.h"

#include "codec/codec_list.h"
#include "codec/wavelet_bands.h"
#include "codec/wavelet_quantizer.h"
#include "codec/wavelet_step_search.h"
#include "codec/wavelet_transform.h"
#include "detail/unit_scale.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

namespace octaclay::core {
namespace {

using detail::ChannelCoding;
using detail::CoefficientPlanes;
using detail::Orientation;

// Stream, little-endian: u8 codec code (4), u16 version, u32 N, u8 channels (the header every
// codec's stream starts with); per channel f32 centre, step and DC; then per band, coarsest
// level first, orientations along i, along j, diagonal: u32 length and the band's range-coded
// bytes.
constexpr std::size_t kFixedHeaderBytes = 1 + 2 + 4 + 1;
constexpr std::uint8_t kWaveletCode = 4;
constexpr std::size_t kChannelHeaderBytes = 3 * 4;
constexpr int kMaxChannels = 4;
std::size_t sampleCount(int n) {
  return static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1);
}

[[noreturn]] void invalid(const std::string& what) {
  throw Error(ErrorKind::InvalidInput, "wavelet stream: " + what);
}

class Writer {
public:
  void u8(std::uint8_t v) { bytes.push_back(v); }
  void u16(std::uint16_t v) {
    for (int k = 0; k < 2; ++k)
      u8(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  void u32(std::uint32_t v) {
    for (int k = 0; k < 4; ++k)
      u8(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  void f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }
  std::vector<std::uint8_t> bytes;
};

class Reader {
public:
  explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::size_t remaining() const { return bytes_.size() - at_; }
  std::size_t position() const { return at_; }
  std::uint32_t uint(int count) {
    if (remaining() < static_cast<std::size_t>(count)) invalid("truncated header");
    std::uint32_t v = 0;
    for (int k = 0; k < count; ++k)
      v |= static_cast<std::uint32_t>(bytes_[at_++]) << (8 * k);
    return v;
  }
  float f32() { return std::bit_cast<float>(uint(4)); }
  std::span<const std::uint8_t> take(std::size_t count) {
    const auto part = bytes_.subspan(at_, count);
    at_ += count;
    return part;
  }

private:
  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 0;
};

struct Band {
  int level;
  Orientation orientation;
};

// Coarsest first: a prefix holds whole levels of detail.
std::vector<Band> bandOrder(int n) {
  std::vector<Band> bands;
  for (int level = detail::waveletLevels(n) - 1; level >= 0; --level)
    for (int o = 0; o < detail::kOrientations; ++o)
      bands.push_back({level, static_cast<Orientation>(o)});
  return bands;
}

void requireEncodable(const FloatImage& image, double bound) {
  requireValidSize(image.n);
  if (image.channels < 1 || image.channels > kMaxChannels)
    throw Error(ErrorKind::InvalidArgument,
                "wavelet: " + std::to_string(image.channels) + " channels; it codes 1 to 4");
  if (image.texels.size() != sampleCount(image.n) * static_cast<std::size_t>(image.channels))
    throw Error(ErrorKind::InvalidArgument, "wavelet: the image holds " +
                                                std::to_string(image.texels.size()) +
                                                " floats, not (N+1)² × channels");
  if (!(bound >= kWaveletMinBound && bound <= kWaveletMaxBound))
    throw Error(ErrorKind::InvalidArgument,
                "wavelet: error bound " + std::to_string(bound) +
                    " is outside [1e-6, 0.1] (a fraction of the bounding-box diagonal)");
  for (float v : image.texels)
    if (!std::isfinite(v))
      throw Error(ErrorKind::InvalidArgument, "wavelet: the image holds a non-finite value");
}

// Channel c of the image with each set of identified samples replaced by its mean.
std::vector<float> seamedPlane(const FloatImage& image, int c) {
  const int n = image.n;
  const auto w = static_cast<std::size_t>(n) + 1;
  const auto channels = static_cast<std::size_t>(image.channels);
  std::vector<float> plane(sampleCount(n));
  for (std::size_t k = 0; k < plane.size(); ++k)
    plane[k] = image.texels[k * channels + static_cast<std::size_t>(c)];
  forEachCanonicalRun(n, [&](int j, int begin, int end) {
    for (int i = begin; i < end; ++i) {
      if (i != 0 && i != n && j != 0 && j != n) continue;
      std::array<Sample, 4> copies;
      const int count = identifiedSamples(n, {i, j}, copies);
      double sum = 0;
      for (int k = 0; k < count; ++k)
        sum += plane[static_cast<std::size_t>(copies[static_cast<std::size_t>(k)].j) * w +
                     static_cast<std::size_t>(copies[static_cast<std::size_t>(k)].i)];
      const auto mean = static_cast<float>(sum / count);
      for (int k = 0; k < count; ++k)
        plane[static_cast<std::size_t>(copies[static_cast<std::size_t>(k)].j) * w +
              static_cast<std::size_t>(copies[static_cast<std::size_t>(k)].i)] = mean;
    }
  });
  return plane;
}

double positionDiagonal(const FloatImage& image) {
  const int spatial = std::min(image.channels, 3);
  double sum = 0;
  for (int c = 0; c < spatial; ++c) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (std::size_t k = static_cast<std::size_t>(c); k < image.texels.size();
         k += static_cast<std::size_t>(image.channels)) {
      lo = std::min(lo, image.texels[k]);
      hi = std::max(hi, image.texels[k]);
    }
    sum += (static_cast<double>(hi) - lo) * (static_cast<double>(hi) - lo);
  }
  return std::sqrt(sum);
}

struct Header {
  std::vector<ChannelCoding> channels;
};

Header readHeader(Reader& in, int n, int channels) {
  const auto code = in.uint(1);
  if (code != kWaveletCode)
    invalid("a stream of codec code " + std::to_string(code) + ", not wavelet (" +
            std::to_string(kWaveletCode) + ")");
  const auto version = in.uint(2);
  if (version != kWaveletVersion)
    invalid("version " + std::to_string(version) + ", this build reads " +
            std::to_string(kWaveletVersion));
  const auto storedN = in.uint(4);
  if (storedN != static_cast<std::uint32_t>(n))
    invalid("it was written for N = " + std::to_string(storedN) + ", not " + std::to_string(n));
  const auto storedChannels = in.uint(1);
  if (storedChannels != static_cast<std::uint32_t>(channels))
    invalid("it holds " + std::to_string(storedChannels) + " channels, not " +
            std::to_string(channels));
  Header header;
  for (int c = 0; c < channels; ++c) {
    ChannelCoding coding;
    coding.centre = in.f32();
    coding.step = in.f32();
    coding.dc = in.f32();
    if (!std::isfinite(coding.centre) || !std::isfinite(coding.dc) || !std::isfinite(coding.step) ||
        !(coding.step > 0))
      invalid("a channel's centre, step or DC is not a finite number");
    header.channels.push_back(coding);
  }
  return header;
}

void requireDecodable(int n, int channels) {
  if (!isValidSize(n)) invalid("N = " + std::to_string(n) + " is not a valid size");
  if (channels < 1 || channels > kMaxChannels)
    invalid(std::to_string(channels) + " channels; it codes 1 to 4");
}

// Decodes the header and every band complete within `limit` bytes (all of them, each with no
// byte to spare, unless `prefix`).
FloatImage decodeStream(std::span<const std::uint8_t> stream, int n, int channels,
                        std::size_t limit, bool prefix) {
  requireDecodable(n, channels);
  Reader in(stream.first(std::min(limit, stream.size())));
  const Header header = readHeader(in, n, channels);
  // The band table must hold together before anything of the image's size is allocated.
  if (!prefix) {
    Reader scan = in;
    for (std::size_t k = 0; k < bandOrder(n).size(); ++k) {
      if (scan.remaining() < 4) invalid("truncated band");
      const std::size_t length = scan.uint(4);
      if (length > scan.remaining()) invalid("truncated band");
      scan.take(length);
    }
    if (scan.remaining() != 0) invalid("bytes after the last band");
  }
  CoefficientPlanes planes{n, channels, {}, {}};
  planes.q.assign(static_cast<std::size_t>(channels), std::vector<std::int32_t>(sampleCount(n)));
  if (channels >= 3) planes.magnitude.assign(sampleCount(n), 0);
  const std::vector<Band> bands = bandOrder(n);
  std::array<detail::BandModels, detail::kOrientations> models;
  std::size_t next = 0;
  while (next < bands.size()) {
    // The bands of one level depend only on coarser ones: decode them side by side.
    const int level = bands[next].level;
    std::vector<std::pair<Band, std::span<const std::uint8_t>>> work;
    bool complete = true;
    for (; next < bands.size() && bands[next].level == level; ++next) {
      if (in.remaining() < 4) {
        complete = false;
        break;
      }
      const std::size_t length = in.uint(4);
      if (length > in.remaining()) {
        complete = false;
        break;
      }
      work.push_back({bands[next], in.take(length)});
    }
    if (!complete && !prefix) invalid("truncated band");
    std::array<bool, detail::kOrientations> intact{true, true, true};
    const auto run = [&](std::size_t k) {
      const Band band = work[k].first;
      intact[k] = detail::decodeBand(work[k].second, planes, band.level, band.orientation,
                                     models[static_cast<std::size_t>(band.orientation)]);
    };
    if (level <= 2 && work.size() > 1) {
      std::vector<std::thread> threads;
      for (std::size_t k = 1; k < work.size(); ++k)
        threads.emplace_back(run, k);
      run(0);
      for (auto& t : threads)
        t.join();
    } else {
      for (std::size_t k = 0; k < work.size(); ++k)
        run(k);
    }
    for (std::size_t k = 0; k < work.size(); ++k)
      if (!intact[k]) invalid("a band is damaged");
    if (!complete) break;
  }
  if (!prefix && in.remaining() != 0) invalid("bytes after the last band");

  std::vector<std::vector<float>> rebuilt;
  detail::rebuild(planes, header.channels, rebuilt);
  FloatImage image{n, channels,
                   std::vector<float>(sampleCount(n) * static_cast<std::size_t>(channels))};
  for (std::size_t c = 0; c < rebuilt.size(); ++c)
    for (std::size_t k = 0; k < rebuilt[c].size(); ++k)
      image.texels[k * static_cast<std::size_t>(channels) + c] = rebuilt[c][k];
  // What the encoder wrote decodes near finite input; anything else was damaged.
  for (float v : image.texels)
    if (!std::isfinite(v)) invalid("it decodes to non-finite values");
  return image;
}

// Encodes image (at about unit scale); the stream's centres, steps and DC terms are written
// times 2^back, which scales every decoded value by exactly 2^back.
std::vector<std::uint8_t> encodeAtUnitScale(const FloatImage& image, double bound, int back) {
  const int n = image.n;
  double diagonal = positionDiagonal(image);
  if (!(diagonal > 0)) diagonal = 1; // a single point: bound the error absolutely
  const double target = bound * diagonal;

  std::vector<std::vector<float>> original, coefficients;
  std::vector<ChannelCoding> coding(static_cast<std::size_t>(image.channels));
  for (int c = 0; c < image.channels; ++c) {
    original.push_back(seamedPlane(image, c));
    const auto [lo, hi] = std::minmax_element(original.back().begin(), original.back().end());
    ChannelCoding& cc = coding[static_cast<std::size_t>(c)];
    cc.centre = 0.5f * (*lo + *hi);
    std::vector<float> plane(original.back().size());
    for (std::size_t k = 0; k < plane.size(); ++k)
      plane[k] = original.back()[k] - cc.centre;
    detail::forwardWavelet(plane, n);
    cc.dc = plane[0];
    coefficients.push_back(std::move(plane));
  }
  CoefficientPlanes planes{n, image.channels, {}, {}};
  planes.q.assign(static_cast<std::size_t>(image.channels),
                  std::vector<std::int32_t>(sampleCount(n)));
  detail::chooseWaveletSteps(original, coefficients, coding, target, planes);

  Writer out;
  out.u8(kWaveletCode);
  out.u16(kWaveletVersion);
  out.u32(static_cast<std::uint32_t>(n));
  out.u8(static_cast<std::uint8_t>(image.channels));
  for (const ChannelCoding& cc : coding) {
    out.f32(std::ldexp(cc.centre, back));
    out.f32(std::ldexp(cc.step, back));
    out.f32(std::ldexp(cc.dc, back));
  }
  detail::setVectorMagnitudes(planes);
  std::array<detail::BandModels, detail::kOrientations> models;
  for (const Band& band : bandOrder(n)) {
    const std::vector<std::uint8_t> bytes = detail::encodeBand(
        planes, band.level, band.orientation, models[static_cast<std::size_t>(band.orientation)]);
    out.u32(static_cast<std::uint32_t>(bytes.size()));
    out.bytes.insert(out.bytes.end(), bytes.begin(), bytes.end());
  }
  return std::move(out.bytes);
}

} // namespace

std::vector<std::uint8_t> encodeWavelet(const FloatImage& image, double bound) {
  requireEncodable(image, bound);
  // In the model's own units (detail/unit_scale.h): the step search squares errors in float,
  // which a model 1e-12 or 1e13 across would underflow or overflow. Scaling by a power of two
  // is exact, and so is the decoded image's scaling back.
  const int e = image.channels >= 3 ? detail::unitScaleExponent(positionDiagonal(image)) : 0;
  if (e == 0) return encodeAtUnitScale(image, bound, 0);
  FloatImage scaled = image;
  for (float& v : scaled.texels)
    v = std::ldexp(v, e);
  return encodeAtUnitScale(scaled, bound, -e);
}

FloatImage decodeWavelet(std::span<const std::uint8_t> stream, int n, int channels) {
  return decodeStream(stream, n, channels, stream.size(), false);
}

FloatImage decodeWaveletPrefix(std::span<const std::uint8_t> stream, int n, int channels,
                               std::size_t bytes) {
  return decodeStream(stream, n, channels, bytes, true);
}

std::vector<std::size_t> waveletBandEnds(std::span<const std::uint8_t> stream, int n,
                                         int channels) {
  requireDecodable(n, channels);
  Reader in(stream);
  readHeader(in, n, channels);
  std::vector<std::size_t> ends;
  for (std::size_t k = 0; k < bandOrder(n).size(); ++k) {
    if (in.remaining() < 4) invalid("truncated band");
    const std::size_t length = in.uint(4);
    if (length > in.remaining()) invalid("truncated band");
    in.take(length);
    ends.push_back(in.position());
  }
  if (in.remaining() != 0) invalid("bytes after the last band");
  return ends;
}

Codec makeWaveletCodec() {
  Codec codec;
  codec.info = CodecInfo{"wavelet",
                         4,
                         kWaveletVersion,
                         true,
                         "error bound as a fraction of the bounding-box diagonal, 1e-6 … 0.1 "
                         "(default 1.5e-5, about 96 dB): the RMS over the vertices of the "
                         "position error along the surface normal (across it: 16x)",
                         kWaveletDefaultBound};
  codec.encode = [](const FloatImage& image, const CodecParams& params) {
    return encodeWavelet(image, params.quality > 0 ? params.quality : kWaveletDefaultBound);
  };
  codec.decode = [](std::span<const std::uint8_t> stream, int n, int channels) {
    return decodeWavelet(stream, n, channels);
  };
  codec.maxEncodedSize = [](int n, int channels, const CodecParams&) {
    requireValidSize(n);
    if (channels < 1 || channels > kMaxChannels)
      throw Error(ErrorKind::InvalidArgument,
                  "wavelet: " + std::to_string(channels) + " channels; it codes 1 to 4");
    std::size_t size = kFixedHeaderBytes + kChannelHeaderBytes * static_cast<std::size_t>(channels);
    for (const Band& band : bandOrder(n))
      size += 4 + detail::maxBandBytes(detail::bandSampleCount(n, band.level, band.orientation),
                                       channels);
    return size;
  };
  return codec;
}

} // namespace octaclay::core
