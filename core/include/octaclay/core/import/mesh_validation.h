#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace octaclay::core {

/// What validation changed to make a mesh usable; every count is zero for a clean file.
struct MeshCleanup {
  std::size_t unusedVerticesRemoved = 0;   ///< referenced by no face (after the removals below)
  std::size_t duplicateVerticesWelded = 0; ///< STL corners at exactly the same position merged
  std::size_t degenerateFacesRemoved = 0;  ///< a corner repeated, or fewer than three corners
  std::size_t duplicateFacesRemoved = 0;   ///< the same three vertices as an earlier face
  std::size_t zeroAreaFacesKept = 0;       ///< three distinct collinear corners: removing one would
                                           ///< open a hole, so they stay (the parameterizer copes)
  std::size_t facesFlipped = 0;            ///< turned to agree with their neighbours
  std::size_t holesFilled = 0;  ///< closed with a fan (only with ValidationOptions::fillHoles)
  bool windingReversed = false; ///< every face turned so that the enclosed volume is positive
};

/// Texture coordinates (u, v) of a triangle's three corners, v pointing up the image (OBJ).
using CornerUv = std::array<std::array<float, 2>, 3>;

/// A mesh ready for spherical parameterization: closed, edge- and vertex-manifold, one
/// component, genus 0, consistently oriented with positive signed volume, no unused vertices,
/// no faces with a repeated corner. The attributes follow the cleanup: colours are renumbered
/// with the vertices, corner coordinates stay with their corners when faces are turned or
/// dropped (a hole-filling face takes its corners' coordinates from their other faces).
struct ValidatedMesh {
  TriangleMesh mesh;
  MeshCleanup cleanup;
  /// One RGBA colour in [0, 1] per vertex of `mesh` when the file has vertex colours (PLY
  /// red/green/blue[/alpha], OBJ `v x y z r g b`); otherwise empty.
  std::vector<Vec4f> vertexColours;
  /// One entry per triangle of `mesh` when every OBJ face has texture coordinates; else empty.
  std::vector<CornerUv> cornerUv;
  /// The OBJ's diffuse texture (the first map_Kd of its material libraries, resolved against
  /// the .mtl's folder) when the file exists and cornerUv is not empty; otherwise empty.
  std::filesystem::path diffuseTexture;
  /// Attributes that were named but could not be used (a missing .mtl or texture, colours on
  /// only some vertices), one sentence each, no path prefix.
  std::vector<std::string> notes;
};

struct ValidationOptions {
  /// Close holes of at most maxHoleEdges boundary edges with a fan around a new centroid vertex
  /// (a single triangle for a three-edge hole). Larger holes are still refused.
  bool fillHoles = false;
  int maxHoleEdges = 64;
};

/// Reads an OBJ, PLY, STL or OFF file (any of their ASCII or binary variants) with strict,
/// bounds-checked readers of its own (OpenMesh's would silently repair the very faults this
/// reports), then cleans it: removes unused vertices, welds STL corners by exact position, drops
/// faces with a repeated corner and repeated faces, orients faces consistently and outward by
/// signed volume, optionally fills small holes. Anything else is refused. Vertex colours, texture
/// coordinates and the diffuse texture are kept (ValidatedMesh); a missing .mtl or texture only
/// adds a note.
/// Vertex numbers in messages count from 1 in file order.
/// Throws Error(Io) when the file cannot be opened or read; Error(InvalidArgument) for an
/// extension other than .obj, .ply, .stl, .off; Error(InvalidInput), starting with the path and
/// saying what is wrong and what to do, for: an empty or truncated file, a malformed line, no
/// faces, NaN or infinite coordinates, out-of-range indices, edges shared by more than two faces,
/// a non-orientable surface, holes ("open: 5 holes, 223 boundary edges — …"), pinch vertices,
/// several components, genus above 0, or zero enclosed volume.
/// Runs in O(F log F) time and O(F) memory for F faces.
ValidatedMesh loadGenus0Mesh(const std::filesystem::path& path,
                             const ValidationOptions& options = {});

/// loadGenus0Mesh for a file of one or more separate closed genus-0 parts (the parts of a
/// scene exported as one mesh): parts are the triangles joined through shared vertices (STL's
/// corners welded by exact position first), in the order of their first triangle, each cleaned
/// and checked as loadGenus0Mesh checks one mesh. One part: exactly loadGenus0Mesh's result
/// (attributes kept); several: the parts' geometry, with a note that colours and texture
/// coordinates are not carried. When a part is no closed genus-0 mesh by itself, throws what
/// loadGenus0Mesh throws for the whole file (its words for pieces that need welding or
/// joining); Error(InvalidInput) for more than maxParts parts.
std::vector<ValidatedMesh> loadGenus0Parts(const std::filesystem::path& path,
                                           const ValidationOptions& options, std::size_t maxParts);
/// The same cleaning and checks on an in-memory mesh (any winding, unused vertices allowed);
/// vertices are not welded. Messages have no path prefix and count vertices and triangles from 1.
/// Throws Error(InvalidInput) as loadGenus0Mesh does.
ValidatedMesh validateGenus0Mesh(TriangleMesh mesh, const ValidationOptions& options = {});

} // namespace octaclay::core
