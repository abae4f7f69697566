#include "raw_exr_lines.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/error.h"

#include <ImfChannelList.h>
#include <ImfPartType.h>
#include <fcntl.h>
#include <half.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

constexpr std::array<const char*, 3> kPositionChannels{"P.X", "P.Y", "P.Z"};
constexpr std::size_t kChunkHeader = 8;      // int32 y, int32 byte count
constexpr int kWriteRows = 16;               // lines per pwrite at least: 3.4 MB at N = 8192
constexpr std::size_t kWriteBytes = 1 << 20; // and as many more as fit in 1 MiB (short lines)

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

// Where part's offset table starts (part -1: a single-part file): after the magic number, the
// version and the headers' attributes (name, type name, int32 size, value), each header ending
// with an empty name, a multi-part file's headers with an empty header; a multi-part file's
// tables follow in part order, each chunkCount lines long. 0 when the headers run past the
// first MiB (the caller then lets OpenEXR read the pixels).
std::uint64_t offsetTableStart(const fs::path& path, const ReadOnlyFile& file, int part) {
  // Most headers fit in the first 64 KiB (16 parts: about 10 KiB); read more only when not.
  for (const std::uint64_t limit : {std::uint64_t{1} << 16, std::uint64_t{1} << 20}) {
    std::vector<char> head(static_cast<std::size_t>(std::min<std::uint64_t>(file.size(), limit)));
    if (!file.readAt(0, head)) refuse(path, "truncated: the file ends inside its header");
    std::size_t at = 8;
    const auto skipName = [&]() -> std::size_t { // the name's length, at moved past its 0
      const auto end = std::find(head.begin() + static_cast<std::ptrdiff_t>(at), head.end(), '\0');
      if (end == head.end()) return std::string::npos;
      const std::size_t length = static_cast<std::size_t>(end - head.begin()) - at;
      at += length + 1;
      return length;
    };
    // One header's attributes; false when they run past what was read. Notes its chunkCount.
    const auto skipHeader = [&](std::int64_t& chunks) {
      while (at < head.size()) {
        const std::size_t nameAt = at;
        const std::size_t name = skipName();
        if (name == std::string::npos) return false;
        if (name == 0) return true;
        if (skipName() == std::string::npos || at + 4 > head.size()) return false;
        std::int32_t size;
        std::memcpy(&size, head.data() + at, 4);
        if (size < 0) refuse(path, "corrupt OpenEXR header: an attribute of negative size");
        at += 4;
        if (name == 10 && std::memcmp(head.data() + nameAt, "chunkCount", 10) == 0 && size == 4 &&
            at + 4 <= head.size()) {
          std::int32_t count;
          std::memcpy(&count, head.data() + at, 4);
          if (count < 0) refuse(path, "corrupt OpenEXR header: a negative chunkCount");
          chunks = count;
        }
        at += static_cast<std::size_t>(size);
      }
      return false;
    };
    if (part < 0) {
      std::int64_t chunks = 0;
      if (skipHeader(chunks)) return at;
    } else {
      std::uint64_t before = 0; // lines of the tables before part's
      bool complete = false;
      for (int k = 0; at < head.size(); ++k) {
        if (head[at] == '\0') { // the empty header that ends a multi-part file's headers
          ++at;
          complete = k > part;
          break;
        }
        std::int64_t chunks = -1;
        if (!skipHeader(chunks)) break;
        if (chunks < 0) refuse(path, "corrupt OpenEXR header: a part without a chunkCount");
        if (k < part) before += static_cast<std::uint64_t>(chunks);
      }
      if (complete) return at + 8 * before;
    }
    if (head.size() == file.size()) return 0;
  }
  return 0;
}

