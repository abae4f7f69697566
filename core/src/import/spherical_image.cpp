#include "import/spherical_image.h"

#include "import/spherical_geometry.h"
#include "import/spherical_progressive.h"
#include "import/spherical_stages.h"

#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/vertex_index.h"
#include "octaclay/core/import/mesh_validation.h"

#include <algorithm>

namespace octaclay::core::detail {
namespace {

// One level of the grid: the image sampled every `step` samples.
std::vector<Tri> trianglesOf(const TriangleMesh& mesh) {
  std::vector<Tri> out;
  out.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    out.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  return out;
}

// The sphere points of the level of size n/fineStep from those of the level n/coarseStep:
// each fine vertex linearly inside the coarse grid triangle that holds it, as extractMesh
// splits the cells (the diagonal b–d where (i < M/2) == (j < M/2), else a–c).
Points refine(int n, int coarseStep, const Points& coarse, int fineStep) {
  const VertexIndex coarseIndex(n, coarseStep), fineIndex(n, fineStep);
  const int mc = coarseIndex.size(), half = mc / 2;
  const int ratio = coarseStep / fineStep;
  const std::vector<Sample> samples = fineIndex.canonicalSamples();
  Points out(samples.size());
  for (std::size_t v = 0; v < samples.size(); ++v) {
    const int ci = std::min(samples[v].i / ratio, mc - 1);
    const int cj = std::min(samples[v].j / ratio, mc - 1);
    const double u = double(samples[v].i - ci * ratio) / ratio;
    const double w = double(samples[v].j - cj * ratio) / ratio;
    const Vec3d& a = coarse[coarseIndex.at(ci, cj)];
    const Vec3d& b = coarse[coarseIndex.at(ci + 1, cj)];
    const Vec3d& c = coarse[coarseIndex.at(ci + 1, cj + 1)];
    const Vec3d& d = coarse[coarseIndex.at(ci, cj + 1)];
    Vec3d p;
    if ((ci < half) == (cj < half)) // triangles abd and bcd
      p = u + w <= 1 ? Vec3d(a + u * (b - a) + w * (d - a))
                     : Vec3d(c + (1 - u) * (d - c) + (1 - w) * (b - c));
    else // triangles abc and acd
      p = u >= w ? Vec3d(a + u * (b - a) + w * (c - b)) : Vec3d(a + u * (c - d) + w * (d - a));
    out[v] = p.normalized();
  }
  return out;
}

} // namespace

SphericalMap parameterizeImageOnSphere(const GeometryImage& image, const TriangleMesh& mesh,
                                       const std::function<bool(float)>& progress,
                                       const ImageParameterizationOptions& options) {
  const int n = image.size();
  if (options.coarseSize < 2 || n < 2 * options.coarseSize)
    return parameterizeOnSphere(mesh, progress);
  // The coarse grid, parameterized whole; a grid its checks refuse (coincident samples make
  // degenerate triangles) leaves the whole mesh to parameterizeOnSphere.
  int step = n / options.coarseSize;
  TriangleMesh coarse;
  SphericalMap coarseMap;
  bool inward = false;
  try {
    TriangleMesh grid = extractMesh(image, step);
    inward = signedVolume(grid) < 0;
    ValidatedMesh validated = validateGenus0Mesh(std::move(grid));
    coarse = std::move(validated.mesh);
    if (coarse.positions.size() != VertexIndex(n, step).vertexCount())
      return parameterizeOnSphere(mesh, progress);
    // The default pipeline at this size (64² + 2 vertices): coarse to fine (its
    // simplification keeps a thin limb the grid has few samples on) and the whole-mesh map (it
    // wins on smooth surfaces such as an imported one) at once, the better kept, then the
    // descent on the largest stretch.
    coarseMap =
        parameterizeOnSphere(coarse, [&](float f) { return !progress || progress(0.5f * f); });
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::Cancelled) throw;
    return parameterizeOnSphere(mesh, progress);
  }
  if (coarseMap.flipped > 0) return parameterizeOnSphere(mesh, progress);
  Points s(coarseMap.sphere.size());
  for (std::size_t v = 0; v < s.size(); ++v)
    s[v] = {coarseMap.sphere[v].x, coarseMap.sphere[v].y, coarseMap.sphere[v].z};
  report(progress, 0.5);

  // Each finer level from the one below, relaxed where the coarse grid's triangles were too
  // big to see the surface's detail.
  const int levels = [&] {
    int count = 0;
    for (int st = step; st > 1; st /= 2)
      ++count;
    return count;
  }();
  int done = 0;
  while (step > 1) {
    const int fine = step / 2;
    s = refine(n, step, s, fine);
    const TriangleMesh levelMesh = fine == 1 ? TriangleMesh{} : extractMesh(image, fine);
    const TriangleMesh& m = fine == 1 ? mesh : levelMesh;
    std::vector<Tri> triangles = trianglesOf(m);
    // extractMesh winds as the image faces; validation turned an inward-facing one around, the
    // full-resolution mesh and the coarse grid alike.
    if (fine > 1 && inward)
      for (Tri& t : triangles)
        std::swap(t[1], t[2]);
    Points x(m.positions.size());
    for (std::size_t v = 0; v < x.size(); ++v)
      x[v] = {m.positions[v].x, m.positions[v].y, m.positions[v].z};
    const Adjacency rings = adjacency(static_cast<int>(x.size()), triangles);
    untangle(s, triangles, rings);
    const double begin = 0.5 + 0.5 * done / levels, end = 0.5 + 0.5 * (done + 1) / levels;
    if (options.sweepsPerLevel > 0 && n / fine <= options.relaxUpToSize)
      relaxStretchWhereMoving(s, x, triangles, rings, options.sweepsPerLevel, progress, begin, end);
    // The descent on the largest stretch once more on the level of finishSize: the tips of
    // thin parts the coarse grid saw too few samples of.
    if (options.finishSweeps > 0 && n / fine == std::min(n, options.finishSize))
      relaxStretchPower(s, x, triangles, 2.0, options.finishSweeps);
    untangle(s, triangles, rings);
    step = fine;
    ++done;
  }
  report(progress, 1);

  SphericalMap map;
  map.sphere.resize(s.size());
  for (std::size_t v = 0; v < s.size(); ++v)
    map.sphere[v] = {static_cast<float>(s[v].x()), static_cast<float>(s[v].y()),
                     static_cast<float>(s[v].z())};
  measureSphericalMap(mesh, map);
  return map;
}

} // namespace octaclay::core::detail
