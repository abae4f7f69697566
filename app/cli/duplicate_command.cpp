#include "commands.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"
#include "transform_arguments.h"

#include "octaclay/core/document/document_mirror.h"
#include "octaclay/core/error.h"

#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {

Command addDuplicateCommand(CLI::App& app) {
  struct Options {
    std::string input, output, object, name, mirror;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "duplicate", "Copy an object, in place or mirrored across the scene's X, Y or Z plane");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object);
  sub->add_option("--name", opt->name,
                  "The copy's name (default: the object's, made unique: "
                  "Leg.001)");
  sub->add_option("--mirror", opt->mirror,
                  "x, y or z: the copy is the object mirrored across the scene's plane through "
                  "the origin normal to that axis (a pair of legs, ears or eyes), still facing "
                  "outward");
  sub->add_option("-o,--output", opt->output, "Document to write (.exr; may be the input)")
      ->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            requireOutputExtension(opt->output, {".exr"}, "the document");
            const int axis = opt->mirror.empty() ? -1 : parseAxis(opt->mirror, "--mirror");
            if (!opt->name.empty())
              if (const auto problem = core::objectNameProblem(opt->name))
                throw core::Error(core::ErrorKind::InvalidArgument, "--name: " + *problem);
            ChosenObject chosen = readChosenObject(opt->input, opt->object);
            core::Scene& scene = chosen.scene;
            if (scene.objects.size() >= core::kMaxSceneObjects)
              throw core::Error(core::ErrorKind::InvalidArgument,
                                opt->input + " already holds the most objects a document holds (" +
                                    std::to_string(core::kMaxSceneObjects) + ")");
            const core::SceneObject& source = chosen.object();
            std::string name = opt->name.empty() ? scene.uniqueName(source.name) : opt->name;
            if (scene.find(name))
              throw core::Error(core::ErrorKind::InvalidArgument,
                                "--name: " + opt->input + " already has an object named '" + name +
                                    "' (names are unique)");
            core::SceneObject copy{
                name, axis < 0 ? source.document : core::mirrorDocument(source.document, axis),
                axis < 0 ? source.transform : core::mirroredTransform(source.transform, axis),
                source.visible, false};
            const std::string from = source.name;
            scene.objects.insert(scene.objects.begin() + static_cast<std::ptrdiff_t>(chosen.index) +
                                     1,
                                 std::move(copy));
            std::ostringstream report;
            if (opt->json)
              report << JsonReply{{"output", opt->output},
                                  {"from", from},
                                  {"name", name},
                                  {"mirror", opt->mirror.empty() ? nlohmann::json(nullptr)
                                                                 : nlohmann::json(opt->mirror)},
                                  {"objects", scene.objects.size()}}
                            .dump()
                     << "\n";
            else
              report << (axis < 0 ? "duplicated " : "mirrored ") << from << " as " << name
                     << (axis < 0 ? "" : " across the scene's " + opt->mirror + " plane")
                     << "; wrote " << opt->output << ": " << scene.objects.size() << " objects\n";
            core::writeScene(scene, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
