// The LOD's vertex buffer: seam vertices split by image coordinates, with the normal and glTF
// tangent frame that both the tangent-space bake and the exported files use.

#include "octaclay/core/lod/lod_vertices.h"

#include "octaclay/core/error.h"

#include <bit>
#include <cmath>
#include <string>
#include <unordered_map>

namespace octaclay::core {
namespace {

struct CornerKey {
  std::uint32_t vertex;
  std::uint32_t u, v; // float bits: corners are split only where their coordinates differ
  friend bool operator==(const CornerKey&, const CornerKey&) = default;
};

struct CornerKeyHash {
  std::size_t operator()(const CornerKey& k) const {
    std::uint64_t h = k.vertex;
    h = h * 0x9E3779B97F4A7C15ull ^ k.u;
    h = h * 0x9E3779B97F4A7C15ull ^ k.v;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

// Any unit vector perpendicular to n.
Vec3f perpendicular(Vec3f n) {
  const Vec3f axis = std::abs(n.x) < 0.6f ? Vec3f{1, 0, 0} : Vec3f{0, 1, 0};
  return normalize(axis - n * dot(n, axis));
}

} // namespace

LodVertices lodVertices(const LodMesh& lod) {
  const TriangleMesh& mesh = lod.mesh;
  if (lod.cornerUv.size() != mesh.triangles.size())
    throw Error(ErrorKind::InvalidArgument,
                "the LOD has " + std::to_string(mesh.triangles.size()) + " triangles but " +
                    std::to_string(lod.cornerUv.size()) + " sets of corner image coordinates");
  LodVertices out;
  std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> split;
  split.reserve(mesh.positions.size() * 5 / 4);
  out.triangles.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t vertex = mesh.triangles[t][static_cast<std::size_t>(c)];
      if (vertex >= mesh.positions.size())
        throw Error(ErrorKind::InvalidArgument,
                    "the LOD's triangle " + std::to_string(t) + " names a vertex it does not have");
      const Vec2f uv = lod.cornerUv[t][static_cast<std::size_t>(c)];
      const CornerKey key{vertex, std::bit_cast<std::uint32_t>(uv.x),
                          std::bit_cast<std::uint32_t>(uv.y)};
      const auto [it, added] = split.try_emplace(key, static_cast<std::uint32_t>(out.uvs.size()));
      if (added) {
        out.uvs.push_back(uv);
        out.welded.push_back(vertex);
        out.positions.push_back(mesh.positions[vertex]);
      }
      out.triangles[t][static_cast<std::size_t>(c)] = it->second;
    }

  // Normals per welded vertex (equal on every copy of a seam vertex): area-weighted faces.
  std::vector<Vec3f> weldedNormals(mesh.positions.size());
  for (const auto& tri : mesh.triangles) {
    const Vec3f p0 = mesh.positions[tri[0]];
    const Vec3f face = cross(mesh.positions[tri[1]] - p0, mesh.positions[tri[2]] - p0);
    for (const std::uint32_t v : tri)
      weldedNormals[v] += face;
  }

  // dP/du and dP/dv per split vertex, each triangle's weighted by its area.
  const std::size_t count = out.uvs.size();
  std::vector<Vec3f> dpdu(count), dpdv(count);
  for (const auto& tri : out.triangles) {
    const Vec3f p0 = out.positions[tri[0]];
    const Vec3f e1 = out.positions[tri[1]] - p0, e2 = out.positions[tri[2]] - p0;
    const Vec2f w0 = out.uvs[tri[0]], w1 = out.uvs[tri[1]], w2 = out.uvs[tri[2]];
    const float du1 = w1.x - w0.x, dv1 = w1.y - w0.y, du2 = w2.x - w0.x, dv2 = w2.y - w0.y;
    const float det = du1 * dv2 - du2 * dv1;
    if (!(std::abs(det) > 0)) continue;
    const float area = 0.5f * length(cross(e1, e2));
    const Vec3f u = normalize((e1 * dv2 - e2 * dv1) * (1.0f / det));
    const Vec3f v = normalize((e2 * du1 - e1 * du2) * (1.0f / det));
    for (const std::uint32_t k : tri) {
      dpdu[k] += u * area;
      dpdv[k] += v * area;
    }
  }

  out.normals.resize(count);
  out.tangents.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    Vec3f n = normalize(weldedNormals[out.welded[k]]);
    if (length(n) == 0) n = normalize(out.positions[k]);
    if (length(n) == 0) n = {0, 0, 1};
    Vec3f t = normalize(dpdu[k] - n * dot(n, dpdu[k]));
    if (length(t) == 0) t = perpendicular(n);
    // glTF: bitangent = cross(n, t) · w points to the image's top (decreasing v).
    const float w = dot(cross(n, t), dpdv[k]) > 0 ? -1.0f : 1.0f;
    out.normals[k] = n;
    out.tangents[k] = {t.x, t.y, t.z, w};
  }
  return out;
}

} // namespace octaclay::core
