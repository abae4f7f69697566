// The LOD written with its baked normal map, and the painted layers when given: OBJ + MTL + PNG
// maps (welded positions and normals, texture coordinates split only in `vt`, through the
// exports' one OBJ writer), or a binary glTF with the maps embedded.

#include "octaclay/core/export/lod_export.h"

#include "export/glb_writer.h"
#include "export/layer_maps.h"
#include "export/obj_writer.h"
#include "lod/normal_map_encoding.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/file_extension.h"
#include "octaclay/core/lod/lod_vertices.h"

#include <algorithm>
#include <string>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {

// Welded normals: every copy of a vertex has the same one, so the first copy's serves.
std::vector<Vec3f> weldedNormals(const LodMesh& lod, const LodVertices& vertices) {
  std::vector<Vec3f> normals(lod.mesh.positions.size(), Vec3f{0, 0, 1});
  for (std::size_t k = 0; k < vertices.welded.size(); ++k)
    normals[vertices.welded[k]] = vertices.normals[k];
  return normals;
}

// The paint maps' files beside the OBJ, in the MTL's order: diffuse, specular, reflectivity.
std::array<fs::path, 3> paintMapPaths(const fs::path& objPath) {
  const std::string stem = objPath.stem().string();
  return {fs::path(objPath).replace_filename(stem + "_diffuse.png"),
          fs::path(objPath).replace_filename(stem + "_specular.png"),
          fs::path(objPath).replace_filename(stem + "_reflectivity.png")};
}

std::string mtlText(const std::string& mapName, NormalMapSpace space, const fs::path& objPath,
                    bool painted) {
  std::string paint;
  if (painted) { // as the full-resolution export's MTL (textured_export.cpp)
    const auto maps = paintMapPaths(objPath);
    const auto name = [&](std::size_t k) { return maps[k].filename().string(); };
    paint = "map_Kd " + name(0) + "\nmap_Ks " + name(1) + "\nmap_refl " + name(2) + "\nmap_Pm " +
            name(2) + "\n";
  }
  return "# Octaclay LOD material: the normal map is " + std::string(normalMapSpaceName(space)) +
         "-space" +
         (space == NormalMapSpace::Tangent
              ? " (glTF convention: +X along u, +Y towards the image's top)\n"
              : " (object-space normals n*0.5+0.5; a tangent-space reader will misread it)\n") +
         "newmtl octaclay_lod\n"
         "Ka 0 0 0\n" +
         (painted ? "Kd 1 1 1\nKs 1 1 1\nNs 64\nd 1\nillum 3\n"
                  : "Kd 0.8 0.8 0.8\nKs 0.04 0.04 0.04\nNs 32\nd 1\nillum 2\n") +
         paint + "norm " + mapName + "\nmap_Bump " + mapName + "\n";
}

void stageObj(const LodMesh& lod, const NormalMap& map, const Document* paint, const fs::path& path,
              OutputSet& set) {
  const std::string stem = path.stem().string();
  const fs::path mtlPath = fs::path(path).replace_filename(stem + ".mtl");
  const fs::path mapPath = fs::path(path).replace_filename(stem + "_normal.png");
  const LodVertices vertices = lodVertices(lod);
  const std::vector<Vec3f> normals = weldedNormals(lod, vertices);
  std::vector<Vec2f> texcoords; // OBJ's v axis points up
  texcoords.reserve(vertices.uvs.size());
  for (const Vec2f& uv : vertices.uvs)
    texcoords.push_back({uv.x, 1.0f - uv.y});

  const detail::ObjMesh mesh{lod.mesh.positions, normals, texcoords, lod.mesh.triangles,
                             vertices.triangles, {}};
  const detail::ObjHeader header{"Octaclay LOD: " + std::to_string(lod.mesh.positions.size()) +
                                     " vertices, " + std::to_string(lod.mesh.triangles.size()) +
                                     " triangles, resampled to M = " +
                                     std::to_string(static_cast<unsigned>(lod.resampledSize)) +
                                     "; " + std::string(normalMapSpaceName(map.space)) +
                                     "-space normal map; vt = image coordinates (x/N, 1 - y/N)",
                                 mtlPath.filename().string(), "octaclay_lod"};
  // Staged in reverse of the order stageLodMesh reports: the normal map comes after the MTL.
  std::vector<detail::ObjMap> maps;
  if (paint) {
    const auto paths = paintMapPaths(path);
    maps.push_back({paths[2], encodePng(detail::featureMap(*paint, 2, map.resolution))});
    maps.push_back({paths[1], encodePng(detail::featureMap(*paint, 1, map.resolution))});
    maps.push_back({paths[0], encodePng(detail::diffuseMap(*paint, map.resolution))});
  }
  maps.push_back({mapPath, detail::encodeNormalMapPng(map)});
  detail::writeObjWithMaterial(
      mesh, header, maps, mtlText(mapPath.filename().string(), map.space, path, paint != nullptr),
      mtlPath, path, set);
}

