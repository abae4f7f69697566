#pragma once

// An uncompressed or RLE scanline OpenEXR document read and written line by line on every
// core, straight between the file and the document (pread / pwrite at each line's offset),
// instead of through OpenEXR's frame buffers, which copy and convert byte by byte on the calling
// thread. A line is a chunk: int32 y, int32 byte count, then each channel's row in the header's
// (alphabetical) channel order, little-endian, float or half (RLE: those bytes coded).
//
// OpenEXR still reads and checks the header and the offset table (InputFile, isComplete()) and
// writes the header: these files are the ones it reads and writes itself.

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/document.h"

#include <ImfHeader.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace octaclay::core::detail {

/// Whether header's pixels can go this way: no compression or RLE (coded and decoded as
/// OpenEXR's RleCompressor does, a line whose code is no smaller stored as it is), scanlines (a
/// single-part file or a part of a multi-part one), every channel sampled 1×1, float or half,
/// and this machine little-endian. Any W × H.
bool rawLinesApply(const Imf::Header& header);

/// Reads the positions (xyz; w stays 0) and, when layers is not empty, the layers the file holds
/// among them (each kept uniform, a fill value, while every texel equals the first; else full
/// texels) of the file OpenEXR opened as header, its part number part in a multi-part file (-1:
/// a single-part file; a multi-part file's part 0 then). positions is (W+1)×(H+1) already.
/// Returns false, having read nothing, when the headers are too long to find the offset table
/// (1 MiB: OpenEXR's frame buffers then read it). Every chunk's part number, line and byte
/// count are checked, and an RLE line's code must expand to exactly the line. Throws
/// Error(InvalidInput) naming the line for a short read, a chunk that is not the expected line or
/// a code that does not decode, Error(Io) when the file cannot be opened.
bool readRawLines(const std::filesystem::path& path, const Imf::Header& header,
                  GeometryImage& positions, const std::vector<Layer*>& layers, int part = -1);

/// Writes document's pixels as header's lines after OpenEXR's header bytes (magic number to the
/// end of the attributes, the offset table's place included but not filled), then fills the
/// offset table, all through sink. header's channels: P.X, P.Y, P.Z float, the layers half.
/// Called from any thread but the process's main one (a modeller's worker), its threads run at
/// the lowest CPU priority while they write, so the GUI and its GL driver keep the cores.
void writeRawLines(const Document& document, const Imf::Header& header,
                   const std::vector<std::uint8_t>& headerBytes, ByteSink& sink);

/// One part to write: its document and the header OpenEXR wrote for it.
struct RawPart {
  const Document& document;
  const Imf::Header& header;
};

/// writeRawLines for several parts: headerBytes is what OpenEXR's MultiPartOutputFile writes
/// before any pixel (magic number, version, every header, the empty header, then the offset
/// tables' places, a line each, in part order, not filled). Each chunk starts with its part
/// number. multiPart false: one part, the single-part layout (writeRawLines). RLE parts are coded
/// on every core as OpenEXR's RleCompressor codes them (a line whose code is no smaller is
/// stored as it is), in rounds of about 8 MiB whose chunks are placed one after another.
void writeRawParts(std::span<const RawPart> parts, bool multiPart,
                   const std::vector<std::uint8_t>& headerBytes, ByteSink& sink);

} // namespace octaclay::core::detail
