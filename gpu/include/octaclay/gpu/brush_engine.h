#pragma once

#include "octaclay/core/geometry/topology.h"
#include "octaclay/core/geometry/vec.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gl_objects.h"
#include "octaclay/gpu/gpu_document.h"

#include <array>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::gpu {

class MaterialCatalog;
namespace detail {
class PassWatchdog;
struct LoadedBrush;
class AllLayersPass;
class ReparameterizePass;
} // namespace detail

/// One application of a brush at one place.
struct Dab {
  core::Vec3f centre;               ///< object space, on the surface
  core::Vec3f centreNormal;         ///< unit (a stroke gives the area normal where a pass reads it)
  core::Sample centreTexel;         ///< the sample under the centre (uv area mode measures from it)
  float radius = 0.1f;              ///< object units
  float strength = 0.5f;            ///< fraction of the radius (push 0.5 moves the centre radius/2)
  float pressure = 1.0f;            ///< pen pressure, 0..1
  float normalAngleDegrees = 80.0f; ///< volume+normal: samples facing further away are left alone
  std::map<std::string, std::array<float, 4>> parameters; ///< by manifest id; missing → default
  /// Splats project their material along this object-space direction (the camera's, through
  /// the centre); unset: along the inward centre normal.
  std::optional<core::Vec3f> viewDirection;
  /// The stroke (API 3, u_strokeDirection, u_strokeDelta, u_drag): the drag since the stroke
  /// began (object units; in the view plane, or along the path on the stroke-start surface),
  /// its change since the stroke's previous dab, and that change's direction (unit; the last
  /// non-zero one, zero before the stroke moved).
  core::Vec3f drag, strokeDelta, strokeDirection;
};

/// What a dab touched.
struct DabResult {
  std::vector<core::TexelRect> tiles; ///< tiles the pass ran over (their union bounds the change)
  std::size_t texels = 0;             ///< texels in those tiles
  /// The border runs the seaming pass rewrote: those the tiles reach and the samples
  /// identified with them (empty when the dab did not reach the border).
  std::vector<core::TexelRect> seams;
};

/// A brush pass that overran the engine's time limit (the watchdog): what() is
/// "<shader file>: a pass took longer than 2 s …". The brush is marked broken; the CLI exits 5.
class BrushTimeoutError : public GlError {
public:
  using GlError::GlError;
};

/// Runs brushes as render-to-texture passes over a GpuDocument. Create and use it on the thread
/// whose GL context is current.
///
/// The watchdog: each pass is fenced (glFenceSync) with its submission time. The CPU does not
/// wait for a pass as it is issued: before the next one it waits for the pass before last (the
/// GPU runs one pass ahead), and before it reads what the passes wrote (a dab's positions, the
/// stroke's end: finishPasses) for all of them, each at most passTimeLimit() after its
/// submission; a pass the GPU finished meanwhile costs no wait. A pass that overruns marks its
/// brush broken (its dabs throw until it is loaded again) and the dab (or finishPasses) throws
/// BrushTimeoutError; a stroke (StrokeSession) then restores the layers from its undo capture.
/// The GPU may still be running the pass: the restore is queued behind it, so the document ends
/// as it was once the pass completes. Drivers that recover from a hung shader only by a context
/// reset (a GPU without preemption; the context reports GL_GUILTY_CONTEXT_RESET through
/// robustness) lose every texture of the context: the caller then recreates the context, a
/// BrushEngine and a GpuDocument from the CPU mirror (GpuDocument::document(), which the restore
/// made equal to the document before the stroke) and reloads the brushes except the broken one.
class BrushEngine {
public:
  BrushEngine();
  ~BrushEngine();
  BrushEngine(const BrushEngine&) = delete;
  BrushEngine& operator=(const BrushEngine&) = delete;

  /// Compiles the brush with the shared prelude. On failure throws GlError naming the brush's
  /// shader file and the compiler's log, and a previously loaded version of it stays in use.
  /// A body that defines `void brushLayers(inout vec4 positions, inout vec4 diffuse, inout vec4
  /// feature, BrushInput b)` instead of `brush()` writes all its layers in one pass (it must not
  /// write the mask; GlError otherwise). Everything else comes from the manifest: its reads
  /// decide which layers are bound and which are written in place, its needs whether normals
  /// are computed (a mixed layer must not be read; GlError otherwise).
  void load(const BrushManifest& manifest, const std::string& shaderSource);
  bool has(const std::string& id) const;
  /// Why the brush with this id is broken (a pass overran the time limit), or nullptr when it
  /// is usable or unknown. Loading it again clears the mark.
  const std::string* brokenReason(const std::string& id) const;

