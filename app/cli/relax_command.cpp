// octaclay-cli relax (issue 21): the global even-out of a document's samples, every layer
// carried, with the stretch figures before and after and how far the surface moved.

#include "commands.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"
#include "progress_line.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/relax/relax.h"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {
// The command's bound on --iterations: 100 sweeps take about 5 s at N = 256 and 90 s at
// N = 1024 here (core allows more for its own callers).
constexpr int kMaxIterations = 100;

Command addRelaxCommand(CLI::App& app) {
  struct Options {
    std::string input, output, object;
    int iterations = 1;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "relax", "Even out the samples over the surface (where it was pulled far, samples come "
               "back); the surface and every painted layer stay where they are. The result is "
               "checked: when the surface would move more than 0.01 % (RMS) or 0.1 % "
               "(Hausdorff) of the diagonal, or the stretch would get worse, a smaller step is "
               "tried, else the document is written unchanged and the reason said (exit 0; "
               "--json: \"changed\": false, \"reason\")");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  sub->add_option("-o,--output", opt->output, "Document to write (.exr)")->required();
  sub->add_option("--iterations", opt->iterations,
                  "Sweeps over the finest level (1 to " + std::to_string(kMaxIterations) +
                      "; default 1)");
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            core::RelaxOptions options;
            options.iterations = opt->iterations;
            requireOutputExtension(opt->output, {".exr"}, "the document");
            if (opt->iterations < 1 || opt->iterations > kMaxIterations)
              throw core::Error(core::ErrorKind::InvalidArgument,
                                "--iterations " + std::to_string(opt->iterations) +
                                    " is outside 1 to " + std::to_string(kMaxIterations) +
                                    " (more sweeps barely change the result; run relax again "
                                    "on its output instead)");
            ProgressLine progress("relax", !opt->json);
            progress.stage("reading");
            ChosenObject chosen = readChosenObject(opt->input, opt->object);
            requireUnlocked(chosen, "relax");
            const core::Document document = std::move(chosen.object().document);
            core::requireUsableSize(document.positions, opt->input);
            // A sweep at N = 256 takes about 54 ms here; say so before a run of minutes.
            const double estimate =
                0.054 * opt->iterations * (document.size() / 256.0) * (document.size() / 256.0);
            if (estimate > 30)
              std::cerr << "octaclay-cli: relax: " << opt->iterations
                        << " sweeps at N = " << document.size() << " take about "
                        << static_cast<int>(estimate / 60 + 1)
                        << " min; Ctrl+C stops it with nothing written\n";
            const auto start = std::chrono::steady_clock::now();
            // The even-out checks its own result (core::evenOut): a step that would move the
            // surface beyond its tolerance or leave the stretch worse is backed off or not taken.
            const core::EvenOutResult result =
                core::evenOut(document, options, {}, [&progress](float f) {
                  progress.report("evening out", f);
                  return true;
                });
            progress.stage("writing");
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            const core::Document& relaxed = result.document;
            const double vertices = double(std::max<std::size_t>(result.vertices, 1));
            std::ostringstream report; // made before the save, which commits last
            if (opt->json) {
              report << app::JsonReply{{"input", opt->input},
                                       {"output", opt->output},
                                       {"size", document.size()},
                                       {"changed", result.changed},
                                       {"reason", result.reason},
                                       {"step", result.step},
                                       {"tries", result.tries},
                                       {"before", toJson(result.before)},
                                       {"after", toJson(result.after)},
                                       {"stretched_share_before",
                                        double(result.stretchedBefore) / vertices},
                                       {"stretched_share_after",
                                        double(result.stretchedAfter) / vertices},
                                       {"rms", result.changed ? result.moved.rms : 0.0},
                                       {"hausdorff", result.changed ? result.moved.hausdorff : 0.0},
                                       {"tried_rms", result.moved.rms},
                                       {"tried_hausdorff", result.moved.hausdorff},
                                       {"report",
                                        surfaceReportJson(
                                            &result.moved,
                                            {.samplesPerSurface =
                                                 core::EvenOutCheckOptions{}.samplesPerSurface})},
                                       {"ms", ms}}
                            .dump()
                     << "\n";
            } else if (!result.changed) {
              report << "left " << opt->input << " unchanged (written to " << opt->output
                     << "): " << result.reason << "\n";
            } else {
              const core::StretchSummary& before = result.before;
              const core::StretchSummary& after = result.after;
              report << std::setprecision(3) << "relaxed " << opt->input << " into " << opt->output
                     << " in " << ms << " ms";
              if (result.step < 1) report << " (" << result.step << " of the full step)";
              report << "\n"
                     << "  longest edge  " << before.longestOverMedian << "x -> "
                     << after.longestOverMedian << "x the median\n"
                     << "  99th pct edge " << before.p99OverMedian << "x -> " << after.p99OverMedian
                     << "x the median\n"
                     << "  over 4x       " << 100 * before.shareOver4x << " % -> "
                     << 100 * after.shareOver4x << " % of samples\n"
                     << "  surface moved RMS " << 100 * result.moved.rms << " %, Hausdorff "
                     << 100 * result.moved.hausdorff << " % of the diagonal\n";
            }
            writeChosenObject(chosen, relaxed, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
