#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/topology.h"

#include <array>
#include <string>
#include <vector>

namespace octaclay::core {

/// A painted layer beside the positions, on the same (N+1)² grid. A layer nobody has painted
/// stays uniform (no texel storage, just its fill value) so large documents stay small.
struct Layer {
  std::string name;            ///< "diffuse", "feature" or "mask"
  int channels = 0;            ///< 4, 3 or 1
  std::array<float, 4> fill{}; ///< value of every texel while uniform
  std::vector<float> texels;   ///< empty while uniform, else (N+1)² × channels, row-major

  bool uniform() const { return texels.empty(); }
  /// Channel names as stored in the EXR file, e.g. {"R","G","B","A"}.
  std::vector<std::string> channelNames() const;
};

/// An Octaclay model: the position image and its layers (DESIGN.md, "The geometry image").
struct Document {
  GeometryImage positions;
  Layer diffuse{"diffuse", 4, {0.8f, 0.8f, 0.8f, 1.0f}, {}};
  Layer feature{"feature", 3, {0.0f, 0.25f, 0.0f, 0.0f}, {}};
  Layer mask{"mask", 1, {1.0f, 0.0f, 0.0f, 0.0f}, {}}; ///< 1 = full brush effect, 0 = blocked
  bool hasMask = false;                                ///< mask.Y is optional in the file
  /// How the image closes up: always positions.topology() (makeDocument and readDocument set it;
  /// writeDocument refuses a document where they differ).
  Topology topology = Topology::Octahedral;

  int size() const { return positions.size(); }
};

/// A new document holding image, with default layers and the image's topology.
Document makeDocument(GeometryImage image);

} // namespace octaclay::core