  /// The watchdog's limit for one pass: 2 s by default, or $OCTACLAY_PASS_TIME_LIMIT_MS
  /// (milliseconds, a fraction allowed) when set; zero turns the watchdog off.
  void setPassTimeLimit(std::chrono::nanoseconds limit) { passTimeLimit_ = limit; }
  std::chrono::nanoseconds passTimeLimit() const { return passTimeLimit_; }

  /// One dab: a pass over the tiles the brush can reach (merged into few rectangles, one draw
  /// call), for each layer it writes (one pass for all of them when the body defines
  /// brushLayers(); for a reparameterize brush, its iterations of brushOffset() and one pass
  /// resampling every painted layer), then the seaming pass when it reached the border; the mirror
  /// is updated for those tiles. Throws core::Error(UnknownId) for an unknown brush id,
  /// BrushTimeoutError when a pass overran the time limit or the brush was marked broken by an
  /// earlier one.
  DabResult dab(GpuDocument& document, const std::string& brushId, const Dab& dab);
  /// The same with the tiles reach() returned for this dab (a caller that needed them first).
  DabResult dab(GpuDocument& document, const std::string& brushId, const Dab& dab,
                std::vector<core::TexelRect> tiles);
  /// Several dabs of one brush (a dab's mirror images), each with its tiles from reach(), and
  /// their results in order. When no pass of one can see another's texels (batches()), one pass
  /// per layer draws them all, each rectangle with its dab's values; else they run one after
  /// the other as dab() runs them. The same texels either way. Throws what dab() throws.
  std::vector<DabResult> dabs(GpuDocument& document, const std::string& brushId,
                              std::span<const Dab> dabs,
                              std::vector<std::vector<core::TexelRect>> tiles);
  /// Whether dabs() draws these dabs in one pass per layer: two to kMaxBatch of them with the
  /// same parameters, of a brush that is neither reparameterize nor bound to a material per dab,
  /// none reaching the border
  /// (no seaming pass), and each one's tiles, grown by what its pass may read around them, clear
  /// of every other's: by one texel (its normals) for a brush that reads no layer, by their own
  /// width and height for one that does ("reads": other texels of them, e.g. smooth's eight
  /// neighbours). No GL work.
  bool batches(const GpuDocument& document, const std::string& brushId, std::span<const Dab> dabs,
               const std::vector<std::vector<core::TexelRect>>& tiles) const;
  /// The most dabs one batch draws (a dab and its seven mirror images).
  static constexpr std::size_t kMaxBatch = 8;

  /// Opens and closes a stroke. A reparameterize brush's dabs between the two share one offset
  /// field and resample from the layers as they were at the stroke's first such dab, so that a
  /// whole stroke moves the surface and its paint by one interpolation, not one per dab. Without
  /// an open stroke every dab is a stroke of its own. Other brushes ignore it.
  /// StrokeSession calls them; endStroke() may be called when no stroke is open.
  /// A brush that needs "stroke_start" sees the positions as they were at the stroke's first
  /// such dab (u_strokeStart): captured once per stroke (once per dab without an open stroke).
  void beginStroke() { strokeOpen_ = true; }
  void endStroke();

  /// Uploads the catalog's materials (replacing earlier ones); a material parameter's value is
  /// an index into them. Throws GlError.
  void setMaterials(const MaterialCatalog& catalog);
  /// The index of the material with this id, or -1.
  int materialIndex(std::string_view id) const;
  std::vector<std::string> materialIds() const;

  /// Whether a dab of this brush reads its centre normal (Dab::centreNormal): whether its
  /// programs for the document's mask kind and these parameters' enum values use u_centreNormal
  /// or the projection frame made from it (the GLSL compiler's active uniforms). A stroke skips
  /// computing the area normal for a brush that does not. Compiles those programs if needed;
  /// throws GlError when one does not compile, core::Error(UnknownId) for an unknown brush.
  bool usesCentreNormal(const GpuDocument& document, const std::string& brushId,
                        const std::map<std::string, std::array<float, 4>>& parameters);

  /// Waits for every pass issued so far, each at most the time limit after its submission:
  /// before the CPU reads what they wrote (StrokeSession::finish, before the paint layers' pull).
  /// Throws BrushTimeoutError, and marks the brush broken, when one overran.
  void finishPasses();

