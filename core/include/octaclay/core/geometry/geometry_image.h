#pragma once

#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/geometry/vec.h"

#include <cstddef>
#include <span>
#include <vector>

namespace octaclay::core {

/// The position image: (N+1)×(N+1) vertex-centred octahedral samples, row-major (j rows of
/// N+1 texels, i along a row). xyz is the object-space position, w the saliency.
class GeometryImage {
public:
  GeometryImage() = default;
  /// All texels zero. Throws Error(InvalidArgument) unless n is a valid size.
  explicit GeometryImage(int n);

  int size() const { return n_; }
  int side() const { return n_ + 1; }
  std::size_t texelCount() const { return texels_.size(); }
  std::size_t byteSize() const { return texels_.size() * sizeof(Vec4f); }

  Vec4f& at(int i, int j) { return texels_[index(i, j)]; }
  const Vec4f& at(int i, int j) const { return texels_[index(i, j)]; }
  Vec4f& at(Sample s) { return at(s.i, s.j); }
  const Vec4f& at(Sample s) const { return at(s.i, s.j); }
  /// The position at any integer sample, read through wrap().
  Vec3f positionWrapped(Sample s) const { return at(wrap(n_, s)).xyz(); }

  std::span<Vec4f> texels() { return texels_; }
  std::span<const Vec4f> texels() const { return texels_; }

private:
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(n_ + 1) +
           static_cast<std::size_t>(i);
  }
  int n_ = 0;
  std::vector<Vec4f> texels_;
};

/// The bounding box of every sample's position (xyz).
BoundingBox boundingBox(const GeometryImage& image);

} // namespace octaclay::core
