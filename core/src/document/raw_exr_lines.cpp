#include "raw_exr_lines.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/error.h"

#include <ImfChannelList.h>
#include <fcntl.h>
#include <half.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstring>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

constexpr std::array<const char*, 3> kPositionChannels{"P.X", "P.Y", "P.Z"};
constexpr std::size_t kChunkHeader = 8; // int32 y, int32 byte count
constexpr int kWriteRows = 16;          // lines per pwrite: 3.4 MB at N = 8192

[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
  throw Error(ErrorKind::InvalidInput, path.string() + ": " + why);
}

// One channel's row in a line, and where its values go or come from.
struct ChannelRow {
  bool half = false;
  std::size_t offset = 0; ///< in the line's pixel data, bytes
  int position = -1;      ///< 0..2: P.X..P.Z
  int layer = -1;         ///< index into the layers, or -1
  int channel = 0;        ///< in the layer
};

struct LineLayout {
  std::vector<ChannelRow> rows;
  std::size_t bytes = 0; ///< a line's pixel data
};

LineLayout lineLayout(const Imf::Header& header, const std::vector<const Layer*>& layers) {
  const int width = header.dataWindow().max.x - header.dataWindow().min.x + 1;
  LineLayout layout;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
    ChannelRow row;
    row.half = it.channel().type == Imf::HALF;
    row.offset = layout.bytes;
    for (int c = 0; c < 3; ++c)
      if (std::strcmp(it.name(), kPositionChannels[c]) == 0) row.position = c;
    for (std::size_t k = 0; k < layers.size(); ++k) {
      const auto names = layers[k]->channelNames();
      for (int c = 0; c < layers[k]->channels; ++c)
        if (layers[k]->name + "." + names[static_cast<std::size_t>(c)] == it.name()) {
          row.layer = static_cast<int>(k);
          row.channel = c;
        }
    }
    layout.bytes += static_cast<std::size_t>(width) * (row.half ? 2 : 4);
    layout.rows.push_back(row);
  }
  return layout;
}

// Runs body(rowBegin, rowEnd) as parallelRows does and rethrows the first exception a band threw.
template <class Body> void parallelRowsOrThrow(int rows, Body&& body, int minRows) {
  std::exception_ptr error;
  std::mutex lock;
  parallelRows(
      rows,
      [&](int a, int b) {
        try {
          body(a, b);
        } catch (...) {
          const std::lock_guard guard(lock);
          if (!error) error = std::current_exception();
        }
      },
      minRows);
  if (error) std::rethrow_exception(error);
}

class ReadOnlyFile {
public:
  explicit ReadOnlyFile(const fs::path& path) : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
    struct stat info {};
    if (fd_ < 0 || ::fstat(fd_, &info) != 0)
      throw Error(ErrorKind::Io, "cannot open " + path.string() + ": " + std::strerror(errno));
    size_ = static_cast<std::uint64_t>(info.st_size);
  }
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;
  ~ReadOnlyFile() { ::close(fd_); }
  std::uint64_t size() const { return size_; }
  /// Reads bytes.size() bytes at offset; false when the file ends first or a read fails.
  bool readAt(std::uint64_t offset, std::span<char> bytes) const {
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n =
          ::pread(fd_, bytes.data() + done, bytes.size() - done, static_cast<off_t>(offset + done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      done += static_cast<std::size_t>(n);
    }
    return true;
  }

private:
  int fd_;
  std::uint64_t size_ = 0;
};

