#pragma once

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/document/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace octaclay::core {

/// An object as its part's header describes it, read without its pixels (`objects`).
struct SceneObjectHeader {
  std::string name;
  Topology topology = Topology::Octahedral;
  int width = 0, height = 0; ///< the image's samples across and down
  ObjectTransform transform;
  bool visible = true;
  bool locked = false;
  DocumentHeader document; ///< format version, N, channels
};

/// The headers of every object of the document at path, in order. A single-part file (every
/// document written before scenes, and every one-object scene) is one object: named by its
/// octaclay.name attribute, else by the file's stem when that is a valid object name, else
/// "Model", at the identity transform, visible and unlocked unless its header says otherwise.
/// A multi-part file is one object per part. Throws what readDocumentHeader throws, and
/// Error(InvalidInput) naming the part and the problem for: more than kMaxSceneObjects parts, a
/// part whose header lies (its octaclay.width or octaclay.height against its data window, an
/// unknown topology, a transform that transformProblem refuses, a visibility or lock other than
/// 0 or 1, a bad or repeated name) and parts that disagree (format versions). Every header is
/// checked before any pixel memory is taken: the headers are scanned, bounded, before OpenEXR
/// reads them (exr_part_scan).
std::vector<SceneObjectHeader> readSceneHeaders(const std::filesystem::path& path);

/// Reads every object (positions bit-exact, transforms bit-exact). Same errors as
/// readSceneHeaders, plus what readDocument throws for a part's pixels.
Scene readScene(const std::filesystem::path& path, const DocumentReadOptions& options = {});

/// Writes the scene atomically (writeFileAtomically, DESIGN.md's output rule). One object: a
/// single-part file, the document as writeDocument writes it plus the object's attributes
/// (octaclay.name, octaclay.width, octaclay.height, octaclay.translation, octaclay.rotation,
/// octaclay.scale, octaclay.visible, octaclay.locked), so every reader of single-part
/// documents opens it. Several: an OpenEXR multi-part file, one part per object in order, each
/// part's channels and attributes as the single-part file's, its part name the object's name.
/// Throws Error(InvalidArgument) for a scene sceneProblem refuses (nothing written), Error(Io).
void writeScene(const Scene& scene, const std::filesystem::path& path,
                const DocumentWriteOptions& options = {});

} // namespace octaclay::core
