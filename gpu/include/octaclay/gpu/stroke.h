#pragma once

#include "octaclay/core/edit_history.h"
#include "octaclay/gpu/brush_engine.h"

#include <array>
#include <vector>

namespace octaclay::gpu {

/// Mirror planes through the model's centre (bounding-box centre at the stroke's start).
enum SymmetryAxis : unsigned { kSymmetryNone = 0, kSymmetryX = 1, kSymmetryY = 2, kSymmetryZ = 4 };

/// A stroke: a path over the image and the brush settings shared by all its dabs.
struct StrokeSettings {
  std::string brush;
  std::vector<std::array<float, 2>> path; ///< (u, v) in [0, 1]; one point is one dab
  float radius = 0.1f;                    ///< object units
  float strength = 0.5f;                  ///< fraction of the radius
  float pressure = 1.0f;
  float spacing = 0.0f; ///< between dabs, fraction of the radius; 0 → the brush's own
  unsigned symmetry = kSymmetryNone;
  std::map<std::string, std::array<float, 4>> parameters;
};

struct StrokeResult {
  int dabs = 0;        ///< including mirrored dabs
  double engineMs = 0; ///< GPU passes, seaming and mirror updates
  core::Stroke undo;   ///< the tiles the stroke changed, before and after
};

/// Runs a stroke: dabs are spaced along the path by object-space distance on the current
/// surface, each centred on the sample under its path point (re-picked after the previous dab),
/// and repeated at the mirrored surface point for each symmetry plane. Throws GlError for an
/// unknown brush, core::Error(InvalidArgument) for an empty path or a point outside [0, 1].
StrokeResult runStroke(BrushEngine& engine, GpuDocument& document, const BrushManifest& brush,
                       const StrokeSettings& settings);

/// The sample whose position is nearest to p (searching only tiles near p).
core::Sample nearestSample(const GpuDocument& document, core::Vec3f p);

} // namespace octaclay::gpu
