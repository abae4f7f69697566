#pragma once

// A stroke setting's value as its error messages show it: "nan", "inf", "-inf" or the number.

#include <cmath>
#include <string>

namespace octaclay::gpu::detail {

inline std::string valueText(float v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  return std::to_string(v);
}

} // namespace octaclay::gpu::detail
