// How decode_fuzzer reads its input, shared with make_fuzz_corpus so that the seeds are valid
// streams in this layout: byte 0 picks the target (0: the .ocz container, k ≥ 1: codec
// (k − 1) mod #codecs, whose byte 1 gives N = 2^(1 + b mod 6) and byte 2 the channels
// 1 + b mod 4, and the wavelet's prefix length in its upper bits); the rest is the stream.
#pragma once

#include "octaclay/core/codec/codec.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fuzz_input {

struct Target {
  const octaclay::core::Codec* codec = nullptr; ///< nullptr: the container
  int n = 0, channels = 0;
  std::span<const std::uint8_t> stream;
};

/// false when the input is too short to name a target.
inline bool parse(std::span<const std::uint8_t> data, Target& out) {
  if (data.empty()) return false;
  if (data[0] == 0) {
    out = {nullptr, 0, 0, data.subspan(1)};
    return true;
  }
  const auto& all = octaclay::core::codecs();
  if (all.empty() || data.size() < 3) return false;
  out.codec = &all[(data[0] - 1u) % all.size()];
  out.n = 1 << (1 + data[1] % 6);
  out.channels = 1 + data[2] % 4;
  out.stream = data.subspan(3);
  return true;
}

/// The header bytes that make parse() pick codec index k at this n (2 … 64) and channels.
inline std::array<std::uint8_t, 3> header(std::size_t k, int n, int channels) {
  int log = 0;
  while ((2 << log) < n)
    ++log;
  return {static_cast<std::uint8_t>(k + 1), static_cast<std::uint8_t>(log),
          static_cast<std::uint8_t>(channels - 1)};
}

} // namespace fuzz_input
