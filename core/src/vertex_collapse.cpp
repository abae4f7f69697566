#include "octaclay/core/vertex_collapse.h"

#include "octaclay/core/error.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModAspectRatioT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalDeviationT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <string>

namespace octaclay::core {
namespace {

struct CollapseTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status);
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<CollapseTraits>;

// Binary module: the caller's veto (octahedral seams), and no collapse into a tetrahedron's
// neighbourhood (4 vertices is the smallest closed genus-0 triangle mesh).
template <class MeshT> class ModVetoT : public OpenMesh::Decimater::ModBaseT<MeshT> {
public:
  DECIMATING_MODULE(ModVetoT, MeshT, Veto);
  explicit ModVetoT(MeshT& mesh) : Base(mesh, true) {}
  void setVeto(const std::function<bool(std::uint32_t, std::uint32_t)>* allow) { allow_ = allow; }
  float collapse_priority(const CollapseInfo& ci) override {
    if (Base::mesh().n_vertices() - collapsed_ <= 4) return Base::ILLEGAL_COLLAPSE;
    if (allow_ && *allow_ &&
        !(*allow_)(static_cast<std::uint32_t>(ci.v0.idx()),
                   static_cast<std::uint32_t>(ci.v1.idx())))
      return Base::ILLEGAL_COLLAPSE;
    if (corners_ && *corners_) {
      const MeshT& mesh = Base::mesh();
      for (const auto f : mesh.vf_range(ci.v0)) {
        if (f == ci.fl || f == ci.fr) continue;
        std::array<std::uint32_t, 3> tri{};
        int k = 0;
        for (const auto v : mesh.fv_range(f))
          tri[k++] = static_cast<std::uint32_t>(v == ci.v0 ? ci.v1.idx() : v.idx());
        const std::array<Vec2f, 3> c = (*corners_)(tri);
        const double area = (double(c[1].x) - c[0].x) * (double(c[2].y) - c[0].y) -
                            (double(c[2].x) - c[0].x) * (double(c[1].y) - c[0].y);
        if (!(area > 0)) return Base::ILLEGAL_COLLAPSE;
      }
    }
    return Base::LEGAL_COLLAPSE;
  }
  void setCorners(
      const std::function<std::array<Vec2f, 3>(const std::array<std::uint32_t, 3>&)>* corners) {
    corners_ = corners;
  }
  void postprocess_collapse(const CollapseInfo&) override { ++collapsed_; }

private:
  const std::function<bool(std::uint32_t, std::uint32_t)>* allow_ = nullptr;
  const std::function<std::array<Vec2f, 3>(const std::array<std::uint32_t, 3>&)>* corners_ =
      nullptr;
  std::size_t collapsed_ = 0;
};

void checkOptions(const VertexCollapseOptions& options) {
  if (options.targetTriangles > 0 && options.targetTriangles <= 4)
    throw Error(ErrorKind::InvalidArgument,
                "triangle target " + std::to_string(options.targetTriangles) +
                    " is too small: a closed mesh has at least 4 triangles; ask for more than 4");
  if (!(options.maxError >= 0))
    throw Error(ErrorKind::InvalidArgument, "maximum error " + std::to_string(options.maxError) +
                                                " is negative; use 0 (no bound) or more");
  if (!(options.maxNormalTurnDegrees > 0 && options.maxNormalTurnDegrees <= 180))
    throw Error(ErrorKind::InvalidArgument, "maximum normal turn " +
                                                std::to_string(options.maxNormalTurnDegrees) +
                                                " degrees is outside (0, 180]");
}

} // namespace

CollapsedMesh collapseVertices(const TriangleMesh& input, const VertexCollapseOptions& options) {
  checkOptions(options);
  const MeshTopology topology = analyzeTopology(input);
  if (!topology.closed() || !topology.manifold())
    throw Error(ErrorKind::InvalidInput,
                "vertex collapse needs a closed, edge-manifold mesh; this one has " +
                    std::to_string(topology.boundaryEdges) + " boundary and " +
                    std::to_string(topology.nonManifoldEdges) + " non-manifold edges");

  Mesh mesh;
  mesh.reserve(input.positions.size(), 3 * input.triangles.size() / 2, input.triangles.size());
  for (const Vec3f& p : input.positions)
    mesh.add_vertex(Mesh::Point(p.x, p.y, p.z));
  for (const auto& t : input.triangles)
    mesh.add_face(Mesh::VertexHandle(int(t[0])), Mesh::VertexHandle(int(t[1])),
                  Mesh::VertexHandle(int(t[2])));
  mesh.update_face_normals();

  using Decimater = OpenMesh::Decimater::DecimaterT<Mesh>;
  Decimater decimater(mesh);
  OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalDeviationT<Mesh>::Handle normals;
  OpenMesh::Decimater::ModAspectRatioT<Mesh>::Handle aspect;
  ModVetoT<Mesh>::Handle veto;
  decimater.add(quadric);
  decimater.add(normals);
  decimater.add(veto);
  if (options.maxAspectRatio > 0) decimater.add(aspect);
  if (options.maxError > 0) {
    const double bound = options.maxError * boundingBox(input).diagonal();
    decimater.module(quadric).set_max_err(bound * bound, false);
  } else {
    decimater.module(quadric).unset_max_err();
  }
  decimater.module(normals).set_normal_deviation(options.maxNormalTurnDegrees);
  decimater.module(veto).setVeto(&options.allowCollapse);
  decimater.module(veto).setCorners(&options.cornerCoordinates);
  if (options.maxAspectRatio > 0) decimater.module(aspect).set_aspect_ratio(options.maxAspectRatio);
  decimater.initialize();
  if (options.targetTriangles > 0)
    decimater.decimate_to_faces(0, options.targetTriangles);
  else
    decimater.decimate();

  CollapsedMesh out;
  std::vector<std::uint32_t> newIndex(mesh.n_vertices(), 0);
  for (const auto v : mesh.vertices()) {
    if (mesh.status(v).deleted()) continue;
    newIndex[v.idx()] = static_cast<std::uint32_t>(out.mesh.positions.size());
    const Mesh::Point& p = mesh.point(v);
    out.mesh.positions.push_back({float(p[0]), float(p[1]), float(p[2])});
    out.inputVertex.push_back(static_cast<std::uint32_t>(v.idx()));
  }
  for (const auto f : mesh.faces()) {
    if (mesh.status(f).deleted()) continue;
    std::array<std::uint32_t, 3> tri{};
    int k = 0;
    for (const auto v : mesh.fv_range(f))
      tri[k++] = newIndex[v.idx()];
    out.mesh.triangles.push_back(tri);
    out.inputTriangle.push_back(static_cast<std::uint32_t>(f.idx()));
  }
  return out;
}

} // namespace octaclay::core
