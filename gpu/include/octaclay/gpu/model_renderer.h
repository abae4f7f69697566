#pragma once

#include "octaclay/core/document/image_io.h"
#include "octaclay/core/geometry/tile_bounds.h"
#include "octaclay/core/geometry/vec.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/gpu/gl_objects.h"
#include "octaclay/gpu/gpu_document.h"

#include <array>
#include <map>
#include <memory>
#include <span>
#include <vector>

namespace octaclay::gpu {
namespace detail {
class ModelChunks;
}

/// What a frame shows and from where.
struct ModelView {
  std::array<float, 16> objectToClip{}; ///< column-major projection × view
  core::Vec3f eye;                      ///< camera position, object space (headlight)
  bool showDiffuse = true;              ///< the diffuse layer as colour, else plain clay
  bool showMask = true;                 ///< masked (blocked) areas tinted
  bool showBrush = false;               ///< the brush outline: a ring on the surface
  core::Vec3f brushCentre;
  float brushRadius = 0;                     ///< object units
  std::array<float, 3> brushColour{1, 1, 1}; ///< outline colour
  /// What the pixels show: the shaded model, one channel alone, the saliency (the positions'
  /// alpha) as a heat map, or the stretch (core::StretchMap::stretch, computed on the GPU from
  /// the positions) as a heat map of the same colours on a log scale: 2× the mean sample
  /// spacing or less blue (a fresh sphere spans 0.6×–1.7×), 2.8× green, 4× or more red.
  enum class Preview {
    Shaded,
    Diffuse,
    HeightDetail,
    Specular,
    Reflectivity,
    Mask,
    Saliency,
    Stretch
  };
  Preview preview = Preview::Shaded;
  /// The shaded model lit (above) or through a matcap (setMatcap's image, looked up by the
  /// pixel's view-space normal), the painted colour multiplying it where the diffuse layer
  /// differs from its fill.
  bool matcap = false;
  core::Vec3f viewRight{1, 0, 0}, viewUp{0, 1, 0}; ///< the camera's axes, object space
  /// The displayed level's triangle edges (or the LOD's) drawn over the pixels.
  bool wireframe = false;
};

/// Draws a GpuDocument at a displayed level straight from its textures (thesis 3.5): vertices
/// are the image's samples every `divisor` texels, fetched by the vertex shader, so no vertex
/// data crosses from the CPU per frame; each pixel is shaded with a normal from a
/// full-resolution normal map that is refreshed only where dabs changed the surface. Create,
/// use and destroy it with the document's context current.
class ModelRenderer {
public:
  /// Compiles the programs. Throws GlError.
  ModelRenderer();
  ~ModelRenderer();
  ModelRenderer(const ModelRenderer&) = delete;
  ModelRenderer& operator=(const ModelRenderer&) = delete;

  /// Shows the model of an N-image every divisor samples (a power of two, N/divisor ≥ 2),
  /// rebuilding the index buffer when either changed. Throws core::Error(InvalidArgument).
  void setLevel(int n, int divisor);
  /// The same for a W × H image of any topology (W/divisor and H/divisor ≥ 1, at least 2 cells
  /// along the longer side): a torus's or plane's cells split along their anti-diagonals.
  void setLevel(const core::SampleGrid& grid, int divisor);
  /// The level a divisor wanted for grid may show: halved until each side keeps a cell and
  /// the longer side two.
  static int fittingDivisor(const core::SampleGrid& grid, int divisor);
  int divisor() const { return divisor_; }
  /// Triangles drawn per frame: 2 (N/divisor)².
  long long displayedTriangles() const;

  /// The environment reflected by reflective surfaces: an equirectangular RGB(A) image, +y up.
  /// Throws GlError.
  void setEnvironment(const core::RasterImage& image);
  /// The matcap ModelView::matcap shows: a square RGB(A) image of a lit sphere seen head-on,
  /// x right and y up (the top row is the sphere's top). Throws GlError.
  void setMatcap(const core::RasterImage& image);
  bool hasMatcap() const { return matcap_.id() != 0; }

