// libFuzzer target for raw_exr_lines' reader: a document's uncompressed or RLE lines, read and
// decoded by our own code, must be refused with core::Error (a lying offset, chunk or RLE code)
// or read into the image, never read out of bounds, overflow or allocate without bound. The
// input is the file after a fixed, valid header (document_lines_input.h).
#include "document_lines_input.h"
#include "raw_exr_lines.h"

#include "octaclay/core/error.h"

#include <unistd.h>

#include <array>
#include <string>

namespace {

struct Files {
  std::filesystem::path path = std::filesystem::temp_directory_path() /
                               ("octaclay_lines_fuzz_" + std::to_string(::getpid()) + ".exr");
  std::array<document_lines_input::Template, 2> templates{
      document_lines_input::makeTemplate(false, path),
      document_lines_input::makeTemplate(true, path)};
  ~Files() { std::filesystem::remove(path); }
};

Files& files() {
  static Files f;
  return f;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  Files& f = files();
  const document_lines_input::Template& t = f.templates[data[0] & 1];
  {
    std::ofstream out(f.path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(t.head.data()),
              static_cast<std::streamsize>(t.head.size()));
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  using namespace octaclay::core;
  Document doc = makeDocument(makeBaseShape(BaseShape::Sphere, document_lines_input::kSize));
  std::vector<Layer*> layers;
  if ((data[0] & 2) == 0) layers = {&doc.diffuse, &doc.feature, &doc.mask};
  try {
    detail::readRawLines(f.path, t.header, doc.positions, layers);
  } catch (const Error&) {
  }
  return 0;
}
