// octaclay-cli resize (issue 30): a document at another N with the same parameterization, every
// layer resampled (up: Catmull-Rom, seams exact; down: filtered).

#include "commands.h"
#include "json_output.h"
#include "object_choice.h"
#include "resample_arguments.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/document/resize.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/measure/surface_distance.h"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {

Command addResizeCommand(CLI::App& app) {
  struct Options {
    std::string input, output, object;
    int size = 0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "resize", "Resample a document to another resolution N (a power of two, 2 to 8192) with "
                "the same parameterization: up smoothly, seams kept exact; down filtered, so "
                "that a later resize up comes back close. Every layer is resampled. The result is "
                "checked: when the surface would move more than 0.05 % (RMS) or 1 % "
                "(Hausdorff) of the diagonal ((N/M)² as much at a coarser N), the document is "
                "written unchanged and the reason said (exit 0; --json: \"changed\": false, "
                "\"reason\")");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  sub->add_option("--size", opt->size, "The new N: a power of two from 2 to 8192")->required();
  sub->add_option("-o,--output", opt->output, "Document to write (.exr, not the input)")
      ->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            requireDocumentSize(opt->size);
            requireNewDocumentOutput(opt->input, opt->output);
            ChosenObject chosen = readChosenObject(opt->input, opt->object);
            requireUnlocked(chosen, "resize");
            const core::Document document = std::move(chosen.object().document);
            const auto start = std::chrono::steady_clock::now();
            const core::ResizeResult r = core::resizeAndCheck(document, {.size = opt->size});
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            std::ostringstream report; // made before the save, which commits last
            if (opt->json)
              report << JsonReply{{"input", opt->input},
                                  {"output", opt->output},
                                  {"size_before", document.size()},
                                  {"size", r.document.size()},
                                  {"changed", r.changed},
                                  {"reason", r.reason},
                                  {"rms", r.moved.rms},
                                  {"hausdorff", r.moved.hausdorff},
                                  {"height_before", document.positions.height()},
                                  {"height", r.document.positions.height()},
                                  {"topology", core::topologyName(document.topology)},
                                  {"before", toJson(r.before)},
                                  {"after", toJson(r.after)},
                                  {"ms", ms}}
                            .dump()
                     << "\n";
            else {
              report << std::setprecision(3);
              if (r.changed || r.reason.empty())
                report << "resized " << opt->input << " from N = " << document.size()
                       << " to N = " << r.document.size() << " into " << opt->output << " in " << ms
                       << " ms\n";
              else
                report << "left " << opt->input << " unchanged at N = " << document.size()
                       << " (written to " << opt->output << "): " << r.reason << "\n";
              report << "  surface moved RMS " << 100 * r.moved.rms << " %, Hausdorff "
                     << 100 * r.moved.hausdorff << " % of the diagonal\n";
            }
            writeChosenObject(chosen, r.document, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
