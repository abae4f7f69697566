#pragma once

// The `wavelet` geometry codec (issue 8): a CDF 9/7 lifting transform over the octahedral
// tiling of the plane (the transform never sees a seam), positions quantized as vectors in a
// frame of the coarser rebuilt surface (fine steps along its normal, 4× coarser across it),
// the step chosen so that an error bound holds, and context-modelled adaptive range coding of
// the coefficients, coarse bands first, so that a prefix of the stream decodes to a coarser
// model.
//
// Guarantee, with D the diagonal of the bounding box of the first min(3, channels) channels
// and RMS taken over the N²+2 vertices (canonical samples) against the input with identified
// samples averaged:
//   - 3 or 4 channels: the RMS of the position error's component along the input surface's
//     vertex normals (core/normals.h computeNormals) is ≤ bound·D, the RMS length of its
//     tangential part ≤ kWaveletTangentFactor·bound·D, and a 4th channel's RMS error ≤ bound·D;
//   - 1 or 2 channels: each channel's RMS error is ≤ bound·D.
// The encoder checks this by rebuilding what the decoder will. Identified samples decode
// bit-equal (no cracks).

#include "octaclay/core/codec/codec.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace octaclay::core {

inline constexpr std::uint16_t kWaveletVersion = 3;
inline constexpr double kWaveletMinBound = 1e-6;
inline constexpr double kWaveletMaxBound = 0.1;
inline constexpr double kWaveletDefaultBound = 1.5e-5; ///< about 96 dB on scanned meshes
/// The tangential error may be this many times the bound (see above): sliding along the
/// surface barely changes its shape.
inline constexpr double kWaveletTangentFactor = 16;

/// Throws Error(InvalidArgument) for a bound outside [kWaveletMinBound, kWaveletMaxBound], an
/// invalid n, 1 ≤ channels ≤ 4 not holding, a texel count other than (N+1)²·channels or a
/// non-finite texel.
std::vector<std::uint8_t> encodeWavelet(const FloatImage& image, double bound);

/// Throws Error(InvalidInput) for any stream encodeWavelet did not write for this n and
/// channels (as far as it can tell: damaged bytes may also decode to a wrong image).
FloatImage decodeWavelet(std::span<const std::uint8_t> stream, int n, int channels);

/// Decodes the first `bytes` bytes of a stream: every band complete in them, the finer ones
/// zero. The error shrinks as the prefix grows. Throws Error(InvalidInput) when the prefix is
/// shorter than the header or a complete band is damaged.
FloatImage decodeWaveletPrefix(std::span<const std::uint8_t> stream, int n, int channels,
                               std::size_t bytes);

/// The prefix lengths at which decodeWaveletPrefix gains a band, shortest first (the last is
/// the whole stream). Throws as decodeWavelet.
std::vector<std::size_t> waveletBandEnds(std::span<const std::uint8_t> stream, int n, int channels);

/// The registry entry: CodecParams::quality is the bound above.
Codec makeWaveletCodec();

} // namespace octaclay::core
