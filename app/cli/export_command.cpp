#include "commands.h"
#include "octaclay/core/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/mesh_extraction.h"
#include "octaclay/core/mesh_io.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace octaclay::app {

Command addExportCommand(CLI::App& app) {
  struct Options {
    std::string input, output;
    int lod = 0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub =
      app.add_subcommand("export", "Write a document's surface as OBJ, PLY, STL or OFF");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  sub->add_option("-o,--output", opt->output,
                  "Mesh to write: .obj, .ply (binary), .stl (binary), .off")
      ->required();
  sub->add_option("--lod", opt->lod,
                  "Export the level of detail of size M (a power of two <= N): (M+1)^2 samples, "
                  "every N/M-th sample of the image. Default: full resolution");
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {
      sub, [opt, sub]() {
        if (!core::meshFormatFromPath(opt->output))
          throw core::Error(core::ErrorKind::InvalidArgument,
                            "cannot export to " + opt->output +
                                ": unknown mesh format; use .obj, .ply, .stl or .off");
        const core::Document document = core::readDocument(opt->input, {.layers = false});
        const int n = document.size();
        const int m = sub->count("--lod") > 0 ? opt->lod : n;
        if (m < 2 || m > n || (m & (m - 1)) != 0)
          throw core::Error(core::ErrorKind::InvalidArgument,
                            "--lod " + std::to_string(opt->lod) +
                                " is not a power of two between 2 and N = " + std::to_string(n));
        const core::TriangleMesh mesh = core::extractMesh(document.positions, n / m);
        core::writeMesh(mesh, opt->output);
        if (opt->json)
          std::cout << nlohmann::json{{"output", opt->output},
                                      {"lod", m},
                                      {"vertices", mesh.positions.size()},
                                      {"triangles", mesh.triangles.size()}}
                           .dump()
                    << "\n";
        else
          std::cout << "wrote " << opt->output << ": " << mesh.positions.size() << " vertices, "
                    << mesh.triangles.size() << " triangles (level " << m << " of " << n << ")\n";
        return kExitOk;
      }};
}

} // namespace octaclay::app
