#pragma once

// An uncompressed single-part scanline OpenEXR document read and written line by line on every
// core, straight between the file and the document (pread / pwrite at each line's offset),
// instead of through OpenEXR's frame buffers, which copy and convert byte by byte on the calling
// thread. An uncompressed line is a chunk: int32 y, int32 byte count, then each channel's row in
// the header's (alphabetical) channel order, little-endian, float or half.
//
// OpenEXR still reads and checks the header and the offset table (InputFile, isComplete()) and
// writes the header: these files are the ones it reads and writes itself.

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/document.h"

#include <ImfHeader.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace octaclay::core::detail {

/// Whether header's pixels can go this way: no compression, single part, scanlines, every channel
/// sampled 1×1, float or half, and this machine little-endian.
bool rawLinesApply(const Imf::Header& header);

/// Reads the positions (xyz; w stays 0) and, when layers is not empty, the layers the file holds
/// among them (each kept uniform, a fill value, while every texel equals the first; else full
/// texels) of the file OpenEXR opened as header. positions is (N+1)² already. Returns false,
/// having read nothing, when the header's attributes are too long to find the offset table (1 MiB:
/// OpenEXR's frame buffers then read it). Throws Error(InvalidInput) naming the line for a short
/// read or a chunk that is not the expected line, Error(Io) when the file cannot be opened.
bool readRawLines(const std::filesystem::path& path, const Imf::Header& header,
                  GeometryImage& positions, const std::vector<Layer*>& layers);

/// Writes document's pixels as header's lines after OpenEXR's header bytes (magic number to the
/// end of the attributes, the offset table's place included but not filled), then fills the
/// offset table, all through sink. header's channels: P.X, P.Y, P.Z float, the layers half.
/// Called from any thread but the process's main one (a modeller's worker), its threads run at
/// the lowest CPU priority while they write, so the GUI and its GL driver keep the cores.
void writeRawLines(const Document& document, const Imf::Header& header,
                   const std::vector<std::uint8_t>& headerBytes, ByteSink& sink);

} // namespace octaclay::core::detail
