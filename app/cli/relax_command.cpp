// octaclay-cli relax (issue 21): the global even-out of a document's samples, every layer
// carried, with the stretch figures before and after and how far the surface moved.

#include "commands.h"
#include "json_output.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"
#include "octaclay/core/relax/relax.h"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {
namespace {

nlohmann::json stretchJson(const core::StretchSummary& s) {
  return {{"longest_over_median", s.longestOverMedian},
          {"p99_over_median", s.p99OverMedian},
          {"share_over_4x", s.shareOver4x},
          {"median_edge", s.medianEdge},
          {"longest_edge", s.longestEdge},
          {"mean_spacing", s.meanSpacing}};
}

} // namespace

Command addRelaxCommand(CLI::App& app) {
  struct Options {
    std::string input, output;
    int iterations = 1;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "relax", "Even out the samples over the surface (where it was pulled far, samples come "
               "back); the surface and every painted layer stay where they are");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  sub->add_option("-o,--output", opt->output, "Document to write (.exr)")->required();
  sub->add_option("--iterations", opt->iterations,
                  "Sweeps over the finest level (1 to " +
                      std::to_string(core::kMaxRelaxIterations) + "; default 1)");
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {
      sub, [opt]() {
        core::RelaxOptions options;
        options.iterations = opt->iterations;
        if (opt->iterations < 1 || opt->iterations > core::kMaxRelaxIterations)
          throw core::Error(core::ErrorKind::InvalidArgument,
                            "--iterations " + std::to_string(opt->iterations) +
                                " is outside 1 to " + std::to_string(core::kMaxRelaxIterations));
        const core::Document document = core::readDocument(opt->input);
        const core::StretchSummary before = core::summarizeStretch(document.positions);
        const auto start = std::chrono::steady_clock::now();
        const core::Document relaxed = core::evenOutSamples(document, options);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        const core::StretchSummary after = core::summarizeStretch(relaxed.positions);
        // A surface collapsed to a point has nothing to even out and no scale to measure by.
        const core::TriangleMesh surface = core::extractMesh(document.positions);
        const core::SurfaceDistance moved =
            core::boundingBox(surface).diagonal() > 0
                ? core::compareSurfaces(surface, core::extractMesh(relaxed.positions),
                                        {.samplesPerSurface = 200'000})
                : core::SurfaceDistance{};
        std::ostringstream report; // made before the save, which commits last
        if (opt->json) {
          report << app::JsonReply{{"input", opt->input},          {"output", opt->output},
                                   {"size", document.size()},      {"before", stretchJson(before)},
                                   {"after", stretchJson(after)},  {"rms", moved.rms},
                                   {"hausdorff", moved.hausdorff}, {"ms", ms}}
                        .dump()
                 << "\n";
        } else {
          report << std::setprecision(3) << "relaxed " << opt->input << " into " << opt->output
                 << " in " << ms << " ms\n"
                 << "  longest edge  " << before.longestOverMedian << "x -> "
                 << after.longestOverMedian << "x the median\n"
                 << "  99th pct edge " << before.p99OverMedian << "x -> " << after.p99OverMedian
                 << "x the median\n"
                 << "  over 4x       " << 100 * before.shareOver4x << " % -> "
                 << 100 * after.shareOver4x << " % of samples\n"
                 << "  surface moved RMS " << 100 * moved.rms << " %, Hausdorff "
                 << 100 * moved.hausdorff << " % of the diagonal\n";
        }
        core::writeDocument(relaxed, opt->output);
        std::cout << report.str();
        return kExitOk;
      }};
}

} // namespace octaclay::app
