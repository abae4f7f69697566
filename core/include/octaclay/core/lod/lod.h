#pragma once

// Automatic level of detail from the geometry image (thesis, chapter 4): resample the image to
// a smaller (M+1)² grid, seam it, then optionally collapse vertices down to a triangle target
// or an error bound. The result is closed, manifold and genus 0, and each triangle corner
// carries the image coordinates its vertex came from, so a normal map baked from the
// full-resolution image textures it.

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/lod/vertex_collapse.h"
#include "octaclay/core/measure/stretch.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace octaclay::core {

/// How each LOD sample is chosen from its footprint of full-resolution samples. LOD sample
/// (a, b) of an M grid stands for full-resolution sample (a·s, b·s), s = N/M, and its
/// footprint is the samples (a·s + di, b·s + dj), |di|, |dj| ≤ s/2, read through wrap(). The
/// tiling's half-turns map LOD grid points onto LOD grid points and footprints onto
/// footprints, so identified LOD samples have the same footprint and stay equal; each vertex is
/// computed once, at its canonical sample, then seamed (seaming.h).
enum class ResampleMethod {
  Point,   ///< the sample at (a·s, b·s)
  Average, ///< the footprint's mean, weight 1 inside and ½ on its rim rows and columns (¼ at
           ///< its corners), so neighbouring footprints' weights sum to one
  SalientAverage, ///< the same mean with each weight times (saliency + 1/64)
  /// The most salient sample within s/4 of (a·s, b·s) (ties: the nearest the centre, then the
  /// first in row order): the thesis's best. s/4 rather than the whole footprint keeps every
  /// LOD triangle counter-clockwise in the image whatever its corners pick. Samples on a seam
  /// pick along the seam only (the vertex stays on it); the octahedron's six vertices (the
  /// image's corners and side midpoints) keep their own sample.
  SalientPoint,
  /// No grid: samples of the full image chosen where the surface bends, by cutting the
  /// right-triangle hierarchy over the image where its error (distance from the plane of the
  /// triangle a sample splits) falls below a threshold set by the triangle target or maxError.
  /// Flat parts get few large triangles, ridges and folds many small ones.
  Adaptive,
  /// No resampling: the welded full-resolution mesh (2N² triangles) collapsed down to the
  /// target (without one: to the size's 2M² triangles) with the grid's seam rules and no
  /// aspect bound, then refit except at sharp creases. What a stretched image needs: the
  /// collapse, not the image, decides where the vertices go (docs/lod.md).
  Collapse,
  /// Picks one of the above per image (chooseLodMethod); LodMesh::methodUsed says which.
  Auto,
};

/// "point", "average", "salient-average", "salient-point", "adaptive", "collapse", "auto".
std::string_view methodName(ResampleMethod method);
std::optional<ResampleMethod> parseResampleMethod(std::string_view name);

struct LodOptions {
  /// M, the resampled grid's size: a power of two, 2 ≤ M < N. 0 = the smallest M whose 2M²
  /// triangles reach targetTriangles, times oversample (M = N/2 at most; N/2 without a target).
  int size = 0;
  /// With size 0 and a target: resample to oversample × that M and collapse the rest. 1 is the
  /// live LOD (fewest collapses); 2 starts from 4× the triangles, so the collapse chooses where
  /// detail goes: closer to the surface for several times the time (docs/lod.md, bench_lod).
  /// A power of two. Adaptive: cut the hierarchy at oversample² × the target's triangles and
  /// collapse down to it.
  int oversample = 1;
  ResampleMethod method = ResampleMethod::SalientPoint;
  /// Vertex collapse down to this many triangles (0 = none); must be > 4 when set.
  std::size_t targetTriangles = 0;
  /// Vertex collapse stops before any collapse whose quadric error exceeds this fraction of
  /// the bounding-box diagonal (0 = no bound). Adaptive: no sample within this distance of the
  /// planes of the triangles it would split is kept.
  double maxError = 0;
  /// A collapse that turns any triangle's normal by more than this is refused.
  float maxNormalTurnDegrees = 60;
  /// A collapse that makes a triangle's longest edge / height exceed this, and twice what its
  /// triangle was in the mesh the collapse starts from, is refused (unless the triangle already
  /// did and gets no worse); 0 = no bound, else at least 2. The factor two leaves the collapse
  /// room where the image stretches the surface (docs/lod.md measures it).
  float maxAspectRatio = 10;
  /// Move each resampled vertex along its normal to fit the full-resolution surface in the
  /// least-squares sense before collapsing (detail: two Jacobi steps over the samples of
  /// each LOD cell). Off: vertices are exactly the resampled samples.
  bool refitToSurface = true;
  /// The live LOD needs the fast engine (vertex_collapse.h); the Decimater gives the strict
  /// error order at a much higher cost.
  CollapseEngine collapseEngine = CollapseEngine::Fast;
  /// Auto chooses per image. The live LOD turns it off: auto then keeps to salient-point, whose
  /// regeneration fits a frame (bench_lod's live line); a collapse of all 2N² triangles does
  /// not.
  bool autoMayCollapse = true;
  /// The collapse method (and auto when it collapses) weighs each full-resolution triangle's
  /// quadric by 1 + this × the mean saliency of its corners where the image carries saliency in
  /// alpha (the modeller's GPU pass keeps it; nothing computes it for this): collapses cost
  /// more where the surface is salient, so detail stays there. 0 = unweighted.
  float collapseSaliencyWeight = 1;
};

