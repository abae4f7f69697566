#pragma once

#include "octaclay/core/document/edit_layer.h"

#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::gpu {

/// The brush API major version this build accepts: a manifest whose "api" is higher is refused.
/// API 2 added "pass" (reparameterize brushes) and "iterations"; API 3 "stroke" (anchored and
/// drag strokes), the need "stroke_start" and the stroke's direction, movement and drag; API 4
/// the pass "all-layers" (one brushLayers() pass writes every layer: declared, where brushes
/// of API 1–3 had it found in their GLSL).
inline constexpr int kBrushApiVersion = 4;
/// The most steps a reparameterize brush may ask for per dab ("iterations").
inline constexpr int kMaxIterations = 64;

/// Where a dab applies: a disc in texture space ("uv"), a sphere in object space ("volume"), or
/// that sphere limited to surface facing the same side as the centre's normal ("volume+normal").
enum class AreaMode { Uv, Volume, VolumeNormal };
/// How weight falls from 1 at the centre to 0 at the rim; Curve samples falloffCurve.
enum class Falloff { Linear, Smooth, Constant, Curve };
/// The brush panel's grouping.
enum class Category { Sculpt, Paint, Splat };
/// A parameter's type; it decides the widget and the GLSL type of its uniform
/// (float, int and bool → float, color → vec4, enum → int). A material parameter declares no
/// uniform: the engine binds the chosen material's maps (u_material*, see the prelude).
enum class ParameterType { Float, Int, Bool, Color, Enum, Material };
/// What the engine computes for a brush beyond its layers ("needs"): Normal is each sample's
/// own surface normal (BrushInput.normal; six position reads a texel); StrokeStart (API 3) the
/// positions as they were when the stroke began (u_strokeStart, captured once per stroke).
enum class BrushNeed { Normal, StrokeStart };
/// How a stroke's dabs fall ("stroke", API 3): Spaced, along the path, each applying strength ×
/// spacing (they add up); Target, along the path, each applying the whole strength (dabs that
/// converge on a target); Drag, along the path with the whole strength, each centred where the
/// previous one left the surface it pulled (the tip follows the drag); Anchored, one dab whose
/// centre stays where the stroke began, run again from the stroke-start positions as the drag
/// changes.
enum class StrokeKind { Spaced, Target, Drag, Anchored };
/// What one dab's pass computes ("pass"): Layers, each written layer's new value (brush() or
/// brushLayers()); Reparameterize, an offset in the image's parameter domain per sample
/// (brushOffset()), after which the engine resamples every layer at the offset coordinates from
/// the layers before the dab, so the surface and its paint stay where they are.
/// How a dab's passes run: one brush() pass per written layer, one brushLayers() pass for
/// every layer, or a brushOffset() step that moves the samples (reparameterize).
enum class PassKind { Layers, Reparameterize, AllLayers };

/// The manifest spelling of each value ("positions", "volume+normal", "color" …). Not named
/// toString: QTest finds that name by ADL and would break QCOMPARE on these enums.
std::string_view toManifestName(core::EditLayer layer);
std::string_view toManifestName(AreaMode area);
std::string_view toManifestName(Falloff falloff);
std::string_view toManifestName(Category category);
std::string_view toManifestName(ParameterType type);
std::string_view toManifestName(BrushNeed need);
std::string_view toManifestName(PassKind pass);
std::string_view toManifestName(StrokeKind stroke);

/// One user-tunable value of a brush, shown as a widget and passed as uniform u_<id> (with '-'
/// replaced by '_').
struct BrushParameter {
  std::string id, label, tooltip;
  ParameterType type = ParameterType::Float;
  /// Float and Int: [0] is the value. Bool: [0] is 0 or 1. Color: RGBA in [0, 1].
  /// Enum: [0] is the index of the default option.
  std::array<float, 4> defaultValue{};
  /// Inclusive range of the value. Bool: [0, 1]; Color: [0, 1] per channel; Enum: option indices.
  float min = 0.0f, max = 1.0f;
  /// Widget increment, > 0 (1 for Int, Bool and Enum).
  float step = 0.01f;
  /// Enum: the option strings, in the order of their indices. Material: one string, the id of
  /// the default material; the value ([0]) is an index into the engine's materials.
  std::vector<std::string> options;
};

