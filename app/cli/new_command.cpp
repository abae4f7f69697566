#include "commands.h"
#include "finite_arguments.h"
#include "json_output.h"
#include "output_rules.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/capsule.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {

Command addNewCommand(CLI::App& app) {
  struct Options {
    std::string shape = "sphere";
    int size = 1024;
    std::string output;
    bool json = false;
    core::Capsule capsule; // --shape capsule's radius and length
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("new", "Create a document from a base shape");
  sub->add_option("--shape", opt->shape,
                  "sphere, cube, cylinder, blob or capsule (radius 0.5, 2 long, along z)")
      ->capture_default_str();
  sub->add_option("--size", opt->size,
                  "N: the image has (N+1)x(N+1) samples; a power of two, 2..8192")
      ->capture_default_str();
  CLI::Option* radiusOption =
      sub->add_option("--radius", opt->capsule.radius, "capsule: its radius, above 0")
          ->check(kFiniteNumber)
          ->capture_default_str();
  CLI::Option* lengthOption =
      sub->add_option("--length", opt->capsule.length,
                      "capsule: the length of its cylinder between the hemispheres' centres, "
                      "0 or more (the capsule spans length + 2 x radius along z)")
          ->check(kFiniteNumber)
          ->capture_default_str();
  sub->add_option("-o,--output", opt->output, "Document to write (.exr)")->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt, radiusOption, lengthOption]() {
            requireOutputExtension(opt->output, {".exr"}, "the document");
            const auto shape = core::parseBaseShape(opt->shape);
            if (!shape)
              throw core::Error(core::ErrorKind::InvalidArgument,
                                "unknown shape '" + opt->shape +
                                    "'; use sphere, cube, cylinder, blob or capsule");
            core::requireValidSize(opt->size);
            if (*shape != core::BaseShape::Capsule &&
                (radiusOption->count() > 0 || lengthOption->count() > 0))
              throw core::Error(core::ErrorKind::InvalidArgument,
                                "--radius and --length shape a capsule; --shape " + opt->shape +
                                    " takes neither");
            const auto start = std::chrono::steady_clock::now();
            const core::Document document = core::makeDocument(
                *shape == core::BaseShape::Capsule ? core::makeCapsule(opt->size, opt->capsule)
                                                   : core::makeBaseShape(*shape, opt->size));
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            std::ostringstream report; // made before the save, which commits last
            if (opt->json) {
              report << app::JsonReply{{"output", opt->output},
                                       {"shape", opt->shape},
                                       {"size", opt->size},
                                       {"vertices",
                                        std::uint64_t(opt->size) * std::uint64_t(opt->size) + 2},
                                       {"ms", ms}}
                            .dump()
                     << "\n";
            } else {
              report << "created " << opt->output << ": " << opt->shape << ", N = " << opt->size
                     << " (" << opt->size + 1 << "x" << opt->size + 1 << " samples) in " << ms
                     << " ms\n";
            }
            core::writeDocument(document, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
