// The import pipeline's entry point: a validated mesh (validateMesh) and its spherical map
// (parameterizeSphere) become a document, with the best diffuse attribute the mesh carries.
#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/spherical_parameterization.h"
#include "octaclay/core/measure/surface_distance.h"

#include <filesystem>
#include <string>
#include <vector>

namespace octaclay::core {

/// Where an imported document's diffuse layer came from.
enum class DiffuseSource { None, VertexColours, Texture };

/// What importValidatedMesh did with the mesh's attributes.
struct ImportedDiffuse {
  DiffuseSource source = DiffuseSource::None;
  std::filesystem::path texture;  ///< when source is Texture
  std::vector<std::string> notes; ///< the mesh's notes, then what could not be used here
};

/// importToDocument with the best attribute `mesh` carries: its diffuse texture (read with
/// readImage, 4 channels) when it has one, else its vertex colours, else the default fill. A
/// texture that cannot be read is a note, not an error (colours are used instead, if any).
/// Throws as importToDocument.
Document importValidatedMesh(const ValidatedMesh& mesh, const SphericalMap& map, int n,
                             ImportedDiffuse* diffuse = nullptr);

/// How faithful an import is.
struct ImportQuality {
  int flipped = 0;          ///< of the spherical map
  float stretchL2 = 0;      ///< of the spherical map (SphericalMap)
  float stretchLinf = 0;    ///< of the spherical map
  SurfaceDistance distance; ///< mesh against the image's extracted mesh (fractions of diagonal)
};

/// Measures map and image against `mesh` (extractMesh(image) at full resolution).
ImportQuality measureImport(const TriangleMesh& mesh, const SphericalMap& map,
                            const GeometryImage& image, const SurfaceDistanceOptions& options = {});

} // namespace octaclay::core
