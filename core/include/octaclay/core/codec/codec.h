#pragma once

// Geometry-image codecs (thesis, chapter 5, and beyond it): each turns the (N+1)² float
// planes of a layer into bytes and back. Decoders never trust their input: a stream that is
// malformed for that N and channel count (truncated, wrong header, sizes that disagree) is
// refused with Error(InvalidInput); a damaged payload that still parses decodes to some image
// of the right shape. Never a crash or an allocation beyond what N and channels imply; the
// .ocz container's CRC-32 refuses damaged files before any codec sees them.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core {

/// `channels` float planes on the (N+1)² vertex-centred octahedral grid, interleaved
/// row-major like GeometryImage (texel (i, j) channel c at ((j·(N+1) + i)·channels + c).
struct FloatImage {
  int n = 0;
  int channels = 0;
  std::vector<float> texels;
};

struct CodecParams {
  /// Codec-specific, documented in each codec's CodecInfo::quality: the regions per side R of
  /// the mip-map (a power of two, 1 … N) for `bytepack`, the JPEG-style quality 1 … 100 for
  /// `dct`, the error bound as a fraction of the bounding-box diagonal for `wavelet`; ignored
  /// by lossless codecs. 0 or less: the codec's default.
  double quality = 0;
  /// `exr` only: "zip", "piz", "pxr24" or "half".
  std::string mode;
};

struct CodecInfo {
  std::string_view id;       ///< "bytepack", "dct", "exr", "wavelet", "lossless"
  std::uint8_t code = 0;     ///< stored in the .ocz container
  std::uint16_t version = 0; ///< written in each stream and checked on decode
  bool lossy = true;         ///< some parameters lose precision (exr: only pxr24 and half)
  std::string_view quality;  ///< what CodecParams::quality means, its range and default
  double defaultQuality = 0;
};

struct Codec {
  CodecInfo info;
  /// Throws Error(InvalidArgument) for parameters out of range or an image it cannot code.
  std::function<std::vector<std::uint8_t>(const FloatImage&, const CodecParams&)> encode;
  /// n and channels come from the container; the stream must agree with them.
  std::function<FloatImage(std::span<const std::uint8_t>, int n, int channels)> decode;
  /// Upper bound of encode's output size for any image of this n and channels.
  std::function<std::size_t(int n, int channels, const CodecParams&)> maxEncodedSize;
  /// The largest |decode(encode(image)) − image| any sample may have, per the codec's own
  /// analysis (0 for exact codecs); empty when the codec states no such bound.
  std::function<double(const FloatImage&, const CodecParams&)> errorBound;
};

/// All codecs, in the order above. Lossy codecs seam their output: identified samples decode
/// to exactly equal values.
const std::vector<Codec>& codecs();
/// nullptr when no codec has this id (or code).
const Codec* findCodec(std::string_view id);
const Codec* findCodec(std::uint8_t code);

} // namespace octaclay::core
