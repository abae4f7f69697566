#pragma once

#include "merge/part_layers.h"
#include "merge/part_locator.h"

#include "octaclay/core/geometry/geometry_image.h"

#include <cstddef>

namespace octaclay::core::detail {

/// Puts the merged surface back onto the parts where it is theirs alone: each sample whose
/// closest point on the nearest part is within maxMove, and whose closest point no other part
/// comes within clearance of, moves onto that point; the others (where parts meet, where the
/// level set rounded a crease between them, and where it bridged a dent narrower than a voxel)
/// stay. The union's mesh is within about half a voxel of the parts, so with maxMove of 0.75
/// voxel and clearance of 1.5 voxels a moved sample never lands inside another part: it would
/// have to have been more than 1.5 − 0.75 − 0.5 voxel inside it already. Seams the image
/// (identified samples move alike, their closest points being one). Returns how many samples
/// moved. When `layers` is given and active, each texel's layers are carried on the way from
/// the very point found for it (the closest point to the texel as it ends, moved or not), so a
/// merge searches once per texel. Runs on every hardware thread, one or two PartLocator
/// queries per sample.
std::size_t snapToParts(const PartLocator& parts, GeometryImage& positions, double maxMove,
                        double clearance, LayerCarrier* layers = nullptr);

} // namespace octaclay::core::detail
