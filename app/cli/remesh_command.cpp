// octaclay-cli remesh (issue 30): the document's surface parameterized again over the
// octahedron as `import` does and resampled evenly, every layer carried by closest point, the
// result checked against the surface it replaces.

#include "commands.h"
#include "json_output.h"
#include "object_choice.h"
#include "progress_line.h"
#include "resample_arguments.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/import/remesh.h"
#include "octaclay/core/measure/stretch.h"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {
namespace {

nlohmann::json carriedJson(const core::CarriedLayer& l) {
  if (!l.painted) return nullptr;
  return {{"mean_error", l.meanError},
          {"max_error", l.maxError},
          {"share_within", l.shareWithin},
          {"painted_share_within", l.paintedShareWithin},
          {"painted_area", l.paintedArea}};
}

} // namespace

Command addRemeshCommand(CLI::App& app) {
  struct Options {
    std::string input, output, object;
    int size = 0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "remesh",
      "Give the surface a new, even sampling: it is parameterized again over the octahedron as "
      "`import` does and resampled at N (default: the document's), every painted layer carried "
      "from the old surface. The result is checked: when the surface would move more than "
      "0.05 % (RMS) or 1 % (Hausdorff) of the diagonal (more at a coarser N: (N/M)² as "
      "much), the document is written unchanged and the reason said (exit 0; --json: "
      "\"changed\": false, \"reason\")");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  CLI::Option* size =
      sub->add_option("--size", opt->size, "The new N: a power of two from 2 to 8192");
  sub->add_option("-o,--output", opt->output, "Document to write (.exr, not the input)")
      ->required();
  sub->add_flag("--json", opt->json,
                "Print one JSON object: stretch before and after, the surface distance, the "
                "carried layers' errors (diffuse: ΔE), the times");

  return {sub, [opt, size]() {
            if (size->count() > 0) requireDocumentSize(opt->size);
            requireNewDocumentOutput(opt->input, opt->output);
            ProgressLine progress("remesh", !opt->json);
            progress.stage("reading");
            ChosenObject chosen = readChosenObject(opt->input, opt->object);
            requireUnlocked(chosen, "remesh");
            const core::Document document = std::move(chosen.object().document);
            core::requireUsableSize(document.positions, opt->input);
            core::requireOctahedral(document.positions, "remesh", opt->input);
            const auto start = std::chrono::steady_clock::now();
            const core::RemeshResult r =
                core::remeshDocument(document, {.size = opt->size}, [&progress](float f) {
                  progress.report("remeshing", f);
                  return true;
                });
            progress.stage("writing");
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            std::ostringstream report; // made before the save, which commits last
            if (opt->json) {
              report << JsonReply{{"input", opt->input},
                                  {"output", opt->output},
                                  {"size_before", document.size()},
                                  {"size", r.document.size()},
                                  {"changed", r.changed},
                                  {"reason", r.reason},
                                  {"before", toJson(r.before)},
                                  {"after", toJson(r.after)},
                                  {"rms", r.moved.rms},
                                  {"hausdorff", r.moved.hausdorff},
                                  {"report",
                                   surfaceReportJson(
                                       &r.moved, {.samplesPerSurface =
                                                      core::RemeshOptions{}.samplesPerSurface})},
                                  {"diffuse", carriedJson(r.diffuse)},
                                  {"feature", carriedJson(r.feature)},
                                  {"mask", carriedJson(r.mask)},
                                  {"flipped", r.flipped},
                                  {"snapped", r.snapped},
                                  {"parameterize_ms", r.parameterizeMs},
                                  {"resample_ms", r.resampleMs},
                                  {"measure_ms", r.measureMs},
                                  {"ms", ms}}
                            .dump()
                     << "\n";
            } else {
              report << std::setprecision(3);
              if (r.changed)
                report << "remeshed " << opt->input << " into " << opt->output
                       << " at N = " << r.document.size() << " in " << ms << " ms\n";
              else
                report << "left " << opt->input << " unchanged (written to " << opt->output
                       << "): " << r.reason << "\n";
              report << "  longest edge  " << r.before.longestOverMedian << "x -> "
                     << r.after.longestOverMedian << "x the median\n"
                     << "  over 4x       " << 100 * r.before.shareOver4x << " % -> "
                     << 100 * r.after.shareOver4x << " % of samples\n"
                     << "  surface moved RMS " << 100 * r.moved.rms << " %, Hausdorff "
                     << 100 * r.moved.hausdorff << " % of the diagonal\n";
              if (r.diffuse.painted)
                report << "  diffuse       mean ΔE " << r.diffuse.meanError << ", "
                       << 100 * r.diffuse.paintedShareWithin
                       << " % of the painted area within ΔE 5\n";
            }
            writeChosenObject(chosen, r.document, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
