#include "octaclay/core/merge/merge.h"

#include "detail/parallel_rows.h"
#include "merge/map_rotation.h"
#include "merge/part_layers.h"
#include "merge/part_locator.h"
#include "merge/part_snap.h"
#include "merge/union_topology.h"
#include "merge/voxel_union.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/object_transform.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/octahedral_resampling.h"
#include "octaclay/core/import/spherical_parameterization.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace octaclay::core {
namespace {

using Clock = std::chrono::steady_clock;

// A number as a message shows it: 6 significant digits (1e-09, 5.01), not to_string's 0.000000.
std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Largest level set a merge builds: in voxels across the union's bounding box, small enough
// that OpenVDB's 32-bit coordinates never overflow; in surface voxels (the parts' area over a
// voxel's face), as many as the largest document has samples (8192²), about 12 GiB of narrow
// band at most, where a chosen voxel size far below the parts' scale would ask for more than
// any machine has.
constexpr double kMaxVoxelsAcross = double(1 << 24);
constexpr double kMaxSurfaceVoxels = 8192.0 * 8192.0 * 1.01;

double determinant3(const std::array<double, 16>& m) {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
         m[2] * (m[4] * m[9] - m[5] * m[8]);
}

void requireUsableTransform(const PartTransform& t, std::size_t part) {
  const std::string which = "part " + std::to_string(part + 1) + "'s transform";
  if (!std::all_of(t.m.begin(), t.m.end(), [](double v) { return std::isfinite(v); }))
    throw Error(ErrorKind::InvalidArgument, which + " has a value that is not a finite number");
  if (t.m[12] != 0 || t.m[13] != 0 || t.m[14] != 0 || t.m[15] != 1)
    throw Error(ErrorKind::InvalidArgument,
                which + " is not affine: its last row must be 0, 0, 0, 1");
  const double det = determinant3(t.m);
  if (!std::isfinite(det) || det == 0)
    throw Error(ErrorKind::InvalidArgument,
                which + " flattens the part (its scale or matrix has determinant 0)");
}

double surfaceArea(const TriangleMesh& mesh) {
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3f a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    area += 0.5 * double(length(cross(b - a, c - a)));
  }
  return area;
}

} // namespace

PartTransform PartTransform::fromTrs(Vec3f translate, Vec3f rotateDegrees, Vec3f scale) {
  // The scene's one convention (object_transform: R = Rz · Ry · Rx, then the scale per axis).
  const std::array<double, 9> linear = linearPart({translate, rotateDegrees, scale});
  PartTransform t;
  for (std::size_t row = 0; row < 3; ++row)
    for (std::size_t col = 0; col < 3; ++col)
      t.m[row * 4 + col] = linear[row * 3 + col];
  t.m[3] = translate.x, t.m[7] = translate.y, t.m[11] = translate.z;
  return t;
}

Vec3f PartTransform::apply(Vec3f p) const {
  const auto row = [&](int r) {
    const std::size_t o = std::size_t(r * 4);
    return float(m[o] * p.x + m[o + 1] * p.y + m[o + 2] * p.z + m[o + 3]);
  };
  return {row(0), row(1), row(2)};
}

