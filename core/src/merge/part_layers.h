#pragma once

#include "merge/part_locator.h"

#include "octaclay/core/document/document.h"

#include <cstdint>
#include <vector>

namespace octaclay::core::detail {

/// Fills merged's diffuse, feature and mask layers from the parts: each texel takes the value
/// at the closest point of the nearest part's placed surface (barycentric over that triangle's
/// corners). A layer uniform with one fill in every part gets that fill and no texels; when
/// every layer is, nothing is searched and sourcePart is left empty, else it gets, per texel,
/// the part the texel's layers came from. merged.hasMask is true when any part's is. Runs on
/// every hardware thread, one PartLocator query per texel.
void carryPartLayers(const PartLocator& parts, Document& merged,
                     std::vector<std::uint16_t>& sourcePart);

} // namespace octaclay::core::detail