// Where the offset table starts: after the magic number, the version and the attributes (name,
// type name, int32 size, value), which end with an empty name. 0 when the attributes run past
// the first MiB (the caller then lets OpenEXR read the pixels).
std::uint64_t offsetTableStart(const fs::path& path, const ReadOnlyFile& file) {
  std::vector<char> head(static_cast<std::size_t>(std::min<std::uint64_t>(file.size(), 1 << 20)));
  if (!file.readAt(0, head)) refuse(path, "truncated: the file ends inside its header");
  std::size_t at = 8;
  const auto skipName = [&]() -> std::size_t { // the name's length, at moved past its 0
    const auto end = std::find(head.begin() + static_cast<std::ptrdiff_t>(at), head.end(), '\0');
    if (end == head.end()) return std::string::npos;
    const std::size_t length = static_cast<std::size_t>(end - head.begin()) - at;
    at += length + 1;
    return length;
  };
  while (at < head.size()) {
    const std::size_t name = skipName();
    if (name == std::string::npos) return 0;
    if (name == 0) return at;
    if (skipName() == std::string::npos || at + 4 > head.size()) return 0;
    std::int32_t size;
    std::memcpy(&size, head.data() + at, 4);
    if (size < 0) refuse(path, "corrupt OpenEXR header: an attribute of negative size");
    at += 4 + static_cast<std::size_t>(size);
  }
  return 0;
}

void convertRow(bool isHalf, const char* from, int width, float* to, std::size_t stride) {
  if (!isHalf) {
    for (int i = 0; i < width; ++i)
      std::memcpy(to + static_cast<std::size_t>(i) * stride, from + 4 * static_cast<std::size_t>(i),
                  4);
    return;
  }
  for (int i = 0; i < width; ++i) {
    std::uint16_t bits;
    std::memcpy(&bits, from + 2 * static_cast<std::size_t>(i), 2);
    half h;
    h.setBits(bits);
    to[static_cast<std::size_t>(i) * stride] = static_cast<float>(h);
  }
}

} // namespace

bool rawLinesApply(const Imf::Header& header) {
  if (header.compression() != Imf::NO_COMPRESSION || std::endian::native != std::endian::little ||
      header.hasType() || header.hasTileDescription())
    return false;
  // Lines of a square image only (a torus or plane may be W ≠ H: OpenEXR's frame buffers read it).
  const Imath::Box2i window = header.dataWindow();
  if (window.max.x - window.min.x != window.max.y - window.min.y) return false;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
    const Imf::Channel& c = it.channel();
    if (c.xSampling != 1 || c.ySampling != 1 || (c.type != Imf::HALF && c.type != Imf::FLOAT))
      return false;
  }
  return true;
}

