#pragma once

// Scalar quantization of one channel's wavelet coefficients and the reconstruction of the
// channel from them; the encoder's error check and the decoder share reconstructPlane, so
// what the encoder measured is what the decoder returns.

#include <cstdint>
#include <span>
#include <vector>

namespace octaclay::core::detail {

/// How one channel was coded: samples = reconstruction + centre, the DC coefficient kept as a
/// float, the others as q·step.
struct ChannelCoding {
  float centre = 0;
  float step = 1;
  float dc = 0;
};

/// The reconstruction point of |q| ≥ 1 is (|q| + kReconstructionOffset)·step: coefficients
/// are peaked at zero, so the mean of each quantization bin lies below its middle.
inline constexpr float kRoundingOffset = 0.5f;
inline constexpr float kReconstructionOffset = 0.0f;

/// Quantizes every sample's coefficient but the DC (at the corners, set to 0).
void quantizePlane(std::span<const float> coefficients, int n, float step,
                   std::span<std::int32_t> q);

/// The channel's (N+1)² samples from its quantized coefficients, seamed (each identified
/// sample a bit copy of its canonical one).
void reconstructPlane(std::span<const std::int32_t> q, int n, const ChannelCoding& coding,
                      std::span<float> out);

} // namespace octaclay::core::detail
