// generateLod (lod.h): resample, refit to the full surface, collapse, and give every triangle
// corner the image coordinates of its vertex's copy on the triangle's side of the seams.
#include "octaclay/core/lod/lod.h"

#include "detail/unit_scale.h"
#include "lod/adaptive.h"
#include "lod/grid_lod.h"
#include "lod/lod_corners.h"
#include "lod/quadric_collapse.h"
#include "lod/refit.h"
#include "lod/resampling.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/vertex_index.h"
#include "octaclay/core/lod/vertex_collapse.h"

#include <algorithm>
#include <string>

namespace octaclay::core {
namespace {

using detail::collapseOptionsFor;
using detail::cornerCoordinates;
using detail::kCollapseNormalTurnDegrees;
using detail::kCollapseRefitCreaseDegrees;
using detail::refitIterations;
using detail::refitStride;
using detail::saliencyWeights;
using detail::setCornerCoordinates;
using detail::takeCollapsed;
using detail::VertexCopies;

// Where a vertex of the octahedral LOD grid may move when collapsed (see seamVeto).
enum class SeamClass : std::uint8_t { Interior, Cone, Bottom, Top, Left, Right };

SeamClass seamClass(int m, Sample s) {
  if (s == Sample{0, 0} || s == Sample{m / 2, 0} || s == Sample{0, m / 2} ||
      s == Sample{m, m / 2} || s == Sample{m / 2, m})
    return SeamClass::Cone;
  if (s.j == 0) return SeamClass::Bottom;
  if (s.j == m) return SeamClass::Top;
  if (s.i == 0) return SeamClass::Left;
  if (s.i == m) return SeamClass::Right;
  return SeamClass::Interior;
}

// The cone point ending seam c besides the corner (0, 0).
Sample seamMidpoint(int m, SeamClass c) {
  switch (c) {
  case SeamClass::Bottom:
    return {m / 2, 0};
  case SeamClass::Top:
    return {m / 2, m};
  case SeamClass::Left:
    return {0, m / 2};
  default:
    return {m, m / 2};
  }
}

void checkOptions(const GeometryImage& image, const LodOptions& options) {
  // A torus's or plane's sizes: gridLod checks M against its sides.
  requireValidGrid(image.grid());
  if (options.size != 0 && image.topology() == Topology::Octahedral)
    detail::requireLodSize(image.size(), options.size);
  if (options.targetTriangles > 0 && options.targetTriangles <= 4)
    throw Error(ErrorKind::InvalidArgument,
                "triangle target " + std::to_string(options.targetTriangles) +
                    " is too small: a closed mesh has at least 4 triangles; ask for more than 4");
  if (options.oversample < 1 || (options.oversample & (options.oversample - 1)) != 0)
    throw Error(ErrorKind::InvalidArgument, "oversampling " + std::to_string(options.oversample) +
                                                " is not a power of two; use 1, 2 or 4");
  if (!(options.maxError >= 0))
    throw Error(ErrorKind::InvalidArgument, "maximum error " + std::to_string(options.maxError) +
                                                " is negative; use 0 (no bound) or more");
  if (!(options.maxAspectRatio == 0 || options.maxAspectRatio >= 2))
    throw Error(ErrorKind::InvalidArgument,
                "maximum aspect ratio " + std::to_string(options.maxAspectRatio) +
                    " is below 2 (an equilateral triangle's is 1.15, a half square's 2); use 0 "
                    "(no bound) or 2 or more");
  if (!(options.collapseSaliencyWeight >= 0))
    throw Error(ErrorKind::InvalidArgument, "saliency weight " +
                                                std::to_string(options.collapseSaliencyWeight) +
                                                " is negative; use 0 (unweighted) or more");
  if (!(options.maxNormalTurnDegrees > 0 && options.maxNormalTurnDegrees <= 180))
    throw Error(ErrorKind::InvalidArgument, "maximum normal turn " +
                                                std::to_string(options.maxNormalTurnDegrees) +
                                                " degrees is outside (0, 180]");
}

int chooseSize(int n, const LodOptions& options) {
  if (options.size != 0) return options.size;
  if (options.targetTriangles == 0) return n / 2;
  int m = 2;
  while (m < n / 2 && 2 * std::size_t(m) * std::size_t(m) < options.targetTriangles)
    m *= 2;
  return std::min(n / 2, m * options.oversample);
}

// The copies of grid sample s of an m grid: its identified samples, each at uvAt(sample).
template <class UvAt> VertexCopies copiesOf(int m, Sample s, UvAt&& uvAt) {
  std::array<Sample, 4> same;
  VertexCopies c;
  c.count = identifiedSamples(m, s, same);
  for (int k = 0; k < c.count; ++k)
    c.uv[k] = uvAt(same[k]);
  return c;
}

std::vector<VertexCopies> vertexCopies(const detail::ResampledImage& resampled,
                                       const VertexIndex& index, int n) {
  const int m = index.size(), side = m + 1;
  std::vector<VertexCopies> copies(index.vertexCount());
  const float inv = 1.0f / float(n);
  const auto uvAt = [&](Sample s) {
    const Vec2f src = resampled.source[static_cast<std::size_t>(s.j) * side + s.i];
    return Vec2f{src.x * inv, src.y * inv};
  };
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) {
      const Sample s{i, j};
      if (canonical(m, s) == s) copies[index.at(i, j)] = copiesOf(m, s, uvAt);
    }
  return copies;
}

// Collapses lod.mesh (vertex v at grid sample sampleOf[v] of an m grid, image copies
// copies[v]) to the options' target or error bound, and gives each triangle its corner
// coordinates. A seam vertex has a copy on each side of its seam; it may only slide along the
// seam (into a vertex of the same seam or one of the seam's end cones), so that each triangle
// keeps corners on one side. Cones stay. Interior vertices move freely.
void collapseLod(LodMesh& lod, int m, const std::vector<Sample>& sampleOf,
                 const std::vector<VertexCopies>& copies, const LodOptions& options,
                 bool normalTurnPerCollapse = false, std::vector<float> vertexWeights = {}) {
  std::vector<SeamClass> classes(sampleOf.size());
  std::uint32_t corner = 0;
  std::array<std::uint32_t, 6> midpoint{};
  for (std::size_t v = 0; v < sampleOf.size(); ++v) {
    const Sample s = sampleOf[v];
    classes[v] = seamClass(m, s);
    if (s == Sample{0, 0}) corner = static_cast<std::uint32_t>(v);
    for (const SeamClass c : {SeamClass::Bottom, SeamClass::Top, SeamClass::Left, SeamClass::Right})
      if (s == seamMidpoint(m, c)) midpoint[static_cast<int>(c)] = static_cast<std::uint32_t>(v);
  }
  VertexCollapseOptions collapseOptions =
      collapseOptionsFor(options, copies, normalTurnPerCollapse, std::move(vertexWeights));
  collapseOptions.allowCollapse = [&](std::uint32_t from, std::uint32_t to) {
    const SeamClass c = classes[from];
    if (c == SeamClass::Interior) return true;
    if (c == SeamClass::Cone) return false;
    return classes[to] == c || to == corner || to == midpoint[static_cast<int>(c)];
  };
  // The mesh is closed and manifold by construction: the fast engine skips collapseVertices'
  // topology check (a sort as costly as the collapse itself).
  CollapsedMesh collapsed = options.collapseEngine == CollapseEngine::Fast
                                ? detail::quadricCollapse(lod.mesh, collapseOptions)
                                : collapseVertices(lod.mesh, collapseOptions);
  takeCollapsed(lod, std::move(collapsed), copies);
}

// Without a target or an error bound, as many triangles as the N/2 grid (or the given M's).
LodMesh adaptiveLod(const GeometryImage& image, const LodOptions& options) {
  const int n = image.size();
  std::size_t target = options.targetTriangles;
  if (target == 0 && options.maxError == 0) {
    const std::size_t m = options.size != 0 ? std::size_t(options.size) : std::size_t(n / 2);
    target = 2 * m * m;
  }
  BoundingBox box;
  if (options.maxError > 0)
    for (const Vec4f& t : image.texels())
      box.extend(t.xyz());
  // Oversampled: oversample² × the target's triangles, collapsed down to it (as the grid).
  const bool collapse = options.oversample > 1 && target > 0;
  const std::size_t cut =
      collapse ? target * std::size_t(options.oversample) * std::size_t(options.oversample)
               : target;
  detail::AdaptiveTriangulation triangulation =
      detail::adaptiveTriangulation(image, cut, options.maxError * box.diagonal());
  LodMesh lod;
  lod.resampledSize = n;
  lod.mesh = std::move(triangulation.mesh);
  lod.cornerUv = std::move(triangulation.cornerUv);
  if (collapse && target < lod.mesh.triangles.size()) {
    const float inv = 1.0f / float(n);
    const auto uvAt = [inv](Sample s) { return Vec2f{float(s.i) * inv, float(s.j) * inv}; };
    std::vector<VertexCopies> copies;
    copies.reserve(triangulation.vertexSample.size());
    for (const Sample s : triangulation.vertexSample)
      copies.push_back(copiesOf(n, s, uvAt));
    LodOptions collapseOptions = options;
    collapseOptions.targetTriangles = target;
    collapseLod(lod, n, triangulation.vertexSample, copies, collapseOptions);
  }
  if (options.refitToSurface)
    detail::refitToSurface(image, lod.cornerUv, lod.mesh,
                           refitStride(double(n) * n, lod.mesh.triangles.size()),
                           refitIterations(double(n) * n, lod.mesh.triangles.size()));
  return lod;
}

// The collapse method: the welded full-resolution mesh collapsed with the grid's seam rules,
// then refit away from creases.
LodMesh fullResolutionCollapse(const GeometryImage& image, const LodOptions& options) {
  const int n = image.size();
  const VertexIndex index(n);
  LodMesh lod;
  lod.resampledSize = n;
  lod.methodUsed = ResampleMethod::Collapse;
  lod.mesh = extractMesh(image);
  const float inv = 1.0f / float(n);
  const auto uvAt = [inv](Sample s) { return Vec2f{float(s.i) * inv, float(s.j) * inv}; };
  std::vector<Sample> sampleOf(index.vertexCount());
  std::vector<VertexCopies> copies(index.vertexCount());
  for (const Sample s : index.canonicalSamples()) {
    const std::uint32_t v = index.at(s.i, s.j);
    sampleOf[v] = s;
    copies[v] = copiesOf(n, s, uvAt);
  }
  // Without a target or an error bound, as many triangles as the N/2 grid (or the given M's).
  std::size_t target = options.targetTriangles;
  if (target == 0 && options.maxError == 0) {
    const std::size_t m = options.size != 0 ? std::size_t(options.size) : std::size_t(n / 2);
    target = 2 * m * m;
  }
  const bool collapse = (target > 0 && target < lod.mesh.triangles.size()) || options.maxError > 0;
  if (collapse) {
    // No aspect bound: the full-resolution triangles already have the image's shapes, and
    // the bound kept the collapse 9 dB below meshoptimizer at 1 % on the armadillo.
    LodOptions unbounded = options;
    unbounded.maxAspectRatio = 0;
    unbounded.maxNormalTurnDegrees = kCollapseNormalTurnDegrees;
    unbounded.targetTriangles = target;
    collapseLod(lod, n, sampleOf, copies, unbounded, true,
                saliencyWeights(image, sampleOf, options.collapseSaliencyWeight));
  } else {
    setCornerCoordinates(lod, copies);
  }
  if (options.refitToSurface)
    detail::refitToSurface(
        image, lod.cornerUv, lod.mesh, refitStride(double(n) * n, lod.mesh.triangles.size()),
        refitIterations(double(n) * n, lod.mesh.triangles.size()), kCollapseRefitCreaseDegrees);
  return lod;
}

} // namespace

