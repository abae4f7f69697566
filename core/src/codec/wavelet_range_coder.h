#pragma once

// An adaptive binary range coder (the LZMA design) coding the wavelet coefficients' decisions.
// Each model mixes a fast and a slow estimate of its probability, and a new model learns from
// its first decisions at rates 1/2, 1/4, …: a context's skew costs a few decisions, not dozens.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace octaclay::core::detail {

constexpr int kProbabilityBits = 15;
constexpr std::uint32_t kProbabilityOne = 1 << kProbabilityBits;
// Adaptation rates 2^-5 and 2^-7 (measured on armadillo at 95 dB: 1.5 % fewer bits than one
// rate of 2^-5; other pairs did no better).
constexpr int kFastShift = 5;
constexpr int kSlowShift = 7;
constexpr std::uint32_t kMinProbability = 64;
/// The most bits one adaptive decision can cost: probabilities stay within [64, 32704] / 32768.
constexpr int kMaxBitsPerDecision = 9;

/// The probability that the next decision is 0, in units of 1/32768.
struct BitModel {
  std::uint16_t fast = kProbabilityOne / 2;
  std::uint16_t slow = kProbabilityOne / 2;
  std::uint16_t seen = 0; // decisions learnt from, up to kSlowShift

  std::uint32_t p() const {
    return std::clamp<std::uint32_t>((std::uint32_t{fast} + slow) >> 1, kMinProbability,
                                     kProbabilityOne - kMinProbability);
  }
  void update(int bit) {
    const int fastShift = std::min<int>(seen + 1, kFastShift);
    const int slowShift = std::min<int>(seen + 1, kSlowShift);
    if (seen < kSlowShift) ++seen;
    if (bit == 0) {
      fast = static_cast<std::uint16_t>(fast + ((kProbabilityOne - fast) >> fastShift));
      slow = static_cast<std::uint16_t>(slow + ((kProbabilityOne - slow) >> slowShift));
    } else {
      fast = static_cast<std::uint16_t>(fast - (fast >> fastShift));
      slow = static_cast<std::uint16_t>(slow - (slow >> slowShift));
    }
  }
};

class RangeEncoder {
public:
  int bit(BitModel& model, int bit) {
    const std::uint32_t bound = (range_ >> kProbabilityBits) * model.p();
    if (bit == 0) {
      range_ = bound;
    } else {
      low_ += bound;
      range_ -= bound;
    }
    model.update(bit);
    normalize();
    return bit;
  }
  /// An equiprobable bit, no model.
  int raw(int bit) {
    range_ >>= 1;
    if (bit != 0) low_ += range_;
    normalize();
    return bit;
  }
  std::vector<std::uint8_t> finish() {
    for (int i = 0; i < 5; ++i)
      shiftLow();
    return std::move(out_);
  }

private:
  void normalize() {
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      shiftLow();
    }
  }
  void shiftLow() {
    if (static_cast<std::uint32_t>(low_) < 0xFF000000u || (low_ >> 32) != 0) {
      const auto carry = static_cast<std::uint8_t>(low_ >> 32);
      std::uint8_t pending = cache_;
      do {
        out_.push_back(static_cast<std::uint8_t>(pending + carry));
        pending = 0xFF;
      } while (--cacheSize_ != 0);
      cache_ = static_cast<std::uint8_t>(low_ >> 24);
    }
    ++cacheSize_;
    low_ = (low_ & 0x00FFFFFFu) << 8;
  }

  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  std::uint64_t cacheSize_ = 1;
  std::vector<std::uint8_t> out_;
};

/// Reads what RangeEncoder wrote. Past the end it reads zeros and counts them: a stream the
/// encoder wrote is never overrun, so overrun() > 0 marks a damaged one.
class RangeDecoder {
public:
  explicit RangeDecoder(std::span<const std::uint8_t> bytes)
      : next_(bytes.data()), end_(bytes.data() + bytes.size()) {
    firstByte_ = nextByte();
    for (int i = 0; i < 4; ++i)
      code_ = (code_ << 8) | nextByte();
  }
  int bit(BitModel& model, int /*unused*/ = 0) {
    const std::uint32_t bound = (range_ >> kProbabilityBits) * model.p();
    int bit;
    if (code_ < bound) {
      range_ = bound;
      bit = 0;
    } else {
      code_ -= bound;
      range_ -= bound;
      bit = 1;
    }
    model.update(bit);
    normalize();
    return bit;
  }
  int raw(int /*unused*/ = 0) {
    range_ >>= 1;
    int bit = 0;
    if (code_ >= range_) {
      code_ -= range_;
      bit = 1;
    }
    normalize();
    return bit;
  }
  /// True when the stream was well formed as far as it was read.
  bool intact() const { return overrun_ == 0 && firstByte_ == 0; }

private:
  void normalize() {
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      code_ = (code_ << 8) | nextByte();
    }
  }
  std::uint32_t nextByte() {
    if (next_ < end_) return *next_++;
    ++overrun_;
    return 0;
  }

  const std::uint8_t* next_;
  const std::uint8_t* end_;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint32_t code_ = 0;
  std::uint32_t firstByte_ = 0;
  std::size_t overrun_ = 0;
};

} // namespace octaclay::core::detail
