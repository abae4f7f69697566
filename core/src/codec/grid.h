#pragma once

// What every codec shares about the (N+1)² vertex grid: argument checks, seams, threads.

#include "octaclay/core/codec/codec.h"

#include <cstddef>
#include <functional>

namespace octaclay::core::detail {

inline std::size_t sampleCount(int n) {
  return static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1);
}

/// Throws Error(InvalidArgument) unless n is a valid size, 1 ≤ channels ≤ 4 and the texels
/// are (N+1)² × channels.
void requireCodableImage(const FloatImage& image, std::string_view codec);
/// Throws Error(InvalidInput) unless n and channels are ones a stream can be decoded for.
void requireDecodableShape(int n, int channels, std::string_view codec);

bool isCanonical(int n, int i, int j);
/// True when every sample identified with another holds the same float bits as it.
bool seamsBitExact(const FloatImage& image);
/// Copies each canonical sample's channels onto the samples identified with it, so the seams
/// of a lossy decode are exact without changing the canonical values.
void copySeams(FloatImage& image);

/// Runs task(k) for k in [0, count) on up to two threads (the machine's cores); rethrows the
/// first exception a task threw.
void parallelTasks(int count, const std::function<void(int)>& task);

} // namespace octaclay::core::detail
