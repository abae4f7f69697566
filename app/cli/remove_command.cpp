#include "commands.h"
#include "json_output.h"
#include "object_choice.h"
#include "output_rules.h"

#include "octaclay/core/error.h"

#include <iostream>
#include <memory>
#include <sstream>

namespace octaclay::app {

Command addRemoveCommand(CLI::App& app) {
  struct Options {
    std::string input, output, object;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("remove", "Remove an object from a document");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  addObjectOption(*sub, opt->object)->required();
  sub->add_option("-o,--output", opt->output, "Document to write (.exr; may be the input)")
      ->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            requireOutputExtension(opt->output, {".exr"}, "the document");
            ChosenObject chosen = readChosenObject(opt->input, opt->object);
            if (chosen.scene.objects.size() == 1)
              throw core::Error(core::ErrorKind::InvalidArgument,
                                "cannot remove '" + chosen.object().name +
                                    "': it is the document's only object (a document holds at "
                                    "least one)");
            requireUnlocked(chosen, "remove");
            const std::string name = chosen.object().name;
            chosen.scene.objects.erase(chosen.scene.objects.begin() +
                                       static_cast<std::ptrdiff_t>(chosen.index));
            std::ostringstream report;
            if (opt->json)
              report << JsonReply{{"output", opt->output},
                                  {"removed", name},
                                  {"objects", chosen.scene.objects.size()}}
                            .dump()
                     << "\n";
            else
              report << "removed " << name << "; wrote " << opt->output << ": "
                     << chosen.scene.objects.size()
                     << (chosen.scene.objects.size() == 1 ? " object\n" : " objects\n");
            writeSceneOrDocument(chosen.scene, chosen.source, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
