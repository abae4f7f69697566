#include "commands.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"
#include "transform_arguments.h"

#include "octaclay/core/error.h"

#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {

Command addTransformCommand(CLI::App& app) {
  struct Options {
    std::string input, output, object;
    TransformArguments transform;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "transform", "Place an object: set its translation, rotation and scale (those given)");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  addTransformOptions(*sub, opt->transform);
  sub->add_option("-o,--output", opt->output, "Document to write (.exr; may be the input)")
      ->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            requireOutputExtension(opt->output, {".exr"}, "the document");
            if (opt->transform.translate.empty() && opt->transform.rotate.empty() &&
                opt->transform.scale.empty())
              throw core::Error(core::ErrorKind::InvalidArgument,
                                "transform changes nothing without --translate, --rotate or "
                                "--scale");
            // Checked before the pixels are read.
            const core::ObjectTransform check = appliedTransform({}, opt->transform);
            (void)check;
            ChosenObject chosen = readChosenObject(opt->input, opt->object);
            requireUnlocked(chosen, "move");
            core::SceneObject& object = chosen.object();
            object.transform = appliedTransform(object.transform, opt->transform);
            const core::ObjectTransform& t = object.transform;
            std::ostringstream report;
            if (opt->json)
              report << JsonReply{{"output", opt->output},
                                  {"object", object.name},
                                  {"translation", toJson(t.translation)},
                                  {"rotation", toJson(t.rotationDegrees)},
                                  {"scale", toJson(t.scale)}}
                            .dump()
                     << "\n";
            else
              report << "placed " << object.name << " at (" << t.translation.x << ", "
                     << t.translation.y << ", " << t.translation.z << "), rotated ("
                     << t.rotationDegrees.x << ", " << t.rotationDegrees.y << ", "
                     << t.rotationDegrees.z << ") degrees, scaled (" << t.scale.x << ", "
                     << t.scale.y << ", " << t.scale.z << "); wrote " << opt->output << "\n";
            writeSceneOrDocument(chosen.scene, chosen.source, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
