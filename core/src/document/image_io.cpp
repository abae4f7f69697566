#include "octaclay/core/document/image_io.h"

#include "../../module/raster_decoder.h"
#include "detail/png_codec.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace octaclay::core {

namespace {

// The most bytes an image file may have: beyond any texture or map Octaclay reads.
constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t(1) << 30;

std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(ErrorKind::Io, path.string() + ": no such file");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(ErrorKind::Io, path.string() + ": cannot read (" + ec.message() + ")");
  if (size > kMaxImageFileBytes)
    throw Error(ErrorKind::InvalidInput, path.string() + ": an image file of " +
                                             std::to_string(size >> 20) +
                                             " MiB is larger than Octaclay reads (1 GiB)");
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
    throw Error(ErrorKind::Io, path.string() + ": cannot read");
  return bytes;
}

// value (0–255 or 0–65535 samples as floats in [0, 1]) of pixel i in a layout of have channels
// (1 grey, 2 grey and alpha, 3 RGB, 4 RGBA) as want channels (1, 3 or 4).
template <typename Sample>
RasterImage convertChannels(int width, int height, int have, const Sample& sample, int want) {
  RasterImage image;
  image.width = width;
  image.height = height;
  image.channels = want;
  const std::size_t count = static_cast<std::size_t>(width) * height;
  image.pixels.resize(count * want);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t in = i * have;
    const bool colour = have >= 3;
    const float r = sample(in), g = colour ? sample(in + 1) : r, b = colour ? sample(in + 2) : r;
    const float a = have == 2 ? sample(in + 1) : have == 4 ? sample(in + 3) : 1.0f;
    float* out = image.pixels.data() + i * want;
    if (want == 1) {
      out[0] = colour ? 0.299f * r + 0.587f * g + 0.114f * b : r; // OpenCV's and Rec. 601 grey
      continue;
    }
    out[0] = r;
    out[1] = g;
    out[2] = b;
    if (want == 4) out[3] = a;
  }
  return image;
}

// OpenCV's codecs, loaded on first use (module/raster_decoder.h says why): the module built
// beside core (OCTACLAY_RASTER_DECODER), else one next to the program or on the library path.
struct RasterDecoder {
  decltype(&octaclay_decode_raster) decode = nullptr;
  decltype(&octaclay_free_raster) free = nullptr;
  std::string problem; ///< why it could not be loaded
};

const RasterDecoder& rasterDecoder() {
  static const RasterDecoder decoder = [] {
    RasterDecoder d;
    std::vector<std::string> candidates{OCTACLAY_RASTER_DECODER};
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::string name = std::filesystem::path(OCTACLAY_RASTER_DECODER).filename().string();
    if (!ec) candidates.push_back((self.parent_path() / name).string());
    candidates.push_back(name);
    for (const std::string& candidate : candidates) {
      void* handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        if (const char* why = ::dlerror(); why && d.problem.empty()) d.problem = why;
        continue;
      }
      d.decode =
          reinterpret_cast<decltype(d.decode)>(::dlsym(handle, OCTACLAY_DECODE_RASTER_SYMBOL));
      d.free = reinterpret_cast<decltype(d.free)>(::dlsym(handle, OCTACLAY_FREE_RASTER_SYMBOL));
      if (d.decode && d.free) return d;
      d.problem = candidate + " lacks " OCTACLAY_DECODE_RASTER_SYMBOL;
      d.decode = nullptr;
      d.free = nullptr;
    }
    return d;
  }();
  return decoder;
}

// Formats other than PNG (a mesh's JPEG or TIFF texture) through OpenCV's codecs.
RasterImage decodeWithOpenCv(const std::vector<std::uint8_t>& bytes,
                             const std::filesystem::path& path, int channels) {
  const RasterDecoder& decoder = rasterDecoder();
  if (!decoder.decode)
    throw Error(ErrorKind::Io, path.string() +
                                   ": an image other than PNG needs OpenCV's decoders, which "
                                   "could not be loaded (" +
                                   decoder.problem + ")");
  int width = 0, height = 0, have = 0;
  float* pixels = nullptr;
  std::array<char, 512> message{};
  if (decoder.decode(bytes.data(), bytes.size(), &width, &height, &have, &pixels, message.data(),
                     message.size()) != 0)
    throw Error(ErrorKind::InvalidInput, path.string() + ": " + message.data());
  const std::unique_ptr<float, decltype(decoder.free)> owned(pixels, decoder.free);
  const float* data = owned.get();
  const auto sample = [data](std::size_t k) { return data[k]; };
  return convertChannels(width, height, have, sample, channels);
}

} // namespace

RasterImage readImage(const std::filesystem::path& path, int channels) {
  if (channels != 1 && channels != 3 && channels != 4)
    throw Error(ErrorKind::InvalidArgument, "images are read as 1, 3 or 4 channels");
  const std::vector<std::uint8_t> bytes = readFileBytes(path);
  if (!detail::isPng(bytes)) return decodeWithOpenCv(bytes, path, channels);
  const detail::DecodedPng png = detail::decodePng(bytes, path.string());
  const auto sample = [&png](std::size_t k) { return png.samples[k] / 255.0f; };
  return convertChannels(png.width, png.height, png.channels, sample, channels);
}

std::vector<std::uint8_t> encodePng(const RasterImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      (image.channels != 1 && image.channels != 3 && image.channels != 4) ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * image.channels)
    throw Error(ErrorKind::InvalidArgument, "encodePng: the image's size and pixels disagree");
  std::vector<std::uint8_t> samples(image.pixels.size());
  std::transform(image.pixels.begin(), image.pixels.end(), samples.begin(), [](float v) {
    return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
  });
  return detail::encodePng(samples, image.width, image.height, image.channels);
}

void writePng(const RasterImage& image, const std::filesystem::path& path) {
  // Encoded in memory and written by the checked writer, all or nothing.
  writeBytesAtomically(path, encodePng(image));
}

} // namespace octaclay::core
