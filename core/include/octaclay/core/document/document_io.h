#pragma once

#include "octaclay/core/document/document.h"

#include <filesystem>
#include <string>
#include <vector>

namespace octaclay::core {

inline constexpr int kDocumentFormatVersion = 1;

struct DocumentReadOptions {
  bool layers = true; ///< false: positions only (layers keep their defaults), for info
};

/// What an Octaclay EXR's header says, readable without loading pixels.
struct DocumentHeader {
  int size = 0;
  int formatVersion = 0;
  std::vector<std::string> channels;
};

/// Reads the header of an Octaclay document. Throws Error(Io) when the file cannot be opened and
/// Error(InvalidInput) naming the problem for a non-EXR, a non-Octaclay EXR, a newer format
/// version, missing P channels, or a size that is not (2^k+1)².
DocumentHeader readDocumentHeader(const std::filesystem::path& path);

/// Reads a document (positions bit-exact). Same errors as readDocumentHeader, plus
/// Error(InvalidInput) for truncated or corrupt pixel data and non-finite positions.
Document readDocument(const std::filesystem::path& path, const DocumentReadOptions& options = {});

/// Writes atomically: into a temporary file beside path, then renamed over it, so a failure
/// never leaves a partial file and never replaces a good one. Throws Error(Io).
void writeDocument(const Document& document, const std::filesystem::path& path);

} // namespace octaclay::core
