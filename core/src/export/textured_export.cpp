// Textured OBJ and binary glTF export: the sample grid with texture coordinates at the layer
// texels' centres, and the layers as PNG maps (DESIGN.md, "The geometry image"). The OBJ writes
// each surface vertex once and splits only its `vt`; the GLB, whose vertices carry one texture
// coordinate each, keeps the grid's seam samples as separate vertices.

#include "octaclay/core/export/textured_export.h"

#include "export/export_grid.h"
#include "export/glb_writer.h"
#include "export/layer_maps.h"
#include "export/obj_writer.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>

namespace octaclay::core {
namespace fs = std::filesystem;
using detail::diffuseMap;
using detail::featureMap;
using detail::metallicRoughnessMap;

namespace {

// The grid welded as extractMesh welds it: its vertices in extractMesh's order, its triangles
// through that numbering (the grid's own triangles then index the texture coordinates).
struct WeldedGrid {
  std::vector<Vec3f> positions, normals;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

WeldedGrid weld(const detail::ExportGrid& grid,
                const std::vector<std::array<std::uint32_t, 3>>& gridTriangles) {
  std::uint32_t count = 0;
  const std::vector<std::uint32_t> welded = detail::weldedVertices(grid, count);
  WeldedGrid out;
  out.positions.resize(count);
  out.normals.resize(count);
  // Identified samples carry their canonical sample's position and normal, so any copy serves.
  for (std::uint32_t k = 0; k < grid.vertexCount(); ++k) {
    out.positions[welded[k]] = grid.positions[k];
    out.normals[welded[k]] = grid.normals[k];
  }
  out.triangles.reserve(gridTriangles.size());
  for (const auto& t : gridTriangles)
    out.triangles.push_back({welded[t[0]], welded[t[1]], welded[t[2]]});
  return out;
}

std::string mtlText(const std::vector<fs::path>& files) {
  const auto name = [&](std::size_t k) { return files[k].filename().string(); };
  return "# Octaclay textured export: maps at the document's full resolution\n"
         "newmtl octaclay\n"
         "Ka 0 0 0\n"
         "Kd 1 1 1\n"
         "Ks 1 1 1\n"
         "Ns 64\n"
         "d 1\n"
         "illum 3\n" // colour, highlight and reflection
         "map_Kd " +
         name(2) + "\n" + "map_Ks " + name(3) + "\n" +
         // No MTL keyword is a scalar reflectivity map: map_refl is the common extension, and
         // map_Pm (the PBR extension's metallic) the closest reading in PBR importers.
         "map_refl " + name(4) + "\n" + "map_Pm " + name(4) + "\n" + "bump " + name(5) + "\n";
}

} // namespace

std::vector<fs::path> texturedObjFiles(const fs::path& objPath) {
  const std::string stem = objPath.stem().string();
  std::vector<fs::path> files{objPath};
  for (const char* suffix :
       {".mtl", "_diffuse.png", "_specular.png", "_reflectivity.png", "_height.png"})
    files.push_back(fs::path(objPath).replace_filename(stem + suffix));
  return files;
}

void stageTexturedObj(const Document& doc, int step, const fs::path& objPath, OutputSet& set) {
  const detail::ExportGrid grid = detail::makeExportGrid(doc, step);
  const std::vector<fs::path> files = texturedObjFiles(objPath);
  if (objPath.filename() == files[1].filename())
    throw Error(ErrorKind::InvalidArgument,
                "cannot export to " + objPath.string() + ": its material file has that name");

  const std::vector<Vec2f> texcoords = detail::gridTexcoords(grid, true);
  const std::vector<std::array<std::uint32_t, 3>> uvTriangles = detail::gridTriangles(grid);
  const WeldedGrid welded = weld(grid, uvTriangles);
  const detail::ObjMesh mesh{welded.positions, welded.normals, texcoords,
                             welded.triangles, uvTriangles,    {}};
  const detail::ObjHeader header{
      "Octaclay textured export: " + std::to_string(welded.positions.size()) + " vertices, " +
          std::to_string(texcoords.size()) + " texture coordinates, " +
          std::string(topologyName(grid.image.topology)) + " of " + std::to_string(grid.mw) +
          " x " + std::to_string(grid.mh) + " cells, maps at " +
          std::to_string(grid.image.width + 1) + " x " + std::to_string(grid.image.height + 1),
      files[1].filename().string(), "octaclay"};
  const detail::ObjMap maps[] = {{files[2], encodePng(diffuseMap(doc))},
                                 {files[3], encodePng(featureMap(doc, 1))},
                                 {files[4], encodePng(featureMap(doc, 2))},
                                 {files[5], encodePng(featureMap(doc, 0))}};
  detail::writeObjWithMaterial(mesh, header, maps, mtlText(files), files[1], objPath, set);
}

void writeTexturedObj(const Document& doc, int step, const fs::path& objPath) {
  OutputSet set;
  stageTexturedObj(doc, step, objPath, set);
  set.commit();
}

void stageGlb(const Document& doc, int step, const fs::path& glbPath, OutputSet& set) {
  const detail::ExportGrid grid = detail::makeExportGrid(doc, step);
  const std::vector<Vec2f> texcoords = detail::gridTexcoords(grid, false);
  const std::vector<std::array<std::uint32_t, 3>> triangles = detail::gridTriangles(grid);

  // Over glTF's limit the binary chunk's 32-bit length would wrap: refuse before building it.
  const double estimate = static_cast<double>(grid.vertexCount()) * (12 + 12 + 8) +
                          static_cast<double>(triangles.size()) * 3 * 4;
  if (estimate > static_cast<double>(std::numeric_limits<std::uint32_t>::max()) - (1 << 26))
    throw Error(ErrorKind::InvalidArgument,
                "the glTF export at level " + std::to_string(std::max(grid.mw, grid.mh)) +
                    " exceeds the 4 GiB a .glb can hold; export a coarser level");

  const detail::GlbMesh mesh{grid.positions, grid.normals, {}, texcoords, triangles};
  const detail::GlbTexture textures[] = {
      {"diffuse", encodePng(diffuseMap(doc))},
      {"metallicRoughness", encodePng(metallicRoughnessMap(doc))}};
  detail::GlbMaterial material;
  material.name = material.meshName = material.nodeName = "octaclay";
  material.baseColorTexture = 0;
  material.metallicRoughnessTexture = 1;
  detail::writeGlbFile(mesh, textures, material, glbPath, set);
}

void writeGlb(const Document& doc, int step, const fs::path& glbPath) {
  OutputSet set;
  stageGlb(doc, step, glbPath, set);
  set.commit();
}

} // namespace octaclay::core
