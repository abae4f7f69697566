#pragma once

// LSB-first bit packing for the raw low bits of residuals; the reader is bounds-checked.

#include "codec/byte_io.h"

#include <cstdint>
#include <span>
#include <vector>

namespace octaclay::core::detail {

class BitWriter {
public:
  /// count ≤ 32 low bits of v.
  void put(std::uint32_t v, int count) {
    acc_ |= static_cast<std::uint64_t>(v) << bits_;
    bits_ += count;
    while (bits_ >= 8) {
      bytes_.push_back(static_cast<std::uint8_t>(acc_));
      acc_ >>= 8;
      bits_ -= 8;
    }
  }
  std::vector<std::uint8_t> finish() {
    if (bits_ > 0) bytes_.push_back(static_cast<std::uint8_t>(acc_));
    acc_ = 0;
    bits_ = 0;
    return std::move(bytes_);
  }

private:
  std::vector<std::uint8_t> bytes_;
  std::uint64_t acc_ = 0;
  int bits_ = 0;
};

class BitReader {
public:
  BitReader(std::span<const std::uint8_t> bytes, const ByteReader& owner)
      : p_(bytes.data()), end_(bytes.data() + bytes.size()), owner_(owner) {}
  std::uint32_t get(int count) {
    while (bits_ < count) {
      if (p_ == end_) owner_.fail("bit stream ends early");
      acc_ |= static_cast<std::uint64_t>(*p_++) << bits_;
      bits_ += 8;
    }
    const std::uint32_t v = static_cast<std::uint32_t>(acc_ & ((std::uint64_t{1} << count) - 1));
    acc_ >>= count;
    bits_ -= count;
    return v;
  }
  /// Refuses unread bytes or non-zero padding.
  void expectEnd() const {
    if (p_ != end_ || acc_ != 0) owner_.fail("bit stream longer than its samples");
  }

private:
  const std::uint8_t* p_;
  const std::uint8_t* end_;
  std::uint64_t acc_ = 0;
  int bits_ = 0;
  const ByteReader& owner_;
};

} // namespace octaclay::core::detail
