#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace octaclay::core {

/// What `octaclay-cli info` reports about a document.
struct DocumentInfo {
  int size = 0;                ///< N
  std::uint64_t vertices = 0;  ///< N²+2 after welding identified samples
  std::uint64_t triangles = 0; ///< 2N²
  std::uint64_t edges = 0;
  long long euler = 0;
  float seamGap = 0;           ///< largest distance between identified samples
  std::uint64_t nonFinite = 0; ///< samples with NaN or infinite coordinates
  std::uint64_t degenerateTriangles = 0;
  bool closed = false;   ///< seams coincide, every position is finite, no boundary (not a plane)
  bool manifold = false; ///< seams coincide, no edge in three triangles, none of zero area
  BoundingBox bbox;
  std::vector<std::string> layers; ///< "positions", "diffuse", "feature" (+ "mask")
};

/// Walks the image once; connectivity counts follow from the octahedral grid (a torus's or
/// plane's from its extracted mesh).
DocumentInfo describeDocument(const Document& document);

} // namespace octaclay::core