MergeResult mergeParts(std::span<const MergePart> parts, const MergeOptions& options,
                       const std::function<bool(float)>& progress) {
  if (parts.empty()) throw Error(ErrorKind::InvalidArgument, "a merge needs at least one part");
  if (parts.size() > 65535) // MergeResult::sourcePart numbers them in 16 bits
    throw Error(ErrorKind::InvalidArgument,
                "a merge takes at most 65 535 parts, not " + std::to_string(parts.size()));
  if (!isValidSize(options.size))
    throw Error(ErrorKind::InvalidArgument, "the merged size N = " + std::to_string(options.size) +
                                                " is out of range: use a power of two from " +
                                                std::to_string(kMinSize) + " to " +
                                                std::to_string(kMaxSize));
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (!parts[k].document)
      throw Error(ErrorKind::InvalidArgument, "part " + std::to_string(k + 1) + " has no document");
    requireUsableTransform(parts[k].transform, k);
    const std::string which =
        parts[k].name.empty() ? "part " + std::to_string(k + 1) : "'" + parts[k].name + "'";
    if (const auto problem = positionsProblem(parts[k].document->positions))
      throw Error(ErrorKind::InvalidInput, which + ": " + *problem);
    // A sheet has no inside: OpenVDB's level set of it is a shell a voxel or two thick, a plate
    // whose thickness would follow N, not the user.
    if (parts[k].document->positions.topology() == Topology::Plane)
      throw Error(ErrorKind::InvalidInput,
                  which + " is a plane, an open sheet with no inside: merge joins closed objects "
                          "(balls, capsules and the like; a torus when the union closes no ring)");
  }
  if (!(std::isfinite(options.voxelSize) && options.voxelSize >= 0))
    throw Error(ErrorKind::InvalidArgument, "the voxel size must be a finite number above 0");
  const auto cancelled = [] { return Error(ErrorKind::Cancelled, "merging was cancelled"); };
  const auto report = [&](float f) {
    if (progress && !progress(f)) throw cancelled();
  };
  report(0);

  MergeResult out;
  auto start = Clock::now();
  // Every part placed in world space: full resolution for the layers, and for the level set
  // every step-th sample where that is still finer than half a voxel.
  std::vector<detail::PlacedSurface> placed;
  double area = 0;
  BoundingBox box;
  for (const MergePart& part : parts) {
    detail::PlacedSurface surface{part.document, extractMesh(part.document->positions)};
    for (Vec3f& p : surface.mesh.positions) {
      p = part.transform.apply(p);
      box.extend(p);
    }
    area += surfaceArea(surface.mesh);
    placed.push_back(std::move(surface));
  }
  const int m =
      options.levelSetSize > 0 ? std::min(options.size, options.levelSetSize) : options.size;
  out.voxelSize = options.voxelSize > 0 ? options.voxelSize : std::sqrt(area / double(m) / m);
  if (!(out.voxelSize > 0) || double(box.diagonal()) / out.voxelSize > kMaxVoxelsAcross ||
      area / (out.voxelSize * out.voxelSize) > kMaxSurfaceVoxels)
    throw Error(ErrorKind::InvalidArgument,
                "the voxel size " + number(out.voxelSize) + " is too small for parts " +
                    number(box.diagonal()) + " across: their surface would take " +
                    number(area / (out.voxelSize * out.voxelSize)) +
                    " voxels, more than 8192² (the largest document's samples)");
  std::vector<TriangleMesh> levelSetMeshes;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Document& doc = *parts[k].document;
    const double partArea = surfaceArea(placed[k].mesh);
    const double spacing = std::sqrt(partArea / (double(doc.size()) * doc.size()));
    int step = 1;
    while (doc.size() / (2 * step) >= 16 && 2 * step * spacing <= 0.5 * out.voxelSize)
      step *= 2;
    if (step == 1) {
      levelSetMeshes.push_back(placed[k].mesh);
      continue;
    }
    TriangleMesh coarse = extractMesh(doc.positions, step);
    for (Vec3f& p : coarse.positions)
      p = parts[k].transform.apply(p);
    levelSetMeshes.push_back(std::move(coarse));
  }
  report(0.05f);
  const TriangleMesh united = detail::voxelUnion(levelSetMeshes, out.voxelSize, [&](float f) {
    return !progress || progress(0.05f + 0.2f * f);
  });
  report(0.25f);
  out.levelSetMs = msSince(start);

  // One closed genus-0 piece, or the reason it is not.
  const detail::UnionTopology topology = detail::analyzeUnion(united);
  out.levelSetVertices = topology.topology.vertices;
  out.levelSetTriangles = topology.topology.triangles;
  out.euler = topology.topology.euler;
  if (topology.pieces == 0)
    throw Error(ErrorKind::InvalidInput, "the parts enclose no volume at a voxel size of " +
                                             number(out.voxelSize) + ": nothing to merge");
  if (topology.pieces > 1)
    throw Error(ErrorKind::InvalidInput,
                "these objects do not touch: their union is " + std::to_string(topology.pieces) +
                    " separate pieces; move them until they overlap, then merge (at a voxel of " +
                    number(out.voxelSize) +
                    ", a part thinner than about two voxels can fall "
                    "apart too)");
  if (topology.topology.euler != 2)
    throw Error(ErrorKind::InvalidInput,
                "the merged surface has genus " + std::to_string(topology.genus()) +
                    " (Euler characteristic " + std::to_string(topology.topology.euler) +
                    "): it has a hole through it, and an object here must be a closed ball "
                    "(genus 0); move the parts so that they close no ring, then merge");

  start = Clock::now();
  ValidatedMesh validated;
  try {
    validated = validateGenus0Mesh(united);
  } catch (const Error& e) {
    throw Error(ErrorKind::InvalidInput,
                std::string("the merged surface cannot become one object: ") + e.what());
  }
  SphericalMap map;
  try {
    map = parameterizeOnSphere(validated.mesh,
                               [&](float f) { return !progress || progress(0.25f + 0.6f * f); });
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::Cancelled) throw cancelled();
    throw Error(ErrorKind::InvalidInput,
                std::string("the merged surface cannot be mapped onto the sphere: ") + e.what());
  }
  if (map.flipped > 0)
    throw Error(ErrorKind::InvalidInput,
                "the merged surface cannot be mapped onto the sphere without folds (" +
                    std::to_string(map.flipped) + " triangles fold); try a larger N");
  report(0.85f);

  // Each vertex of the union's mesh belongs to the nearest part; the map is turned so that the
  // grid samples the parts as evenly as it can (map_rotation.h).
  const detail::PartLocator locator(placed);
  std::vector<std::uint16_t> vertexPart(validated.mesh.positions.size(), 0);
  detail::parallelRows(
      int(vertexPart.size()),
      [&](int begin, int end) {
        detail::PartLocator::Cursor cursor = locator.cursor();
        for (int v = begin; v < end; ++v)
          vertexPart[std::size_t(v)] = std::uint16_t(
              locator.nearest(detail::Vec3d(validated.mesh.positions[std::size_t(v)]), cursor)
                  .part);
      },
      1024);
  const detail::MapRotationEstimate turn =
      detail::rotateMapForEvenParts(validated.mesh, vertexPart, parts.size(), map);
  out.leastShareUnturned = turn.before;
  out.leastShareTurned = turn.after;
  out.document = makeDocument(resampleOctahedral(validated.mesh, map, options.size));
  out.parameterizeMs = msSince(start);
  report(0.9f);

  // Snapped and the layers carried in one search per texel (or the layers alone).
  start = Clock::now();
  if (options.snapToParts) {
    detail::LayerCarrier layers(locator, out.document, out.sourcePart);
    out.snapped = detail::snapToParts(locator, out.document.positions, 0.75 * out.voxelSize,
                                      1.5 * out.voxelSize, &layers);
  } else {
    detail::carryPartLayers(locator, out.document, out.sourcePart);
  }
  out.partsMs = msSince(start);
  report(1.0f);
  return out;
}

} // namespace octaclay::core
