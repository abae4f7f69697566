#pragma once

// The stroke rules the modeller and octaclay-cli share (gpu::StrokeSession applies them; no
// caller scales a stroke's strength or spaces its dabs itself):
// - dabs fall at arc length 0, s, 2s, … along the path, measured on the surface as it was when
//   the stroke began (the stroke's own dabs do not stretch or shrink its spacing), with the
//   remainder carried from one path segment and one StrokeSession::moveTo call to the next;
// - the path is a straight line in image coordinates between its points, its positions
//   interpolated on the grid mesh's triangles (never rounded to samples), so the dabs of a
//   stroke fall at the same surface points at every N;
// - s = dabSpacing() × radius; a sculpt brush's dab applies strength × dabShare(), so that one
//   stroke moves the surface by about strength × radius per radius travelled whatever the
//   spacing; paint and splats blend toward a target and apply the whole strength.

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/gpu/brush_manifest.h"

#include <array>

namespace octaclay::gpu {

/// The smallest dab spacing, as a fraction of the radius: closer dabs would only cost time.
inline constexpr float kMinDabSpacing = 0.01f;

/// The distance between dabs as a fraction of the radius: spacing when it is > 0 (a stroke's
/// own, e.g. octaclay-cli's --spacing), else the brush's; at least kMinDabSpacing.
float dabSpacing(const BrushManifest& brush, float spacing);

/// The share of a stroke's strength each dab applies: dabSpacing(brush, spacing) clamped to
/// [kMinDabSpacing, 1] for sculpt brushes (overlapping dabs add up), 1 for paint and splat
/// brushes (they blend toward a target, so overlapping dabs converge instead).
float dabShare(const BrushManifest& brush, float spacing);

/// A point of the image's surface mesh: the grid triangle holding image coordinates (x, y)
/// (in samples, each in [0, N]) and the barycentric weights of its corners, which sum to 1.
/// Triangles are core::cellTriangles'; a point on an edge belongs to either side (the
/// interpolated value is the same).
struct SurfacePoint {
  std::array<core::Sample, 3> corners;
  std::array<float, 3> weights;
};
SurfacePoint surfacePointAt(int n, double x, double y);

/// image's position at p, interpolated linearly over its triangle.
core::Vec3f interpolatePosition(const core::GeometryImage& image, const SurfacePoint& p);

/// The unit normal at p: the corners' vertex normals (core::vertexNormal) interpolated and
/// normalised; the nearest corner's when they cancel out.
core::Vec3f interpolateNormal(const core::GeometryImage& image, const SurfacePoint& p);

} // namespace octaclay::gpu
