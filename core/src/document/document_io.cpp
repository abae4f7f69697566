#include "octaclay/core/document/document_io.h"

#include "detail/exr_memory_stream.h"
#include "detail/exr_sink_stream.h"
#include "detail/parallel_rows.h"
#include "document_parts.h"
#include "raw_exr_lines.h"

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
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <new>
#include <string_view>
#include <thread>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {
using detail::kHeightAttribute, detail::kParameterizationAttribute, detail::kTopologyAttribute,
    detail::kWidthAttribute;

constexpr const char* kFormatAttribute = "octaclay.format";
constexpr const char* kSamplingAttribute = "octaclay.sampling";
constexpr std::array<const char*, 3> kPositionChannels{"P.X", "P.Y", "P.Z"};
// Rows per readPixels / writePixels call: enough line buffers for every thread of OpenEXR's pool,
// while a band of layer texels stays small (8193 × 8 channels × 4 bytes × 128 rows = 34 MB).
constexpr int kBandRows = 128;

// OpenEXR's pool, one thread per core, started once (its tasks decode and encode line buffers).
int exrThreads() {
  static const int threads = [] {
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    Imf::setGlobalThreadCount(cores);
    return cores;
  }();
  return threads;
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
  const bool read = in.gcount() == 4;
  // A compressed model (.ocz: "OCZ1") is a common mix-up: say how to open it.
  if (read && magic[0] == 'O' && magic[1] == 'C' && magic[2] == 'Z' && magic[3] == '1')
    refuse(path, "a compressed Octaclay model (.ocz), not a document: decompress it first "
                 "(octaclay-cli decompress " +
                     path.string() + " -o model.exr), or open it in the modeller");
  if (!read || magic[0] != 0x76 || magic[1] != 0x2f || magic[2] != 0x31 || magic[3] != 0x01)
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
  const auto* topology = header.findTypedAttribute<Imf::StringAttribute>(kTopologyAttribute);
  if (topology) {
    const auto parsed = parseTopology(topology->value());
    if (!parsed)
      refuse(path,
             "topology '" + topology->value() + "' is not supported (octahedral, torus or plane)");
    result.topology = *parsed;
  }
  const auto* param = header.findTypedAttribute<Imf::StringAttribute>(kParameterizationAttribute);
  if (param && param->value() != topologyName(result.topology))
    refuse(path, "parameterization '" + param->value() + "' does not match the topology '" +
                     std::string(topologyName(result.topology)) + "'");

  const Imath::Box2i window = header.dataWindow();
  const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
  const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
  if (result.topology == Topology::Octahedral) {
    result.size = width == height && width <= kMaxSize + 1 ? sizeFromSide(int(width)) : 0;
    if (result.size == 0)
      refuse(path, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                       " is not (2^k+1)x(2^k+1) with 2 <= 2^k <= 8192");
    result.width = result.height = result.size;
  } else {
    const auto* w = header.findTypedAttribute<Imf::IntAttribute>(kWidthAttribute);
    const auto* h = header.findTypedAttribute<Imf::IntAttribute>(kHeightAttribute);
    if (!w || !h)
      refuse(path, "a " + std::string(topologyName(result.topology)) +
                       " document needs octaclay.width and octaclay.height attributes");
    const SampleGrid grid{result.topology, w->value(), h->value()};
    if (!isValidGrid(grid))
      refuse(path, std::string(topologyName(result.topology)) + " image size " +
                       std::to_string(grid.width) + "x" + std::to_string(grid.height) +
                       " is not valid (powers of two from 2 to 8192" +
                       (grid.topology == Topology::Torus ? ", at least 4)" : ")"));
    if (width != grid.width + 1LL || height != grid.height + 1LL)
      refuse(path, "the image holds " + std::to_string(width) + "x" + std::to_string(height) +
                       " samples but its header says " + std::to_string(grid.width) + "x" +
                       std::to_string(grid.height) + " cells (" + std::to_string(grid.width + 1) +
                       "x" + std::to_string(grid.height + 1) + " samples)");
    result.width = grid.width;
    result.height = grid.height;
    result.size = grid.width;
  }

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

// The position image's P.X, P.Y, P.Z as float slices of frame (the reader's and the writer's).
void insertPositionSlices(Imf::FrameBuffer& frame, const GeometryImage& positions,
                          const Imath::Box2i& window) {
  const std::size_t xStride = sizeof(Vec4f), yStride = xStride * positions.side();
  auto* base = const_cast<float*>(&positions.texels()[0].x);
  for (int c = 0; c < 3; ++c)
    frame.insert(
        kPositionChannels[c],
        Imf::Slice(Imf::FLOAT, shifted(base + c, window, xStride, yStride), xStride, yStride));
}

// OpenEXR converts pixel types when reading but not when writing, so a layer is handed over as
// half, a band of rows at a time: one row of its fill value while uniform (a zero y stride repeats
// it down the band; OpenEXR loops forever on a zero x stride), else the band's texels converted.
void addLayerWriteSlices(Imf::FrameBuffer& frame, const Imath::Box2i& window, const Layer& layer,
                         int side, int rowBegin, int rowEnd, std::vector<half>& halves) {
  const std::size_t xStride = sizeof(half) * layer.channels;
  std::size_t yStride = 0;
  if (layer.uniform()) {
    if (halves.empty()) {
      halves.resize(static_cast<std::size_t>(side) * layer.channels);
      for (std::size_t k = 0; k < halves.size(); ++k)
        halves[k] = half(layer.fill[k % layer.channels]);
    }
  } else {
    const std::size_t row = static_cast<std::size_t>(side) * layer.channels;
    halves.resize(row * static_cast<std::size_t>(rowEnd - rowBegin));
    const float* from = layer.texels.data() + row * static_cast<std::size_t>(rowBegin);
    detail::parallelRows(
        rowEnd - rowBegin,
        [&](int a, int b) {
          for (std::size_t k = row * a; k < row * b; ++k)
            halves[k] = half(from[k]);
        },
        16);
    yStride = xStride * side;
  }
  // OpenEXR addresses row y at base + y·yStride: the band's first row is rowBegin.
  half* base = halves.data() -
               (layer.uniform() ? 0 : static_cast<std::size_t>(rowBegin) * side * layer.channels);
  const auto names = layer.channelNames();
  for (int c = 0; c < layer.channels; ++c)
    frame.insert(
        layer.name + "." + names[c],
        Imf::Slice(Imf::HALF, shifted(base + c, window, xStride, yStride), xStride, yStride));
}

// Reads a layer a band of rows at a time and keeps it as its fill value while every texel so far
// held one value: a uniform layer never takes (N+1)² texels of memory, even while being read.
class LayerReader {
public:
  LayerReader(Layer& layer, int side, int rows) : layer_(layer), side_(side), rows_(rows) {
    layer_.texels.clear();
  }

  const Layer& layer() const { return layer_; }
  /// Every texel read so far holds the first one's value.
  bool uniformSoFar() const { return layer_.texels.empty(); }

  /// The band's texels, (rowEnd − rowBegin) rows of (N+1) × channels floats, to be filled.
  float* band(int rowBegin, int rowEnd) {
    band_.resize(static_cast<std::size_t>(side_) * layer_.channels *
                 static_cast<std::size_t>(rowEnd - rowBegin));
    return band_.data();
  }

  void addSlices(Imf::FrameBuffer& frame, const Imath::Box2i& window, int rowBegin, int rowEnd) {
    const std::size_t row = static_cast<std::size_t>(side_) * layer_.channels;
    float* base = band(rowBegin, rowEnd) - static_cast<std::ptrdiff_t>(row) * rowBegin;
    const std::size_t xStride = sizeof(float) * layer_.channels;
    const auto names = layer_.channelNames();
    for (int c = 0; c < layer_.channels; ++c)
      frame.insert(layer_.name + "." + names[c],
                   Imf::Slice(Imf::FLOAT, shifted(base + c, window, xStride, xStride * side_),
                              xStride, xStride * side_));
  }

  // Called after the band's pixels were read.
  void takeBand(int rowBegin) {
    const std::size_t channels = static_cast<std::size_t>(layer_.channels);
    const std::size_t row = static_cast<std::size_t>(side_) * channels;
    if (rowBegin == 0)
      for (std::size_t c = 0; c < channels; ++c)
        fill_[c] = band_[c];
    if (layer_.texels.empty()) {
      std::size_t k = 0;
      while (k < band_.size() && band_[k] == fill_[k % channels])
        ++k;
      if (k == band_.size()) return; // still uniform
      layer_.texels.resize(row * static_cast<std::size_t>(rows_));
      for (std::size_t t = 0; t < row * static_cast<std::size_t>(rowBegin); ++t)
        layer_.texels[t] = fill_[t % channels];
    }
    std::copy(band_.begin(), band_.end(),
              layer_.texels.begin() + static_cast<std::ptrdiff_t>(row * rowBegin));
  }

  void finish() {
    if (layer_.texels.empty()) layer_.fill = fill_;
    band_.clear();
    band_.shrink_to_fit();
  }

private:
  Layer& layer_;
  int side_, rows_; ///< samples along a row and rows
  std::vector<float> band_;
  std::array<float, 4> fill_{}; ///< the first texel: the layer's fill while every texel equals it
};

bool layerInFile(const DocumentHeader& header, const Layer& layer) {
  // checkHeader refused a partial layer: one channel tells.
  return std::count(header.channels.begin(), header.channels.end(),
                    layer.name + "." + layer.channelNames()[0]) > 0;
}

// The automatic choice (docs/documents.md has the table): RLE up to N = 2048, where unpainted
// layers shrink to nothing (13 MB instead of 27 at N = 1024) for little time; raw above, where
// float positions barely compress (at N = 4096 ZIP level 1 takes 40 % off RLE's size for about
// 10x raw's time to write and 8x to read) and raw lines are read without OpenEXR's conversion
// (readRawPixels).
constexpr int kLargestCompressedSize = 2048;

Imf::Compression exrCompression(DocumentCompression compression, int n) {
  switch (compression) {
  case DocumentCompression::None:
    return Imf::NO_COMPRESSION;
  case DocumentCompression::Rle:
    return Imf::RLE_COMPRESSION;
  case DocumentCompression::Zips:
    return Imf::ZIPS_COMPRESSION;
  case DocumentCompression::Zip:
    return Imf::ZIP_COMPRESSION;
  case DocumentCompression::Automatic:
    break;
  }
  return n <= kLargestCompressedSize ? Imf::RLE_COMPRESSION : Imf::NO_COMPRESSION;
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
  return detail::readDocumentInspecting(path, options, nullptr);
}

namespace detail {

int exrThreads() {
  return core::exrThreads();
}

void requireExrMagic(const fs::path& path) {
  core::requireExrMagic(path);
}

DocumentHeader checkDocumentHeader(const fs::path& path, const Imf::Header& header) {
  return checkHeader(path, header);
}

Document readDocumentInspecting(const fs::path& path, const DocumentReadOptions& options,
                                const std::function<void(const Imf::Header&)>& inspect) {
  core::requireExrMagic(path);
  try {
    Imf::InputFile file(path.c_str(), core::exrThreads());
    const DocumentHeader header = checkHeader(path, file.header());
    if (inspect) inspect(file.header());
    if (!file.isComplete())
      refuse(path, "truncated: the file ends before all its pixels (an interrupted copy?)");
    return readDocumentPixels(path, file.header(), header, options,
                              [&](const Imf::FrameBuffer& frame, int first, int last) {
                                file.setFrameBuffer(frame);
                                file.readPixels(first, last);
                              });
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    refuse(path, "not enough memory to read it: the document is larger than this machine can "
                 "hold");
  } catch (const std::exception& e) {
    refuse(path, std::string("corrupt or truncated OpenEXR data: ") + e.what());
  }
}

Document
readDocumentPixels(const fs::path& path, const Imf::Header& fileHeader,
                   const DocumentHeader& header, const DocumentReadOptions& options,
                   const std::function<void(const Imf::FrameBuffer&, int, int)>& readPixels,
                   int part) {
  Document document;
  document.positions = GeometryImage(header.topology, header.width, header.height);
  document.topology = header.topology;
  const int side = header.width + 1, rows = header.height + 1;
  const Imath::Box2i window = fileHeader.dataWindow();

  std::vector<Layer*> inFile;
  if (options.layers)
    for (Layer* layer : {&document.diffuse, &document.feature, &document.mask})
      if (layerInFile(header, *layer)) inFile.push_back(layer);
  std::vector<LayerReader> layers;
  layers.reserve(3);
  // Uncompressed lines on every core (raw_exr_lines); else band by band through OpenEXR's frame
  // buffers: positions straight into the image, layers through a band buffer each.
  if (!(detail::rawLinesApply(fileHeader) &&
        detail::readRawLines(path, fileHeader, document.positions, inFile, part))) {
    for (Layer* layer : inFile)
      layers.emplace_back(*layer, side, rows);
    for (int rowBegin = 0; rowBegin < rows; rowBegin += kBandRows) {
      const int rowEnd = std::min(rows, rowBegin + kBandRows);
      Imf::FrameBuffer frame;
      insertPositionSlices(frame, document.positions, window);
      for (LayerReader& layer : layers)
        layer.addSlices(frame, window, rowBegin, rowEnd);
      readPixels(frame, window.min.y + rowBegin, window.min.y + rowEnd - 1);
      for (LayerReader& layer : layers)
        layer.takeBand(rowBegin);
    }
  }
  for (LayerReader& layer : layers)
    layer.finish();

  if (const auto problem = positionsProblem(document.positions)) refuse(path, *problem);
  for (const Layer* layer : {&document.diffuse, &document.feature, &document.mask})
    if (const auto problem = layerValuesProblem(*layer, header.size)) refuse(path, *problem);
  document.hasMask = std::count(header.channels.begin(), header.channels.end(), "mask.Y") > 0;
  return document;
}

} // namespace detail

void writeDocument(const Document& document, const fs::path& path,
                   const DocumentWriteOptions& options) {
  detail::writeDocumentWithAttributes(document, path, options, nullptr);
}

namespace detail {

Imf::Header documentPartHeader(const Document& document, const DocumentWriteOptions& options) {
  const int n = document.size();
  const GeometryImage& positions = document.positions;
  requireValidGrid(positions.grid());
  if (document.topology != positions.topology())
    throw Error(ErrorKind::InvalidArgument,
                "the document's topology (" + std::string(topologyName(document.topology)) +
                    ") is not its image's (" + std::string(topologyName(positions.topology())) +
                    ")");
  const int side = positions.side(), rows = positions.rows();
  Imf::Header header(side, rows);
  header.compression() = exrCompression(options.compression, n);
  header.zipCompressionLevel() = std::clamp(options.zipLevel, 1, 9);
  header.insert(kFormatAttribute, Imf::IntAttribute(kDocumentFormatVersion));
  // The ball's header stays as it always was, so today's readers open it; a torus or plane names
  // its topology in the parameterization too, which those readers refuse by name.
  header.insert(kParameterizationAttribute,
                Imf::StringAttribute(std::string(topologyName(positions.topology()))));
  if (positions.topology() != Topology::Octahedral) {
    header.insert(kTopologyAttribute,
                  Imf::StringAttribute(std::string(topologyName(positions.topology()))));
    header.insert(kWidthAttribute, Imf::IntAttribute(positions.width()));
    header.insert(kHeightAttribute, Imf::IntAttribute(positions.height()));
  }
  header.insert(kSamplingAttribute, Imf::StringAttribute("vertex-centred N+1"));
  for (const char* name : kPositionChannels)
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  for (const Layer* layer : {&document.diffuse, &document.feature, &document.mask})
    if (layer != &document.mask || document.hasMask)
      for (const auto& c : layer->channelNames())
        header.channels().insert(layer->name + "." + c, Imf::Channel(Imf::HALF));
  return header;
}

void writeDocumentPixels(const Document& document, const Imf::Header& header,
                         const std::function<void(const Imf::FrameBuffer&, int)>& writePixels) {
  const int side = document.positions.side(), rows = document.positions.rows();
  const Imath::Box2i window = header.dataWindow();
  std::vector<const Layer*> layers{&document.diffuse, &document.feature};
  if (document.hasMask) layers.push_back(&document.mask);
  std::array<std::vector<half>, 3> halves;
  for (int rowBegin = 0; rowBegin < rows; rowBegin += kBandRows) {
    const int rowEnd = std::min(rows, rowBegin + kBandRows);
    Imf::FrameBuffer frame;
    insertPositionSlices(frame, document.positions, window);
    for (std::size_t k = 0; k < layers.size(); ++k)
      addLayerWriteSlices(frame, window, *layers[k], side, rowBegin, rowEnd, halves[k]);
    writePixels(frame, rowEnd - rowBegin);
  }
}

void writeDocumentWithAttributes(const Document& document, const fs::path& path,
                                 const DocumentWriteOptions& options,
                                 const std::function<void(Imf::Header&)>& addAttributes) {
  Imf::Header header = documentPartHeader(document, options);
  if (addAttributes) addAttributes(header);

  if (detail::rawLinesApply(header)) {
    // OpenEXR writes the header (and a zero offset table) into memory; the lines are made and
    // written on every core, each at its place (raw_exr_lines).
    detail::ExrMemoryStream head;
    { Imf::OutputFile file(head, header, 1); }
    writeFileAtomically(
        path, [&](ByteSink& sink) { detail::writeRawLines(document, header, head.bytes(), sink); });
    return;
  }
  writeFileAtomically(path, [&](ByteSink& sink) {
    detail::ExrSinkStream stream(sink);
    {
      Imf::OutputFile file(stream, header, core::exrThreads());
      writeDocumentPixels(document, header, [&](const Imf::FrameBuffer& frame, int rows) {
        file.setFrameBuffer(frame);
        file.writePixels(rows);
      });
    }
    stream.finish(); // the offset table OutputFile's destructor wrote, and any error it met
  });
}

} // namespace detail

} // namespace octaclay::core
