// `exr`: the layer as an OpenEXR scanline image held in memory, one channel per layer channel:
// float32 with ZIP or PIZ (lossless), float32 with PXR24 (24-bit floats) or half with ZIP.

#include "codec/byte_io.h"
#include "codec/channel_stats.h"
#include "codec/codec_list.h"
#include "codec/grid.h"
#include "detail/exr_memory_stream.h"

#include "octaclay/core/error.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <half.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <thread>

namespace octaclay::core {
namespace {

using namespace detail;

constexpr CodecInfo kInfo{"exr",
                          3,
                          1,
                          true,
                          "ignored; CodecParams::mode chooses zip (default) or piz, both "
                          "bit-exact, pxr24 (24-bit floats) or half",
                          0};

struct Mode {
  std::string_view name;
  Imf::Compression compression;
  Imf::PixelType type;
  bool exact;
};
constexpr std::array<Mode, 4> kModes{{{"zip", Imf::ZIP_COMPRESSION, Imf::FLOAT, true},
                                      {"piz", Imf::PIZ_COMPRESSION, Imf::FLOAT, true},
                                      {"pxr24", Imf::PXR24_COMPRESSION, Imf::FLOAT, false},
                                      {"half", Imf::ZIP_COMPRESSION, Imf::HALF, false}}};

std::uint8_t modeIndex(const CodecParams& params) {
  if (params.mode.empty()) return 0;
  for (std::size_t k = 0; k < kModes.size(); ++k)
    if (kModes[k].name == params.mode) return static_cast<std::uint8_t>(k);
  throw Error(ErrorKind::InvalidArgument,
              "exr: mode '" + params.mode + "' is not one of zip, piz, pxr24, half");
}

class MemoryIStream : public Imf::IStream {
public:
  explicit MemoryIStream(std::span<const std::uint8_t> bytes)
      : Imf::IStream("exr stream"), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || position_ > bytes_.size() || bytes_.size() - position_ < std::size_t(n))
      throw Error(ErrorKind::InvalidInput, "exr stream: truncated OpenEXR data");
    std::memcpy(c, bytes_.data() + position_, static_cast<std::size_t>(n));
    position_ += static_cast<std::size_t>(n);
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t pos) override { position_ = static_cast<std::size_t>(pos); }

private:
  std::span<const std::uint8_t> bytes_;
  std::size_t position_ = 0;
};

std::string channelName(int c) {
  return "C" + std::to_string(c);
}

int exrThreads() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

std::vector<std::uint8_t> encode(const FloatImage& image, const CodecParams& params) {
  requireCodableImage(image, kInfo.id);
  const std::uint8_t mode = modeIndex(params);
  const int side = image.n + 1, channels = image.channels;
  if (kModes[mode].type == Imf::HALF)
    for (const ChannelRange& r : channelRanges(image))
      if (!(r.largestMagnitude() <= 65504.0f))
        throw Error(ErrorKind::InvalidArgument,
                    "exr: values beyond ±65504 do not fit half floats; use zip, piz or pxr24");
  Imf::Header header(side, side);
  header.compression() = kModes[mode].compression;
  for (int c = 0; c < channels; ++c)
    header.channels().insert(channelName(c), Imf::Channel(kModes[mode].type));
  std::vector<half> halves;
  if (kModes[mode].type == Imf::HALF) halves.assign(image.texels.begin(), image.texels.end());
  Imf::FrameBuffer frame;
  for (int c = 0; c < channels; ++c) {
    const bool isHalf = kModes[mode].type == Imf::HALF;
    const std::size_t element = isHalf ? sizeof(half) : sizeof(float);
    char* base = isHalf ? reinterpret_cast<char*>(halves.data() + c)
                        : const_cast<char*>(reinterpret_cast<const char*>(image.texels.data() + c));
    frame.insert(channelName(c), Imf::Slice(kModes[mode].type, base, element * channels,
                                            element * channels * side));
  }
  detail::ExrMemoryStream stream;
  {
    Imf::OutputFile file(stream, header, exrThreads());
    file.setFrameBuffer(frame);
    file.writePixels(side);
  }
  ByteWriter out;
  writeStreamHeader(out, kInfo, image.n, channels);
  out.u8(mode);
  out.append(stream.bytes());
  return out.take();
}

