#include "commands.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/export/lod_export.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/export/scene_export.h"
#include "octaclay/core/export/textured_export.h"
#include "octaclay/core/file_extension.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/lod_vertices.h"
#include "octaclay/core/lod/normal_map.h"
#include "octaclay/core/lod/saliency.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <system_error>
#include <vector>

namespace octaclay::app {
namespace {

// .obj and .glb carry the painted layers (core/textured_export.h); the others are geometry only
// and go through OpenMesh.
enum class ExportKind { TexturedObj, Glb, Plain };

ExportKind exportKindFromPath(const std::string& output) {
  const std::string ext = core::lowerExtension(output);
  if (ext == ".obj") return ExportKind::TexturedObj;
  if (ext == ".glb") return ExportKind::Glb;
  if (core::meshFormatFromPath(output)) return ExportKind::Plain;
  throw core::Error(core::ErrorKind::InvalidArgument,
                    "cannot export to " + output +
                        ": unknown mesh format; use .obj, .glb, .ply, .stl or .off");
}

// N; a torus's or plane's longer side: the normal maps' resolution, the level --lod counts in.
int longerSide(const core::GeometryImage& image) {
  return std::max(image.width(), image.height());
}

// --normal-map: the full-resolution object-space normals over the image coordinates (they do
// not depend on the mesh), committed with the mesh's files as one set.
void stageFullNormalMap(const core::GeometryImage& full, const std::string& path,
                        core::OutputSet& set, std::vector<std::string>& files) {
  if (path.empty()) return;
  core::stageNormalMap(
      core::bakeNormalMap(full, {}, core::NormalMapSpace::Object, longerSide(full)), path, set);
  files.push_back(path);
}

// --triangles: the lod command's pipeline (salient-point resampling from --lod M or the smallest
// M that reaches T, then vertex collapse). .obj and .glb carry an object-space normal map baked
// from the full resolution; the other formats are geometry only.
ExitCode exportCollapsed(core::GeometryImage& full, ExportKind kind, int lodSize,
                         std::size_t triangles, const std::string& output,
                         const std::string& normalMap, bool json) {
  if (std::all_of(full.texels().begin(), full.texels().end(),
                  [](const core::Vec4f& t) { return t.w == 0; }))
    core::computeSaliency(full);
  core::LodOptions options;
  options.size = lodSize;
  options.targetTriangles = triangles;
  const core::LodMesh lod = core::generateLod(full, options);
  core::OutputSet set;
  std::vector<std::string> files;
  std::size_t fileVertices = lod.mesh.positions.size();
  if (kind == ExportKind::Plain) {
    core::stageMesh(lod.mesh, output, set);
    files.push_back(output);
  } else {
    const core::NormalMap map =
        core::bakeNormalMap(full, lod, core::NormalMapSpace::Object, longerSide(full));
    for (const std::filesystem::path& path : core::stageLodMesh(lod, map, output, set))
      files.push_back(path.string());
    fileVertices = core::lodVertices(lod).positions.size();
  }
  stageFullNormalMap(full, normalMap, set, files);
  // The report is made before the commit: a failure there leaves the previous files.
  std::ostringstream report;
  if (json) {
    report << app::JsonReply{{"output", output},
                             {"files", files},
                             {"lod", lod.resampledSize},
                             {"vertices", lod.mesh.positions.size()},
                             {"triangles", lod.mesh.triangles.size()},
                             {"file_vertices", fileVertices}}
                  .dump()
           << "\n";
  } else {
    report << "wrote " << output << ": " << lod.mesh.positions.size() << " vertices, "
           << lod.mesh.triangles.size() << " triangles (resampled to " << lod.resampledSize
           << " of " << longerSide(full) << ", then collapsed)\n";
    for (std::size_t k = 1; k < files.size(); ++k)
      report << "wrote " << files[k] << "\n";
  }
  set.commit();
  std::cout << report.str();
  return kExitOk;
}

} // namespace

namespace {

struct ExportOptions {
  std::string input, output, object;
  int lod = 0;
  long long triangles = 0;
  std::string normalMap;
  bool json = false;
};

// A document of several objects without --object: every visible object, placed
// (scene_export.h): GLB nodes, OBJ groups, or one world-space mesh.
int exportScene(const ExportOptions& opt, ExportKind kind, std::size_t inFile,
                bool oneObjectOptions) {
  if (oneObjectOptions)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "--lod, --triangles and --normal-map export one object, and " + opt.input +
                          " holds " + std::to_string(inFile) +
                          " objects: name it with --object NAME (see octaclay-cli objects)");
  const core::Scene scene = core::readScene(opt.input, {.layers = kind == ExportKind::Glb});
  std::size_t objects = 0, vertices = 0, triangles = 0;
  for (const core::SceneObject& object : scene.objects)
    if (object.visible) {
      const core::SampleGrid& grid = object.document.positions.grid();
      ++objects;
      vertices +=
          static_cast<std::size_t>(core::vertexCount(grid.topology, grid.width, grid.height));
      triangles += 2 * static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height);
    }
  std::ostringstream report;
  if (opt.json)
    report << app::JsonReply{{"output", opt.output},
                             {"files", {opt.output}},
                             {"objects", objects},
                             {"vertices", vertices},
                             {"triangles", triangles}}
                  .dump()
           << "\n";
  else
    report << "wrote " << opt.output << ": " << objects << " visible objects, " << vertices
           << " vertices, " << triangles << " triangles, placed in the scene\n";
  core::writeSceneMeshes(scene, opt.output);
  std::cout << report.str();
  return kExitOk;
}

} // namespace

