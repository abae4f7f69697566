#pragma once

// The arguments `resize` and `remesh` share, checked before the input is read: a new size, an
// .exr output that is not the input.

#include "octaclay/core/error.h"
#include "octaclay/core/file_extension.h"
#include "octaclay/core/geometry/octahedral.h"

#include <filesystem>
#include <string>
#include <system_error>

namespace octaclay::app {

/// Throws Error(InvalidArgument) unless size is a power of two in 2 … 8192.
inline void requireDocumentSize(int size) {
  if (!core::isValidSize(size))
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "--size " + std::to_string(size) + " is not a power of two from " +
                          std::to_string(core::kMinSize) + " to " + std::to_string(core::kMaxSize));
}

/// Throws Error(InvalidArgument) unless output ends in .exr and names another file than input.
inline void requireNewDocumentOutput(const std::string& input, const std::string& output) {
  if (core::lowerExtension(output) != ".exr")
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "-o " + output + ": an Octaclay document is written as .exr");
  namespace fs = std::filesystem;
  std::error_code inputError, outputError, linkError;
  const fs::path a = fs::weakly_canonical(input, inputError);
  const fs::path b = fs::weakly_canonical(output, outputError);
  bool same = !inputError && !outputError
                  ? a == b
                  : fs::path(input).lexically_normal() == fs::path(output).lexically_normal();
  if (!same) same = fs::equivalent(input, output, linkError) && !linkError; // a hard link
  if (same)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "-o " + output +
                          " is the input: write the result to another file (the input is kept "
                          "so a bad result can be compared and thrown away)");
}

} // namespace octaclay::app
