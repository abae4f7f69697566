#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <nlohmann/json.hpp>

namespace octaclay::app {

inline nlohmann::json toJson(core::Vec3f v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

inline nlohmann::json toJson(const core::BoundingBox& box) {
  return {{"min", toJson(box.min)}, {"max", toJson(box.max)}, {"diagonal", box.diagonal()}};
}

} // namespace octaclay::app
