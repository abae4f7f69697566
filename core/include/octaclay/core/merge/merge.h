#pragma once

// Merge (issue 33, item 7): several closed parts placed in world space become one closed
// genus-0 document through a voxel union (docs/ARCHITECTURE.md, "A merge").

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/vec.h"

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core {

/// An affine placement: world = m · (x, y, z, 1), m row-major with the last row (0, 0, 0, 1).
struct PartTransform {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  /// Scale (per axis, negative mirrors), then rotate about x, then y, then z (degrees), then
  /// translate: the order of Blender's and the modeller's G/R/S.
  static PartTransform fromTrs(Vec3f translate, Vec3f rotateDegrees = {0, 0, 0},
                               Vec3f scale = {1, 1, 1});
  Vec3f apply(Vec3f p) const;
};

/// One part of a merge: a document (an octahedral geometry image and its layers) and where it
/// stands. The document is read, never changed, and must outlive the call.
struct MergePart {
  const Document* document = nullptr;
  PartTransform transform;
  std::string name = {}; ///< the object's, for messages ("part k" when empty)
};

struct MergeOptions {
  int size = 256; ///< N of the merged document
  /// The level set's resolution: its voxel is √(A / M²), A the placed parts' total area and
  /// M = min(size, levelSetSize), so the union's mesh has at most about M² vertices (a voxel
  /// face per voxel² of surface; fewer where the parts overlap). Mapping that mesh onto the
  /// sphere costs most of a merge and grows faster than its vertices (docs/ARCHITECTURE.md, "A
  /// merge", has the figures), so above levelSetSize the merged document samples the union's
  /// mesh finer than the mesh itself, and detail finer than a voxel is kept only where
  /// snapToParts puts the samples back onto the parts. 0 or less: M = size.
  int levelSetSize = 128;
  double voxelSize = 0; ///< when > 0, this voxel size (world units) instead of the rule above
  /// Each sample where the surface is one part's alone (farther than 1.5 voxels from every
  /// other part) moved onto that part's closest point when it is within 0.75 voxel: the merged
  /// surface is the parts' own there, not the level set's facets (src/merge/part_snap.h).
  bool snapToParts = true;
};

/// What a merge measured on the way.
struct MergeResult {
  Document document;
  double voxelSize = 0;
  std::size_t levelSetVertices = 0, levelSetTriangles = 0; ///< the union's mesh
  long long euler = 0;                                     ///< of that mesh: 2 for genus 0
  /// Per texel ((N+1)², row-major) the index of the part its layers were carried from; empty
  /// when every layer has one fill in every part (nothing to carry, nothing searched).
  std::vector<std::uint16_t> sourcePart;
  /// The least part's fair share of samples as the grid would sample the sphere map before and
  /// after it was turned for the parts (estimated from the map, before resampling).
  double leastShareUnturned = 0, leastShareTurned = 0;
  std::size_t snapped = 0; ///< samples moved onto their part (MergeOptions::snapToParts)
  /// Times: the level set and its checks; the map, its turn and the resampling; the search of
  /// the parts per texel (snapping and the layers).
  double levelSetMs = 0, parameterizeMs = 0, partsMs = 0;
};

/// The parts' voxel union as one octahedral document of N = options.size. Each part's surface
/// (extractMesh at full resolution, placed by its transform) becomes a narrow-band level set
/// (OpenVDB meshToLevelSet, 3 voxels each side) at the voxel size of MergeOptions; the sets are
/// united (csgUnion) and meshed again (volumeToMesh, adaptivity 0, quads split along their
/// shorter diagonal); that mesh is checked (one piece, genus 0), cleaned (validateGenus0Mesh),
/// mapped onto the sphere (parameterizeOnSphere), turned so that the grid's denser directions
/// fall where they even out the parts' shares of samples (the part of a point: the nearest
/// placed part), and resampled at N (resampleOctahedral), as `octaclay-cli import` does; where
/// the surface is one part's alone its samples are moved onto that part (snapToParts). Every
/// layer is carried from the parts: each new sample takes the value at its closest point on the
/// placed parts, the nearest part winning (a layer uniform with the same fill in every part stays
/// uniform; hasMask when any part has one). Saliency 0.
///
/// Throws, with nothing changed (the parts are only read):
/// - Error(InvalidArgument) for no parts or more than 65 535, a null document, an N out of
///   range, a transform with a
///   non-finite entry, a last row other than (0, 0, 0, 1) or a singular 3×3 part, a voxel size
///   that is not finite, or one so small that the level set would exceed 2²⁴ voxels across or
///   the parts' surface 8192² voxels (the largest document's samples);
/// - Error(InvalidInput) for a part with non-finite positions; a plane or disc (an open sheet
///   encloses nothing: its voxel shell would be a plate as thick as a voxel, whatever N); "these
///   objects do not touch"
///   when the union has more than one piece (the count named); "the merged surface has genus G
///   (Euler characteristic χ) …" when it is not genus 0; when the union's mesh cannot be mapped
///   onto the sphere without folds;
/// - Error(Cancelled) when progress (fraction done in [0, 1], called on the caller's thread)
///   returns false.
MergeResult mergeParts(std::span<const MergePart> parts, const MergeOptions& options = {},
                       const std::function<bool(float)>& progress = {});

} // namespace octaclay::core
