#include "octaclay/core/export/scene_export.h"

#include "export/export_grid.h"
#include "export/glb_writer.h"
#include "export/layer_maps.h"
#include "export/obj_writer.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/geometry/mesh_extraction.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <string>
#include <vector>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {

std::vector<const SceneObject*> visibleObjects(const Scene& scene, const fs::path& path) {
  std::vector<const SceneObject*> objects;
  for (const SceneObject& object : scene.objects)
    if (object.visible) objects.push_back(&object);
  if (objects.empty())
    throw Error(ErrorKind::InvalidArgument,
                "cannot export to " + path.string() + ": the document has no visible object");
  return objects;
}

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

double determinant(const std::array<double, 9>& m) {
  return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
         m[2] * (m[3] * m[7] - m[4] * m[6]);
}

// Per object: the grid and maps as writeGlb makes them for one document, kept alive until the
// file is staged (the GLB mesh holds spans into them).
struct GlbObject {
  detail::ExportGrid grid;
  std::vector<Vec2f> texcoords;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

void stageSceneGlb(const std::vector<const SceneObject*>& objects, const fs::path& path,
                   OutputSet& set) {
  std::vector<GlbObject> parts;
  parts.reserve(objects.size());
  std::vector<detail::GlbTexture> textures;
  std::vector<detail::GlbNode> nodes;
  double estimate = 0;
  for (const SceneObject* object : objects) {
    GlbObject& part = parts.emplace_back();
    part.grid = detail::makeExportGrid(object->document, 1);
    part.texcoords = detail::gridTexcoords(part.grid, false);
    part.triangles = detail::gridTriangles(part.grid);
    estimate += static_cast<double>(part.grid.vertexCount()) * (12 + 12 + 8) +
                static_cast<double>(part.triangles.size()) * 3 * 4;
    if (estimate > static_cast<double>(std::numeric_limits<std::uint32_t>::max()) - (1 << 26))
      throw Error(ErrorKind::InvalidArgument,
                  "the scene's glTF export exceeds the 4 GiB a .glb can hold; export its objects "
                  "one by one (--object) at a coarser level (--lod)");
    detail::GlbMaterial material;
    material.name = material.meshName = material.nodeName = object->name;
    material.baseColorTexture = static_cast<int>(textures.size());
    textures.push_back(
        {object->name + " diffuse", encodePng(detail::diffuseMap(object->document))});
    material.metallicRoughnessTexture = static_cast<int>(textures.size());
    textures.push_back({object->name + " metallicRoughness",
                        encodePng(detail::metallicRoughnessMap(object->document))});
    const ObjectTransform& t = object->transform;
    const auto q = rotationQuaternion(t);
    nodes.push_back({{part.grid.positions, part.grid.normals, {}, part.texcoords, part.triangles},
                     material,
                     {t.translation.x, t.translation.y, t.translation.z},
                     {q[0], q[1], q[2], q[3]},
                     {t.scale.x, t.scale.y, t.scale.z}});
  }
  detail::writeGlbNodes(nodes, textures, path, set);
}

void stageSceneObj(const std::vector<const SceneObject*>& objects, const fs::path& path,
                   OutputSet& set) {
  TriangleMesh all;
  std::vector<detail::ObjGroup> groups;
  for (const SceneObject* object : objects) {
    const TriangleMesh mesh = worldMesh(*object);
    const auto base = static_cast<std::uint32_t>(all.positions.size());
    groups.push_back({object->name, base, static_cast<std::uint32_t>(all.triangles.size())});
    all.positions.insert(all.positions.end(), mesh.positions.begin(), mesh.positions.end());
    for (const auto& t : mesh.triangles)
      all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  detail::stageObj(
      {all.positions, {}, {}, all.triangles, {}, groups},
      {"Octaclay scene: " + std::to_string(groups.size()) + " objects in world space", {}, {}},
      path, set);
}

} // namespace

TriangleMesh worldMesh(const SceneObject& object) {
  TriangleMesh mesh = extractMesh(object.document.positions);
  for (Vec3f& p : mesh.positions)
    p = applyTransform(object.transform, p);
  if (determinant(linearPart(object.transform)) < 0)
    for (auto& t : mesh.triangles)
      std::swap(t[1], t[2]);
  return mesh;
}

void stageSceneMeshes(const Scene& scene, const fs::path& path, OutputSet& set) {
  const std::string ext = lowerExtension(path);
  if (ext != ".glb" && !meshFormatFromPath(path))
    throw Error(ErrorKind::InvalidArgument,
                "cannot export to " + path.string() + ": use .glb, .obj, .ply, .stl or .off");
  const std::vector<const SceneObject*> objects = visibleObjects(scene, path);
  if (ext == ".glb") return stageSceneGlb(objects, path, set);
  if (ext == ".obj") return stageSceneObj(objects, path, set);
  TriangleMesh all;
  for (const SceneObject* object : objects) {
    const TriangleMesh mesh = worldMesh(*object);
    const auto base = static_cast<std::uint32_t>(all.positions.size());
    all.positions.insert(all.positions.end(), mesh.positions.begin(), mesh.positions.end());
    for (const auto& t : mesh.triangles)
      all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  stageMesh(all, path, set);
}

void writeSceneMeshes(const Scene& scene, const fs::path& path) {
  OutputSet set;
  stageSceneMeshes(scene, path, set);
  set.commit();
}

} // namespace octaclay::core
