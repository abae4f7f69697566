#include "octaclay/core/export/mesh_io.h"

#include "export/obj_writer.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {

using OpenMeshTriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// Enough digits that a float written as text reads back as the same float.
constexpr std::streamsize kFloatDigits = 9;

// OpenMesh chats on its log streams; the CLI's stdout must stay one JSON object, and failures
// are reported through Error instead.
void silenceOpenMesh() {
  omlog().disable();
  omout().disable();
  omerr().disable();
}

OpenMeshTriMesh toOpenMesh(const TriangleMesh& mesh) {
  OpenMeshTriMesh out;
  out.reserve(mesh.positions.size(), mesh.triangles.size() * 3 / 2, mesh.triangles.size());
  for (const Vec3f& p : mesh.positions)
    out.add_vertex({p.x, p.y, p.z});
  std::size_t rejected = 0;
  for (const auto& t : mesh.triangles) {
    const auto face = out.add_face(OpenMeshTriMesh::VertexHandle(int(t[0])),
                                   OpenMeshTriMesh::VertexHandle(int(t[1])),
                                   OpenMeshTriMesh::VertexHandle(int(t[2])));
    rejected += face.is_valid() ? 0 : 1;
  }
  if (rejected)
    throw Error(ErrorKind::InvalidInput, "mesh has " + std::to_string(rejected) +
                                             " non-manifold triangles that cannot be written");
  return out;
}

} // namespace

std::optional<MeshFormat> meshFormatFromPath(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".off") return MeshFormat::Off;
  return std::nullopt;
}

void stageMesh(const TriangleMesh& mesh, const fs::path& path, OutputSet& set) {
  const auto format = meshFormatFromPath(path);
  if (!format)
    throw Error(ErrorKind::InvalidArgument,
                "cannot write " + path.string() +
                    ": unknown mesh format; use .obj, .ply, .stl or .off");
  silenceOpenMesh();
  const OpenMeshTriMesh om = toOpenMesh(mesh); // also refuses non-manifold triangles
  if (*format == MeshFormat::Obj) {            // the exports' one OBJ writer, streamed
    detail::stageObj({mesh.positions, {}, {}, mesh.triangles, {}, {}},
                     {"Octaclay mesh: " + std::to_string(mesh.positions.size()) + " vertices, " +
                          std::to_string(mesh.triangles.size()) + " triangles",
                      {},
                      {}},
                     path, set);
    return;
  }
  OpenMesh::IO::Options options;
  if (*format == MeshFormat::Ply || *format == MeshFormat::Stl)
    options += OpenMesh::IO::Options::Binary;
  const std::string ext = "." + std::string(*format == MeshFormat::Ply   ? "ply"
                                            : *format == MeshFormat::Stl ? "stl"
                                                                         : "off");
  // OpenMesh writes to a stream: a memory one, handed whole to the one checked writer (OpenMesh
  // itself reports success when the disk refused the bytes).
  std::ostringstream out(std::ios::binary);
  if (!OpenMesh::IO::write_mesh(om, out, ext, options, kFloatDigits))
    throw Error(ErrorKind::Io, "cannot write " + path.string() + ": the mesh writer failed");
  set.stageText(path, out.view());
}

void writeMesh(const TriangleMesh& mesh, const fs::path& path) {
  OutputSet set;
  stageMesh(mesh, path, set);
  set.commit();
}

TriangleMesh readMesh(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw Error(ErrorKind::Io, "cannot open " + path.string() + ": no such file");
  if (!meshFormatFromPath(path))
    throw Error(ErrorKind::InvalidArgument,
                "cannot read " + path.string() +
                    ": unknown mesh format; use .obj, .ply, .stl or .off");
  silenceOpenMesh();
  OpenMeshTriMesh om;
  OpenMesh::IO::Options options;
  if (!OpenMesh::IO::read_mesh(om, path.string(), options))
    throw Error(ErrorKind::InvalidInput, path.string() + ": not a readable mesh file");
  if (om.n_faces() == 0)
    throw Error(ErrorKind::InvalidInput, path.string() + ": the mesh has no triangles");

  TriangleMesh mesh;
  mesh.positions.reserve(om.n_vertices());
  for (const auto v : om.vertices()) {
    const auto& p = om.point(v);
    mesh.positions.push_back({p[0], p[1], p[2]});
  }
  mesh.triangles.reserve(om.n_faces());
  for (const auto f : om.faces()) {
    std::array<std::uint32_t, 3> tri{};
    int k = 0;
    for (const auto v : om.fv_range(f)) {
      if (k < 3) tri[k] = static_cast<std::uint32_t>(v.idx());
      ++k;
    }
    if (k == 3) mesh.triangles.push_back(tri);
  }
  return mesh;
}

} // namespace octaclay::core