  /// The tiles a dab of this brush at this place would run over (no GL work).
  std::vector<core::TexelRect> reach(const GpuDocument& document, const std::string& brushId,
                                     const Dab& dab) const;

private:
  using LoadedBrush = detail::LoadedBrush;
  struct GpuMaterial {
    std::string id;
    float tileSize = 0, heightScale = 0;
    int mapSize = 0;
    std::vector<Texture> colour;  // RGBA, one view per mip level
    std::vector<Texture> surface; // R height, G specular, B reflectivity, one view per level
  };
  void bindMaterial(const Program& program, const BrushManifest& manifest,
                    const GpuDocument& document, const Dab& dab) const;
  /// Unbinds the material samplers from their units (they would override the filtering of
  /// whatever else binds textures there).
  static void releaseMaterialUnits();
  std::vector<GpuMaterial> materials_;
  /// The brush's program for a layer, mask kind and enum parameters' values, for one dab or a
  /// batch of them, compiled on first use. Throws GlError.
  const Program& program(LoadedBrush& brush, core::EditLayer layer, bool maskTexture,
                         const std::vector<int>& enums, bool batched = false);
  std::map<std::string, std::unique_ptr<LoadedBrush>> brushes_;
  std::chrono::nanoseconds passTimeLimit_ = std::chrono::seconds(2);
  /// The watchdog's fences, the passes not yet known to be finished.
  std::unique_ptr<detail::PassWatchdog> watchdog_;
  /// A pass of brush was just issued: fenced, and the pass before last waited for (the GPU
  /// runs one pass ahead of the CPU).
  void passIssued(const LoadedBrush& brush);
  /// Waits for the passes issued so far, before the CPU reads what they wrote.
  void awaitPasses();
  /// What keepWithin returned: nullptr, or the owner of an overrun pass, which is marked broken
  /// (the framebuffer unbound) and thrown as BrushTimeoutError.
  void checkOverrun(const std::string* overran);
  Program seamProgram_;
  /// The material maps' filters, bound per texture unit for a dab.
  Sampler nearestMaps_, bilinearMaps_;
  RectPass rectPass_;
  /// The pass kinds that keep GL objects between dabs (the plain one, layer_passes, keeps
  /// none): a brushLayers() body's target, a reparameterize brush's offset field.
  std::unique_ptr<detail::AllLayersPass> allLayers_;
  std::unique_ptr<detail::ReparameterizePass> reparameterize_;
  bool strokeOpen_ = false;
  /// A batch's per-dab values (uploadBatch), the storage its programs read.
  Buffer batchDabs_;
  /// One dab's passes, or a batch's (rectDabs: each rectangle's dab; empty for one dab), over
  /// rects; then each layer written is finished: back into its texture, seamed over `seamed`,
  /// and noted changed over rects and seams.
  void runPasses(GpuDocument& document, LoadedBrush& brush, std::span<const Dab> dabs,
                 const std::vector<core::TexelRect>& rects, const std::vector<int>& rectDabs,
                 const std::vector<core::TexelRect>& seamed,
                 const std::vector<core::TexelRect>& seams);
  /// The positions at the stroke's start, for brushes that need "stroke_start"; taken at the
  /// stroke's first such dab of strokeStartOf_ (null: not taken).
  Texture strokeStart_;
  const GpuDocument* strokeStartOf_ = nullptr;
  /// Copies the document's positions into strokeStart_ unless this stroke already did.
  void captureStrokeStart(GpuDocument& document);
};

/// The border samples that a pass over tiles (of an image `side` samples wide) may change, and
/// the samples identified with them (seam.glsl's partners: (N - i, j) along the bottom and top
/// rows, (i, N - j) along the left and right columns, the four corners together): what the
/// seaming pass after it rewrites. A torus's partners are (i, 0) and (i, N), (0, j) and (N, j)
/// (column and row N are column and row 0); a plane has none.
std::vector<core::TexelRect> seamRuns(const std::vector<core::TexelRect>& tiles, int side,
                                      core::Topology topology = core::Topology::Octahedral);
/// The same for an image `side` samples wide and `rows` high (a W × H torus: column W is
/// column 0, row H is row 0).
std::vector<core::TexelRect> seamRuns(const std::vector<core::TexelRect>& tiles, int side, int rows,
                                      core::Topology topology);

} // namespace octaclay::gpu
