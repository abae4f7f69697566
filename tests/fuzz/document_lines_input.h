// How document_lines_fuzzer reads its input, shared with make_fuzz_corpus so that its seeds are
// valid files: byte 0 picks the document (bit 0: RLE, else uncompressed; bit 1: the positions
// alone, else every layer too); the rest replaces everything after the document's header (the
// offset table and the lines), so that raw_exr_lines' reader, not OpenEXR's header parser, is
// what the input reaches.
#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <stdexcept>
#include <vector>

namespace document_lines_input {

constexpr int kSize = 8; // N: 9 lines of 9 samples

/// A small painted document (diffuse painted, feature uniform, a mask) in one of the fuzzer's
/// files: its header bytes up to the offset table, the rest of the file, and its header.
struct Template {
  std::vector<std::uint8_t> head, body;
  Imf::Header header;
};

/// The document written as compression (RLE or none) to a file at scratch, split where the
/// offset table starts: the first of its kSize + 1 offsets points just past the table.
inline Template makeTemplate(bool rle, const std::filesystem::path& scratch) {
  using namespace octaclay::core;
  Document doc = makeDocument(makeBaseShape(BaseShape::Blob, kSize));
  const std::size_t texels = doc.positions.texelCount();
  doc.diffuse.texels.assign(texels * 4, 0.5f);
  for (std::size_t t = 0; t < doc.diffuse.texels.size(); t += 3)
    doc.diffuse.texels[t] = float(t % 17) / 16.0f;
  doc.hasMask = true;
  writeDocument(doc, scratch, {rle ? DocumentCompression::Rle : DocumentCompression::None, 1});
  std::ifstream in(scratch, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  Template t;
  t.header = Imf::InputFile(scratch.c_str()).header();
  const std::size_t table = 8 * (kSize + 1);
  for (std::size_t k = 8; k + table <= bytes.size(); ++k) {
    std::uint64_t first;
    std::memcpy(&first, bytes.data() + k, 8);
    if (first == k + table) {
      t.head.assign(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(k));
      t.body.assign(bytes.begin() + static_cast<std::ptrdiff_t>(k), bytes.end());
      return t;
    }
  }
  throw std::logic_error("document_lines_input: no offset table found");
}

} // namespace document_lines_input
