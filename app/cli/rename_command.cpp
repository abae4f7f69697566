#include "commands.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"

#include "octaclay/core/error.h"

#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {

Command addRenameCommand(CLI::App& app) {
  struct Options {
    std::string input, output, object, to;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("rename", "Give an object of a document another name");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object)->required();
  sub->add_option("--to", opt->to, "The new name (unique in the document)")->required();
  sub->add_option("-o,--output", opt->output, "Document to write (.exr; may be the input)")
      ->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            requireOutputExtension(opt->output, {".exr"}, "the document");
            if (const auto problem = core::objectNameProblem(opt->to))
              throw core::Error(core::ErrorKind::InvalidArgument, "--to: " + *problem);
            ChosenObject chosen = readChosenObject(opt->input, opt->object);
            const core::SceneObject* other = chosen.scene.find(opt->to);
            if (other && other != &chosen.object())
              throw core::Error(core::ErrorKind::InvalidArgument,
                                "--to: " + opt->input + " already has an object named '" + opt->to +
                                    "' (names are unique)");
            const std::string before = chosen.object().name;
            chosen.object().name = opt->to;
            std::ostringstream report;
            if (opt->json)
              report << JsonReply{{"output", opt->output}, {"from", before}, {"to", opt->to}}.dump()
                     << "\n";
            else
              report << "renamed " << before << " to " << opt->to << "; wrote " << opt->output
                     << "\n";
            core::writeScene(chosen.scene, opt->output); // the name is kept, even for one object
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