std::string_view methodName(ResampleMethod method) {
  switch (method) {
  case ResampleMethod::Point:
    return "point";
  case ResampleMethod::Average:
    return "average";
  case ResampleMethod::SalientAverage:
    return "salient-average";
  case ResampleMethod::SalientPoint:
    return "salient-point";
  case ResampleMethod::Adaptive:
    return "adaptive";
  case ResampleMethod::Collapse:
    return "collapse";
  case ResampleMethod::Auto:
    return "auto";
  }
  return "salient-point";
}

std::optional<ResampleMethod> parseResampleMethod(std::string_view name) {
  for (const ResampleMethod m :
       {ResampleMethod::Point, ResampleMethod::Average, ResampleMethod::SalientAverage,
        ResampleMethod::SalientPoint, ResampleMethod::Adaptive, ResampleMethod::Collapse,
        ResampleMethod::Auto})
    if (methodName(m) == name) return m;
  return std::nullopt;
}

GeometryImage resampleImage(const GeometryImage& image, int m, ResampleMethod method) {
  requireOctahedral(image, "resampling to an LOD grid", "this image");
  requireValidSize(image.size());
  if (method == ResampleMethod::Adaptive || method == ResampleMethod::Collapse ||
      method == ResampleMethod::Auto)
    throw Error(ErrorKind::InvalidArgument,
                "the " + std::string(methodName(method)) +
                    " method makes no grid to resample to; choose point, average, "
                    "salient-average or salient-point");
  return detail::resampleWithSources(image, m, method).image;
}

