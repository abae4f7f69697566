// Strict, bounds-checked readers for the four mesh formats validation accepts: the file is read
// here and handed to its format's reader (obj_reader.cpp, ply_reader.cpp, stl_reader.cpp,
// off_reader.cpp).

#include "import/mesh_readers.h"

#include "import/mesh_reader_common.h"

#include "octaclay/core/error.h"

#include <string>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

RawMesh readRawMesh(const fs::path& path) {
  const auto format = meshFormatFromPath(path);
  if (!format)
    throw Error(ErrorKind::InvalidArgument,
                "cannot read " + path.string() +
                    ": unknown mesh format; use .obj, .ply, .stl or .off");
  return parseRawMesh(path, *format, readAll(path));
}

RawMesh parseRawMesh(const fs::path& path, MeshFormat format, std::string_view text) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) fail(path, "the file is empty");
  switch (format) {
  case MeshFormat::Obj:
    return readObj(path, text);
  case MeshFormat::Off:
    return readOff(path, text);
  case MeshFormat::Ply:
    return readPly(path, text);
  case MeshFormat::Stl:
    return readStl(path, text);
  }
  fail(path, "unknown mesh format");
}

} // namespace octaclay::core::detail
