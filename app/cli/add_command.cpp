#include "commands.h"
#include "finite_arguments.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"
#include "shape_arguments.h"
#include "transform_arguments.h"

#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/capsule.h"

#include <cctype>
#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {

Command addAddCommand(CLI::App& app) {
  struct Options {
    std::string input, output, shape, name;
    int size = 0;
    core::Capsule capsule;
    TransformArguments transform;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("add", "Add an object made from a base shape to a document");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  sub->add_option("--shape", opt->shape,
                  "sphere, cube, cylinder, blob, capsule, torus, plane or disc (as `new` makes "
                  "them)")
      ->required();
  sub->add_option("--name", opt->name,
                  "The new object's name (default: the shape's, made unique: Sphere.001)");
  sub->add_option("--size", opt->size,
                  "N of the new object's image (default: the document's first object's)");
  CLI::Option* radiusOption =
      sub->add_option("--radius", opt->capsule.radius, "capsule: its radius, above 0")
          ->check(kFiniteNumber);
  CLI::Option* lengthOption =
      sub->add_option("--length", opt->capsule.length,
                      "capsule: the length of its cylinder between the hemispheres' centres")
          ->check(kFiniteNumber);
  addTransformOptions(*sub, opt->transform);
  sub->add_option("-o,--output", opt->output, "Document to write (.exr; may be the input)")
      ->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {
      sub, [opt, radiusOption, lengthOption]() {
        requireOutputExtension(opt->output, {".exr"}, "the document");
        checkShapeArguments(opt->shape, radiusOption->count() > 0 || lengthOption->count() > 0);
        if (opt->size != 0) core::requireValidSize(opt->size);
        const core::ObjectTransform transform = appliedTransform({}, opt->transform);
        if (!opt->name.empty())
          if (const auto problem = core::objectNameProblem(opt->name))
            throw core::Error(core::ErrorKind::InvalidArgument, "--name: " + *problem);

        core::Scene scene = core::readScene(opt->input);
        if (scene.objects.size() >= core::kMaxSceneObjects)
          throw core::Error(core::ErrorKind::InvalidArgument,
                            opt->input + " already holds " + std::to_string(scene.objects.size()) +
                                " objects, the most a document holds");
        std::string name = opt->name;
        if (name.empty()) {
          name = opt->shape;
          name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
          name = scene.uniqueName(name);
        } else if (scene.find(name)) {
          throw core::Error(core::ErrorKind::InvalidArgument,
                            "--name: " + opt->input + " already has an object named '" + name +
                                "' (names are unique; leave --name out for " +
                                scene.uniqueName(name) + ")");
        }
        const int n = opt->size != 0 ? opt->size : scene.objects.front().document.size();
        core::Document document = core::makeDocument(makeShapeImage(opt->shape, n, opt->capsule));
        scene.objects.push_back({name, std::move(document), transform, true, false});

        std::ostringstream report; // made before the save, which commits last
        if (opt->json)
          report << JsonReply{{"output", opt->output},
                              {"name", name},
                              {"shape", opt->shape},
                              {"size", n},
                              {"objects", scene.objects.size()}}
                        .dump()
                 << "\n";
        else
          report << "added " << name << " (" << opt->shape << ", N = " << n << ") to "
                 << opt->output << ": " << scene.objects.size() << " objects\n";
        core::writeScene(scene, opt->output);
        std::cout << report.str();
        return kExitOk;
      }};
}

} // namespace octaclay::app