// OpenEXR's RLE of one line's bytes (ImfRleCompressor: the bytes split into even and odd halves,
// each byte replaced by its difference from the previous plus 128, then runs of 3 to 128 equal
// bytes as (count - 1, byte) and other stretches of up to 127 as (-length, bytes)), written at
// out, which has room for size + size / 127 + 2 bytes. Returns the coded size.
std::size_t codeRle(const char* in, std::size_t size, std::vector<char>& scratch, char* out) {
  scratch.resize(size);
  char* t1 = scratch.data();
  char* t2 = scratch.data() + (size + 1) / 2;
  for (std::size_t k = 0; k < size; k += 2)
    *t1++ = in[k];
  for (std::size_t k = 1; k < size; k += 2)
    *t2++ = in[k];
  auto* t = reinterpret_cast<unsigned char*>(scratch.data());
  int previous = size > 0 ? t[0] : 0;
  for (std::size_t k = 1; k < size; ++k) {
    const int d = int(t[k]) - previous + (128 + 256);
    previous = t[k];
    t[k] = static_cast<unsigned char>(d);
  }
  constexpr std::ptrdiff_t kMinRun = 3, kMaxRun = 127;
  char* write = out;
  const char* end = scratch.data() + size;
  const char* runStart = scratch.data();
  const char* runEnd = runStart + 1;
  while (runStart < end) {
    while (runEnd < end && *runStart == *runEnd && runEnd - runStart - 1 < kMaxRun)
      ++runEnd;
    if (runEnd - runStart >= kMinRun) {
      *write++ = static_cast<char>((runEnd - runStart) - 1);
      *write++ = *runStart;
      runStart = runEnd;
    } else {
      while (runEnd < end &&
             ((runEnd + 1 >= end || *runEnd != *(runEnd + 1)) ||
              (runEnd + 2 >= end || *(runEnd + 1) != *(runEnd + 2))) &&
             runEnd - runStart < kMaxRun)
        ++runEnd;
      *write++ = static_cast<char>(runStart - runEnd);
      std::memcpy(write, runStart, static_cast<std::size_t>(runEnd - runStart));
      write += runEnd - runStart;
      runStart = runEnd;
    }
    ++runEnd;
  }
  return static_cast<std::size_t>(write - out);
}

// OpenEXR's RLE decoding of one line (ImfRleCompressor's uncompress, codeRle undone): the runs
// expanded into exactly size bytes at out, the differences summed back, the even and odd halves
// interleaved. False, out partly written, when the code does not expand to exactly size bytes.
bool decodeRle(const char* in, std::size_t inSize, std::size_t size, std::vector<char>& scratch,
               char* out) {
  scratch.resize(size);
  auto* t = reinterpret_cast<unsigned char*>(scratch.data());
  std::size_t at = 0, written = 0;
  while (at < inSize) {
    const auto code = static_cast<signed char>(in[at++]);
    if (code < 0) { // a stretch of -code bytes as they are
      const auto count = static_cast<std::size_t>(-static_cast<int>(code));
      if (count > inSize - at || count > size - written) return false;
      std::memcpy(t + written, in + at, count);
      at += count;
      written += count;
    } else { // code + 1 copies of the next byte
      const auto count = static_cast<std::size_t>(code) + 1;
      if (at == inSize || count > size - written) return false;
      std::memset(t + written, static_cast<unsigned char>(in[at++]), count);
      written += count;
    }
  }
  if (written != size) return false;
  for (std::size_t k = 1; k < size; ++k)
    t[k] = static_cast<unsigned char>(int(t[k - 1]) + int(t[k]) - 128);
  const char* t1 = scratch.data();
  const char* t2 = scratch.data() + (size + 1) / 2;
  for (std::size_t k = 0; k < size; k += 2)
    out[k] = *t1++;
  for (std::size_t k = 1; k < size; k += 2)
    out[k] = *t2++;
  return true;
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
  // A multi-part file's parts name their type: scan lines only.
  const Imf::Compression compression = header.compression();
  if ((compression != Imf::NO_COMPRESSION && compression != Imf::RLE_COMPRESSION) ||
      std::endian::native != std::endian::little ||
      (header.hasType() && header.type() != Imf::SCANLINEIMAGE) || header.hasTileDescription())
    return false;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
    const Imf::Channel& c = it.channel();
    if (c.xSampling != 1 || c.ySampling != 1 || (c.type != Imf::HALF && c.type != Imf::FLOAT))
      return false;
  }
  return true;
}

