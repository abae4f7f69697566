#include "octaclay/core/lod/vertex_collapse.h"

#include "lod/quadric_collapse.h"

#include "octaclay/core/error.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <algorithm>
#include <cmath>
#include <string>

namespace octaclay::core {
namespace {

struct CollapseTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status);
};
// OpenMesh's TriConnectivity::is_collapse_ok looks its working property up by name on every
// call, which dominated the Decimater's time; the Decimater calls is_collapse_ok on its mesh
// type, so this mesh answers it with the same test for closed manifold meshes: the link
// condition (v0 and v1 share exactly the two neighbours opposite the edge), by stamping v0's
// neighbours.
class Mesh : public OpenMesh::TriMesh_ArrayKernelT<CollapseTraits> {
public:
  bool is_collapse_ok(HalfedgeHandle v0v1) {
    if (status(edge_handle(v0v1)).deleted()) return false;
    const HalfedgeHandle v1v0 = opposite_halfedge_handle(v0v1);
    const VertexHandle v0 = to_vertex_handle(v1v0), v1 = to_vertex_handle(v0v1);
    if (status(v0).deleted() || status(v1).deleted()) return false;
    if (is_boundary(v0v1) || is_boundary(v1v0)) return false;
    const VertexHandle vl = to_vertex_handle(next_halfedge_handle(v0v1));
    const VertexHandle vr = to_vertex_handle(next_halfedge_handle(v1v0));
    if (vl == vr) return false;
    if (stamp_.size() < n_vertices()) stamp_.resize(n_vertices(), 0);
    ++current_;
    for (const VertexHandle v : vv_range(v0))
      stamp_[v.idx()] = current_;
    int shared = 0;
    for (const VertexHandle v : vv_range(v1))
      if (stamp_[v.idx()] == current_) {
        if (v != vl && v != vr) return false;
        ++shared;
      }
    return shared == 2;
  }

private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_ = 0;
};

// Binary module guarding each collapse v0 → v1, one pass over v0's surviving triangles:
//  - normals: a triangle whose normal would turn more than maxNormalTurnDegrees away from its
//    input triangle's normal (or whose area would vanish) is refused; measured against the input
//    rather than the previous step, so turns cannot add up over many collapses (with
//    normalTurnPerCollapse: against the triangle before this collapse);
//  - shape: a triangle whose aspect ratio (longest edge / its height) would exceed
//    maxAspectRatio, or maxAspectGrowth × its input triangle's, is refused unless it was
//    already that thin;
//  - texture: with cornerCoordinates, a triangle whose corner coordinates would not stay
//    counter-clockwise is refused;
//  - the caller's allowCollapse veto, and no collapse below a tetrahedron (4 vertices).
// One module instead of OpenMesh's ModNormalFlipping, ModNormalDeviation and ModAspectRatio,
// which walk the one-ring once each and recompute normal cones with acos: together they took
// three quarters of the Decimater's time on LOD meshes.
template <class MeshT> class ModGuardT : public OpenMesh::Decimater::ModBaseT<MeshT> {
public:
  DECIMATING_MODULE(ModGuardT, MeshT, Guard);
  explicit ModGuardT(MeshT& mesh) : Base(mesh, true) {}

  void configure(const VertexCollapseOptions& options, std::vector<OpenMesh::Vec3d> inputNormals,
                 std::vector<double> inputAspects) {
    options_ = &options;
    minCos_ = std::cos(double(options.maxNormalTurnDegrees) * M_PI / 180.0);
    inputNormals_ = std::move(inputNormals);
    inputAspects_ = std::move(inputAspects);
  }

  float collapse_priority(const CollapseInfo& ci) override {
    if (Base::mesh().n_vertices() - collapsed_ <= 4) return Base::ILLEGAL_COLLAPSE;
    const auto v0 = static_cast<std::uint32_t>(ci.v0.idx());
    const auto v1 = static_cast<std::uint32_t>(ci.v1.idx());
    if (options_->allowCollapse && !options_->allowCollapse(v0, v1)) return Base::ILLEGAL_COLLAPSE;
    const MeshT& mesh = Base::mesh();
    const double maxAspect = options_->maxAspectRatio;
    for (const auto f : mesh.vf_range(ci.v0)) {
      if (f == ci.fl || f == ci.fr) continue;
      std::array<std::uint32_t, 3> tri{};
      std::array<OpenMesh::Vec3d, 3> p;
      int k = 0;
      int moved = 0;
      for (const auto v : mesh.fv_range(f)) {
        if (v == ci.v0) moved = k;
        tri[k] = static_cast<std::uint32_t>(v == ci.v0 ? v1 : v.idx());
        p[k++] = v == ci.v0 ? ci.p1 : mesh.point(v);
      }
      const OpenMesh::Vec3d cross = (p[1] - p[0]) % (p[2] - p[0]);
      const double twiceArea = cross.norm();
      if (!(twiceArea > 0)) return Base::ILLEGAL_COLLAPSE;
      OpenMesh::Vec3d reference = inputNormals_[f.idx()];
      if (options_->normalTurnPerCollapse) {
        std::array<OpenMesh::Vec3d, 3> q = p;
        q[moved] = ci.p0;
        reference = ((q[1] - q[0]) % (q[2] - q[0])).normalize_cond();
      }
      if ((cross | reference) < minCos_ * twiceArea) return Base::ILLEGAL_COLLAPSE;
      if (maxAspect > 0) {
        const double longest =
            std::max({(p[1] - p[0]).sqrnorm(), (p[2] - p[1]).sqrnorm(), (p[0] - p[2]).sqrnorm()});
        // longest / height = longest² / (2·area)
        const double bound =
            std::max(maxAspect, double(options_->maxAspectGrowth) * inputAspects_[f.idx()]);
        if (longest > bound * twiceArea) {
          std::array<OpenMesh::Vec3d, 3> q = p;
          q[moved] = ci.p0;
          const double before = ((q[1] - q[0]) % (q[2] - q[0])).norm();
          const double beforeLongest =
              std::max({(q[1] - q[0]).sqrnorm(), (q[2] - q[1]).sqrnorm(), (q[0] - q[2]).sqrnorm()});
          if (longest * before > beforeLongest * twiceArea) return Base::ILLEGAL_COLLAPSE;
        }
      }
      if (options_->cornerCoordinates) {
        const std::array<Vec2f, 3> c = options_->cornerCoordinates(tri);
        const double uvArea = (double(c[1].x) - c[0].x) * (double(c[2].y) - c[0].y) -
                              (double(c[2].x) - c[0].x) * (double(c[1].y) - c[0].y);
        if (!(uvArea > 0)) return Base::ILLEGAL_COLLAPSE;
      }
    }
    return Base::LEGAL_COLLAPSE;
  }
  void postprocess_collapse(const CollapseInfo&) override { ++collapsed_; }

private:
  const VertexCollapseOptions* options_ = nullptr;
  double minCos_ = 0.5;
  std::vector<OpenMesh::Vec3d> inputNormals_;
  std::vector<double> inputAspects_; // aspectRatio of the input triangles
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
  if (!(options.maxAspectRatio >= 0 && options.maxAspectGrowth >= 0))
    throw Error(ErrorKind::InvalidArgument,
                "aspect bound " + std::to_string(options.maxAspectRatio) + " or growth " +
                    std::to_string(options.maxAspectGrowth) + " is negative; use 0 (none) or more");
}

} // namespace

