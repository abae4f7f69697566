#include "octaclay/core/document/document_io.h"

#include "detail/exr_memory_stream.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>
#include <half.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <memory>
#include <new>
#include <thread>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {

constexpr const char* kFormatAttribute = "octaclay.format";
constexpr const char* kParameterizationAttribute = "octaclay.parameterization";
constexpr const char* kSamplingAttribute = "octaclay.sampling";
constexpr std::array<const char*, 3> kPositionChannels{"P.X", "P.Y", "P.Z"};
constexpr int kLargestCompressedSize = 2048;

// OpenEXR's thread pool pays off for compressed files only: on uncompressed ones its one-line
// tasks made reading 60 % slower here.
int exrThreads(Imf::Compression compression) {
  return compression == Imf::NO_COMPRESSION
             ? 0
             : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

std::unique_ptr<Imf::InputFile> openExr(const fs::path& path) {
  auto file = std::make_unique<Imf::InputFile>(path.c_str(), 0);
  const Imf::Compression compression = file->header().compression();
  if (exrThreads(compression) > 0)
    file = std::make_unique<Imf::InputFile>(path.c_str(), exrThreads(compression));
  return file;
}

[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
  throw Error(ErrorKind::InvalidInput, path.string() + ": " + why);
}

// OpenEXR's own message for a non-EXR file is obscure; check the magic number first.
void requireExrMagic(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw Error(ErrorKind::Io, "cannot open " + path.string() + ": it is a folder, not a document");
  // A pipe or device would block or never end: only regular files are read.
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec))
    throw Error(ErrorKind::Io, "cannot open " + path.string() + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error(ErrorKind::Io, "cannot open " + path.string() +
                                   (fs::exists(path) ? ": permission denied" : ": no such file"));
  unsigned char magic[4] = {};
  in.read(reinterpret_cast<char*>(magic), 4);
  if (in.gcount() != 4 || magic[0] != 0x76 || magic[1] != 0x2f || magic[2] != 0x31 ||
      magic[3] != 0x01)
    refuse(path, "not an OpenEXR file (wrong magic number); an Octaclay document is an .exr "
                 "written by octaclay-cli or the modeller");
}

int sizeFromSide(int side) {
  const int n = side - 1;
  return isValidSize(n) ? n : 0;
}

DocumentHeader checkHeader(const fs::path& path, const Imf::Header& header) {
  const auto* format = header.findTypedAttribute<Imf::IntAttribute>(kFormatAttribute);
  if (!format)
    refuse(path, "an OpenEXR image but not an Octaclay document (no octaclay.format attribute); "
                 "import meshes with `octaclay-cli import`");
  DocumentHeader result;
  result.formatVersion = format->value();
  if (result.formatVersion < 1 || result.formatVersion > kDocumentFormatVersion)
    refuse(path, "document format version " + std::to_string(result.formatVersion) +
                     " is not supported (this Octaclay reads version " +
                     std::to_string(kDocumentFormatVersion) + "); update Octaclay");
  const auto* param = header.findTypedAttribute<Imf::StringAttribute>(kParameterizationAttribute);
  if (param && param->value() != "octahedral")
    refuse(path, "parameterization '" + param->value() + "' is not supported (only octahedral)");

  const Imath::Box2i window = header.dataWindow();
  const int width = window.max.x - window.min.x + 1;
  const int height = window.max.y - window.min.y + 1;
  result.size = sizeFromSide(width);
  if (width != height || result.size == 0)
    refuse(path, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                     " is not (2^k+1)x(2^k+1) with 2 <= 2^k <= 8192");

  for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
    result.channels.emplace_back(it.name());
  for (const char* name : kPositionChannels)
    if (!header.channels().findChannel(name))
      refuse(path, std::string("missing channel ") + name + " (positions need P.X, P.Y, P.Z)");
  if (const auto problem = layerChannelsProblem(result.channels)) refuse(path, *problem);
  return result;
}

char* shifted(void* base, const Imath::Box2i& window, std::size_t xStride, std::size_t yStride) {
  // OpenEXR addresses pixel (x, y) at base + x·xStride + y·yStride, in data-window coordinates.
  return static_cast<char*>(base) - static_cast<std::ptrdiff_t>(window.min.x) * xStride -
         static_cast<std::ptrdiff_t>(window.min.y) * yStride;
}

// OpenEXR converts pixel types when reading but not when writing, so a layer is handed over as
// half: one row of its fill value while uniform (a zero y stride repeats it down the image;
// OpenEXR loops forever on a zero x stride), else all its texels converted.
void addLayerSlices(Imf::FrameBuffer& frame, const Imath::Box2i& window, const Layer& layer,
                    int side, std::vector<half>& halves) {
  const std::size_t xStride = sizeof(half) * layer.channels;
  std::size_t yStride = 0;
  if (layer.uniform()) {
    halves.resize(static_cast<std::size_t>(side) * layer.channels);
    for (std::size_t k = 0; k < halves.size(); ++k)
      halves[k] = half(layer.fill[k % layer.channels]);
  } else {
    halves.assign(layer.texels.begin(), layer.texels.end());
    yStride = xStride * side;
  }
  const auto names = layer.channelNames();
  for (int c = 0; c < layer.channels; ++c)
    frame.insert(layer.name + "." + names[c],
                 Imf::Slice(Imf::HALF, shifted(halves.data() + c, window, xStride, yStride),
                            xStride, yStride));
}

