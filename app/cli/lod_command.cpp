// octaclay-cli lod: the thesis's automatic level of detail (chapter 4) from a document, written
// with a normal map baked from the full-resolution image, and measured against it.

#include "commands.h"
#include "finite_arguments.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"
#include "progress_line.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/export/lod_export.h"
#include "octaclay/core/file_extension.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/lod_vertices.h"
#include "octaclay/core/lod/normal_map.h"
#include "octaclay/core/lod/saliency.h"
#include "octaclay/core/measure/surface_distance.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace octaclay::app {
namespace {

using core::Error;
using core::ErrorKind;

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

bool isPowerOfTwo(long long v) {
  return v > 0 && (v & (v - 1)) == 0;
}

bool saliencyIsEmpty(const core::GeometryImage& image) {
  return std::all_of(image.texels().begin(), image.texels().end(),
                     [](const core::Vec4f& t) { return t.w == 0; });
}

} // namespace

Command addLodCommand(CLI::App& app) {
  struct Options {
    std::string input, output, method = "auto", normalMap, space, object;
    long long size = 0, triangles = 0, mapSize = 0, oversample = 1;
    double maxError = 0, maxAspect = 10;
    std::size_t samples = 200'000;
    bool json = false, noReport = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "lod", "Generate a level of detail (resample, then collapse vertices) and write it with a "
             "normal map baked from the full-resolution image (OBJ + MTL + map, or GLB)");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  sub->add_option("--size", opt->size,
                  "M: resample to (M+1)^2 samples, a power of two below N. Optional with "
                  "--triangles (then the smallest M whose 2M^2 triangles reach T)");
  sub->add_option("--method", opt->method,
                  "How each LOD sample is chosen: salient-point (the thesis's best), "
                  "salient-average, point or average; adaptive: full-resolution samples "
                  "where the surface bends, no grid (--size then only sets 2M^2 triangles); "
                  "collapse: the whole full-resolution mesh collapsed down to T (weighted by "
                  "the document's saliency when it has one); auto: adaptive where the image "
                  "samples a smooth surface evenly, collapse where it stretches or the surface "
                  "is rough (reported as method_used)")
      ->capture_default_str();
  sub->add_option("--triangles", opt->triangles,
                  "Collapse vertices down to T triangles (more than 4)");
  sub->add_option("--oversample", opt->oversample,
                  "With --triangles: start from K times the grid (adaptive: K^2 times the "
                  "triangles) and collapse down to T, so the collapse chooses where detail goes: "
                  "closer to the surface, for several times the time. A power of two")
      ->capture_default_str();
  sub->add_option("--max-aspect", opt->maxAspect,
                  "Refuse collapses that make a triangle thinner (longest edge / height) than "
                  "this and than twice what it was before the collapse began (0: no bound, else "
                  "2 or more)")
      ->check(kFiniteNumber)
      ->capture_default_str();
  sub->add_option("--max-error", opt->maxError,
                  "Stop collapsing before an error above this fraction of the bounding-box "
                  "diagonal (0: no bound)")
      ->check(kFiniteNumber);
  sub->add_option("--normal-map", opt->normalMap,
                  "Also write the baked normal map here: .png (8-bit) or .exr (float)");
  sub->add_option("--normal-space", opt->space,
                  "object (the thesis's choice: full-resolution normals) or tangent (relative "
                  "to the LOD's glTF tangent frame; what glTF viewers read as normalTexture). "
                  "Default: object for .obj, tangent for .glb");
  sub->add_option("--map-size", opt->mapSize,
                  "Normal map resolution R (R x R texels, 2 to 8192). Default: N");
  sub->add_option("--samples", opt->samples,
                  "Points sampled on each surface for the RMS / Hausdorff / PSNR figures")
      ->capture_default_str();
  sub->add_option("-o,--output", opt->output,
                  "LOD to write: .obj (with .mtl and stem_normal.png beside it) or .glb")
      ->required();
  sub->add_flag("--no-report", opt->noReport,
                "Skip the RMS / Hausdorff / PSNR figures (the sampled surface distance)");
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {
      sub, [opt, sub]() {
        // Arguments first, so a bad one is reported before any file is read.
        const std::string ext = core::lowerExtension(opt->output);
        if (ext != ".obj" && ext != ".glb")
          throw Error(ErrorKind::InvalidArgument, "cannot write the LOD to " + opt->output +
                                                      ": use .obj (with .mtl and normal "
                                                      "map) or .glb");
        const std::optional<core::ResampleMethod> method = core::parseResampleMethod(opt->method);
        if (!method)
          throw Error(ErrorKind::InvalidArgument,
                      "unknown --method '" + opt->method +
                          "': use auto, salient-point, salient-average, point, "
                          "average, adaptive or collapse");
        // glTF viewers read only tangent-space maps, so a .glb gets one unless told.
        if (opt->space.empty()) opt->space = ext == ".glb" ? "tangent" : "object";
        const std::optional<core::NormalMapSpace> space = core::parseNormalMapSpace(opt->space);
        if (!space)
          throw Error(ErrorKind::InvalidArgument,
                      "unknown --normal-space '" + opt->space + "': use object or tangent");
        if (!opt->normalMap.empty()) {
          requireOutputExtension(opt->normalMap, {".png", ".exr"},
                                 "the normal map (8-bit .png or float .exr)");
          requireNotInput(opt->normalMap, opt->input, "--normal-map");
        }
        requireNotInput(opt->output, opt->input);
        const bool hasSize = sub->count("--size") > 0, hasTriangles = opt->triangles != 0;
        if (!hasSize && !hasTriangles)
          throw Error(ErrorKind::InvalidArgument,
                      "say how coarse: --size M (a power of two below N) and/or "
                      "--triangles T");
        if (hasSize && (opt->size < 2 || !isPowerOfTwo(opt->size)))
          throw Error(ErrorKind::InvalidArgument,
                      "--size " + std::to_string(opt->size) +
                          " is not a power of two of at least 2 (e.g. 64, 128, 256)");
        if (opt->triangles < 0 || (hasTriangles && opt->triangles <= 4))
          throw Error(ErrorKind::InvalidArgument,
                      "--triangles " + std::to_string(opt->triangles) +
                          " is too small: a closed mesh has at least 4 triangles; ask for "
                          "more than 4");
        if (opt->oversample < 1 || opt->oversample > 16 || !isPowerOfTwo(opt->oversample))
          throw Error(ErrorKind::InvalidArgument,
                      "--oversample " + std::to_string(opt->oversample) +
                          " is not a power of two from 1 to 16 (e.g. 1, 2 or 4)");
        if (!(opt->maxAspect == 0 || opt->maxAspect >= 2))
          throw Error(ErrorKind::InvalidArgument,
                      "--max-aspect " + std::to_string(opt->maxAspect) +
                          " is below 2: use 0 (no bound) or 2 or more (default 10)");
        if (!(opt->maxError >= 0))
          throw Error(ErrorKind::InvalidArgument,
                      "--max-error " + std::to_string(opt->maxError) +
                          " is negative: use 0 (no bound) or a fraction of the diagonal");
        if (sub->count("--map-size") > 0 && (opt->mapSize < 2 || opt->mapSize > 8192))
          throw Error(ErrorKind::InvalidArgument, "--map-size " + std::to_string(opt->mapSize) +
                                                      " is out of range: use 2 to 8192");
        if (opt->samples == 0)
          throw Error(ErrorKind::InvalidArgument, "--samples must be at least 1");

        const auto commandStart = std::chrono::steady_clock::now();
        ProgressLine progress("lod", !opt->json);
        progress.stage("reading");
        core::Document document = std::move(
            readChosenObject(opt->input, opt->object, {.layers = false}).object().document);
        core::requireUsableSize(document.positions, opt->input);
        core::GeometryImage& full = document.positions;
        // N; a torus's or plane's longer side (--size is M of that side, gridLod checks the other).
        const int n = std::max(full.width(), full.height());
        const std::size_t fullTriangles =
            2 * std::size_t(full.width()) * std::size_t(full.height());
        if (full.topology() == core::Topology::Octahedral && n < 4)
          throw Error(
              ErrorKind::InvalidArgument,
              "an LOD needs a document of N = 4 or more: this one is N = " + std::to_string(n) +
                  " (" + std::to_string(2 * n * n) + " triangles), already as coarse as it gets");
        if (hasSize && opt->size >= n)
          throw Error(ErrorKind::InvalidArgument,
                      "--size " + std::to_string(opt->size) +
                          " must be smaller than the document's N = " + std::to_string(n) +
                          " (an LOD has fewer samples than the full image)");

        core::LodOptions options;
        options.size = hasSize ? static_cast<int>(opt->size) : 0;
        options.targetTriangles = static_cast<std::size_t>(opt->triangles);
        options.maxError = opt->maxError;
        options.oversample = static_cast<int>(opt->oversample);
        options.maxAspectRatio = static_cast<float>(opt->maxAspect);
        // auto's choice is made here (a stretch summary of a 64 grid and a roughness of
        // a sparse one: about a millisecond) so that only a salient choice pays for the
        // saliency.
        const auto chooseStart = std::chrono::steady_clock::now();
        options.method =
            *method == core::ResampleMethod::Auto ? core::chooseLodMethod(full, options) : *method;
        const double chooseMs = millisecondsSince(chooseStart);
        // The salient methods read saliency from alpha; a document that never had it
        // computed (all zero) gets the CPU reference pass.
        const bool salient = options.method == core::ResampleMethod::SalientPoint ||
                             options.method == core::ResampleMethod::SalientAverage;
        double saliencyMs = 0;
        const bool computeSaliency = salient && saliencyIsEmpty(full);
        if (computeSaliency) {
          const auto start = std::chrono::steady_clock::now();
          core::computeSaliency(full);
          saliencyMs = millisecondsSince(start);
        }

        progress.stage("simplifying");
        const auto lodStart = std::chrono::steady_clock::now();
        const core::LodMesh lod = core::generateLod(full, options);
        const double lodMs = chooseMs + millisecondsSince(lodStart);

        const int mapSize = sub->count("--map-size") > 0 ? static_cast<int>(opt->mapSize) : n;
        progress.stage("baking the normal map");
        const auto bakeStart = std::chrono::steady_clock::now();
        const core::NormalMap map = core::bakeNormalMap(full, lod, *space, mapSize);
        const double bakeMs = millisecondsSince(bakeStart);

        // Every file is staged, measured and reported before the set is committed: any
        // failure until then leaves the previous files and no temporary.
        progress.stage("writing");
        const auto writeStart = std::chrono::steady_clock::now();
        core::OutputSet set;
        std::vector<std::string> files;
        for (const std::filesystem::path& f : core::stageLodMesh(lod, map, opt->output, set))
          files.push_back(f.string());
        if (!opt->normalMap.empty()) {
          core::stageNormalMap(map, opt->normalMap, set);
          files.push_back(opt->normalMap);
        }
        const double writeMs = millisecondsSince(writeStart);

        progress.stage("measuring");
        const auto measureStart = std::chrono::steady_clock::now();
        const core::SurfaceDistanceOptions distanceOptions{.samplesPerSurface = opt->samples};
        const core::SurfaceDistance distance =
            opt->noReport
                ? core::SurfaceDistance{}
                : core::compareSurfaces(core::extractMesh(full), lod.mesh, distanceOptions);
        const double measureMs = millisecondsSince(measureStart);
        // With --no-report the figures are null: nothing was measured.
        const auto figure = [&opt](double v) {
          return opt->noReport ? nlohmann::json(nullptr) : nlohmann::json(v);
        };
        const std::size_t fileVertices = core::lodVertices(lod).positions.size();
        const double totalMs = millisecondsSince(commandStart);

        std::ostringstream report;
        if (opt->json) {
          report << app::JsonReply{{"input", opt->input},
                                   {"output", opt->output},
                                   {"files", files},
                                   {"document_size", n},
                                   {"size", lod.resampledSize},
                                   {"method", core::methodName(*method)},
                                   {"method_used", core::methodName(lod.methodUsed)},
                                   {"oversample", opt->oversample},
                                   {"triangles", lod.mesh.triangles.size()},
                                   {"vertices", lod.mesh.positions.size()},
                                   {"file_vertices", fileVertices},
                                   {"full_triangles", fullTriangles},
                                   {"topology", core::topologyName(full.topology())},
                                   {"normal_space", core::normalMapSpaceName(*space)},
                                   {"map_size", mapSize},
                                   {"saliency_computed", computeSaliency},
                                   {"ms", lodMs},
                                   {"saliency_ms", saliencyMs},
                                   {"bake_ms", bakeMs},
                                   {"write_ms", writeMs},
                                   {"measure_ms", measureMs},
                                   {"total_ms", totalMs},
                                   {"rms", figure(distance.rms)},
                                   {"hausdorff", figure(distance.hausdorff)},
                                   {"psnr", figure(distance.psnr)},
                                   {"diagonal", distance.diagonal},
                                   {"report", surfaceReportJson(opt->noReport ? nullptr : &distance,
                                                                distanceOptions)}}
                        .dump()
                 << "\n";
        } else {
          report << "wrote " << opt->output << ": " << lod.mesh.triangles.size() << " triangles, "
                 << lod.mesh.positions.size() << " vertices ("
                 << (lod.methodUsed == core::ResampleMethod::Adaptive ||
                             lod.methodUsed == core::ResampleMethod::Collapse
                         ? "samples of N = " + std::to_string(n)
                         : "M = " + std::to_string(lod.resampledSize) +
                               " of N = " + std::to_string(n))
                 << ", "
                 << (*method == core::ResampleMethod::Auto
                         ? "auto: " + std::string(core::methodName(lod.methodUsed))
                         : std::string(core::methodName(*method)))
                 << ") in " << lodMs << " ms\n";
          if (!opt->noReport)
            report << "  against full resolution: RMS " << distance.rms * 100 << " %, Hausdorff "
                   << distance.hausdorff * 100 << " % of the diagonal, PSNR " << distance.psnr
                   << " dB"
                   << (distance.boundedQueries > 0 ? " (at most: the surface tangles)" : "")
                   << "\n";
          report << "  " << core::normalMapSpaceName(*space) << "-space normal map " << mapSize
                 << "x" << mapSize << " baked in " << bakeMs << " ms\n";
          if (computeSaliency)
            report << "  saliency was empty: computed in " << saliencyMs << " ms\n";
          for (std::size_t k = 1; k < files.size(); ++k)
            report << "wrote " << files[k] << "\n";
        }
        set.commit();
        std::cout << report.str();
        return kExitOk;
      }};
}

} // namespace octaclay::app