LodMesh generateLod(const GeometryImage& image, const LodOptions& options) {
  if (const int e = detail::unitScaleExponent(image); e != 0) {
    checkOptions(image, options);
    LodMesh lod = generateLod(detail::scaledPositions(image, e), options);
    detail::scaleMesh(lod.mesh, -e);
    return lod;
  }
  checkOptions(image, options);
  if (image.topology() != Topology::Octahedral) return detail::gridLod(image, options);
  const int n = image.size();
  if (options.method == ResampleMethod::Auto) {
    LodOptions chosen = options;
    chosen.method = chooseLodMethod(image, options);
    return generateLod(image, chosen);
  }
  if (options.method == ResampleMethod::Adaptive) {
    LodMesh lod = adaptiveLod(image, options);
    lod.methodUsed = ResampleMethod::Adaptive;
    return lod;
  }
  if (options.method == ResampleMethod::Collapse) return fullResolutionCollapse(image, options);
  const int m = chooseSize(n, options);
  const detail::ResampledImage resampled = detail::resampleWithSources(image, m, options.method);
  const VertexIndex index(m);

  LodMesh lod;
  lod.resampledSize = m;
  lod.methodUsed = options.method;
  lod.mesh = extractMesh(resampled.image);
  const std::vector<VertexCopies> copies = vertexCopies(resampled, index, n);

  const bool collapse =
      (options.targetTriangles > 0 && options.targetTriangles < lod.mesh.triangles.size()) ||
      options.maxError > 0;
  if (collapse) {
    std::vector<Sample> sampleOf(index.vertexCount());
    for (const Sample s : index.canonicalSamples())
      sampleOf[index.at(s.i, s.j)] = s;
    collapseLod(lod, m, sampleOf, copies, options);
  } else {
    setCornerCoordinates(lod, copies);
  }
  if (options.refitToSurface)
    detail::refitToSurface(image, lod.cornerUv, lod.mesh,
                           refitStride(double(n) * n, lod.mesh.triangles.size()),
                           refitIterations(double(n) * n, lod.mesh.triangles.size()));
  return lod;
}

} // namespace octaclay::core
