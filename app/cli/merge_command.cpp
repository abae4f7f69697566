#include "commands.h"
#include "json_output.h"
#include "output_rules.h"
#include "progress_line.h"

#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/merge/merge.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

namespace octaclay::app {

namespace {

[[noreturn]] void badArgument(const std::string& message) {
  throw core::Error(core::ErrorKind::InvalidArgument, message);
}

std::vector<std::string> splitNames(const std::string& text) {
  std::vector<std::string> names;
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ','))
    names.push_back(name);
  if (!text.empty() && text.back() == ',') names.emplace_back();
  return names;
}

// The object's transform as the merge's affine placement: world = L · p + t, the same matrix
// worldPositions applies.
core::PartTransform placement(const core::ObjectTransform& t) {
  const auto l = core::linearPart(t);
  core::PartTransform result;
  result.m = {l[0], l[1], l[2], t.translation.x, l[3], l[4], l[5], t.translation.y,
              l[6], l[7], l[8], t.translation.z, 0,    0,    0,    1};
  return result;
}

} // namespace

Command addMergeCommand(CLI::App& app) {
  struct Options {
    std::string input, output, objects, name;
    int size = 0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "merge", "Merge objects into one closed octahedral object: a voxel union of their placed "
               "surfaces, parameterized again, every layer carried from the object it came from");
  sub->add_option("document", opt->input, "Octaclay document (.exr)")->required();
  sub->add_option("--objects", opt->objects, "A,B,...: two or more objects to merge, by name")
      ->required();
  sub->add_option("--name", opt->name, "The merged object's name (default: the first listed)");
  sub->add_option("--size", opt->size,
                  "N of the merged object (default: the largest N of the objects merged)");
  sub->add_option("-o,--output", opt->output, "Document to write (.exr; may be the input)")
      ->required();
  sub->add_flag("--json", opt->json, "Print one JSON object");

  return {sub, [opt]() {
            requireOutputExtension(opt->output, {".exr"}, "the document");
            const std::vector<std::string> names = splitNames(opt->objects);
            if (names.size() < 2)
              badArgument("--objects names " + std::to_string(names.size()) +
                          " object; a merge takes two or more (A,B,...)");
            std::set<std::string> unique;
            for (const std::string& name : names) {
              if (name.empty()) badArgument("--objects '" + opt->objects + "' has an empty name");
              if (!unique.insert(name).second) badArgument("--objects names '" + name + "' twice");
            }
            if (opt->size != 0) core::requireValidSize(opt->size);
            if (!opt->name.empty())
              if (const auto problem = core::objectNameProblem(opt->name))
                badArgument("--name: " + *problem);

            ProgressLine progress("merge", !opt->json);
            progress.stage("reading");
            // Every name checked against the headers before any pixel is read.
            {
              core::Scene listed;
              for (const auto& header : core::readSceneHeaders(opt->input))
                listed.objects.push_back({header.name, {}, {}, true, false});
              for (const std::string& name : names)
                (void)listed.require(name);
            }
            core::Scene scene = core::readScene(opt->input);
            std::vector<core::MergePart> parts;
            int n = opt->size;
            for (const std::string& name : names) {
              const core::SceneObject& object = scene.require(name);
              if (object.locked)
                badArgument("cannot merge object '" + name +
                            "': it is locked (unlock it in the modeller's Objects list)");
              parts.push_back({&object.document, placement(object.transform), name});
              if (opt->size == 0) n = std::max(n, object.document.size());
            }
            const std::string mergedName = opt->name.empty() ? names.front() : opt->name;
            if (const core::SceneObject* other = scene.find(mergedName);
                other && !unique.count(mergedName))
              badArgument("--name: " + opt->input + " already has an object named '" + mergedName +
                          "' (names are unique)");

            progress.stage("merging");
            core::MergeOptions options;
            options.size = n;
            const auto start = std::chrono::steady_clock::now();
            core::MergeResult result = core::mergeParts(parts, options, [&](float done) {
              progress.report("merging", done);
              return true;
            });
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();

            // The merged object takes the first listed object's place; the others go.
            std::erase_if(scene.objects, [&](const core::SceneObject& o) {
              return o.name != names.front() && unique.count(o.name) > 0;
            });
            core::SceneObject& target = scene.require(names.front());
            target = core::SceneObject{
                mergedName, std::move(result.document), {}, target.visible, false};
            std::ostringstream report;
            if (opt->json)
              report << JsonReply{{"output", opt->output},
                                  {"merged", names},
                                  {"name", mergedName},
                                  {"size", n},
                                  {"voxel_size", result.voxelSize},
                                  {"level_set_vertices", result.levelSetVertices},
                                  {"objects", scene.objects.size()},
                                  {"ms", ms}}
                            .dump()
                     << "\n";
            else
              report << "merged " << opt->objects << " into " << mergedName << " (N = " << n
                     << ", voxel " << result.voxelSize << ") in " << ms << " ms; wrote "
                     << opt->output << ": " << scene.objects.size()
                     << (scene.objects.size() == 1 ? " object\n" : " objects\n");
            progress.stage("writing");
            core::writeScene(scene, opt->output);
            std::cout << report.str();
            return kExitOk;
          }};
}

} // namespace octaclay::app
