#pragma once

// One document as one part of an EXR file: document_io's header, checks and pixel loops, shared
// with scene_io (a scene's objects are the parts of a multi-part file). The header and pixel
// code stay in document_io.cpp; these are its doors.

#include "octaclay/core/document/document_io.h"

#include <ImfFrameBuffer.h>
#include <ImfHeader.h>

#include <filesystem>
#include <functional>

namespace octaclay::core::detail {

// Header attributes a part of a document carries (docs/documents.md), read and written by
// document_io (one object's image) and scene_io (the object's name and placement).
inline constexpr const char* kParameterizationAttribute = "octaclay.parameterization";
// How the image closes up (core::Topology's name); absent in files of the ball alone. The torus's
// and plane's width and height in cells, which must agree with the data window.
inline constexpr const char* kTopologyAttribute = "octaclay.topology";
inline constexpr const char* kWidthAttribute = "octaclay.width";
inline constexpr const char* kHeightAttribute = "octaclay.height";

/// OpenEXR's pool, one thread per core, started once: the thread count to hand OpenEXR's files.
int exrThreads();

/// Error(Io) for a folder, a non-regular file or one that cannot be opened; Error(InvalidInput)
/// for a file that is not an OpenEXR file.
void requireExrMagic(const std::filesystem::path& path);

/// What readDocumentHeader checks of a header (any part's), with its messages.
DocumentHeader checkDocumentHeader(const std::filesystem::path& path, const Imf::Header& header);

/// The header writeDocument writes for document: format, parameterization, sampling, channels
/// and compression.
Imf::Header documentPartHeader(const Document& document, const DocumentWriteOptions& options);

/// Hands writePixels a frame buffer and its row count per band, in order, until every row of
/// header's data window was handed over (the part or file writes them).
void writeDocumentPixels(const Document& document, const Imf::Header& header,
                         const std::function<void(const Imf::FrameBuffer&, int rows)>& writePixels);

/// Reads a document whose header was checked (checkDocumentHeader) band by band through
/// readPixels(frame, firstRow, lastRow) (data-window rows, inclusive), then checks positions and
/// layers as readDocument does. part: the header's part number in a multi-part file (-1: a
/// single-part file), for the uncompressed lines read straight from the file (raw_exr_lines).
/// OpenEXR's exceptions pass through.
Document readDocumentPixels(
    const std::filesystem::path& path, const Imf::Header& header, const DocumentHeader& checked,
    const DocumentReadOptions& options,
    const std::function<void(const Imf::FrameBuffer&, int firstRow, int lastRow)>& readPixels,
    int part = -1);

/// readDocument that shows the checked header to inspect (which may throw) before any pixel
/// memory is taken.
Document readDocumentInspecting(const std::filesystem::path& path,
                                const DocumentReadOptions& options,
                                const std::function<void(const Imf::Header&)>& inspect);

/// writeDocument with attributes added to its header by addAttributes.
void writeDocumentWithAttributes(const Document& document, const std::filesystem::path& path,
                                 const DocumentWriteOptions& options,
                                 const std::function<void(Imf::Header&)>& addAttributes);

} // namespace octaclay::core::detail
