#include "commands.h"
#include "json_output.h"
#include "object_choice.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/measure/surface_distance.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <memory>

namespace octaclay::app {
namespace {

// A document's full-resolution surface (its object named object, or its only one), or a mesh
// file's.
core::TriangleMesh loadSurface(const std::string& path, const std::string& object) {
  if (core::meshFormatFromPath(path)) return core::readMesh(path);
  return core::extractMesh(
      readChosenObject(path, object, {.layers = false}).object().document.positions);
}

} // namespace

Command addCompareCommand(CLI::App& app) {
  struct Options {
    std::string a, b, object;
    std::size_t samples = 1'000'000;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "compare",
      "Distance between two surfaces: RMS and Hausdorff as fractions of a's bounding-box "
      "diagonal, and PSNR = 20 log10(1/RMS)");
  sub->add_option("a", opt->a, "Reference: document (.exr) or mesh")->required();
  sub->add_option("b", opt->b, "Compared: document (.exr) or mesh (.obj, .ply, .stl, .off)")
      ->required();
  addObjectOption(*sub, opt->object)
      ->description("The object compared in each document given (by name; may be left out "
                    "when a document holds one object)");
  sub->add_option("--samples", opt->samples, "Random points per surface besides its vertices")
      ->capture_default_str();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            const core::TriangleMesh a = loadSurface(opt->a, opt->object);
            // Distances are fractions of a's size: a has to have one.
            if (const auto problem = core::sizeProblem(core::boundingBox(a)))
              throw core::Error(core::ErrorKind::InvalidInput, opt->a + ": " + *problem);
            const core::TriangleMesh b = loadSurface(opt->b, opt->object);
            const core::SurfaceDistanceOptions options{.samplesPerSurface = opt->samples};
            const core::SurfaceDistance d = core::compareSurfaces(a, b, options);
            if (opt->json) {
              nlohmann::json out{{"a", opt->a},
                                 {"b", opt->b},
                                 {"rms", d.rms},
                                 {"hausdorff", d.hausdorff},
                                 {"diagonal", d.diagonal},
                                 {"samples", d.samples},
                                 {"report", surfaceReportJson(&d, options)}};
              // JSON has no infinity: identical surfaces report psnr null.
              out["psnr"] =
                  std::isfinite(d.psnr) ? nlohmann::json(d.psnr) : nlohmann::json(nullptr);
              std::cout << jsonText(out) << "\n";
            } else {
              std::cout << "RMS        " << d.rms << " of the diagonal (" << d.rms * d.diagonal
                        << ")\n"
                        << "Hausdorff  " << d.hausdorff << " of the diagonal ("
                        << d.hausdorff * d.diagonal << ")\n"
                        << "PSNR       " << d.psnr << " dB\n"
                        << "samples    " << d.samples << "\n";
              if (d.boundedQueries > 0)
                std::cout << "note       " << d.boundedQueries
                          << " queries stopped at their work bound (a tangled surface): the "
                             "figures are upper bounds\n";
            }
            return kExitOk;
          }};
}

} // namespace octaclay::app
