#pragma once

// NaN and infinity parse as numbers but are never meaningful arguments: a NaN strength or view
// would be written into the document. Every float option and list is checked here.

#include "octaclay/core/error.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace octaclay::app {

/// A CLI11 check for float options: refuses nan and inf before the command runs (exit 2).
inline const CLI::Validator kFiniteNumber(
    [](std::string& text) -> std::string {
      try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used == text.size() && !std::isfinite(v))
          return "'" + text + "' is not a finite number";
        // Options are floats: 1e39 would become infinity and be reported as 'inf'.
        if (used == text.size() && std::abs(v) > std::numeric_limits<float>::max())
          return "'" + text + "' is beyond the range of a float (±3.4e38)";
      } catch (const std::exception&) {
        // Not a number at all: CLI11's own conversion reports it.
      }
      return {};
    },
    "FINITE");

/// Throws Error(InvalidArgument) naming the option when value is NaN or infinite.
inline void requireFinite(float value, const std::string& what) {
  if (!std::isfinite(value))
    throw core::Error(core::ErrorKind::InvalidArgument,
                      what + ": '" + std::to_string(value) + "' is not a finite number");
}

} // namespace octaclay::app