/// A validated brush manifest (plugins/brushes/<folder>/manifest.json).
struct BrushManifest {
  /// Unique key of the brush, [a-z0-9-]+.
  std::string id, name, version, description;
  /// The brush API major version the brush was written for, 1 … kBrushApiVersion.
  int api = kBrushApiVersion;
  Category category = Category::Sculpt;
  /// File name of the shader, relative to folder; the file existed when parsed.
  std::string shaderFile;
  /// Layers the shader samples beyond the value(s) it is given (empty allowed): the engine binds
  /// only these, and writes a layer in place only when nothing reads it. Layers it writes, one
  /// pass each, never empty and without duplicates.
  std::vector<core::EditLayer> reads, writes;
  /// What the engine computes for the shader; without Normal, BrushInput.normal is the centre's
  /// normal (area "volume+normal" computes it anyway).
  std::vector<BrushNeed> needs;
  /// Layers (diffuse or feature, each also in writes) a brushLayers() body hands back as a
  /// colour to mix in and its amount in alpha: the GPU's blender mixes rgb by that amount and
  /// keeps the layer's alpha, so the pass never reads the layer (its argument starts at zero).
  std::vector<core::EditLayer> mix;
  /// Reparameterize (API 2): writes holds all four layers and mix is empty. AllLayers (API 4;
  /// for API 1–3 found in the shader when the catalog loads it): writes holds no mask.
  PassKind pass = PassKind::Layers;
  /// Reparameterize only: brushOffset() steps composed per dab, 1 … kMaxIterations.
  int iterations = 1;
  /// How the stroke's dabs fall (API 3); Anchored implies StrokeStart.
  StrokeKind stroke = StrokeKind::Spaced;
  AreaMode area = AreaMode::Volume;
  Falloff falloff = Falloff::Smooth;
  /// Falloff::Curve only: 2 … 64 weights in [0, 1], sampled evenly from centre to rim.
  std::vector<float> falloffCurve;
  /// Distance between dabs along a stroke, as a fraction of the radius, > 0.
  float spacing = 0.15f;
  /// In manifest order; ids are unique.
  std::vector<BrushParameter> parameters;
  /// Optional "icon": an SVG or PNG path relative to folder, inside it; the file existed when
  /// parsed. Empty: the modeller draws one from the name and category.
  std::string iconFile;
  /// The folder holding manifest.json and the shader.
  std::filesystem::path folder;

  /// Whether layer is in reads.
  bool readsLayer(core::EditLayer layer) const;
  /// Whether the passes compute each sample's normal: needs Normal, or area VolumeNormal.
  bool needsNormal() const;
  /// Whether the engine captures the positions at the stroke's start: needs StrokeStart, or an
  /// anchored stroke.
  bool needsStrokeStart() const;
  /// The parameter with this id, or nullptr.
  const BrushParameter* parameter(std::string_view parameterId) const;
  /// folder / shaderFile.
  std::filesystem::path shaderPath() const { return folder / shaderFile; }
  /// folder / iconFile, or empty without an icon.
  std::filesystem::path iconPath() const {
    return iconFile.empty() ? std::filesystem::path() : folder / iconFile;
  }
};

/// A brush that cannot be loaded. what() always starts with the manifest (or shader) file path,
/// then the field, then the reason, e.g.
/// `/x/foo/manifest.json: parameters[2].type: unknown type "vector" (use float, int, …)`.
class BrushLoadError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Reads and validates a manifest.json; folder becomes its parent folder. Unknown fields are
/// errors (a typo must not be silently ignored) except those whose name starts with "x-".
/// Throws BrushLoadError on the first problem: unreadable file, JSON syntax (with the byte
/// position), a missing or mistyped field, a value out of range, an api newer than
/// kBrushApiVersion, a shader file that is not beside the manifest, or an icon that is not an
/// .svg or .png file inside the brush folder. Only a regular file of at
/// most 1 MB is read: a FIFO, a device (a link to /dev/zero) or a link loop is refused, naming
/// the file, without blocking. Checks take time linear in the manifest's size. Any thread.
BrushManifest parseBrushManifest(const std::filesystem::path& manifestFile);
/// The same over text already read, as if it were manifestFile's contents (the shader is still
/// looked for beside manifestFile). For tests and the manifest fuzzer.
BrushManifest parseBrushManifestText(std::string_view text,
                                     const std::filesystem::path& manifestFile);

} // namespace octaclay::gpu
