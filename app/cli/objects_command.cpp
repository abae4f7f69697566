#include "commands.h"
#include "json_output.h"

#include "octaclay/core/document/scene_io.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace octaclay::app {

namespace {

std::string triple(core::Vec3f v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
  return text;
}

} // namespace

Command addObjectsCommand(CLI::App& app) {
  struct Options {
    std::string input;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "objects", "List a document's objects: name, topology, size, transform, visible, locked");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            // Headers only: listing a scene reads no pixels.
            const auto objects = core::readSceneHeaders(opt->input);
            if (opt->json) {
              nlohmann::json list = nlohmann::json::array();
              for (const auto& o : objects)
                list.push_back({{"name", o.name},
                                {"topology", std::string(core::topologyName(o.topology))},
                                {"size", o.document.size},
                                {"width", o.width},
                                {"height", o.height},
                                {"translation", toJson(o.transform.translation)},
                                {"rotation", toJson(o.transform.rotationDegrees)},
                                {"scale", toJson(o.transform.scale)},
                                {"visible", o.visible},
                                {"locked", o.locked}});
              std::cout << JsonReply{{"document", opt->input}, {"objects", list}}.dump() << "\n";
              return kExitOk;
            }
            std::cout << opt->input << ": " << objects.size()
                      << (objects.size() == 1 ? " object\n" : " objects\n");
            for (const auto& o : objects)
              std::cout << "  " << o.name << "  " << core::topologyName(o.topology)
                        << ", N = " << o.document.size << " (" << o.width << "x" << o.height
                        << " samples), at " << triple(o.transform.translation) << ", rotated "
                        << triple(o.transform.rotationDegrees) << " degrees, scaled "
                        << triple(o.transform.scale) << (o.visible ? "" : ", hidden")
                        << (o.locked ? ", locked" : "") << "\n";
            return kExitOk;
          }};
}

} // namespace octaclay::app
