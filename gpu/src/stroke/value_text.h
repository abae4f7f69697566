#pragma once

// A stroke setting's value as its error messages show it: "nan", "inf", "-inf" or the number;
// a figure in a refusal to three digits.

#include <cmath>
#include <cstdio>
#include <string>

namespace octaclay::gpu::detail {

inline std::string valueText(float v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  return std::to_string(v);
}

/// A figure in a stroke's refusal (dab counts, diagonals): three significant digits.
inline std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

} // namespace octaclay::gpu::detail