Command addExportCommand(CLI::App& app) {
  using Options = ExportOptions;
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "export", "Write a document's surface as textured OBJ or glTF (.glb), or PLY, STL, OFF");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  sub->add_option("-o,--output", opt->output,
                  "Mesh to write: .obj (with .mtl and PNG maps of the painted layers beside it), "
                  ".glb (binary glTF, textures embedded), .ply (binary), .stl (binary), .off")
      ->required();
  sub->add_option("--lod", opt->lod,
                  "Export the level of detail of size M (a power of two <= N): (M+1)^2 samples, "
                  "every N/M-th sample of the image. Default: full resolution");
  sub->add_option("--triangles", opt->triangles,
                  "Collapse vertices down to T triangles (> 4) as `octaclay-cli lod` does, from "
                  "--lod M (below N) or the smallest M that reaches T. .obj and .glb then carry "
                  "an object-space normal map baked from the full resolution instead of the "
                  "painted layers");
  sub->add_option("--normal-map", opt->normalMap,
                  "Also write the object-space normal map of the full-resolution surface, N x N "
                  "texels over the image coordinates: .png (8-bit) or .exr (float)");
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {
      sub, [opt, sub]() -> int {
        const ExportKind kind = exportKindFromPath(opt->output);
        const bool collapse = opt->triangles != 0;
        if (opt->triangles < 0 || (collapse && opt->triangles <= 4))
          throw core::Error(core::ErrorKind::InvalidArgument,
                            "--triangles " + std::to_string(opt->triangles) +
                                " is too small: a closed mesh has at least 4 triangles; ask "
                                "for more than 4");
        if (!opt->normalMap.empty()) {
          requireOutputExtension(opt->normalMap, {".png", ".exr"},
                                 "the normal map (8-bit .png or float .exr)");
          requireNotInput(opt->normalMap, opt->input, "--normal-map");
        }
        requireNotInput(opt->output, opt->input);
        if (opt->object.empty()) {
          const std::size_t objects = core::readSceneHeaders(opt->input).size();
          if (objects > 1)
            return exportScene(*opt, kind, objects,
                               sub->count("--lod") > 0 || collapse || !opt->normalMap.empty());
        }
        core::Document document =
            std::move(readChosenObject(opt->input, opt->object,
                                       {.layers = kind != ExportKind::Plain && !collapse})
                          .object()
                          .document);
        const int n = longerSide(document.positions);
        if (collapse && document.positions.topology() == core::Topology::Octahedral && n < 4)
          throw core::Error(core::ErrorKind::InvalidArgument,
                            "--triangles needs a document of N = 4 or more: this one is N = " +
                                std::to_string(n) + " (" + std::to_string(2 * n * n) +
                                " triangles); export it without --triangles");
        if (collapse) core::requireUsableSize(document.positions, opt->input);
        const int m = sub->count("--lod") > 0 ? opt->lod : n;
        if (m < 2 || m > n || (m & (m - 1)) != 0)
          throw core::Error(core::ErrorKind::InvalidArgument,
                            "--lod " + std::to_string(opt->lod) +
                                " is not a power of two between 2 and N = " + std::to_string(n));
        if (collapse) {
          if (sub->count("--lod") > 0 && m == n)
            throw core::Error(core::ErrorKind::InvalidArgument,
                              "--lod " + std::to_string(m) +
                                  " with --triangles must be below N = " + std::to_string(n) +
                                  ": vertex collapse starts from a resampled image");
          return exportCollapsed(document.positions, kind, sub->count("--lod") > 0 ? m : 0,
                                 static_cast<std::size_t>(opt->triangles), opt->output,
                                 opt->normalMap, opt->json);
        }
        // vertices and triangles describe the surface (welded, as info counts them); the OBJ
        // writes each once (its seams split only `vt`), the GLB stores (Mw+1)(Mh+1) samples,
        // seam samples twice with their own texture coordinates.
        const int step = n / m;
        const core::SampleGrid& grid = document.positions.grid();
        const auto mw = static_cast<std::size_t>(grid.width / step);
        const auto mh = static_cast<std::size_t>(grid.height / step);
        const std::size_t least = grid.topology == core::Topology::Torus ? core::kMinTorusSize : 1;
        if (std::min(mw, mh) < least)
          throw core::Error(core::ErrorKind::InvalidArgument,
                            "--lod " + std::to_string(m) + " leaves this " +
                                std::string(core::topologyName(grid.topology)) + " of " +
                                std::to_string(grid.width) + " x " + std::to_string(grid.height) +
                                " cells " + std::to_string(mw) + " x " + std::to_string(mh) +
                                "; it needs at least " + std::to_string(least) +
                                " cells each way: use a larger --lod");
        std::size_t vertices = static_cast<std::size_t>(core::vertexCount(
                        grid.topology, static_cast<int>(mw), static_cast<int>(mh))),
                    triangles = 2 * mw * mh, fileVertices = vertices;
        core::OutputSet set;
        std::vector<std::string> files;
        switch (kind) {
        case ExportKind::TexturedObj:
          core::stageTexturedObj(document, step, opt->output, set);
          for (const std::filesystem::path& path : core::texturedObjFiles(opt->output))
            files.push_back(path.string());
          break;
        case ExportKind::Glb:
          core::stageGlb(document, step, opt->output, set);
          files.push_back(opt->output);
          fileVertices = (mw + 1) * (mh + 1);
          break;
        case ExportKind::Plain: {
          const core::TriangleMesh mesh = core::extractMesh(document.positions, step);
          core::stageMesh(mesh, opt->output, set);
          files.push_back(opt->output);
          vertices = fileVertices = mesh.positions.size();
          triangles = mesh.triangles.size();
          break;
        }
        }
        stageFullNormalMap(document.positions, opt->normalMap, set, files);
        // The report is made before the commit: a failure there leaves the previous files.
        std::ostringstream report;
        if (opt->json) {
          report << app::JsonReply{{"output", opt->output},
                                   {"files", files},
                                   {"lod", m},
                                   {"vertices", vertices},
                                   {"triangles", triangles},
                                   {"file_vertices", fileVertices}}
                        .dump()
                 << "\n";
        } else {
          report << "wrote " << opt->output << ": " << vertices << " vertices, " << triangles
                 << " triangles (level " << m << " of " << n << ")";
          if (fileVertices != vertices)
            report << ", " << fileVertices << " samples with texture coordinates";
          report << "\n";
          for (std::size_t k = 1; k < files.size(); ++k)
            report << "wrote " << files[k] << "\n";
        }
        set.commit();
        std::cout << report.str();
        return kExitOk;
      }};
}

} // namespace octaclay::app