CollapsedMesh collapseVertices(const TriangleMesh& input, const VertexCollapseOptions& options) {
  checkOptions(options);
  if (options.engine == CollapseEngine::Fast) {
    const MeshTopology topology = analyzeTopology(input);
    if (!topology.closed() || !topology.manifold())
      throw Error(ErrorKind::InvalidInput,
                  "vertex collapse needs a closed, manifold mesh; this one has " +
                      std::to_string(topology.boundaryEdges) + " boundary edges and " +
                      std::to_string(topology.nonManifoldEdges) + " edges that are not manifold");
    return detail::quadricCollapse(input, options);
  }
  Mesh mesh;
  mesh.reserve(input.positions.size(), 3 * input.triangles.size() / 2, input.triangles.size());
  for (const Vec3f& p : input.positions)
    mesh.add_vertex(Mesh::Point(p.x, p.y, p.z));
  std::vector<OpenMesh::Vec3d> inputNormals;
  std::vector<double> inputAspects;
  inputNormals.reserve(input.triangles.size());
  inputAspects.reserve(input.triangles.size());
  std::size_t refused = 0;
  for (const auto& t : input.triangles) {
    const auto f = mesh.add_face(Mesh::VertexHandle(int(t[0])), Mesh::VertexHandle(int(t[1])),
                                 Mesh::VertexHandle(int(t[2])));
    if (!f.is_valid()) {
      ++refused;
      continue;
    }
    inputNormals.push_back(mesh.calc_face_normal(f));
    inputAspects.push_back(
        aspectRatio(input.positions[t[0]], input.positions[t[1]], input.positions[t[2]]));
  }
  std::size_t boundary = 0;
  for (const auto h : mesh.halfedges())
    boundary += mesh.is_boundary(h);
  if (refused > 0 || boundary > 0)
    throw Error(ErrorKind::InvalidInput,
                "vertex collapse needs a closed, manifold mesh; this one has " +
                    std::to_string(boundary) + " boundary edges and " + std::to_string(refused) +
                    " triangles that are not manifold");

  using Decimater = OpenMesh::Decimater::DecimaterT<Mesh>;
  Decimater decimater(mesh);
  OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
  ModGuardT<Mesh>::Handle guard;
  decimater.add(quadric);
  decimater.add(guard);
  if (options.maxError > 0) {
    // ModQuadric weights each plane by its triangle's area; dividing by the mean area gives
    // the quadric the scale of a sum of squared distances, as the fast engine uses.
    double totalArea = 0;
    for (const auto& t : input.triangles) {
      const Vec3f p0 = input.positions[t[0]];
      totalArea +=
          0.5 * double(length(cross(input.positions[t[1]] - p0, input.positions[t[2]] - p0)));
    }
    const double meanArea = totalArea / double(std::max<std::size_t>(1, input.triangles.size()));
    const double bound = options.maxError * boundingBox(input).diagonal();
    decimater.module(quadric).set_max_err(bound * bound * meanArea, false);
  } else {
    decimater.module(quadric).unset_max_err();
  }
  decimater.module(guard).configure(options, std::move(inputNormals), std::move(inputAspects));
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
