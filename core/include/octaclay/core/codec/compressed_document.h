#pragma once

// The .ocz container: magic "OCZ1", format version, N, then per layer (positions, diffuse,
// feature, mask) its codec code, parameters and stream length, then the streams; a CRC-32 of
// everything before it ends the file. Positions use the chosen geometry codec; painted layers
// use `lossless` unless told otherwise; uniform layers store only their fill.

#include "octaclay/core/codec/codec.h"
#include "octaclay/core/document/document.h"

#include <filesystem>
#include <span>
#include <vector>

namespace octaclay::core {

struct CompressOptions {
  std::string codec = "wavelet"; ///< for the positions
  CodecParams params;            ///< quality < 0 or unset (0 for lossy) = the codec's default
  std::string layerCodec = "lossless";
};

std::vector<std::uint8_t> compressDocument(const Document& doc, const CompressOptions& options);
/// Throws Error(InvalidInput) naming what is wrong: magic, version, N, codec, a stream.
Document decompressDocument(std::span<const std::uint8_t> bytes);

/// Atomic write (beside, then rename); Error(Io) when it cannot be written or read.
void writeCompressedDocument(const Document& doc, const CompressOptions& options,
                             const std::filesystem::path& path);
Document readCompressedDocument(const std::filesystem::path& path);

} // namespace octaclay::core
