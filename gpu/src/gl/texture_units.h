#pragma once

#include <epoxy/gl.h>

#include <array>

// The texture units of a brush pass: the one table that binding a texture and pointing a
// prelude sampler at it both read, so the two cannot disagree.
namespace octaclay::gpu::detail {

/// A texture unit and the sampler uniform that reads it.
struct BrushUnit {
  const char* sampler;
  GLint unit;

  /// Binds texture (0: none) to the unit; leaves the unit active.
  void bind(GLuint texture) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, texture);
  }
};

inline constexpr BrushUnit kPositionsUnit{"u_positions", 0};
inline constexpr BrushUnit kLayerUnit{"u_layer", 1}; // the layer the pass writes
inline constexpr BrushUnit kMaskUnit{"u_mask", 2};
inline constexpr BrushUnit kFeatureUnit{"u_featureLayer", 3};
inline constexpr BrushUnit kDiffuseUnit{"u_diffuseLayer", 6};
/// A reparameterize brush's offset field (the engine's, not the document's).
inline constexpr BrushUnit kOffsetsUnit{"u_offsets", 4};
/// The positions as they were when the stroke began ("needs": ["stroke_start"]).
inline constexpr BrushUnit kStrokeStartUnit{"u_strokeStart", 5};
/// The document's layers, the offset field and the stroke-start positions.
inline constexpr std::array kLayerUnits{kPositionsUnit, kLayerUnit,   kMaskUnit,       kFeatureUnit,
                                        kDiffuseUnit,   kOffsetsUnit, kStrokeStartUnit};
/// A material's four maps: both projections' colour and surface (height, specular,
/// reflectivity).
inline constexpr std::array kMaterialUnits{
    BrushUnit{"u_materialColour", 7}, BrushUnit{"u_materialSurface", 8},
    BrushUnit{"u_materialColourUv", 9}, BrushUnit{"u_materialSurfaceUv", 10}};

} // namespace octaclay::gpu::detail
