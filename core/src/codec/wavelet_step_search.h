#pragma once

// The wavelet encoder's rate control: the coarsest quantization steps that keep the decoded
// image within the error bound, found by measuring the reconstruction the decoder will make.

#include "codec/wavelet_quantizer.h"

#include <vector>

namespace octaclay::core::detail {

/// The largest steps whose reconstruction keeps every error within `target` (an absolute
/// distance): RMS over the vertices of the position error along the original surface's normals
/// ≤ target and across them ≤ kWaveletTangentFactor × target, every other channel's RMS
/// ≤ target. `original` holds the seamed channels, `coefficients` their centred forward
/// transforms; sets coding's steps and leaves q quantized with them. Throws
/// Error(InvalidArgument) when no step meets the bound in float precision.
void chooseWaveletSteps(const std::vector<std::vector<float>>& original,
                        const std::vector<std::vector<float>>& coefficients,
                        std::vector<ChannelCoding>& coding, double target, CoefficientPlanes& q);

} // namespace octaclay::core::detail
