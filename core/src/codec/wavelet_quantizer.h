#pragma once

// Quantization of the wavelet coefficients and the reconstruction of the image from them, one
// level at a time, coarse to fine. Positions (the first three channels of an image with three
// or more) are quantized as vectors in a frame of the surface the coarser levels rebuilt: along
// its normal with the finest step, across it (where the geometric error barely moves) with a
// coarser one. The encoder and the decoder run the same code, so the frames, and what the
// encoder measured, are what the decoder gets.

#include "codec/wavelet_bands.h"

#include <cstdint>
#include <span>
#include <vector>

namespace octaclay::core::detail {

/// How one channel was coded: samples = reconstruction + centre, the DC coefficient kept as a
/// float, the others as q·step·0.85^level (level 0 the finest). For positions, the steps of
/// channels 0, 1, 2 are those of the frame's normal and two tangents.
struct ChannelCoding {
  float centre = 0;
  float step = 1;
  float dc = 0;
};

/// Positions are coded in frames when the image has at least this many channels.
inline constexpr int kVectorChannels = 3;

/// Fills `planes` (channels × (N+1)², seamed) from the quantized coefficients in q (zero for
/// bands a progressive prefix lacks). With `exact` (the forward transform of the image,
/// centred), first quantizes it into q, level by level, in the frames the decoder will see.
void rebuild(CoefficientPlanes& q, std::span<const ChannelCoding> coding,
             std::vector<std::vector<float>>& planes,
             const std::vector<std::vector<float>>* exact = nullptr);

} // namespace octaclay::core::detail
