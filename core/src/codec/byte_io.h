#pragma once

// Little-endian byte writing and bounds-checked reading for codec streams and the container.

#include "octaclay/core/codec/codec.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core::detail {

class ByteWriter {
public:
  void u8(std::uint8_t v) { bytes_.push_back(v); }
  void u16(std::uint16_t v) { little(v, 2); }
  void u32(std::uint32_t v) { little(v, 4); }
  void u64(std::uint64_t v) { little(v, 8); }
  void f32(float v);
  void f64(double v);
  /// LEB128: 7 bits a byte, low first.
  void varint(std::uint64_t v) {
    for (; v >= 0x80; v >>= 7)
      bytes_.push_back(static_cast<std::uint8_t>(v | 0x80));
    bytes_.push_back(static_cast<std::uint8_t>(v));
  }
  void append(std::span<const std::uint8_t> data) {
    bytes_.insert(bytes_.end(), data.begin(), data.end());
  }
  std::size_t size() const { return bytes_.size(); }
  std::vector<std::uint8_t>& bytes() { return bytes_; }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

private:
  void little(std::uint64_t v, int count) {
    for (int k = 0; k < count; ++k)
      bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  std::vector<std::uint8_t> bytes_;
};

/// Every read checks the bounds; a short stream throws Error(InvalidInput) naming `what`.
class ByteReader {
public:
  ByteReader(std::span<const std::uint8_t> bytes, std::string what)
      : bytes_(bytes), what_(std::move(what)) {}
  std::uint8_t u8() { return static_cast<std::uint8_t>(little(1)); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(little(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(little(4)); }
  std::uint64_t u64() { return little(8); }
  float f32();
  double f64();
  /// A LEB128 value of at most 32 bits.
  std::uint32_t varint32();
  std::span<const std::uint8_t> take(std::uint64_t count);
  std::size_t offset() const { return offset_; }
  std::size_t remaining() const { return bytes_.size() - offset_; }
  /// Refuses bytes left over after the last field.
  void expectEnd() const;
  [[noreturn]] void fail(const std::string& why) const;

private:
  std::uint64_t little(int count);
  std::span<const std::uint8_t> bytes_;
  std::size_t offset_ = 0;
  std::string what_;
};

/// Every codec stream starts with the codec's code, its version, N and the channel count.
void writeStreamHeader(ByteWriter& out, const CodecInfo& info, int n, int channels);
/// Checks that header against the codec and what the container says; returns the version.
std::uint16_t readStreamHeader(ByteReader& in, const CodecInfo& info, int n, int channels);
inline constexpr std::size_t kStreamHeaderSize = 1 + 2 + 4 + 1;

/// zlib's CRC-32 of bytes (any length): what ends an .ocz container.
std::uint32_t crc32Of(std::span<const std::uint8_t> bytes);

/// The whole of an .ocz file: a folder, a pipe or a device is refused (it would block or never
/// end), as are a missing or unreadable file, each with its path named (Error(Io)).
std::vector<std::uint8_t> readCompressedFileBytes(const std::filesystem::path& path);

} // namespace octaclay::core::detail
