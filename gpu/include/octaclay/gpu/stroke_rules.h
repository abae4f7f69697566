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
#include "octaclay/core/geometry/grid_point.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gpu_document.h"

#include <array>
#include <span>

namespace octaclay::gpu {

/// The smallest dab spacing, as a fraction of the radius: closer dabs would only cost time.
inline constexpr float kMinDabSpacing = 0.01f;

/// The distance between dabs as a fraction of the radius: spacing when it is > 0 (a stroke's
/// own, e.g. octaclay-cli's --spacing), else the brush's; at least kMinDabSpacing.
float dabSpacing(const BrushManifest& brush, float spacing);

/// The share of a stroke's strength each dab applies: dabSpacing(brush, spacing) clamped to
/// [kMinDabSpacing, 1] for sculpt brushes (overlapping dabs add up), 1 for paint and splat
/// brushes (they blend toward a target, so overlapping dabs converge instead) and for brushes
/// whose "stroke" is not "spaced" (their dabs converge, follow the drag or are anchored).
float dabShare(const BrushManifest& brush, float spacing);

/// A stroke's settings checked before they are used, the same words for every door: throws
/// core::Error(InvalidArgument) "<what> <value> is not a finite number" unless v is finite.
void requireFinite(const char* what, float v);
/// Throws core::Error(InvalidArgument) "path point (u, v) is outside [0, 1]" unless uv is in the
/// image.
void requirePathPoint(core::Vec2f uv);

/// A point of the image's surface mesh (core::GridPoint) at image coordinates (x, y), in
/// samples, each clamped to [0, N].
core::GridPoint surfacePointAt(int n, double x, double y);
/// The same on the image's own grid (a torus's or plane's cells split as core::locateGridPoint's).
core::GridPoint surfacePointAt(const core::SampleGrid& grid, double x, double y);

/// The unit normal at p: the corners' grid normals (core::gridNormal) interpolated and
/// normalised; the nearest corner's when they cancel out.
core::Vec3f interpolateNormal(const core::GeometryImage& image, const core::GridPoint& p);

/// A dab pushes along the surface's mean normal within this fraction of its radius (the
/// "area normal" of sculpting tools), when at least kAreaNormalTriangles triangles lie there.
inline constexpr float kAreaNormalRadius = 1.0f;
inline constexpr int kAreaNormalTriangles = 32;

/// Reads back the positions of tiles (as core::TileBounds numbers them, with the first sample
/// past each) where their read-back waits, so a dab's rules can read them from the mirror.
void syncTiles(const GpuDocument& document, std::span<const int> tiles);
/// The same for the samples around image point (x, y) (in samples) that a centre's position and
/// normals read, and the border's strips when they reach across a seam.
void syncAround(const GpuDocument& document, double x, double y);

/// The area vectors' sum areaNormal averages, over the cells of tiles (core::TileBounds numbers)
/// read from the mirror (synced first) on the CPU: the same sum as GpuDocument::areaSum up to
/// float rounding (its order differs). Where the driver is a software rasterizer.
AreaSum areaSumOnCpu(const GpuDocument& document, std::span<const int> tiles, core::Vec3f centre,
                     float radius);

/// The mean of the area-weighted normals of the triangles whose centroids lie within radius
/// of centre: the same however the samples are spread there, so a relaxed or an evened-out
/// surface is pushed the same way; fallback when fewer than kAreaNormalTriangles lie there.
core::Vec3f areaNormal(const GpuDocument& document, core::Vec3f centre, float radius,
                       core::Vec3f fallback);

} // namespace octaclay::gpu
