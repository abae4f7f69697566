#pragma once

// A scene's visible objects exported together: what `octaclay-cli export` writes for a document
// of several objects when no --object picks one.

#include "octaclay/core/document/scene.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <filesystem>

namespace octaclay::core {

class OutputSet;

/// The object's full-resolution closed mesh (extractMesh) in world space, still facing outward:
/// a transform that mirrors (an odd number of negative scales) has its triangles' winding
/// turned back.
TriangleMesh worldMesh(const SceneObject& object);

/// Writes the scene's visible objects, in order, by path's extension:
/// - `.glb`: one node per object, named by it, with its transform as the node's translation,
///   rotation (quaternion) and scale, its mesh in object space at full resolution (as writeGlb
///   writes one document: POSITION, NORMAL, TEXCOORD_0) and its own material named by it (the
///   diffuse layer as baseColorTexture, metallicRoughnessTexture as writeGlb's);
/// - `.obj`: one `o NAME` per object: its worldMesh (welded, closed), `v` and `f` only;
/// - `.ply`, `.stl`, `.off`: every object's worldMesh in one mesh (world space).
/// Written atomically (one file). Throws Error(InvalidArgument) for another extension or a scene
/// with no visible object, Error(Io) when it cannot be written.
void writeSceneMeshes(const Scene& scene, const std::filesystem::path& path);
void stageSceneMeshes(const Scene& scene, const std::filesystem::path& path, OutputSet& set);

} // namespace octaclay::core
