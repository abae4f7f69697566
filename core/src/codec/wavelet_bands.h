#pragma once

// Entropy coding of one detail band of quantized wavelet coefficients: each canonical sample of
// the band, all channels interleaved, through the adaptive range coder with contexts from the
// sample's coded neighbours in the band, its parent in the next coarser band and the channels
// already coded at the same sample; the models carry over from each band to the next finer one.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace octaclay::core::detail {

/// Which lattice positions of a level hold the band: details along i (odd i, even j),
/// along j (even i, odd j), or both (odd, odd).
enum class Orientation { AlongI = 0, AlongJ = 1, Diagonal = 2 };
inline constexpr int kOrientations = 3;

/// |q| stays below this so that every coefficient codes in a bounded number of decisions.
inline constexpr std::int32_t kMaxMagnitude = 1 << 28;

/// Quantized coefficients: one (N+1)² plane per channel, identified samples equal.
struct CoefficientPlanes {
  int n = 0;
  int channels = 0;
  std::vector<std::vector<std::int32_t>> q;
  /// With three or more channels: |q0| + |q1| + |q2| of the samples coded so far (contexts).
  std::vector<std::int32_t> magnitude;
};

/// Fills planes.magnitude from complete planes (the encoder, before encodeBand).
void setVectorMagnitudes(CoefficientPlanes& planes);

/// Canonical samples of the band at this level (0 = finest) and orientation.
std::size_t bandSampleCount(int n, int level, Orientation orientation);

/// The adaptive models of one orientation's bands. Each band starts from what the next coarser
/// band of its orientation learnt, so the encoder and the decoder code an orientation's bands
/// coarsest first, all with one BandModels.
class BandModels {
public:
  BandModels();
  ~BandModels();
  BandModels(BandModels&&) noexcept;
  BandModels& operator=(BandModels&&) noexcept;
  struct State;
  std::unique_ptr<State> state;
};

std::vector<std::uint8_t> encodeBand(const CoefficientPlanes& planes, int level,
                                     Orientation orientation, BandModels& models);

/// Fills the band's samples and their identified copies. Returns false for a damaged stream
/// (the values written are then meaningless but bounded).
bool decodeBand(std::span<const std::uint8_t> bytes, CoefficientPlanes& planes, int level,
                Orientation orientation, BandModels& models);

/// The most bytes encodeBand can write for a band of `samples` samples of `channels` channels.
std::size_t maxBandBytes(std::size_t samples, int channels);

} // namespace octaclay::core::detail