bool readRawLines(const fs::path& path, const Imf::Header& header, GeometryImage& positions,
                  const std::vector<Layer*>& layers) {
  const ReadOnlyFile file(path);
  const std::uint64_t tableStart = offsetTableStart(path, file);
  if (tableStart == 0) return false;
  const int side = positions.side();
  const int firstY = header.dataWindow().min.y;
  const LineLayout layout = lineLayout(header, {layers.begin(), layers.end()});
  std::vector<std::uint64_t> offsets(static_cast<std::size_t>(side));
  if (!file.readAt(tableStart, {reinterpret_cast<char*>(offsets.data()), offsets.size() * 8}))
    refuse(path, "truncated: the file ends inside its line offset table");
  for (int j = 0; j < side; ++j)
    if (offsets[static_cast<std::size_t>(j)] < tableStart + offsets.size() * 8 ||
        offsets[static_cast<std::size_t>(j)] > file.size() ||
        file.size() - offsets[static_cast<std::size_t>(j)] < kChunkHeader + layout.bytes)
      refuse(path, "corrupt: line " + std::to_string(j) + "'s offset is outside the file");

  // The bytes of a line that hold the rows wanted: [0, upTo) of its pixel data.
  std::size_t positionsEnd = 0;
  for (const ChannelRow& row : layout.rows)
    if (row.position >= 0)
      positionsEnd = std::max(positionsEnd, row.offset + side * std::size_t(4));
  const auto readLine = [&](int j, std::size_t upTo, std::vector<char>& line) {
    line.resize(kChunkHeader + upTo);
    if (!file.readAt(offsets[static_cast<std::size_t>(j)], line))
      refuse(path, "truncated: line " + std::to_string(j) + " ends early");
    std::int32_t y, bytes;
    std::memcpy(&y, line.data(), 4);
    std::memcpy(&bytes, line.data() + 4, 4);
    if (y != firstY + j || static_cast<std::size_t>(bytes) != layout.bytes)
      refuse(path, "corrupt: line " + std::to_string(j) + " holds line " + std::to_string(y) +
                       " of " + std::to_string(bytes) + " bytes where " +
                       std::to_string(layout.bytes) + " were expected");
    return line.data() + kChunkHeader;
  };

  // Positions, and whether each layer's rows repeat line 0's first sample (a uniform layer).
  const std::size_t wanted = layers.empty() ? positionsEnd : layout.bytes;
  std::vector<char> first;
  const char* line0 = readLine(0, layout.bytes, first);
  std::vector<char> uniformLine(layout.bytes);
  for (const ChannelRow& row : layout.rows) {
    const std::size_t size = row.half ? 2 : 4;
    for (int i = 0; i < side; ++i)
      std::memcpy(uniformLine.data() + row.offset + i * size, line0 + row.offset, size);
  }
  float* positionFloats = reinterpret_cast<float*>(positions.texels().data()); // xyzw per texel
  std::vector<std::atomic<bool>> painted(layers.size());
  parallelRowsOrThrow(
      side,
      [&](int rowBegin, int rowEnd) {
        std::vector<char> buffer;
        std::vector<bool> differs(layers.size(), false);
        for (int j = rowBegin; j < rowEnd; ++j) {
          const char* line = readLine(j, wanted, buffer);
          for (const ChannelRow& row : layout.rows)
            if (row.position >= 0)
              convertRow(row.half, line + row.offset, side,
                         positionFloats + static_cast<std::size_t>(j) * side * 4 +
                             static_cast<std::size_t>(row.position),
                         4);
            else if (row.layer >= 0 && !differs[static_cast<std::size_t>(row.layer)])
              differs[static_cast<std::size_t>(row.layer)] =
                  std::memcmp(line + row.offset, uniformLine.data() + row.offset,
                              static_cast<std::size_t>(side) * (row.half ? 2 : 4)) != 0;
        }
        for (std::size_t k = 0; k < layers.size(); ++k)
          if (differs[k]) painted[k] = true;
      },
      16);

  // Each layer: its fill, or every texel in a second pass over its rows.
  for (std::size_t k = 0; k < layers.size(); ++k) {
    Layer& layer = *layers[k];
    const std::size_t channels = static_cast<std::size_t>(layer.channels);
    if (!painted[k]) {
      layer.texels.clear();
      for (const ChannelRow& row : layout.rows)
        if (row.layer == static_cast<int>(k))
          convertRow(row.half, line0 + row.offset, 1,
                     &layer.fill[static_cast<std::size_t>(row.channel)], 1);
      continue;
    }
    layer.texels.assign(static_cast<std::size_t>(side) * side * channels, 0.0f);
    parallelRowsOrThrow(
        side,
        [&](int rowBegin, int rowEnd) {
          std::vector<char> buffer;
          for (int j = rowBegin; j < rowEnd; ++j) {
            const char* line = readLine(j, layout.bytes, buffer);
            for (const ChannelRow& row : layout.rows)
              if (row.layer == static_cast<int>(k))
                convertRow(row.half, line + row.offset, side,
                           layer.texels.data() + static_cast<std::size_t>(j) * side * channels +
                               static_cast<std::size_t>(row.channel),
                           channels);
          }
        },
        16);
  }
  return true;
}

