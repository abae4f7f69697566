#pragma once

#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/sample_grid.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/geometry/vec.h"

#include <cstddef>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace octaclay::core {

/// The position image: (W+1)×(H+1) vertex-centred samples of a topology, row-major (j rows of
/// W+1 texels, i along a row). xyz is the object-space position, w the saliency. The octahedral
/// ball is square (W = H = N); a torus or plane may have W ≠ H.
class GeometryImage {
public:
  GeometryImage() = default;
  /// An octahedral N image, all texels zero. Throws Error(InvalidArgument) unless n is valid.
  explicit GeometryImage(int n);
  /// A W × H image of the topology, all texels zero. Throws unless isValidGrid.
  GeometryImage(Topology topology, int width, int height);

  Topology topology() const { return grid_.topology; }
  const SampleGrid& grid() const { return grid_; }
  int width() const { return grid_.width; }
  int height() const { return grid_.height; }
  bool square() const { return grid_.width == grid_.height; }
  /// N of a square image (always so for the octahedral ball); the width W otherwise.
  int size() const { return grid_.width; }
  /// Samples along a row (W+1): the row stride, and the side of a square image.
  int side() const { return grid_.width + 1; }
  /// Rows of samples (H+1).
  int rows() const { return grid_.height + 1; }
  std::size_t texelCount() const { return texels_.size(); }
  std::size_t byteSize() const { return texels_.size() * sizeof(Vec4f); }

  Vec4f& at(int i, int j) { return texels_[index(i, j)]; }
  const Vec4f& at(int i, int j) const { return texels_[index(i, j)]; }
  Vec4f& at(Sample s) { return at(s.i, s.j); }
  const Vec4f& at(Sample s) const { return at(s.i, s.j); }
  /// The position at any integer sample, read through the topology's wrap().
  Vec3f positionWrapped(Sample s) const {
    return grid_.topology == Topology::Octahedral ? at(wrap(grid_.width, s)).xyz()
                                                  : at(wrap(grid_, s)).xyz();
  }

  std::span<Vec4f> texels() { return texels_; }
  std::span<const Vec4f> texels() const { return texels_; }

private:
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(grid_.width + 1) +
           static_cast<std::size_t>(i);
  }
  /// Makes no texel when the vector grows (Vec4f is plain data), so the constructors can zero
  /// a large image on every core instead of in one thread's memset.
  template <class T> struct GrowsUninitialized : std::allocator<T> {
    template <class U> struct rebind { using other = GrowsUninitialized<U>; };
    GrowsUninitialized() = default;
    template <class U> GrowsUninitialized(const GrowsUninitialized<U>&) noexcept {}
    template <class U> void construct(U*) noexcept {}
    template <class U, class... Args> void construct(U* p, Args&&... args) {
      ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
  };
  void zeroTexels(std::size_t count);

  SampleGrid grid_;
  std::vector<Vec4f, GrowsUninitialized<Vec4f>> texels_;
};

/// The bounding box of every sample's position (xyz).
BoundingBox boundingBox(const GeometryImage& image);

} // namespace octaclay::core
