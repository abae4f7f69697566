#include "octaclay/core/document/image_io.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdint>
#include <system_error>
#include <vector>

namespace octaclay::core {

RasterImage readImage(const std::filesystem::path& path, int channels) {
  if (channels != 1 && channels != 3 && channels != 4)
    throw Error(ErrorKind::InvalidArgument, "images are read as 1, 3 or 4 channels");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(ErrorKind::Io, path.string() + ": no such file");
  cv::Mat raw;
  try {
    raw = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw Error(ErrorKind::InvalidInput,
                path.string() + ": not a readable image (" + e.what() + ")");
  }
  if (raw.empty())
    throw Error(ErrorKind::InvalidInput,
                path.string() + ": not an image (PNG, JPEG, TIFF …) this build can decode");
  const double scale = raw.depth() == CV_8U ? 1.0 / 255 : raw.depth() == CV_16U ? 1.0 / 65535 : 1.0;
  cv::Mat converted;
  raw.convertTo(converted, CV_32F, scale);
  // OpenCV keeps colour as BGR(A): reorder to RGB(A) and adapt the channel count.
  cv::Mat out;
  const int have = converted.channels();
  if (channels == 1 && have == 1)
    out = converted;
  else if (channels == 1)
    cv::cvtColor(converted, out, have == 3 ? cv::COLOR_BGR2GRAY : cv::COLOR_BGRA2GRAY);
  else if (channels == 3)
    cv::cvtColor(converted, out,
                 have == 1   ? cv::COLOR_GRAY2RGB
                 : have == 3 ? cv::COLOR_BGR2RGB
                             : cv::COLOR_BGRA2RGB);
  else
    cv::cvtColor(converted, out,
                 have == 1   ? cv::COLOR_GRAY2RGBA
                 : have == 3 ? cv::COLOR_BGR2RGBA
                             : cv::COLOR_BGRA2RGBA);
  RasterImage image;
  image.width = out.cols;
  image.height = out.rows;
  image.channels = channels;
  image.pixels.resize(static_cast<std::size_t>(out.cols) * out.rows * channels);
  for (int y = 0; y < out.rows; ++y) {
    const float* row = out.ptr<float>(y);
    std::copy(row, row + static_cast<std::ptrdiff_t>(out.cols) * channels,
              image.pixels.begin() + static_cast<std::ptrdiff_t>(y) * out.cols * channels);
  }
  return image;
}

std::vector<std::uint8_t> encodePng(const RasterImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      (image.channels != 1 && image.channels != 3 && image.channels != 4) ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * image.channels)
    throw Error(ErrorKind::InvalidArgument, "encodePng: the image's size and pixels disagree");
  cv::Mat rgb(image.height, image.width, CV_8UC(image.channels));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width * image.channels; ++x)
      rgb.ptr<std::uint8_t>(y)[x] = static_cast<std::uint8_t>(
          std::clamp(image.pixels[static_cast<std::size_t>(y) * image.width * image.channels + x],
                     0.0f, 1.0f) *
              255.0f +
          0.5f);
  cv::Mat bgr;
  if (image.channels == 3)
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  else if (image.channels == 4)
    cv::cvtColor(rgb, bgr, cv::COLOR_RGBA2BGRA);
  else
    bgr = rgb;
  std::vector<std::uint8_t> bytes;
  bool ok = false;
  try {
    ok = cv::imencode(".png", bgr, bytes);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) throw Error(ErrorKind::Io, "cannot encode the image as PNG");
  return bytes;
}

void writePng(const RasterImage& image, const std::filesystem::path& path) {
  // Encoded in memory and written by the checked writer: imwrite does not report a failed close.
  writeBytesAtomically(path, encodePng(image));
}

} // namespace octaclay::core
