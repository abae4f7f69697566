#pragma once

// PNG through libpng's simplified API, not OpenCV's imgcodecs: the first use of imgcodecs
// starts GDAL (Debian's OpenCV is built with it), which a machine without Debian's libraries
// (the GPU benchmarks' bundle) cannot load, and the brushes' materials, the normal maps and the
// plots are all PNG.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core::detail {

/// Whether bytes begin with PNG's eight-byte signature.
bool isPng(std::span<const std::uint8_t> bytes);

/// A decoded PNG: 8 bits a sample, in the file's own layout (1 grey, 2 grey and alpha, 3 RGB,
/// 4 RGBA), rows from the top.
struct DecodedPng {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> samples; ///< width × height × channels
};

/// Decodes PNG bytes (palettes and transparency expanded, 16-bit samples scaled to 8). Throws
/// Error(InvalidInput), naming name, when they are not a PNG libpng decodes or the image would
/// exceed kMaxPngPixels.
DecodedPng decodePng(std::span<const std::uint8_t> bytes, const std::string& name);

/// The most pixels a decoded PNG may hold (16384 × 16384): checked before memory is sized.
inline constexpr std::uint64_t kMaxPngPixels = 16384ull * 16384ull;

/// Encodes 8-bit samples (1 grey, 3 RGB or 4 RGBA channels; rows from the top) as PNG. Throws
/// Error(InvalidArgument) when the sizes disagree, Error(Io) when libpng fails.
std::vector<std::uint8_t> encodePng(std::span<const std::uint8_t> samples, int width, int height,
                                    int channels);

} // namespace octaclay::core::detail