  /// Recomputes the normal map over rects of the positions (after dabs or undo). The stretch
  /// preview's map is refreshed over the same rects at its next draw.
  void refreshNormals(GpuDocument& document, std::span<const core::TexelRect> rects);
  /// Recomputes the whole normal map (a new or reloaded document).
  void refreshAllNormals(GpuDocument& document);
  /// The normal map as refreshed so far: RGBA8, (N+1)², each texel a unit normal mapped to
  /// [0, 1]. For tests that check what a refresh covered.
  const Texture& normalMap() const { return normals_; }

  /// Draws into the bound framebuffer with the current viewport, depth-tested, skipping chunks
  /// of the level that wholly face away from view.eye. Leaves the program, vertex array and
  /// texture units 0–6 unbound. Preview::Stretch first brings the stretch map up to date
  /// (the rects refreshNormals() was given since, and the mean spacing from the document's
  /// mirror: O(N²) on the CPU once after each change), restoring the framebuffer, viewport and
  /// enables it found.
  void draw(GpuDocument& document, const ModelView& view);
  /// The stretch preview's map as of the last Preview::Stretch draw (empty before): R32F,
  /// (N+1)², each texel core::StretchMap::stretch times meanSpacing(), i.e. object units per
  /// sample step. For tests and tools that read it back.
  const Texture& stretchMap() const { return stretch_; }
  /// The mean sample spacing the last Preview::Stretch draw divided by (core::meanSpacing).
  double meanSpacing() const { return meanSpacing_; }
  /// Triangles the last draw() sent to the rasterizer (after chunk culling).
  long long drawnTriangles() const { return drawnTriangles_; }

  /// Replaces the level-of-detail mesh drawLod() draws: a vertex buffer of its triangles'
  /// corners with their image coordinates (lod.cornerUv), so it is shaded per pixel from the
  /// full-resolution normal map and layers. Throws GlError.
  void setLodMesh(const core::LodMesh& lod);
  /// Triangles of the mesh setLodMesh() gave (0 before).
  long long lodTriangles() const { return lodTriangles_; }
  /// Draws the LOD mesh as draw() draws the level: same shading, layers and previews, into the
  /// bound framebuffer with the current viewport. Does nothing while there is no LOD mesh.
  void drawLod(GpuDocument& document, const ModelView& view);

private:
  /// The draw program for one state, compiled on first use. Throws GlError.
  struct Variant {
    bool diffuseTexture, featureTexture, maskTint, reflection;
    int preview;
    bool lodVertices, matcap, wireframe;
  };
  const Program& drawVariant(const Variant& v);
  /// Picks draw()'s or drawLod()'s program for view and sets its textures and uniforms.
  const Program& prepareDraw(GpuDocument& document, const ModelView& view, bool lodVertices);
  /// Runs the stretch pass over the stale rects and re-measures the mean spacing if stale.
  void refreshStretch(GpuDocument& document);

  Program normalProgram_;
  std::map<int, Program> drawPrograms_;
  RectPass rectPass_;
  Texture normals_, environment_, matcap_;
  Program stretchProgram_;                    // compiled by the first stretch preview
  Texture stretch_;                           // R32F, (N+1)²: stretch_map.glsl's figure
  std::vector<core::TexelRect> staleStretch_; // rects changed since the last stretch pass
  bool stretchAllStale_ = true;
  double meanSpacing_ = 0;
  bool meanSpacingStale_ = true;
  VertexArray vertexArray_;
  Buffer indexBuffer_;
  int n_ = 0, divisor_ = 0;
  core::SampleGrid grid_; // the level's image
  long long indexCount_ = 0, drawnTriangles_ = 0;
  std::unique_ptr<detail::ModelChunks> chunks_;
  bool chunksStale_ = true;
  VertexArray lodVertexArray_; // made by the first setLodMesh()
  Buffer lodBuffer_;
  long long lodTriangles_ = 0;
};

} // namespace octaclay::gpu
