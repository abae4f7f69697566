#pragma once

#include "merge/part_locator.h"

#include "octaclay/core/document/document.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace octaclay::core::detail {

/// Fills a merged document's diffuse, feature and mask layers from the parts: each texel takes
/// the value at the closest point of the nearest part's placed surface (barycentric over that
/// triangle's corners). A layer uniform with one fill in every part gets that fill and no
/// texels; when every layer is, nothing needs searching (active() is false) and sourcePart is
/// left empty, else it gets, per texel, the part the texel's layers came from. merged.hasMask
/// is true when any part's is.
class LayerCarrier {
public:
  /// Sets the uniform layers and sizes the others and sourcePart; merged's positions are the
  /// texels' points. merged and sourcePart must outlive the carrier.
  LayerCarrier(const PartLocator& parts, Document& merged, std::vector<std::uint16_t>& sourcePart);

  bool active() const { return !carried_.empty(); }
  /// Texel t (row-major in merged) takes its layers from `found`, the nearest part's closest
  /// point to it. Distinct texels may be carried on different threads at once.
  void carry(std::size_t texel, const PartLocator::Found& found);

private:
  const PartLocator& parts_;
  Document& merged_;
  std::vector<std::uint16_t>& sourcePart_;
  std::vector<int> carried_;                          // 0 diffuse, 1 feature, 2 mask
  std::vector<std::vector<std::size_t>> vertexTexel_; // per part, per mesh vertex
};

/// LayerCarrier over every texel, each found with its own PartLocator query, on every hardware
/// thread (what a merge runs when it does not snap, which finds them on the way).
void carryPartLayers(const PartLocator& parts, Document& merged,
                     std::vector<std::uint16_t>& sourcePart);

} // namespace octaclay::core::detail
