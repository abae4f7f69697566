#pragma once

// Checks the edit history's recorder, store and appliers share.

#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/texel_rect.h"

#include <cstddef>
#include <string>

namespace octaclay::core::detail {

[[noreturn]] inline void invalidEdit(const std::string& message) {
  throw Error(ErrorKind::InvalidArgument, message);
}

inline const char* editLayerName(EditLayer layer) {
  switch (layer) {
  case EditLayer::Positions:
    return "positions";
  case EditLayer::Diffuse:
    return "diffuse";
  case EditLayer::Feature:
    return "feature";
  case EditLayer::Mask:
    return "mask";
  }
  return "unknown";
}

inline std::size_t texelArea(TexelRect r) {
  return static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height);
}

} // namespace octaclay::core::detail
