#pragma once

// Reading and writing the small raster images Octaclay ships and exports (material maps,
// environment maps, exported textures): PNG through libpng, the other formats (a mesh's JPEG or
// TIFF texture) through OpenCV's codecs.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace octaclay::core {

/// A float image, row-major from the top row, `channels` floats per pixel in [0, 1].
struct RasterImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels; ///< width × height × channels

  float at(int x, int y, int c) const {
    return pixels[(static_cast<std::size_t>(y) * width + x) * channels + c];
  }
};

/// Reads an image as `channels` (1, 3 or 4) channels in [0, 1]: grey is replicated, a missing
/// alpha is 1, 8- and 16-bit files are scaled by their maximum. Throws Error(Io) when the file
/// cannot be read, Error(InvalidInput) when it is not an image libpng or OpenCV decodes, or is
/// larger than 16384² pixels (PNG) or 1 GiB.
RasterImage readImage(const std::filesystem::path& path, int channels);

/// The image as PNG bytes (values clamped to [0, 1], 8 bits per channel). Throws
/// Error(InvalidArgument) when size and pixels disagree, Error(Io) when encoding fails.
std::vector<std::uint8_t> encodePng(const RasterImage& image);

/// Writes an 8-bit PNG (1, 3 or 4 channels; values clamped to [0, 1]) atomically. Throws
/// Error(InvalidArgument) for a bad image, Error(Io) when it cannot be written.
void writePng(const RasterImage& image, const std::filesystem::path& path);

} // namespace octaclay::core
