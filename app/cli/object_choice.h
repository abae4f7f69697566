#pragma once

// The object a single-object command (stroke, relax, info, lod, export, compress) works on:
// `--object NAME`, or the document's only object. The document is read as a scene and the
// result put back into it, so the other objects of a multi-object document are written back
// as they were.

#include "octaclay/core/document/scene_io.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>

namespace octaclay::app {

/// Adds `--object NAME` to sub, storing into name.
CLI::Option* addObjectOption(CLI::App& sub, std::string& name);

struct ChosenObject {
  core::Scene scene;
  std::size_t index = 0;
  std::string source; ///< the file it was read from
  core::SceneObject& object() { return scene.objects[index]; }
  const core::SceneObject& object() const { return scene.objects[index]; }
};

/// Reads the document at path and picks the object named name, or, when name is empty, its only
/// object. Throws core::Error(InvalidArgument) (exit 2) for an unknown name (naming every
/// object) and for a multi-object document without --object (naming them, asking for
/// --object); the reader's errors otherwise.
ChosenObject readChosenObject(const std::string& path, const std::string& name,
                              const core::DocumentReadOptions& options = {});

/// Throws core::Error(InvalidArgument) when the chosen object is locked: what edits it asks the
/// user to unlock it first.
void requireUnlocked(const ChosenObject& chosen, const std::string& what);

/// Writes chosen's scene to path with the chosen object's document replaced by result (through
/// writeSceneOrDocument, chosen.source the file it came from).
void writeChosenObject(ChosenObject& chosen, core::Document result, const std::string& path);

/// Whether scene is what a plain document at path reads as: one object named by path's stem (or
/// "Model"), at the identity, visible, unlocked.
bool isPlainDocument(const core::Scene& scene, const std::string& path);

/// Writes scene to path. A plain document (one object as source, a file without scene
/// attributes, reads: named by source's stem or "Model", at the identity, visible, unlocked) is
/// written as writeDocument writes it, byte for byte as before scenes; anything else through
/// writeScene.
void writeSceneOrDocument(const core::Scene& scene, const std::string& source,
                          const std::string& path);

} // namespace octaclay::app