void writeRawLines(const Document& document, const Imf::Header& header,
                   const std::vector<std::uint8_t>& headerBytes, ByteSink& sink) {
  const int side = document.positions.side();
  const std::vector<const Layer*> layers{&document.diffuse, &document.feature, &document.mask};
  const LineLayout layout = lineLayout(header, layers);
  const std::size_t chunk = kChunkHeader + layout.bytes;
  const std::uint64_t dataStart = headerBytes.size();
  const std::int32_t firstY = header.dataWindow().min.y;
  if (headerBytes.size() < 8 * static_cast<std::size_t>(side) + 8)
    throw std::logic_error("OpenEXR wrote no line offset table");

  // The header with its offset table filled in: each line's place is known before any is made.
  std::vector<std::uint8_t> head = headerBytes;
  for (int j = 0; j < side; ++j) {
    const std::uint64_t offset = dataStart + static_cast<std::uint64_t>(j) * chunk;
    std::memcpy(head.data() + dataStart - 8 * static_cast<std::size_t>(side - j), &offset, 8);
  }
  sink.writeAt(0, head);

  const float* positionFloats =
      reinterpret_cast<const float*>(document.positions.texels().data()); // xyzw per texel
  // A uniform layer's row is one row of halves, made once.
  std::vector<std::vector<half>> fills(layers.size());
  for (std::size_t k = 0; k < layers.size(); ++k)
    if (layers[k]->uniform()) {
      fills[k].resize(static_cast<std::size_t>(side) * layers[k]->channels);
      for (std::size_t t = 0; t < fills[k].size(); ++t)
        fills[k][t] = half(layers[k]->fill[t % static_cast<std::size_t>(layers[k]->channels)]);
    }

  const bool background = ::gettid() != ::getpid();
  const auto writeLines = [&](int rowBegin, int rowEnd) {
    // Called from a worker (the modeller's save and autosave), the writer yields the cores to
    // the threads that draw: the GUI and its GL driver's rasterizer, which otherwise waited
    // for them (modeller_render_test: 2-4 GUI ticks in a 1.1-1.8 s save at N = 4096, 20-42
    // at the lowest priority). From a program's main thread (octaclay-cli) it keeps its own.
    if (background) ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 19);
    std::vector<char> lines;
    for (int j0 = rowBegin; j0 < rowEnd; j0 += kWriteRows) {
      const int j1 = std::min(rowEnd, j0 + kWriteRows);
      lines.resize(chunk * static_cast<std::size_t>(j1 - j0));
      for (int j = j0; j < j1; ++j) {
        char* line = lines.data() + chunk * static_cast<std::size_t>(j - j0);
        const std::int32_t y = firstY + j, bytes = static_cast<std::int32_t>(layout.bytes);
        std::memcpy(line, &y, 4);
        std::memcpy(line + 4, &bytes, 4);
        char* pixels = line + kChunkHeader;
        for (const ChannelRow& row : layout.rows) {
          char* to = pixels + row.offset;
          if (row.position >= 0) {
            const float* from = positionFloats + static_cast<std::size_t>(j) * side * 4 +
                                static_cast<std::size_t>(row.position);
            for (int i = 0; i < side; ++i)
              std::memcpy(to + 4 * static_cast<std::size_t>(i), from + 4 * i, 4);
            continue;
          }
          const Layer& layer = *layers[static_cast<std::size_t>(row.layer)];
          const std::size_t channels = static_cast<std::size_t>(layer.channels);
          if (layer.uniform()) {
            const half* fill = fills[static_cast<std::size_t>(row.layer)].data();
            for (int i = 0; i < side; ++i)
              std::memcpy(to + 2 * static_cast<std::size_t>(i),
                          fill + i * channels + static_cast<std::size_t>(row.channel), 2);
            continue;
          }
          const float* from = layer.texels.data() + static_cast<std::size_t>(j) * side * channels +
                              static_cast<std::size_t>(row.channel);
          for (int i = 0; i < side; ++i) {
            const half h(from[static_cast<std::size_t>(i) * channels]);
            const std::uint16_t bits = h.bits();
            std::memcpy(to + 2 * static_cast<std::size_t>(i), &bits, 2);
          }
        }
      }
      sink.writeAt(dataStart + static_cast<std::uint64_t>(j0) * chunk,
                   std::span(reinterpret_cast<const std::uint8_t*>(lines.data()), lines.size()));
    }
  };
  // A worker's writing threads are made for it (so only they are lowered, never the caller).
  if (!background) {
    parallelRowsOrThrow(side, writeLines, 16);
    return;
  }
  std::exception_ptr error;
  std::thread lowered([&] {
    try {
      parallelRowsOrThrow(side, writeLines, 16);
    } catch (...) {
      error = std::current_exception();
    }
  });
  lowered.join();
  if (error) std::rethrow_exception(error);
}

} // namespace octaclay::core::detail
