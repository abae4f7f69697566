#include "object_choice.h"

#include "octaclay/core/error.h"

#include <filesystem>

namespace octaclay::app {

namespace {

std::string listOfNames(const core::Scene& scene) {
  std::string list;
  for (const core::SceneObject& object : scene.objects)
    list += (list.empty() ? "" : ", ") + object.name;
  return list;
}

} // namespace

bool isPlainDocument(const core::Scene& scene, const std::string& path) {
  if (scene.objects.size() != 1) return false;
  const core::SceneObject& object = scene.objects.front();
  const std::string stem = std::filesystem::path(path).stem().string();
  const std::string plainName = core::objectNameProblem(stem) ? "Model" : stem;
  return object.name == plainName && object.transform == core::ObjectTransform{} &&
         object.visible && !object.locked;
}

CLI::Option* addObjectOption(CLI::App& sub, std::string& name) {
  return sub.add_option("--object", name,
                        "The object to work on, by name (see `octaclay-cli objects`); may be "
                        "left out when the document holds one object");
}

ChosenObject readChosenObject(const std::string& path, const std::string& name,
                              const core::DocumentReadOptions& options) {
  // The names first, from the headers: a wrong name costs no pixel reading.
  const auto headers = core::readSceneHeaders(path);
  core::Scene names;
  for (const auto& header : headers)
    names.objects.push_back({header.name, {}, {}, true, false});
  if (name.empty() && headers.size() > 1)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      path + " holds " + std::to_string(headers.size()) + " objects (" +
                          listOfNames(names) + "): name the one to work on with --object NAME");
  std::size_t index = 0;
  if (!name.empty()) index = static_cast<std::size_t>(&names.require(name) - names.objects.data());
  ChosenObject chosen{core::readScene(path, options), index, path};
  return chosen;
}

void requireUnlocked(const ChosenObject& chosen, const std::string& what) {
  if (chosen.object().locked)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "cannot " + what + " object '" + chosen.object().name +
                          "': it is locked (unlock it in the modeller's Objects list)");
}

void writeChosenObject(ChosenObject& chosen, core::Document result, const std::string& path) {
  chosen.object().document = std::move(result);
  writeSceneOrDocument(chosen.scene, chosen.source, path);
}

void writeSceneOrDocument(const core::Scene& scene, const std::string& source,
                          const std::string& path) {
  if (isPlainDocument(scene, source))
    core::writeDocument(scene.objects.front().document, path);
  else
    core::writeScene(scene, path);
}

} // namespace octaclay::app
