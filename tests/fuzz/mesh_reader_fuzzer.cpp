// libFuzzer target for one mesh reader (issue 19), built once per format with
// OCTACLAY_FUZZ_FORMAT naming it (Obj, Ply, Stl, Off): any input must be read or refused with
// core::Error (truncated, malformed or hostile files) — never crash, read out of bounds,
// overflow or allocate without bound. Anything else escaping (or a sanitizer report) is a
// finding. The input goes through parseRawMesh, the in-memory entry behind readRawMesh.

#include "import/mesh_readers.h"

#include "octaclay/core/error.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

using octaclay::core::MeshFormat;

constexpr MeshFormat kFormat = MeshFormat::OCTACLAY_FUZZ_FORMAT;

// OBJ material libraries are looked for beside this (missing) file: they become notes.
constexpr const char* kPath = "/nonexistent/fuzz-input";

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto raw = octaclay::core::detail::parseRawMesh(kPath, kFormat, text);
    // A mesh that reads has every face's corners among its vertices, and corner texture
    // coordinates for every triangle or none. (Its colours may not match its vertices, as in a
    // PLY with two vertex elements: validation refuses a colour count other than #V.)
    const std::size_t vertices = raw.mesh.positions.size();
    for (const auto& triangle : raw.mesh.triangles)
      for (std::uint32_t corner : triangle)
        if (corner >= vertices) std::abort();
    if (!raw.cornerUv.empty() && raw.cornerUv.size() != raw.mesh.triangles.size()) std::abort();
  } catch (const octaclay::core::Error&) {
  }
  return 0;
}
