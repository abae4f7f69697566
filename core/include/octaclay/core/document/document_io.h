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
  int size = 0; ///< N of the ball; a torus's or plane's width
  Topology topology = Topology::Octahedral;
  int width = 0, height = 0; ///< in cells: the image has (width+1)×(height+1) samples
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

/// How a document's pixels are compressed in the file. Automatic is the measured choice
/// (docs/documents.md: size against time at N = 1024, 4096 and 8192); the others are there to
/// measure it again (bench_document_io). Every choice reads back bit-exact.
enum class DocumentCompression { Automatic, None, Rle, Zips, Zip };

struct DocumentWriteOptions {
  DocumentCompression compression = DocumentCompression::Automatic;
  int zipLevel = 1; ///< 1 (fastest) .. 9 (smallest), for Zips and Zip
};

/// Writes atomically: into a temporary file beside path, then renamed over it, so a failure
/// never leaves a partial file and never replaces a good one. Throws Error(Io). The file is
/// written as it is encoded (OpenEXR's thread pool, bands of rows), never built whole in memory:
/// beside the document it holds a few MB.
void writeDocument(const Document& document, const std::filesystem::path& path,
                   const DocumentWriteOptions& options = {});

} // namespace octaclay::core
