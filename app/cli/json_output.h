#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <nlohmann/json.hpp>

#include <string>

namespace octaclay::app {

inline nlohmann::json toJson(core::Vec3f v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

inline nlohmann::json toJson(const core::BoundingBox& box) {
  return {{"min", toJson(box.min)}, {"max", toJson(box.max)}, {"diagonal", box.diagonal()}};
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