void stageGlb(const LodMesh& lod, const NormalMap& map, const Document* paint, const fs::path& path,
              OutputSet& set) {
  const LodVertices v = lodVertices(lod);
  const detail::GlbMesh mesh{v.positions, v.normals, v.tangents, v.uvs, v.triangles};
  std::vector<detail::GlbTexture> textures{
      {std::string(normalMapSpaceName(map.space)) + "_normal", detail::encodeNormalMapPng(map)}};
  detail::GlbMaterial material;
  material.name = "octaclay_lod";
  material.meshName = "octaclay_lod_" + std::to_string(lod.mesh.triangles.size());
  material.nodeName = "octaclay_lod";
  material.metallicFactor = 0.0;
  material.roughnessFactor = 0.6;
  // Standard viewers shade with NORMAL where the map is object-space.
  if (map.space == NormalMapSpace::Tangent)
    material.normalTexture = 0;
  else
    material.objectSpaceNormalTexture = 0;
  if (paint) { // the full-resolution export's material (textured_export.cpp)
    textures.push_back({"diffuse", encodePng(detail::diffuseMap(*paint, map.resolution))});
    textures.push_back(
        {"metallicRoughness", encodePng(detail::metallicRoughnessMap(*paint, map.resolution))});
    material.baseColorTexture = 1;
    material.metallicRoughnessTexture = 2;
    material.metallicFactor = material.roughnessFactor = 1.0;
  }
  detail::writeGlbFile(mesh, textures, material, path, set);
}

std::vector<fs::path> stageLod(const LodMesh& lod, const NormalMap& map, const Document* paint,
                               const fs::path& path, OutputSet& set) {
  detail::requireNormalMap(map);
  if (lod.mesh.triangles.empty())
    throw Error(ErrorKind::InvalidArgument, "cannot write " + path.string() + ": the LOD is empty");
  const std::string ext = lowerExtension(path);
  if (ext != ".glb" && ext != ".obj")
    throw Error(ErrorKind::InvalidArgument, "cannot write the LOD to " + path.string() +
                                                ": use .obj (with .mtl and map) or .glb");
  const std::size_t first = set.targets().size();
  if (ext == ".glb")
    stageGlb(lod, map, paint, path, set);
  else
    stageObj(lod, map, paint, path, set);
  // OBJ, MTL, normal map, paint maps: the reverse of their staging order.
  std::vector<fs::path> files(set.targets().begin() + static_cast<std::ptrdiff_t>(first),
                              set.targets().end());
  std::reverse(files.begin(), files.end());
  return files;
}

} // namespace

std::vector<fs::path> stageLodMesh(const LodMesh& lod, const NormalMap& map, const fs::path& path,
                                   OutputSet& set) {
  return stageLod(lod, map, nullptr, path, set);
}

std::vector<fs::path> stageLodMesh(const LodMesh& lod, const NormalMap& map, const Document& paint,
                                   const fs::path& path, OutputSet& set) {
  return stageLod(lod, map, &paint, path, set);
}

std::vector<fs::path> writeLodMesh(const LodMesh& lod, const NormalMap& map, const fs::path& path) {
  OutputSet set;
  std::vector<fs::path> files = stageLodMesh(lod, map, path, set);
  set.commit();
  return files;
}

std::vector<fs::path> writeLodMesh(const LodMesh& lod, const NormalMap& map, const Document& paint,
                                   const fs::path& path) {
  OutputSet set;
  std::vector<fs::path> files = stageLodMesh(lod, map, paint, path, set);
  set.commit();
  return files;
}

} // namespace octaclay::core