struct LodMesh {
  /// Welded, manifold, counter-clockwise seen from outside; of the image's topology: closed
  /// genus 0 (the ball), closed genus 1 (a torus), one boundary loop (a plane).
  TriangleMesh mesh;
  /// Per triangle, the image coordinates of its three corners, in the same order as
  /// mesh.triangles. Vertices on the octahedral seams have several image positions; each
  /// triangle gets the copies that lie together, so no triangle spans the seam in the image.
  /// Image coordinates are (x / N, y / N) for full-resolution sample (x, y): the sample the
  /// vertex came from (point methods) or its LOD grid position scaled to the full image
  /// (average methods). Every triangle's corners are counter-clockwise in the image and the
  /// triangles tile the unit square once (collapses that would fold them are refused).
  std::vector<std::array<Vec2f, 3>> cornerUv;
  int resampledSize = 0; ///< M that was used; N for the adaptive and collapse methods (no grid)
  /// The method that made it: options.method, or what Auto chose.
  ResampleMethod methodUsed = ResampleMethod::SalientPoint;
};

/// The LOD: resample to M (resampleImage), extract the welded mesh (2M² triangles), collapse
/// to targetTriangles / maxError when set (vertex_collapse.h; seam vertices only slide along
/// their seam, the octahedron's six vertices stay, no collapse folds the corner coordinates),
/// then, with refitToSurface, move the vertices along their normals to the least-squares fit
/// of the full-resolution samples each triangle covers in the image. Thread-safe for distinct
/// images; uses two threads for the large loops.
/// Throws Error(InvalidArgument) with a message naming the bad value when M ≥ N, M is not a
/// power of two or M < 2, when targetTriangles is 1 … 4, maxError < 0, oversample is not a
/// power of two, maxNormalTurnDegrees is outside (0, 180] or collapseSaliencyWeight < 0. Needs the
/// image's saliency in alpha for the salient methods (computeSaliency in saliency.h, or the GPU
/// pass).
/// A torus or plane image (W × H) is resampled by a power of two d to (W/d) × (H/d) cells, M
/// = max(W, H)/d; its wrap lines and boundary are kept as the ball's seams are (salient samples
/// and collapses move along them only), a plane's boundary samples average along it; adaptive
/// is its collapse (methodUsed says so).
LodMesh generateLod(const GeometryImage& image, const LodOptions& options);

/// Auto's choice for this image and these options (cheap: a stretch summary over a coarse
/// sub-grid of the image and a roughness over a sparse one, O(N²/256) past N = 128): the
/// image-based adaptive method where the image samples a smooth surface evenly
/// (imageStretches false, imageRoughness at most kSmoothRoughness), the full-resolution
/// collapse elsewhere (docs/lod.md gives the benchmark behind the thresholds). With
/// options.autoMayCollapse false (the live LOD): salient-point, whatever the image. A torus or
/// plane: the collapse (its grid has no adaptive hierarchy).
ResampleMethod chooseLodMethod(const GeometryImage& image, const LodOptions& options);
/// The stretch summary chooseLodMethod judges by: summarizeStretch of the image point-sampled
/// to a 64 grid (the image itself below N = 4).
StretchSummary coarseStretch(const GeometryImage& image);
/// Auto's threshold: the image samples the surface evenly when its coarse p99 edge is at most
/// this many medians and its longest at most that many (sculpted N = 1024 sphere: 1.55 and
/// 2.02; max_planck_decimated: 1.60 and 1.83, 3-4 dB better collapsed). igea (1.46 and 1.64)
/// passes it but is a scan, rough sample to sample: kSmoothRoughness tells it.
inline constexpr double kEvenP99OverMedian = 1.58, kEvenLongestOverMedian = 2.15;
bool imageStretches(const StretchSummary& summary);
/// How much rougher the surface is sample to sample than at 8 samples' spacing: the median
/// bend (|a + c − 2b| / |c − a| over three samples in a row) at spacing 1, times 8, over the
/// median at spacing 8, on a sparse set of image positions (about 128² at most). About 1 on a
/// smooth surface (the bend grows with the spacing), up to 8 where noise or fine detail
/// dominates (a scan).
double imageRoughness(const GeometryImage& image);
/// Auto's roughness threshold: the sculpted N = 1024 sphere has 0.99 (adaptive: 2.8-4 dB above
/// meshopt_simplify at 1-25 % for a 20th of its time), igea 1.86 (adaptive 1.9 dB below it at
/// 1 %, the collapse 1.6 dB above; bench_lod).
inline constexpr double kSmoothRoughness = 1.4;

/// The resampled, seamed (M+1)² image alone (step 1 of generateLod).
GeometryImage resampleImage(const GeometryImage& image, int m, ResampleMethod method);

} // namespace octaclay::core
