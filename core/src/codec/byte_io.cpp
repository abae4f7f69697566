#include "codec/byte_io.h"

#include "octaclay/core/error.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <fstream>
#include <iterator>

namespace octaclay::core::detail {

void ByteWriter::f32(float v) {
  u32(std::bit_cast<std::uint32_t>(v));
}

void ByteWriter::f64(double v) {
  u64(std::bit_cast<std::uint64_t>(v));
}

float ByteReader::f32() {
  return std::bit_cast<float>(u32());
}

double ByteReader::f64() {
  return std::bit_cast<double>(u64());
}

std::uint32_t ByteReader::varint32() {
  std::uint64_t v = 0;
  for (int shift = 0;; shift += 7) {
    const std::uint8_t byte = u8();
    v |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
    if (v > 0xffffffffu) fail("varint longer than 32 bits at offset " + std::to_string(offset_));
    if (!(byte & 0x80)) return static_cast<std::uint32_t>(v);
    if (shift >= 28) fail("varint longer than 32 bits at offset " + std::to_string(offset_));
  }
}

std::uint64_t ByteReader::little(int count) {
  if (remaining() < static_cast<std::size_t>(count))
    fail("truncated: needs " + std::to_string(count) + " more bytes at offset " +
         std::to_string(offset_) + " of " + std::to_string(bytes_.size()));
  std::uint64_t v = 0;
  for (int k = 0; k < count; ++k)
    v |= static_cast<std::uint64_t>(bytes_[offset_ + k]) << (8 * k);
  offset_ += static_cast<std::size_t>(count);
  return v;
}

std::span<const std::uint8_t> ByteReader::take(std::uint64_t count) {
  if (remaining() < count)
    fail("truncated: a block of " + std::to_string(count) + " bytes at offset " +
         std::to_string(offset_) + " runs past the end (" + std::to_string(bytes_.size()) +
         " bytes)");
  const auto block = bytes_.subspan(offset_, static_cast<std::size_t>(count));
  offset_ += static_cast<std::size_t>(count);
  return block;
}

void ByteReader::expectEnd() const {
  if (remaining() != 0)
    fail(std::to_string(remaining()) + " unexpected bytes after the end of the data");
}

void ByteReader::fail(const std::string& why) const {
  throw Error(ErrorKind::InvalidInput, what_ + ": " + why);
}

void writeStreamHeader(ByteWriter& out, const CodecInfo& info, int n, int channels) {
  out.u8(info.code);
  out.u16(info.version);
  out.u32(static_cast<std::uint32_t>(n));
  out.u8(static_cast<std::uint8_t>(channels));
}

std::uint16_t readStreamHeader(ByteReader& in, const CodecInfo& info, int n, int channels) {
  const std::uint8_t code = in.u8();
  if (code != info.code)
    in.fail("stream of codec code " + std::to_string(code) + ", not " + std::string(info.id) +
            " (" + std::to_string(info.code) + ")");
  const std::uint16_t version = in.u16();
  if (version != info.version)
    in.fail("stream version " + std::to_string(version) + " is not supported (this Octaclay " +
            "reads version " + std::to_string(info.version) + "); update Octaclay");
  const std::uint32_t storedN = in.u32();
  if (storedN != static_cast<std::uint32_t>(n))
    in.fail("stream is for N = " + std::to_string(storedN) + ", the container says " +
            std::to_string(n));
  const std::uint8_t storedChannels = in.u8();
  if (storedChannels != channels)
    in.fail("stream has " + std::to_string(storedChannels) + " channels, expected " +
            std::to_string(channels));
  return version;
}

std::uint32_t crc32Of(std::span<const std::uint8_t> bytes) {
  uLong crc = crc32(0L, Z_NULL, 0);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const uInt chunk = static_cast<uInt>(std::min<std::size_t>(bytes.size() - done, 1u << 30));
    crc = crc32(crc, bytes.data() + done, chunk);
    done += chunk;
  }
  return static_cast<std::uint32_t>(crc);
}

std::vector<std::uint8_t> readCompressedFileBytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorKind::Io, "cannot open " + path.string() + ": it is a folder");
  // A pipe or device would block or never end: only regular files are read.
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw Error(ErrorKind::Io, "cannot open " + path.string() + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error(ErrorKind::Io,
                "cannot open " + path.string() +
                    (std::filesystem::exists(path) ? ": permission denied" : ": no such file"));
  std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                  std::istreambuf_iterator<char>()};
  if (in.bad()) throw Error(ErrorKind::Io, "cannot read " + path.string());
  return bytes;
}

} // namespace octaclay::core::detail
