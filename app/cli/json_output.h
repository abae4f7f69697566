#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"

#include <nlohmann/json.hpp>

#include <string>

namespace octaclay::app {

inline nlohmann::json toJson(core::Vec3f v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

inline nlohmann::json toJson(const core::BoundingBox& box) {
  return {{"min", toJson(box.min)}, {"max", toJson(box.max)}, {"diagonal", box.diagonal()}};
}

/// The stretch figures as info, relax and remesh report them.
inline nlohmann::json toJson(const core::StretchSummary& s) {
  return {{"longest_over_median", s.longestOverMedian},
          {"p99_over_median", s.p99OverMedian},
          {"share_over_4x", s.shareOver4x},
          {"median_edge", s.medianEdge},
          {"longest_edge", s.longestEdge},
          {"mean_spacing", s.meanSpacing}};
}

/// How a command measured the surface distance it reports (issue 34): sampled closest points
/// with a work bound per query and in all (every stride-th sample when a pilot says the whole
/// would pass it), so a report never costs more than the work; null when the user asked for
/// none (--no-report).
inline nlohmann::json surfaceReportJson(const core::SurfaceDistance* distance,
                                        const core::SurfaceDistanceOptions& options) {
  if (distance == nullptr) return nullptr;
  return {{"method", "sampled"},
          {"samples", distance->samples},
          {"leaves_per_query", options.leavesPerQuery},
          {"leaf_budget", options.leafBudget},
          {"stride", distance->stride},
          {"bounded_queries", distance->boundedQueries},
          {"exact", distance->boundedQueries == 0}};
}

/// What commands print with --json: nlohmann::json whose dump() never throws (see jsonText).
struct JsonReply : nlohmann::json {
  using nlohmann::json::json;
  std::string dump() const {
    return nlohmann::json::dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  }
};

/// The one way commands encode their JSON: file names, OBJ object names and manifest text need
/// not be UTF-8, so invalid bytes become U+FFFD instead of an exception after the work is done.
inline std::string jsonText(const nlohmann::json& value) {
  return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace octaclay::app
