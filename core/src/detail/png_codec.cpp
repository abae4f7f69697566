#include "png_codec.h"

#include "octaclay/core/error.h"

#include <png.h>

#include <algorithm>
#include <array>

namespace octaclay::core::detail {
namespace {

// Frees libpng's state however the caller leaves.
struct ImageGuard {
  png_image& image;
  ~ImageGuard() { png_image_free(&image); }
};

} // namespace

bool isPng(std::span<const std::uint8_t> bytes) {
  constexpr std::array<std::uint8_t, 8> kSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return bytes.size() >= kSignature.size() &&
         std::equal(kSignature.begin(), kSignature.end(), bytes.begin());
}

DecodedPng decodePng(std::span<const std::uint8_t> bytes, const std::string& name) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  ImageGuard guard{image};
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
    throw Error(ErrorKind::InvalidInput, name + ": not a readable PNG (" + image.message + ")");
  if (static_cast<std::uint64_t>(image.width) * image.height > kMaxPngPixels)
    throw Error(ErrorKind::InvalidInput, name + ": a PNG of " + std::to_string(image.width) +
                                             " × " + std::to_string(image.height) +
                                             " pixels is larger than Octaclay reads (16384²)");
  // The file's own grey or colour and alpha, at 8 bits: no colour conversion, no premultiplying
  // (only the 16-bit "linear" formats premultiply); 16-bit files are scaled, not re-gamma'd.
  image.format &= PNG_FORMAT_FLAG_COLOR | PNG_FORMAT_FLAG_ALPHA;
  image.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
  DecodedPng out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.channels = static_cast<int>(PNG_IMAGE_PIXEL_CHANNELS(image.format));
  out.samples.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.samples.data(), 0, nullptr))
    throw Error(ErrorKind::InvalidInput, name + ": a damaged PNG (" + image.message + ")");
  return out;
}

std::vector<std::uint8_t> encodePng(std::span<const std::uint8_t> samples, int width, int height,
                                    int channels) {
  if (width <= 0 || height <= 0 || (channels != 1 && channels != 3 && channels != 4) ||
      samples.size() != static_cast<std::size_t>(width) * height * channels)
    throw Error(ErrorKind::InvalidArgument, "encodePng: the image's size and samples disagree");
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = channels == 1 ? PNG_FORMAT_GRAY : channels == 3 ? PNG_FORMAT_RGB : PNG_FORMAT_RGBA;
  ImageGuard guard{image};
  // First the size, then the bytes (libpng's two-call form).
  png_alloc_size_t size = 0;
  if (!png_image_write_get_memory_size(image, size, 0, samples.data(), 0, nullptr))
    throw Error(ErrorKind::Io,
                std::string("cannot encode the image as PNG (") + image.message + ")");
  std::vector<std::uint8_t> bytes(size);
  if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, samples.data(), 0, nullptr))
    throw Error(ErrorKind::Io,
                std::string("cannot encode the image as PNG (") + image.message + ")");
  bytes.resize(size);
  return bytes;
}

} // namespace octaclay::core::detail
