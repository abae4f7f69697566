#pragma once

// The arguments `resize` and `remesh` share, checked before the input is read: a new size, an
// .exr output that is not the input.

#include "output_rules.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"

#include <string>

namespace octaclay::app {

/// Throws Error(InvalidArgument) unless size is a power of two in 2 … 8192.
inline void requireDocumentSize(int size) {
  if (!core::isValidSize(size))
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "--size " + std::to_string(size) + " is not a power of two from " +
                          std::to_string(core::kMinSize) + " to " + std::to_string(core::kMaxSize));
}

/// Throws Error(InvalidArgument) unless output ends in .exr and names another file than input
/// (the input is kept, so a bad result can be compared and thrown away).
inline void requireNewDocumentOutput(const std::string& input, const std::string& output) {
  requireOutputExtension(output, {".exr"}, "the document");
  requireNotInput(output, input);
}

} // namespace octaclay::app
