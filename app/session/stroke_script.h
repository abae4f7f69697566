#pragma once

// A stroke given as a script rather than by a pointer: `octaclay-cli stroke`'s path and drag
// points, played through the session's one stroke door (SculptSession::beginStroke, moveTo,
// finishStroke) as the viewport's pointer samples are, the way f3d replays a recorded
// interaction through the interactor that live input uses.

#include "sculpt_session.h"

#include "octaclay/core/geometry/vec.h"

#include <array>
#include <functional>
#include <vector>

namespace octaclay::app {

/// A scripted stroke: how it begins, the image points it moves through (one point is one dab;
/// consecutive points are joined) and, for a dragging brush, the object-space points the drag
/// moves through after the path.
struct StrokeScript {
  StrokeStart start;
  std::vector<std::array<float, 2>> path; ///< (u, v), each in [0, 1]
  std::vector<core::Vec3f> dragPoints;
};

/// Plays script through session's stroke door and ends the stroke (recorded in its history).
/// Before the stroke begins it refuses, with core::Error(InvalidArgument), an empty path, drag
/// points for a brush that does not drag or that are not finite, and a path point outside
/// [0, 1]; then what SculptSession::beginStroke throws, and the expected dab count past
/// gpu::kMaxStrokeDabs (SculptSession::expectDabs) before the first dab; then what the moves
/// and finishStroke throw (a failed dab leaves the layers as before the stroke). progress, when
/// set, is told (dabs made, dabs expected) after each dab. Precondition: session has a document
/// and brushes and no stroke; the brush's GL context is current.
StrokeEnd playStroke(SculptSession& session, const StrokeScript& script,
                     const std::function<void(int, int)>& progress = {});

} // namespace octaclay::app
