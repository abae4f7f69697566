#pragma once

#include "octaclay/core/lod/normal_map.h"

#include <vector>

namespace octaclay::core::detail {

/// Throws Error(InvalidArgument) unless the map holds resolution² texels, resolution ≥ 1.
void requireNormalMap(const NormalMap& map);

/// The map as an 8-bit RGB PNG in memory, each component n·0.5 + 0.5 rounded to 1/255.
std::vector<unsigned char> encodeNormalMapPng(const NormalMap& map);

} // namespace octaclay::core::detail
