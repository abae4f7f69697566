#include "commands.h"
#include "octaclay/core/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/mesh_extraction.h"
#include "octaclay/core/mesh_io.h"
#include "octaclay/core/textured_export.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

namespace octaclay::app {
namespace {

// .obj and .glb carry the painted layers (core/textured_export.h); the others are geometry only
// and go through OpenMesh.
enum class ExportKind { TexturedObj, Glb, Plain };

ExportKind exportKindFromPath(const std::string& output) {
  std::string ext = std::filesystem::path(output).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return ExportKind::TexturedObj;
  if (ext == ".glb") return ExportKind::Glb;
  if (core::meshFormatFromPath(output)) return ExportKind::Plain;
  throw core::Error(core::ErrorKind::InvalidArgument,
                    "cannot export to " + output +
                        ": unknown mesh format; use .obj, .glb, .ply, .stl or .off");
}

} // namespace

Command addExportCommand(CLI::App& app) {
  struct Options {
    std::string input, output;
    int lod = 0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "export", "Write a document's surface as textured OBJ or glTF (.glb), or PLY, STL, OFF");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  sub->add_option("-o,--output", opt->output,
                  "Mesh to write: .obj (with .mtl and PNG maps of the painted layers beside it), "
                  ".glb (binary glTF, textures embedded), .ply (binary), .stl (binary), .off")
      ->required();
  sub->add_option("--lod", opt->lod,
                  "Export the level of detail of size M (a power of two <= N): (M+1)^2 samples, "
                  "every N/M-th sample of the image. Default: full resolution");
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt, sub]() {
            const ExportKind kind = exportKindFromPath(opt->output);
            const core::Document document =
                core::readDocument(opt->input, {.layers = kind != ExportKind::Plain});
            const int n = document.size();
            const int m = sub->count("--lod") > 0 ? opt->lod : n;
            if (m < 2 || m > n || (m & (m - 1)) != 0)
              throw core::Error(
                  core::ErrorKind::InvalidArgument,
                  "--lod " + std::to_string(opt->lod) +
                      " is not a power of two between 2 and N = " + std::to_string(n));
            // vertices and triangles describe the surface (welded, as info counts them); the
            // textured formats store (M+1)^2 samples, seam samples twice with their own texcoords.
            const auto mm = static_cast<std::size_t>(m) * static_cast<std::size_t>(m);
            std::size_t vertices = mm + 2, triangles = 2 * mm, fileVertices = vertices;
            std::vector<std::string> files;
            switch (kind) {
            case ExportKind::TexturedObj:
              core::writeTexturedObj(document, n / m, opt->output);
              for (const std::filesystem::path& path : core::texturedObjFiles(opt->output))
                files.push_back(path.string());
              fileVertices = static_cast<std::size_t>(m + 1) * static_cast<std::size_t>(m + 1);
              break;
            case ExportKind::Glb:
              core::writeGlb(document, n / m, opt->output);
              files.push_back(opt->output);
              fileVertices = static_cast<std::size_t>(m + 1) * static_cast<std::size_t>(m + 1);
              break;
            case ExportKind::Plain: {
              const core::TriangleMesh mesh = core::extractMesh(document.positions, n / m);
              core::writeMesh(mesh, opt->output);
              files.push_back(opt->output);
              vertices = fileVertices = mesh.positions.size();
              triangles = mesh.triangles.size();
              break;
            }
            }
            if (opt->json) {
              std::cout << nlohmann::json{{"output", opt->output},
                                          {"files", files},
                                          {"lod", m},
                                          {"vertices", vertices},
                                          {"triangles", triangles},
                                          {"file_vertices", fileVertices}}
                               .dump()
                        << "\n";
            } else {
              std::cout << "wrote " << opt->output << ": " << vertices << " vertices, " << triangles
                        << " triangles (level " << m << " of " << n << ")";
              if (fileVertices != vertices)
                std::cout << ", " << fileVertices << " samples with texture coordinates";
              std::cout << "\n";
              for (std::size_t k = 1; k < files.size(); ++k)
                std::cout << "wrote " << files[k] << "\n";
            }
            return kExitOk;
          }};
}

} // namespace octaclay::app
