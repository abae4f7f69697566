#include "commands.h"
#include "json_output.h"
#include "output_rules.h"
#include "progress_line.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/import/import.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/spherical_parameterization.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace octaclay::app {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// "vertex colours", "texture <path>" or "none": what the diffuse layer was made from.
std::string describe(const core::ImportedDiffuse& diffuse) {
  switch (diffuse.source) {
  case core::DiffuseSource::VertexColours:
    return "vertex colours";
  case core::DiffuseSource::Texture:
    return "texture " + diffuse.texture.string();
  case core::DiffuseSource::None:
    break;
  }
  return "none";
}

} // namespace

Command addImportCommand(CLI::App& app) {
  struct Options {
    std::string input, output;
    int size = 256;
    bool fillHoles = false, json = false, quiet = false;
    int maxHoleEdges = 64;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "import", "Turn a closed genus-0 mesh (OBJ, PLY, STL, OFF) into an Octaclay document");
  sub->add_option("mesh", opt->input, "Mesh file (.obj, .ply, .stl, .off)")->required();
  sub->add_option("--size", opt->size, "N: the image has (N+1)x(N+1) samples; a power of two")
      ->capture_default_str();
  sub->add_flag("--fill-holes", opt->fillHoles, "Close small holes and say what was done");
  sub->add_option("--max-hole-edges", opt->maxHoleEdges,
                  "With --fill-holes: the largest hole closed, in boundary edges")
      ->capture_default_str();
  sub->add_option("-o,--output", opt->output, "Document to write (.exr)")->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");
  sub->add_flag("--quiet", opt->quiet,
                "No progress line on stderr (shown only on a terminal, never with --json)");

  return {sub, [opt]() {
            requireOutputExtension(opt->output, {".exr"}, "the document");
            requireNotInput(opt->output, opt->input);
            core::requireValidSize(opt->size);
            const auto start = std::chrono::steady_clock::now();
            ProgressLine progress("import", !opt->quiet && !opt->json);
            progress.stage("reading the mesh");
            core::ValidationOptions validation;
            validation.fillHoles = opt->fillHoles;
            validation.maxHoleEdges = opt->maxHoleEdges;
            std::vector<core::ValidatedMesh> parts =
                core::loadGenus0Parts(opt->input, validation, core::kMaxSceneObjects);
            if (parts.size() > 1) {
              // Several closed lumps (a scene exported as one mesh): one object each, in place.
              core::Scene scene;
              nlohmann::json triangles = nlohmann::json::array();
              for (std::size_t k = 0; k < parts.size(); ++k) {
                const core::SphericalMap map =
                    core::parameterizeOnSphere(parts[k].mesh, [&](float fraction) {
                      progress.report("mapping part " + std::to_string(k + 1) + " of " +
                                          std::to_string(parts.size()),
                                      fraction);
                      return true;
                    });
                if (map.flipped > 0)
                  throw core::Error(core::ErrorKind::InvalidInput,
                                    opt->input + ": the spherical map of part " +
                                        std::to_string(k + 1) + " folds over itself (" +
                                        std::to_string(map.flipped) +
                                        " flipped triangles); this mesh is not supported yet");
                scene.objects.push_back({scene.uniqueName("Part"),
                                         core::importValidatedMesh(parts[k], map, opt->size),
                                         {},
                                         true,
                                         false});
                triangles.push_back(parts[k].mesh.triangles.size());
              }
              std::ostringstream report;
              if (opt->json)
                report << app::JsonReply{{"input", opt->input},
                                         {"output", opt->output},
                                         {"size", opt->size},
                                         {"objects", scene.objects.size()},
                                         {"part_triangles", triangles},
                                         {"total_ms", millisecondsSince(start)}}
                              .dump()
                       << "\n";
              else
                report << "imported " << opt->input << " as " << opt->output << ": "
                       << scene.objects.size()
                       << " objects (Part, Part.001, ...), N = " << opt->size << " each, in "
                       << millisecondsSince(start) << " ms\n";
              progress.stage("writing");
              core::writeScene(scene, opt->output);
              std::cout << report.str();
              return kExitOk;
            }
            const core::ValidatedMesh validated = std::move(parts.front());
            const double loadMs = millisecondsSince(start);

            const auto mapStart = std::chrono::steady_clock::now();
            const core::SphericalMap map =
                core::parameterizeOnSphere(validated.mesh, [&](float fraction) {
                  progress.report("mapping to the sphere", fraction);
                  return true;
                });
            const double mapMs = millisecondsSince(mapStart);
            if (map.flipped > 0)
              throw core::Error(core::ErrorKind::InvalidInput,
                                opt->input + ": the spherical map folds over itself (" +
                                    std::to_string(map.flipped) +
                                    " flipped triangles); this mesh is not supported yet");
            progress.stage("resampling");
            const auto sampleStart = std::chrono::steady_clock::now();
            core::ImportedDiffuse diffuse;
            const core::Document document =
                core::importValidatedMesh(validated, map, opt->size, &diffuse);
            const double sampleMs = millisecondsSince(sampleStart);
            progress.stage("measuring");
            core::SurfaceDistanceOptions distanceOptions;
            distanceOptions.samplesPerSurface = 200'000;
            const core::ImportQuality quality =
                core::measureImport(validated.mesh, map, document.positions, distanceOptions);
            const double totalMs = millisecondsSince(start);
            const core::MeshCleanup& c = validated.cleanup;
            const std::string diffuseFrom = describe(diffuse);

            // Measured and reported before the document is committed.
            std::ostringstream report;
            if (opt->json) {
              report << app::JsonReply{{"input", opt->input},
                                       {"output", opt->output},
                                       {"size", opt->size},
                                       {"mesh_vertices", validated.mesh.positions.size()},
                                       {"mesh_triangles", validated.mesh.triangles.size()},
                                       {"cleanup",
                                        {{"unused_vertices_removed", c.unusedVerticesRemoved},
                                         {"duplicate_vertices_welded", c.duplicateVerticesWelded},
                                         {"degenerate_faces_removed", c.degenerateFacesRemoved},
                                         {"duplicate_faces_removed", c.duplicateFacesRemoved},
                                         {"faces_flipped", c.facesFlipped},
                                         {"winding_reversed", c.windingReversed},
                                         {"holes_filled", c.holesFilled}}},
                                       {"diffuse", diffuseFrom},
                                       {"notes", diffuse.notes},
                                       {"flipped_triangles", quality.flipped},
                                       {"stretch_l2", quality.stretchL2},
                                       {"stretch_linf", quality.stretchLinf},
                                       {"rms", quality.distance.rms},
                                       {"hausdorff", quality.distance.hausdorff},
                                       {"load_ms", loadMs},
                                       {"parameterize_ms", mapMs},
                                       {"resample_ms", sampleMs},
                                       {"total_ms", totalMs}}
                            .dump()
                     << "\n";
            } else {
              report << "imported " << opt->input << " (" << validated.mesh.triangles.size()
                     << " triangles) as " << opt->output << ", N = " << opt->size << "\n"
                     << "  stretch    L2 " << quality.stretchL2 << ", Linf " << quality.stretchLinf
                     << ", flipped triangles " << quality.flipped << "\n"
                     << "  distance   RMS " << quality.distance.rms * 100 << " %, Hausdorff "
                     << quality.distance.hausdorff * 100 << " % of the bounding-box diagonal\n"
                     << "  diffuse    " << diffuseFrom << "\n"
                     << "  time       " << totalMs << " ms (parameterization " << mapMs << " ms)\n";
              if (c.windingReversed) report << "  note       faces were wound inward: reversed\n";
              if (c.holesFilled) report << "  note       " << c.holesFilled << " holes filled\n";
              for (const std::string& note : diffuse.notes)
                report << "  note       " << note << "\n";
            }
            progress.stage("writing");
            core::writeDocument(document, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
