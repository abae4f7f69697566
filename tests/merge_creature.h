#pragma once

// Issue 33's creature from parts, shared by merge_test and bench_merge: a ball body, four capsule
// legs, a capsule neck and a sphere head, each a document of its own placed by a transform
// (the legs and the neck reach into the body, the head over the neck's end), and the analytic
// surfaces they stand for, to measure a merge against.

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/capsule.h"
#include "octaclay/core/merge/merge.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace octaclay::testing {

/// One part: a capsule (a segment from a to b, radius r; a == b for a ball), its document and
/// its placement.
struct CreaturePiece {
  std::string name;
  core::Vec3f a, b;
  float radius;
  std::shared_ptr<core::Document> document;
  core::PartTransform transform;
};

/// Signed distance from p to a piece's analytic surface (negative inside).
inline float pieceDistance(const CreaturePiece& piece, core::Vec3f p) {
  const core::Vec3f ab = piece.b - piece.a;
  const float len2 = core::dot(ab, ab);
  const float t = len2 > 0 ? std::clamp(core::dot(p - piece.a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return core::length(p - (piece.a + ab * t)) - piece.radius;
}

/// Signed distance to the union of the pieces (the least of theirs).
inline float unionDistance(const std::vector<CreaturePiece>& pieces, core::Vec3f p) {
  float d = std::numeric_limits<float>::infinity();
  for (const CreaturePiece& piece : pieces)
    d = std::min(d, pieceDistance(piece, p));
  return d;
}

/// The piece whose surface is nearest p (by absolute distance), and by how much it is nearer
/// than the next one (a point near a junction is ambiguous).
inline int nearestPiece(const std::vector<CreaturePiece>& pieces, core::Vec3f p,
                        float* margin = nullptr) {
  int best = -1;
  float first = std::numeric_limits<float>::infinity(), second = first;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const float d = std::abs(pieceDistance(pieces[k], p));
    if (d < first)
      second = first, first = d, best = int(k);
    else
      second = std::min(second, d);
  }
  if (margin) *margin = second - first;
  return best;
}

/// The creature, its parts' documents at partSize: the body a unit ball at the origin, the
/// modeller's up +y and front +z; legs of radius 0.2 and 1.2 long (a capsule document of their
/// own proportions, turned to point down) under the body's four quarters, their tops 0.17 inside
/// it; a neck of radius 0.25 rising forward at 45°; a head of radius 0.45 over the neck's end.
inline std::vector<CreaturePiece> mergeCreature(int partSize) {
  using core::Vec3f;
  std::vector<CreaturePiece> out;
  const auto sphere = [&](std::string name, Vec3f centre, float radius) {
    out.push_back({std::move(name), centre, centre, radius,
                   std::make_shared<core::Document>(
                       core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, partSize))),
                   core::PartTransform::fromTrs(centre, {0, 0, 0}, {radius, radius, radius})});
  };
  // A capsule along +z turned by rotateDegrees about x, centred at centre.
  const auto capsule = [&](std::string name, Vec3f centre, float radius, float length,
                           float rotateX) {
    const core::PartTransform t = core::PartTransform::fromTrs(centre, {rotateX, 0, 0});
    const float h = 0.5f * length;
    out.push_back({std::move(name), t.apply({0, 0, -h}), t.apply({0, 0, h}), radius,
                   std::make_shared<core::Document>(
                       core::makeDocument(core::makeCapsule(partSize, {radius, length}))),
                   t});
  };
  sphere("body", {0, 0, 0}, 1.0f);
  for (const float x : {-0.45f, 0.45f})
    for (const float z : {-0.45f, 0.45f})
      capsule(std::string("leg ") + (z > 0 ? "front " : "back ") + (x > 0 ? "left" : "right"),
              {x, -1.2f, z}, 0.2f, 0.8f, 90.0f);
  const float c = std::sqrt(0.5f); // up and forward
  capsule("neck", Vec3f{0, c, c} * 1.15f, 0.25f, 0.6f, -45.0f);
  sphere("head", Vec3f{0, c, c} * 1.95f, 0.45f);
  return out;
}

/// The pieces as merge parts (the documents stay owned by the pieces).
inline std::vector<core::MergePart> creatureMergeParts(const std::vector<CreaturePiece>& pieces) {
  std::vector<core::MergePart> parts;
  for (const CreaturePiece& piece : pieces)
    parts.push_back({piece.document.get(), piece.transform});
  return parts;
}

} // namespace octaclay::testing
