#pragma once

// Automatic level of detail from the geometry image (thesis, chapter 4): resample the image to
// a smaller (M+1)² grid, seam it, then optionally collapse vertices down to a triangle target
// or an error bound. The result is closed, manifold and genus 0, and each triangle corner
// carries the image coordinates its vertex came from, so a normal map baked from the
// full-resolution image textures it.

#include <array>
#include <cstddef>
#include <octaclay/core/geometry_image.h>
#include <octaclay/core/triangle_mesh.h>
#include <optional>
#include <string_view>
#include <vector>

namespace octaclay::core {

/// How each LOD sample is chosen from its footprint of full-resolution samples.
enum class ResampleMethod {
  Point,          ///< the sample at the same image coordinates
  Average,        ///< the mean of the footprint
  SalientAverage, ///< the saliency-weighted mean of the footprint
  SalientPoint,   ///< the footprint's most salient sample (the thesis's best)
};

/// "point", "average", "salient-average", "salient-point".
std::string_view methodName(ResampleMethod method);
std::optional<ResampleMethod> parseResampleMethod(std::string_view name);

struct LodOptions {
  /// M, the resampled grid's size: a power of two, 2 ≤ M < N. 0 = the smallest M whose 2M²
  /// triangles reach targetTriangles (M = N/2 at most).
  int size = 0;
  ResampleMethod method = ResampleMethod::SalientPoint;
  /// Vertex collapse down to this many triangles (0 = none); must be > 4 when set.
  std::size_t targetTriangles = 0;
  /// Vertex collapse stops before any collapse whose quadric error exceeds this fraction of
  /// the bounding-box diagonal (0 = no bound).
  double maxError = 0;
  /// A collapse that turns any triangle's normal by more than this is refused.
  float maxNormalTurnDegrees = 60;
  /// Move each resampled vertex along its normal to fit the full-resolution surface in the
  /// least-squares sense before collapsing (detail: two Jacobi steps over the samples of
  /// each LOD cell). Off: vertices are exactly the resampled samples.
  bool refitToSurface = true;
};

struct LodMesh {
  /// Welded, closed, manifold, genus 0, counter-clockwise seen from outside.
  TriangleMesh mesh;
  /// Per triangle, the image coordinates of its three corners, in the same order as
  /// mesh.triangles. Vertices on the octahedral seams have several image positions; each
  /// triangle gets the copies that lie together, so no triangle spans the seam in the image.
  /// Image coordinates are (x / N, y / N) for full-resolution sample (x, y).
  std::vector<std::array<Vec2f, 3>> cornerUv;
  int resampledSize = 0; ///< M that was used
};

/// Throws Error(InvalidArgument) with a message naming the bad value when M ≥ N, M is not a
/// power of two or M < 2, when targetTriangles is 1 … 4, or maxError < 0. Needs the image's
/// saliency in alpha for the salient methods (computeSaliency, or the GPU pass).
LodMesh generateLod(const GeometryImage& image, const LodOptions& options);

/// The resampled, seamed (M+1)² image alone (step 1 of generateLod).
GeometryImage resampleImage(const GeometryImage& image, int m, ResampleMethod method);

struct SaliencyOptions {
  /// Centre-surround scales in full-resolution samples: saliency is the sum over scales s of
  /// |G(curvature, s) − G(curvature, 2s)| (Lee et al. 2005), curvature being the change of
  /// normal across the sample's neighbourhood. Empty = {1, 2, 4, 8, 16} scaled to N/256.
  std::vector<float> scales;
};

/// CPU reference of the GPU saliency pass: writes each sample's saliency, normalised to
/// [0, 1] over the image, into the position image's alpha. Identified samples get equal
/// values.
void computeSaliency(GeometryImage& image, const SaliencyOptions& options = {});

} // namespace octaclay::core