// Adds slices that read a layer's channels into its texels; an absent layer keeps its default.
void addLayerReadSlices(Imf::FrameBuffer& frame, const Imath::Box2i& window,
                        const DocumentHeader& header, Layer& layer, int side) {
  const auto names = layer.channelNames();
  int present = 0;
  for (const auto& n : names)
    present += std::count(header.channels.begin(), header.channels.end(), layer.name + "." + n) > 0;
  if (present == 0) return; // checkHeader refused a partial layer

  layer.texels.assign(static_cast<std::size_t>(side) * side * layer.channels, 0.0f);
  const std::size_t xStride = sizeof(float) * layer.channels;
  for (int c = 0; c < layer.channels; ++c)
    frame.insert(layer.name + "." + names[c],
                 Imf::Slice(Imf::FLOAT,
                            shifted(layer.texels.data() + c, window, xStride, xStride * side),
                            xStride, xStride * side));
}

// A layer whose texels all hold one value is kept as that fill value.
void collapseUniformLayer(Layer& layer) {
  if (layer.texels.empty()) return;
  const std::size_t channels = static_cast<std::size_t>(layer.channels);
  for (std::size_t k = channels; k < layer.texels.size(); ++k)
    if (layer.texels[k] != layer.texels[k % channels]) return;
  for (std::size_t c = 0; c < channels; ++c)
    layer.fill[c] = layer.texels[c];
  layer.texels.clear();
  layer.texels.shrink_to_fit();
}

} // namespace

DocumentHeader readDocumentHeader(const fs::path& path) {
  requireExrMagic(path);
  try {
    Imf::InputFile file(path.c_str());
    return checkHeader(path, file.header());
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    refuse(path, std::string("corrupt OpenEXR header: ") + e.what());
  }
}

Document readDocument(const fs::path& path, const DocumentReadOptions& options) {
  requireExrMagic(path);
  Document document;
  try {
    const auto opened = openExr(path);
    Imf::InputFile& file = *opened;
    const DocumentHeader header = checkHeader(path, file.header());
    if (!file.isComplete())
      refuse(path, "truncated: the file ends before all its pixels (an interrupted copy?)");
    document.positions = GeometryImage(header.size);
    const int side = header.size + 1;
    const Imath::Box2i window = file.header().dataWindow();
    const std::size_t xStride = sizeof(Vec4f), yStride = xStride * side;
    Imf::FrameBuffer frame;
    float* base = &document.positions.texels()[0].x;
    for (int c = 0; c < 3; ++c)
      frame.insert(
          kPositionChannels[c],
          Imf::Slice(Imf::FLOAT, shifted(base + c, window, xStride, yStride), xStride, yStride));
    if (options.layers)
      for (Layer* layer : {&document.diffuse, &document.feature, &document.mask})
        addLayerReadSlices(frame, window, header, *layer, side);
    // One read for every channel: each readPixels call decompresses the whole file again.
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);

    if (const auto problem = positionsProblem(document.positions)) refuse(path, *problem);
    for (const Layer* layer : {&document.diffuse, &document.feature, &document.mask})
      if (const auto problem = layerValuesProblem(*layer, header.size)) refuse(path, *problem);

    for (Layer* layer : {&document.diffuse, &document.feature, &document.mask})
      collapseUniformLayer(*layer);
    document.hasMask = std::count(header.channels.begin(), header.channels.end(), "mask.Y") > 0;
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    refuse(path, "not enough memory to read it: the document is larger than this machine can "
                 "hold");
  } catch (const std::exception& e) {
    refuse(path, std::string("corrupt or truncated OpenEXR data: ") + e.what());
  }
  return document;
}

void writeDocument(const Document& document, const fs::path& path) {
  const int n = document.size();
  requireValidSize(n);
  const int side = n + 1;
  // The file is built in memory, then written whole by the one checked writer.
  std::vector<std::uint8_t> bytes;
  {
    Imf::Header header(side, side);
    // ZIP level 1: most of ZIP's gain on float positions for a fraction of its time.
    // RLE up to N = 2048: unpainted layers shrink to nothing and saving stays near raw speed
    // (N = 1024 here: RLE 120 ms / 13 MB, ZIP 430 ms / 8-12 MB, none 65 ms / 27 MB). Float
    // positions barely compress, so larger documents are written raw to keep saves under
    // two seconds; compact storage is `octaclay-cli compress`'s job.
    header.compression() = n <= kLargestCompressedSize ? Imf::RLE_COMPRESSION : Imf::NO_COMPRESSION;
    header.insert(kFormatAttribute, Imf::IntAttribute(kDocumentFormatVersion));
    header.insert(kParameterizationAttribute, Imf::StringAttribute("octahedral"));
    header.insert(kSamplingAttribute, Imf::StringAttribute("vertex-centred N+1"));
    for (const char* name : kPositionChannels)
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    std::vector<const Layer*> layers{&document.diffuse, &document.feature};
    if (document.hasMask) layers.push_back(&document.mask);
    for (const Layer* layer : layers)
      for (const auto& c : layer->channelNames())
        header.channels().insert(layer->name + "." + c, Imf::Channel(Imf::HALF));

    const Imath::Box2i window = header.dataWindow();
    Imf::FrameBuffer frame;
    const std::size_t xStride = sizeof(Vec4f), yStride = xStride * side;
    auto* base = const_cast<float*>(&document.positions.texels()[0].x);
    for (int c = 0; c < 3; ++c)
      frame.insert(
          kPositionChannels[c],
          Imf::Slice(Imf::FLOAT, shifted(base + c, window, xStride, yStride), xStride, yStride));
    std::array<std::vector<half>, 3> halves;
    for (std::size_t k = 0; k < layers.size(); ++k)
      addLayerSlices(frame, window, *layers[k], side, halves[k]);

    detail::ExrMemoryStream stream;
    {
      Imf::OutputFile file(stream, header, exrThreads(header.compression()));
      file.setFrameBuffer(frame);
      file.writePixels(side);
    }
    bytes = std::move(stream.bytes());
  }
  writeBytesAtomically(path, bytes);
}

} // namespace octaclay::core
