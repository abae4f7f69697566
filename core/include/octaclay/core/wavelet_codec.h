#pragma once

// The `wavelet` geometry codec (issue 8): a CDF 9/7 lifting transform over the octahedral
// tiling of the plane (no seam is ever seen), one quantizer step per channel found so that an
// error bound holds, and context-modelled adaptive range coding of the coefficients, coarse
// bands first, so that a prefix of the stream decodes to a coarser model.
//
// Guarantee: for every channel c, the RMS over the N²+2 vertices (canonical samples) of
// decoded − original (seamed: identified samples averaged) is ≤ bound × D, where D is the
// diagonal of the bounding box of the first min(3, channels) channels (the positions). The
// encoder checks this by decoding what it wrote. Identified samples decode bit-equal.

#include "octaclay/core/codec.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace octaclay::core {

inline constexpr std::uint16_t kWaveletVersion = 1;
inline constexpr double kWaveletMinBound = 1e-6;
inline constexpr double kWaveletMaxBound = 0.1;
inline constexpr double kWaveletDefaultBound = 2e-5;
/// The tangential error may be this many times the bound (see above).
inline constexpr double kWaveletTangentFactor = 8;

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
