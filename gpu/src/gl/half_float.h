#pragma once

// Half floats as a texture read back gives them, widened to float on the CPU.

#include <bit>
#include <cstdint>

namespace octaclay::gpu::detail {

/// Exact half → float without branches, so the compiler vectorizes a row of them: the half's
/// exponent and mantissa moved into a float's and scaled by 2^112 (subnormal halves become
/// subnormal floats and scale exactly too); infinities and NaNs keep the all-ones exponent.
inline float widenHalf(std::uint16_t h) {
  const std::uint32_t magnitude = h & 0x7fffu;
  const float scaled = std::bit_cast<float>(magnitude << 13) * 0x1p112f;
  const std::uint32_t special = 0u - static_cast<std::uint32_t>(magnitude >= 0x7c00u);
  const std::uint32_t bits = (((magnitude << 13) | 0x7f800000u) & special) |
                             (std::bit_cast<std::uint32_t>(scaled) & ~special);
  return std::bit_cast<float>(bits | (static_cast<std::uint32_t>(h & 0x8000u) << 16));
}

} // namespace octaclay::gpu::detail
