#include "octaclay/core/import/import.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/import/octahedral_resampling.h"

#include <optional>
#include <utility>

namespace octaclay::core {

Document importValidatedMesh(const ValidatedMesh& mesh, const SphericalMap& map, int n,
                             ImportedDiffuse* diffuse) {
  ImportedDiffuse what;
  what.notes = mesh.notes;
  std::optional<RasterImage> texture;
  if (!mesh.diffuseTexture.empty() && !mesh.cornerUv.empty()) {
    try {
      texture = readImage(mesh.diffuseTexture, 4);
    } catch (const Error& e) {
      what.notes.push_back("texture " + mesh.diffuseTexture.filename().string() +
                           " could not be read (" + e.what() + "): no texture");
    }
  }
  Document document;
  if (texture) {
    document = importToDocument(mesh.mesh, map, n, mesh.cornerUv, *texture);
    what.source = DiffuseSource::Texture;
    what.texture = mesh.diffuseTexture;
    if (!mesh.vertexColours.empty())
      what.notes.push_back("vertex colours ignored: the texture is used instead");
  } else if (!mesh.vertexColours.empty()) {
    document = importToDocument(mesh.mesh, map, n, mesh.vertexColours);
    what.source = DiffuseSource::VertexColours;
  } else {
    document = importToDocument(mesh.mesh, map, n);
  }
  // Resampling can overflow where the mesh did not; such a document could never be read again.
  if (const auto problem = positionsProblem(document.positions))
    throw Error(ErrorKind::InvalidInput, "the imported surface cannot be stored: " + *problem);
  if (diffuse) *diffuse = std::move(what);
  return document;
}

ImportQuality measureImport(const TriangleMesh& mesh, const SphericalMap& map,
                            const GeometryImage& image, const SurfaceDistanceOptions& options) {
  ImportQuality quality;
  quality.flipped = map.flipped;
  quality.stretchL2 = map.stretchL2;
  quality.stretchLinf = map.stretchLinf;
  quality.distance = compareSurfaces(mesh, extractMesh(image), options);
  return quality;
}

} // namespace octaclay::core
