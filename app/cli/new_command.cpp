#include "commands.h"
#include "finite_arguments.h"
#include "json_output.h"
#include "output_rules.h"
#include "shape_arguments.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/capsule.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"

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
    core::Torus torus;     // --shape torus's major and minor radius
    int height = 0;        // --shape torus: cells around the tube (0: from the radii)
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("new", "Create a document from a base shape");
  sub->add_option("--shape", opt->shape,
                  "sphere, cube, cylinder, blob or capsule (radius 0.5, 2 long, along z) "
                  "(octahedral balls); torus (a ring around z); plane or disc (open sheets in "
                  "z = 0)")
      ->capture_default_str();
  sub->add_option("--size", opt->size,
                  "N: the image has (N+1)x(N+1) samples; a power of two, 2..8192 (a torus: N "
                  "samples around the ring, its height around the tube chosen from the radii)")
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
  CLI::Option* majorOption =
      sub->add_option("--major", opt->torus.major, "torus: the radius of its ring, above --minor")
          ->check(kFiniteNumber)
          ->capture_default_str();
  CLI::Option* minorOption =
      sub->add_option("--minor", opt->torus.minor, "torus: the radius of its tube, above 0")
          ->check(kFiniteNumber)
          ->capture_default_str();
  CLI::Option* heightOption = sub->add_option(
      "--height", opt->height,
      "torus: cells around the tube, a power of two from 4 to 8192 (default: chosen from the "
      "radii so cells are about square; give --height equal to --size for a square image)");
  sub->add_option("-o,--output", opt->output, "Document to write (.exr)")->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt, radiusOption, lengthOption, majorOption, minorOption, heightOption]() {
            requireOutputExtension(opt->output, {".exr"}, "the document");
            checkShapeArguments(opt->shape, radiusOption->count() > 0 || lengthOption->count() > 0);
            const bool torus = opt->shape == "torus";
            core::requireValidSize(opt->size);
            if (!torus &&
                (majorOption->count() > 0 || minorOption->count() > 0 || heightOption->count() > 0))
              throw core::Error(core::ErrorKind::InvalidArgument,
                                "--major, --minor and --height shape a torus; --shape " +
                                    opt->shape + " takes none of them");
            const auto start = std::chrono::steady_clock::now();
            const core::Document document =
                core::makeDocument(makeShapeImage(opt->shape, opt->size, opt->capsule, opt->torus,
                                                  heightOption->count() > 0 ? opt->height : 0));
            const core::GeometryImage& image = document.positions;
            const std::string topology(core::topologyName(image.topology()));
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            std::ostringstream report; // made before the save, which commits last
            if (opt->json) {
              report << app::JsonReply{{"output", opt->output},
                                       {"shape", opt->shape},
                                       {"size", opt->size},
                                       {"topology", topology},
                                       {"width", image.width()},
                                       {"height", image.height()},
                                       {"vertices",
                                        std::uint64_t(core::vertexCount(
                                            image.topology(), image.width(), image.height()))},
                                       {"ms", ms}}
                            .dump()
                     << "\n";
            } else {
              report << "created " << opt->output << ": " << opt->shape;
              if (image.topology() == core::Topology::Octahedral)
                report << ", N = " << opt->size;
              else
                report << (opt->shape == topology ? "" : " (" + topology + ")") << ", "
                       << image.width() << "x" << image.height() << " cells";
              report << " (" << image.side() << "x" << image.rows() << " samples) in " << ms
                     << " ms\n";
            }
            core::writeDocument(document, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
