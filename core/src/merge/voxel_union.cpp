// Based on: Museth 2013, "VDB: High-resolution sparse volumes with dynamic topology" (OpenVDB's
// level sets, their CSG and meshing), as Debian's libopenvdb-dev ships them.

#include "merge/voxel_union.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <mutex>

namespace octaclay::core::detail {
namespace {

constexpr float kHalfWidth = 3.0f; // voxels each side: enough for csgUnion and the mesher

void initializeOpenVdbOnce() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

float lengthSquared(const openvdb::Vec3s& a, const openvdb::Vec3s& b) {
  return (a - b).lengthSqr();
}

} // namespace

TriangleMesh voxelUnion(std::span<const TriangleMesh> meshes, double voxelSize,
                        const std::function<bool(float)>& progress) {
  initializeOpenVdbOnce();
  const auto transform = openvdb::math::Transform::createLinearTransform(voxelSize);
  openvdb::FloatGrid::Ptr united;
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    if (progress && !progress(0.8f * float(k) / float(meshes.size()))) return {};
    const TriangleMesh& mesh = meshes[k];
    std::vector<openvdb::Vec3s> points;
    points.reserve(mesh.positions.size());
    for (const Vec3f& p : mesh.positions)
      points.emplace_back(p.x, p.y, p.z);
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
      triangles.emplace_back(t[0], t[1], t[2]);
    auto grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, triangles,
                                                                   kHalfWidth);
    if (!united)
      united = grid;
    else
      openvdb::tools::csgUnion(*united, *grid); // grid is emptied
  }
  if (progress && !progress(0.8f)) return {};
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  if (united) openvdb::tools::volumeToMesh(*united, points, triangles, quads, 0.0, 0.0);

  TriangleMesh out;
  out.positions.reserve(points.size());
  for (const auto& p : points)
    out.positions.push_back({p.x(), p.y(), p.z()});
  out.triangles.reserve(triangles.size() + 2 * quads.size());
  for (const auto& t : triangles)
    out.triangles.push_back({t[0], t[1], t[2]});
  for (const auto& q : quads) {
    // The shorter diagonal gives the better-shaped pair of triangles.
    if (lengthSquared(points[q[0]], points[q[2]]) <= lengthSquared(points[q[1]], points[q[3]])) {
      out.triangles.push_back({q[0], q[1], q[2]});
      out.triangles.push_back({q[0], q[2], q[3]});
    } else {
      out.triangles.push_back({q[0], q[1], q[3]});
      out.triangles.push_back({q[1], q[2], q[3]});
    }
  }
  return out;
}

} // namespace octaclay::core::detail
