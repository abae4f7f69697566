#pragma once

// What every reader (native .exr, .ocz, import) requires of a document before handing it on, so
// that `info`, `lod`, `stroke`, `export` and `compress` accept and refuse the same files.

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <optional>
#include <string>
#include <vector>

namespace octaclay::core {

/// Largest coordinate magnitude a document may hold, the same for every reader, command and
/// stroke: far enough below float's limit that squared distances, bounding boxes and error
/// figures stay finite and exact enough (a model is measured in units of its own size).
inline constexpr float kMaxCoordinate = 1e15f;

/// Smallest bounding-box diagonal a command that needs the model's size accepts (a stroke's
/// radius, a tolerance, a LOD's error): below it the squared edge lengths of an N = 8192 image
/// reach float's smallest normal numbers and lose their precision.
inline constexpr double kMinDiagonal = 1e-12;

/// Why these positions cannot be a document's (a non-finite sample, or a coordinate beyond
/// kMaxCoordinate), or nothing when they are fine.
std::optional<std::string> positionsProblem(const GeometryImage& positions);

/// Why a model has no usable size, or nothing when it has one: every sample at one point, a
/// diagonal below kMinDiagonal, or a diagonal below float precision at the model's position
/// (1e-6 of its largest coordinate). Commands that need a size (stroke, relax, lod, export,
/// compress, compare) refuse such a document with this reason; `info` still describes it.
std::optional<std::string> sizeProblem(const GeometryImage& positions);
/// The same for a bounding box already known (a stroke's tile bounds).
std::optional<std::string> sizeProblem(const BoundingBox& box);

/// Why a layer's values are unusable (a NaN or infinity at a sample, named), or nothing.
std::optional<std::string> layerValuesProblem(const Layer& layer, int size);

/// Throws Error(InvalidInput) "<what>: <sizeProblem>" when the model has no usable size.
void requireUsableSize(const GeometryImage& positions, const std::string& what);

/// Throws Error(InvalidArgument) "<operation> works on octahedral documents only; <what> is a
/// torus (…)" unless the image is the octahedral ball: for operations not yet written for the
/// torus and plane.
void requireOctahedral(const GeometryImage& positions, const std::string& operation,
                       const std::string& what);

/// Why a layer stored in these channels is unusable (some but not all of its channels, e.g.
/// diffuse.R without diffuse.A), or nothing. The channel names are as in the .exr file.
std::optional<std::string> layerChannelsProblem(const std::vector<std::string>& channels);

} // namespace octaclay::core