bool readRawLines(const fs::path& path, const Imf::Header& header, GeometryImage& positions,
                  const std::vector<Layer*>& layers, int part) {
  const ReadOnlyFile file(path);
  // OpenEXR's InputFile opens a multi-part file's first part too: its chunks carry part numbers.
  std::array<char, 8> start{};
  if (!file.readAt(0, start)) refuse(path, "truncated: the file ends inside its header");
  std::uint32_t version;
  std::memcpy(&version, start.data() + 4, 4);
  constexpr std::uint32_t kMultiPartFlag = 0x1000;
  if ((version & kMultiPartFlag) == 0 && part > 0) return false;
  if ((version & kMultiPartFlag) != 0 && part < 0) part = 0;
  if ((version & kMultiPartFlag) == 0) part = -1;
  const std::uint64_t tableStart = offsetTableStart(path, file, part);
  if (tableStart == 0) return false;
  const int side = positions.side(), rows = positions.rows();
  const std::size_t prefix = part < 0 ? kChunkHeader : kChunkHeader + 4;
  const int firstY = header.dataWindow().min.y;
  const LineLayout layout = lineLayout(header, {layers.begin(), layers.end()});
  std::vector<std::uint64_t> offsets(static_cast<std::size_t>(rows));
  if (!file.readAt(tableStart, {reinterpret_cast<char*>(offsets.data()), offsets.size() * 8}))
    refuse(path, "truncated: the file ends inside its line offset table");
  // An RLE line's chunk is as long as its code: at most the line itself (a code no shorter is
  // stored as the line), and it ends where the next chunk starts or the file does.
  const bool rle = header.compression() == Imf::RLE_COMPRESSION;
  for (int j = 0; j < rows; ++j)
    if (offsets[static_cast<std::size_t>(j)] < tableStart + offsets.size() * 8 ||
        offsets[static_cast<std::size_t>(j)] > file.size() ||
        file.size() - offsets[static_cast<std::size_t>(j)] < prefix + (rle ? 1 : layout.bytes))
      refuse(path, "corrupt: line " + std::to_string(j) + "'s offset is outside the file");
  std::vector<std::uint64_t> ends; // RLE: where each line's chunk ends at the latest
  if (rle) {
    ends.assign(offsets.size(), file.size());
    std::vector<std::uint64_t> sorted = offsets;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t j = 0; j < offsets.size(); ++j) {
      const auto next = std::upper_bound(sorted.begin(), sorted.end(), offsets[j]);
      if (next != sorted.end()) ends[j] = *next;
    }
  }

  // The bytes of a line that hold the rows wanted: [0, upTo) of its pixel data.
  std::size_t positionsEnd = 0;
  for (const ChannelRow& row : layout.rows)
    if (row.position >= 0)
      positionsEnd = std::max(positionsEnd, row.offset + side * std::size_t(4));
  // A band's buffers: the chunk as read, and an RLE line decoded.
  struct LineBuffers {
    std::vector<char> chunk, decoded, scratch;
  };
  const auto whichLine = [&](int j) {
    return "line " + std::to_string(j) + (part >= 0 ? " of part " + std::to_string(part) : "");
  };
  const auto endsEarly = [&](int j) {
    refuse(path, "truncated: line " + std::to_string(j) + " ends early");
  };
  const auto readLine = [&](int j, std::size_t upTo, LineBuffers& buffers) -> const char* {
    const std::uint64_t offset = offsets[static_cast<std::size_t>(j)];
    std::vector<char>& line = buffers.chunk;
    line.resize(
        rle ? static_cast<std::size_t>(std::min<std::uint64_t>(
                  prefix + layout.bytes,
                  std::max<std::uint64_t>(ends[static_cast<std::size_t>(j)] - offset, prefix)))
            : prefix + upTo);
    if (!file.readAt(offset, line)) endsEarly(j);
    std::int32_t number = part, y, bytes;
    if (part >= 0) std::memcpy(&number, line.data(), 4);
    std::memcpy(&y, line.data() + prefix - kChunkHeader, 4);
    std::memcpy(&bytes, line.data() + prefix - kChunkHeader + 4, 4);
    const bool sized = rle ? bytes > 0 && static_cast<std::size_t>(bytes) <= layout.bytes
                           : static_cast<std::size_t>(bytes) == layout.bytes;
    if (number != part || y != firstY + j || !sized)
      refuse(path, "corrupt: " + whichLine(j) + " holds line " + std::to_string(y) +
                       (part >= 0 ? " of part " + std::to_string(number) : std::string()) + " of " +
                       std::to_string(bytes) + " bytes where " + (rle ? "at most " : "") +
                       std::to_string(layout.bytes) + " were expected");
    if (!rle) return line.data() + prefix;
    const auto coded = static_cast<std::size_t>(bytes);
    if (coded > line.size() - prefix) {
      // The next chunk starts inside this one's code (chunks out of order or overlapping).
      if (offset + prefix + coded > file.size()) endsEarly(j);
      line.resize(prefix + coded);
      if (!file.readAt(offset, line)) endsEarly(j);
    }
    if (coded == layout.bytes) return line.data() + prefix; // stored as it is
    buffers.decoded.resize(layout.bytes);
    if (!decodeRle(line.data() + prefix, coded, layout.bytes, buffers.scratch,
                   buffers.decoded.data()))
      refuse(path, "corrupt: " + whichLine(j) + "'s RLE code does not expand to its " +
                       std::to_string(layout.bytes) + " bytes");
    return buffers.decoded.data();
  };

  // Positions, and whether each layer's rows repeat line 0's first sample (a uniform layer).
  const std::size_t wanted = layers.empty() ? positionsEnd : layout.bytes;
  LineBuffers first;
  const char* line0 = readLine(0, layout.bytes, first);
  std::vector<char> uniformLine(layout.bytes);
  for (const ChannelRow& row : layout.rows) {
    const std::size_t size = row.half ? 2 : 4;
    for (int i = 0; i < side; ++i)
      std::memcpy(uniformLine.data() + row.offset + i * size, line0 + row.offset, size);
  }
  float* positionFloats = reinterpret_cast<float*>(positions.texels().data()); // xyzw per texel
  std::vector<std::atomic<bool>> painted(layers.size());
  // RLE lines decoded once: a painted layer's second pass reads them kept (up to 512 MiB; a
  // larger RLE document decodes its lines again).
  constexpr std::size_t kKeptBytes = std::size_t{512} << 20;
  const std::unique_ptr<char[]> kept(
      rle && !layers.empty() && layout.bytes * static_cast<std::size_t>(rows) <= kKeptBytes
          ? new char[layout.bytes * static_cast<std::size_t>(rows)]
          : nullptr);
  parallelRowsOrThrow(
      rows,
      [&](int rowBegin, int rowEnd) {
        LineBuffers buffer;
        std::vector<bool> differs(layers.size(), false);
        for (int j = rowBegin; j < rowEnd; ++j) {
          const char* line = readLine(j, wanted, buffer);
          if (kept)
            std::memcpy(kept.get() + layout.bytes * static_cast<std::size_t>(j), line,
                        layout.bytes);
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
    layer.texels.assign(static_cast<std::size_t>(side) * rows * channels, 0.0f);
    parallelRowsOrThrow(
        rows,
        [&](int rowBegin, int rowEnd) {
          LineBuffers buffer;
          for (int j = rowBegin; j < rowEnd; ++j) {
            const char* line = kept ? kept.get() + layout.bytes * static_cast<std::size_t>(j)
                                    : readLine(j, layout.bytes, buffer);
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

namespace {

// One part's lines as they are written: chunk after chunk from dataStart (each chunk: the part
// number in a multi-part file, int32 y, int32 byte count, the line).
class PartLines {
public:
  PartLines(const RawPart& part, int partNumber, std::uint64_t dataStart)
      : document_(part.document), partNumber_(partNumber), dataStart_(dataStart),
        columns_(part.document.positions.side()), layers_{&part.document.diffuse,
                                                          &part.document.feature,
                                                          &part.document.mask},
        layout_(lineLayout(part.header, layers_)),
        chunk_((partNumber < 0 ? kChunkHeader : kChunkHeader + 4) + layout_.bytes),
        firstY_(part.header.dataWindow().min.y), fills_(layers_.size()),
        rle_(part.header.compression() == Imf::RLE_COMPRESSION) {
    // A uniform layer's row is one row of halves, made once.
    for (std::size_t k = 0; k < layers_.size(); ++k)
      if (layers_[k]->uniform()) {
        fills_[k].resize(static_cast<std::size_t>(columns_) * layers_[k]->channels);
        for (std::size_t t = 0; t < fills_[k].size(); ++t)
          fills_[k][t] = half(layers_[k]->fill[t % static_cast<std::size_t>(layers_[k]->channels)]);
      }
  }

  int rows() const { return document_.positions.rows(); }
  std::size_t chunkBytes() const { return chunk_; }
  bool rle() const { return rle_; }

  /// The most bytes writeChunk writes for one line: RLE's worst case, a count byte every 127.
  std::size_t mostChunkBytes() const { return chunk_ + layout_.bytes / 127 + 2; }

  /// Writes line j's chunk at out (room for mostChunkBytes) as OpenEXR writes it: RLE-coded
  /// when that is smaller, else the line itself. Returns the chunk's size.
  std::size_t writeChunk(int j, std::vector<char>& line, std::vector<char>& scratch,
                         char* out) const {
    line.resize(chunk_);
    makeLine(j, line.data());
    const std::size_t prefix = chunk_ - layout_.bytes;
    std::memcpy(out, line.data(), prefix);
    std::size_t coded =
        rle_ ? codeRle(line.data() + prefix, layout_.bytes, scratch, out + prefix) : layout_.bytes;
    if (!rle_ || coded >= layout_.bytes) {
      std::memcpy(out + prefix, line.data() + prefix, layout_.bytes);
      coded = layout_.bytes;
    }
    const auto size = static_cast<std::int32_t>(coded);
    std::memcpy(out + prefix - 4, &size, 4);
    return prefix + coded;
  }
  std::uint64_t dataStart() const { return dataStart_; }

  /// Writes lines [rowBegin, rowEnd), kWriteRows or 1 MiB of them at a time, through lines (a
  /// scratch buffer): a scene's short lines take as few pwrites as one large object's.
  void write(int rowBegin, int rowEnd, std::vector<char>& lines, ByteSink& sink) const {
    const int batch = std::max(kWriteRows, static_cast<int>(kWriteBytes / chunk_));
    for (int j0 = rowBegin; j0 < rowEnd; j0 += batch) {
      const int j1 = std::min(rowEnd, j0 + batch);
      lines.resize(chunk_ * static_cast<std::size_t>(j1 - j0));
      for (int j = j0; j < j1; ++j)
        makeLine(j, lines.data() + chunk_ * static_cast<std::size_t>(j - j0));
      sink.writeAt(dataStart_ + static_cast<std::uint64_t>(j0) * chunk_,
                   std::span(reinterpret_cast<const std::uint8_t*>(lines.data()), lines.size()));
    }
  }

private:
  void makeLine(int j, char* line) const {
    const float* positionFloats =
        reinterpret_cast<const float*>(document_.positions.texels().data()); // xyzw per texel
    const std::int32_t y = firstY_ + j, bytes = static_cast<std::int32_t>(layout_.bytes);
    if (partNumber_ >= 0) {
      const std::int32_t number = partNumber_;
      std::memcpy(line, &number, 4);
      line += 4;
    }
    std::memcpy(line, &y, 4);
    std::memcpy(line + 4, &bytes, 4);
    char* pixels = line + kChunkHeader;
    for (const ChannelRow& row : layout_.rows) {
      char* to = pixels + row.offset;
      if (row.position >= 0) {
        const float* from = positionFloats + static_cast<std::size_t>(j) * columns_ * 4 +
                            static_cast<std::size_t>(row.position);
        for (int i = 0; i < columns_; ++i)
          std::memcpy(to + 4 * static_cast<std::size_t>(i), from + 4 * i, 4);
        continue;
      }
      const Layer& layer = *layers_[static_cast<std::size_t>(row.layer)];
      const std::size_t channels = static_cast<std::size_t>(layer.channels);
      if (layer.uniform()) {
        const half* fill = fills_[static_cast<std::size_t>(row.layer)].data();
        for (int i = 0; i < columns_; ++i)
          std::memcpy(to + 2 * static_cast<std::size_t>(i),
                      fill + i * channels + static_cast<std::size_t>(row.channel), 2);
        continue;
      }
      const float* from = layer.texels.data() + static_cast<std::size_t>(j) * columns_ * channels +
                          static_cast<std::size_t>(row.channel);
      for (int i = 0; i < columns_; ++i) {
        const half h(from[static_cast<std::size_t>(i) * channels]);
        const std::uint16_t bits = h.bits();
        std::memcpy(to + 2 * static_cast<std::size_t>(i), &bits, 2);
      }
    }
  }

  const Document& document_;
  int partNumber_;
  std::uint64_t dataStart_;
  int columns_;
  std::vector<const Layer*> layers_;
  LineLayout layout_;
  std::size_t chunk_;
  std::int32_t firstY_;
  std::vector<std::vector<half>> fills_;
  bool rle_;
};

// writeRawParts for files with RLE parts: a chunk's size is known only once it is coded, so the
// lines go in rounds of about kRoundBytes, each round's bands coded on every core into a buffer
// each; a band then waits for the band before it to be placed, writes its chunks after them and
// fills in their offsets, so writing overlaps the coding of the bands after it.
constexpr std::size_t kRoundBytes = 32 << 20;

void writeCodedParts(const std::vector<PartLines>& plans, int lines, std::uint64_t dataStart,
                     std::vector<std::uint8_t>& head, std::size_t table, ByteSink& sink) {
  struct Line {
    const PartLines* plan;
    int j;
  };
  std::vector<Line> all;
  all.reserve(static_cast<std::size_t>(lines));
  for (const PartLines& plan : plans)
    for (int j = 0; j < plan.rows(); ++j)
      all.push_back({&plan, j});
  const bool background = ::gettid() != ::getpid();
  std::uint64_t at = dataStart; // where the next band's chunks go
  std::size_t done = 0;
  while (done < all.size()) {
    std::size_t end = done, bytes = 0;
    while (end < all.size() && (end == done || bytes + all[end].plan->chunkBytes() <= kRoundBytes))
      bytes += all[end++].plan->chunkBytes();
    std::mutex lock;
    std::condition_variable placed;
    int placedUpTo = 0; // the round's lines whose chunks are written, in order
    const auto code = [&](int begin, int stop) {
      if (background) ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 19);
      // The band's buffer is taken whole at its worst case and never grown or zeroed: a grown
      // one moved and faulted in fresh pages at every save (16 objects of N = 256 saved 1.4x
      // slower per sample than one of N = 1024, all of it in page faults).
      std::size_t most = 0;
      for (int k = begin; k < stop; ++k)
        most += all[done + static_cast<std::size_t>(k)].plan->mostChunkBytes();
      const std::unique_ptr<char[]> data(new char[most]);
      std::size_t used = 0;
      std::vector<char> line, scratch;
      std::vector<std::uint64_t> sizes;
      sizes.reserve(static_cast<std::size_t>(stop - begin));
      std::exception_ptr failed; // still takes its turn, so the bands after it never wait forever
      try {
        for (int k = begin; k < stop; ++k) {
          const Line& l = all[done + static_cast<std::size_t>(k)];
          sizes.push_back(l.plan->writeChunk(l.j, line, scratch, data.get() + used));
          used += sizes.back();
        }
      } catch (...) {
        failed = std::current_exception();
      }
      std::unique_lock guard(lock);
      placed.wait(guard, [&] { return placedUpTo == begin; });
      if (failed) {
        placedUpTo = stop;
        guard.unlock();
        placed.notify_all();
        std::rethrow_exception(failed);
      }
      const std::uint64_t start = at;
      at += used;
      std::size_t entry = table + 8 * (done + static_cast<std::size_t>(begin));
      std::uint64_t offset = start;
      for (const std::uint64_t size : sizes) {
        std::memcpy(head.data() + entry, &offset, 8);
        entry += 8;
        offset += size;
      }
      guard.unlock();
      // Placed: the next band may go on while this one's bytes are written.
      {
        const std::lock_guard next(lock);
        placedUpTo = stop;
      }
      placed.notify_all();
      sink.writeAt(start, std::span(reinterpret_cast<const std::uint8_t*>(data.get()), used));
    };
    const int count = static_cast<int>(end - done);
    if (background) {
      std::exception_ptr error;
      std::thread lowered([&] {
        try {
          parallelRowsOrThrow(count, code, 8);
        } catch (...) {
          error = std::current_exception();
        }
      });
      lowered.join();
      if (error) std::rethrow_exception(error);
    } else {
      parallelRowsOrThrow(count, code, 8);
    }
    done = end;
  }
  sink.writeAt(0, head);
}

} // namespace

void writeRawParts(std::span<const RawPart> parts, bool multiPart,
                   const std::vector<std::uint8_t>& headerBytes, ByteSink& sink) {
  if (parts.empty() || (!multiPart && parts.size() != 1))
    throw std::logic_error("writeRawParts: one part, or a multi-part file");
  // The offset tables end OpenEXR's header bytes, one per part in order, a line each.
  int lines = 0;
  for (const RawPart& part : parts)
    lines += part.document.positions.rows();
  const std::uint64_t dataStart = headerBytes.size();
  if (headerBytes.size() < 8 * static_cast<std::size_t>(lines) + 8)
    throw std::logic_error("OpenEXR wrote no line offset table");

  std::vector<std::uint8_t> head = headerBytes;
  std::vector<PartLines> plans;
  plans.reserve(parts.size());
  std::size_t table = headerBytes.size() - 8 * static_cast<std::size_t>(lines);
  for (std::size_t k = 0; k < parts.size(); ++k)
    if (parts[k].header.compression() == Imf::RLE_COMPRESSION) {
      for (std::size_t m = 0; m < parts.size(); ++m)
        plans.emplace_back(parts[m], multiPart ? static_cast<int>(m) : -1, 0);
      writeCodedParts(plans, lines, dataStart, head, table, sink);
      return;
    }
  // The header with its offset tables filled in: each line's place is known before any is made.
  std::uint64_t at = dataStart;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    plans.emplace_back(parts[k], multiPart ? static_cast<int>(k) : -1, at);
    for (int j = 0; j < plans.back().rows(); ++j, at += plans.back().chunkBytes(), table += 8)
      std::memcpy(head.data() + table, &at, 8);
  }
  sink.writeAt(0, head);

  // Every part's lines in one pass over the cores (one fork and join for the file, so a scene's
  // small parts cost what one large part does).
  const bool background = ::gettid() != ::getpid();
  const auto writeLines = [&](int lineBegin, int lineEnd) {
    // Called from a worker (the modeller's save and autosave), the writer yields the cores to
    // the threads that draw: the GUI and its GL driver's rasterizer, which otherwise waited
    // for them (modeller_render_test: 2-4 GUI ticks in a 1.1-1.8 s save at N = 4096, 20-42
    // at the lowest priority). From a program's main thread (octaclay-cli) it keeps its own.
    if (background) ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 19);
    std::vector<char> buffer;
    int first = 0; // the part's first line among all
    for (const PartLines& plan : plans) {
      const int begin = std::max(lineBegin, first), end = std::min(lineEnd, first + plan.rows());
      if (begin < end) plan.write(begin - first, end - first, buffer, sink);
      first += plan.rows();
    }
  };
  // A worker's writing threads are made for it (so only they are lowered, never the caller).
  if (!background) {
    parallelRowsOrThrow(lines, writeLines, 16);
    return;
  }
  std::exception_ptr error;
  std::thread lowered([&] {
    try {
      parallelRowsOrThrow(lines, writeLines, 16);
    } catch (...) {
      error = std::current_exception();
    }
  });
  lowered.join();
  if (error) std::rethrow_exception(error);
}

void writeRawLines(const Document& document, const Imf::Header& header,
                   const std::vector<std::uint8_t>& headerBytes, ByteSink& sink) {
  const RawPart part{document, header};
  writeRawParts(std::span(&part, 1), false, headerBytes, sink);
}

} // namespace octaclay::core::detail
