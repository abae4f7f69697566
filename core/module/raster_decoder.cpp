// liboctaclay_raster_decoder: OpenCV's imgcodecs behind a C interface (raster_decoder.h), loaded
// by core's image_io on the first non-PNG image.
#include "raster_decoder.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace {

int fail(char* message, std::size_t messageSize, const std::string& why) {
  if (messageSize > 0) {
    const std::size_t n = std::min(why.size(), messageSize - 1);
    std::memcpy(message, why.data(), n);
    message[n] = '\0';
  }
  return 1;
}

} // namespace

extern "C" int octaclay_decode_raster(const unsigned char* bytes, std::size_t size, int* width,
                                      int* height, int* channels, float** pixels, char* message,
                                      std::size_t messageSize) {
  try {
    const std::vector<unsigned char> data(bytes, bytes + size);
    const cv::Mat raw = cv::imdecode(data, cv::IMREAD_UNCHANGED);
    if (raw.empty())
      return fail(message, messageSize, "not an image (PNG, JPEG, TIFF …) this build can decode");
    const double scale = raw.depth() == CV_8U    ? 1.0 / 255
                         : raw.depth() == CV_16U ? 1.0 / 65535
                                                 : 1.0;
    cv::Mat converted;
    raw.convertTo(converted, CV_32F, scale);
    const int have = converted.channels();
    if (have != 1 && have != 3 && have != 4)
      return fail(message, messageSize,
                  "an image of " + std::to_string(have) + " channels (1, 3 or 4 are read)");
    if (!converted.isContinuous()) converted = converted.clone();
    const std::size_t count =
        static_cast<std::size_t>(converted.cols) * static_cast<std::size_t>(converted.rows);
    auto* out = static_cast<float*>(std::malloc(count * static_cast<std::size_t>(have) * 4));
    if (!out) return fail(message, messageSize, "not enough memory to decode it");
    const float* in = converted.ptr<float>(0);
    // OpenCV keeps colour as BGR(A): red and blue swap places.
    for (std::size_t p = 0; p < count; ++p)
      for (int c = 0; c < have; ++c) {
        const int from = have >= 3 && c != 1 && c != 3 ? 2 - c : c;
        out[p * static_cast<std::size_t>(have) + static_cast<std::size_t>(c)] =
            in[p * static_cast<std::size_t>(have) + static_cast<std::size_t>(from)];
      }
    *width = converted.cols;
    *height = converted.rows;
    *channels = have;
    *pixels = out;
    return 0;
  } catch (const std::exception& e) {
    return fail(message, messageSize, std::string("not a readable image (") + e.what() + ")");
  } catch (...) {
    return fail(message, messageSize, "not a readable image");
  }
}

extern "C" void octaclay_free_raster(float* pixels) {
  std::free(pixels);
}