// OpenEXR allocates what a header's attribute sizes and data window say before it reads them,
// so the header is walked here first: every attribute must fit in the stream, and the data
// window must be the (N+1)² grid.
void checkExrHeaderBytes(const ByteReader& owner, std::span<const std::uint8_t> file, int n) {
  ByteReader in(file, "exr stream");
  if (in.u32() != 0x01312f76u) owner.fail("not an OpenEXR image (wrong magic number)");
  if (in.u32() != 2u) owner.fail("not a single-part scanline OpenEXR image");
  const auto nameOf = [&] {
    std::string name;
    for (std::uint8_t c = in.u8(); c != 0; c = in.u8())
      if (name.size() < 255)
        name += static_cast<char>(c);
      else
        owner.fail("OpenEXR attribute name too long");
    return name;
  };
  bool window = false;
  for (int count = 0;; ++count) {
    const std::string name = nameOf();
    if (name.empty()) break;
    if (count >= 64) owner.fail("too many OpenEXR attributes");
    const std::string type = nameOf();
    const std::uint32_t size = in.u32();
    if (size > in.remaining()) owner.fail("OpenEXR attribute " + name + " runs past the end");
    ByteReader value(in.take(size), "exr stream");
    if (name == "dataWindow" || name == "displayWindow") {
      if (type != "box2i" || size != 16) owner.fail("OpenEXR " + name + " is not a box2i");
      const std::uint32_t expected[4] = {0, 0, static_cast<std::uint32_t>(n),
                                         static_cast<std::uint32_t>(n)};
      for (std::uint32_t e : expected)
        if (value.u32() != e) owner.fail("OpenEXR " + name + " is not the (N+1)² grid");
      window = window || name == "dataWindow";
    }
  }
  if (!window) owner.fail("OpenEXR header has no data window");
}

void checkExrHeader(const ByteReader& in, const Imf::Header& header, const Mode& mode, int n,
                    int channels) {
  const Imath::Box2i window = header.dataWindow();
  if (window.min.x != 0 || window.min.y != 0 || window.max.x != n || window.max.y != n)
    in.fail("OpenEXR data window is not the (N+1)² grid");
  if (header.compression() != mode.compression || header.hasTileDescription())
    in.fail("OpenEXR compression or layout differs from the stream's mode");
  int count = 0;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it, ++count)
    if (count >= channels || it.name() != channelName(count) || it.channel().type != mode.type ||
        it.channel().xSampling != 1 || it.channel().ySampling != 1)
      in.fail(std::string("unexpected OpenEXR channel ") + it.name());
  if (count != channels) in.fail("OpenEXR image lacks channels");
}

FloatImage decode(std::span<const std::uint8_t> bytes, int n, int channels) {
  requireDecodableShape(n, channels, kInfo.id);
  ByteReader in(bytes, "exr stream");
  readStreamHeader(in, kInfo, n, channels);
  const std::uint8_t mode = in.u8();
  if (mode >= kModes.size()) in.fail("unknown mode " + std::to_string(mode));
  const auto exrBytes = in.take(in.remaining());
  checkExrHeaderBytes(in, exrBytes, n);
  MemoryIStream stream(exrBytes);
  FloatImage image{n, channels, std::vector<float>(sampleCount(n) * channels)};
  const std::size_t xStride = sizeof(float) * channels;
  try {
    Imf::InputFile file(stream, exrThreads());
    checkExrHeader(in, file.header(), kModes[mode], n, channels);
    if (!file.isComplete()) in.fail("OpenEXR data truncated");
    Imf::FrameBuffer frame;
    for (int c = 0; c < channels; ++c)
      frame.insert(channelName(c),
                   Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(image.texels.data() + c), xStride,
                              xStride * (n + 1)));
    file.setFrameBuffer(frame);
    file.readPixels(0, n);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    in.fail(std::string("corrupt OpenEXR data: ") + e.what());
  }
  if (!kModes[mode].exact) copySeams(image);
  return image;
}

std::size_t maxEncodedSize(int n, int channels, const CodecParams& params) {
  modeIndex(params);
  // OpenEXR stores incompressible lines raw: pixels plus header, offset table and per-line
  // headers, with generous slack for the header's attributes.
  const std::size_t side = static_cast<std::size_t>(n) + 1;
  return kStreamHeaderSize + 1 + sampleCount(n) * channels * sizeof(float) + side * 16 + 4096;
}

// PXR24 keeps 15 of float32's 23 mantissa bits (rounded); half keeps 10 and flushes below 2^-24.
double errorBound(const FloatImage& image, const CodecParams& params) {
  const Mode& mode = kModes[modeIndex(params)];
  if (mode.exact) return 0;
  double largest = 0;
  for (const ChannelRange& r : channelRanges(image))
    largest = std::max(largest, double(r.largestMagnitude()));
  return mode.type == Imf::HALF ? largest * 0x1p-11 + 0x1p-24 : largest * 0x1p-16;
}

} // namespace

Codec makeExrCodec() {
  return {kInfo, encode, decode, maxEncodedSize, errorBound};
}

} // namespace octaclay::core
