#pragma once

// A look at an EXR file's headers before OpenEXR reads them: OpenEXR sizes its tables from
// what the headers declare (a part per header, a line-offset table per data window), so a file
// that declares 10^6 parts or a window 2^30 lines high would be allocated for before any check.
// This reads the header bytes alone, bounded, and refuses such a file first.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace octaclay::core::detail {

/// What a part's header declares, as far as the scan reads it.
struct ExrPartOutline {
  int width = 0, height = 0; ///< of the data window
  std::string name;          ///< the part's "name" attribute, if any
};

struct ExrFileOutline {
  bool multiPart = false;
  std::vector<ExrPartOutline> parts; ///< one for a single-part file
};

/// The largest side and area a data window may declare (a valid document's is smaller).
inline constexpr int kLargestScannedSide = 16385;
inline constexpr long long kLargestScannedArea = 8193LL * 8193LL;

/// Reads the headers of the EXR file at path (its magic number already checked): at most
/// maxParts parts, each attribute's declared size checked against the file's length, every
/// part's data window within kLargestScannedSide and kLargestScannedArea, scan lines only (no
/// tiles, no deep data). Throws Error(InvalidInput) naming the problem; Error(Io) when the file
/// cannot be read. Reads only the header bytes (a few hundred per part), allocates only the
/// outline.
ExrFileOutline scanExrHeaders(const std::filesystem::path& path, std::size_t maxParts);

} // namespace octaclay::core::detail
