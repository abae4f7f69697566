// The exports' one OBJ writer: text through to_chars (shortest round-trip form, so positions are
// exact), handed to the one checked writer in large blocks so that multi-gigabyte OBJs need no
// second copy in memory.

#include "export/obj_writer.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <charconv>
#include <string_view>
#include <system_error>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

class TextWriter {
public:
  explicit TextWriter(ByteSink& out) : out_(out) { buffer_.reserve(kBlock + 256); }
  TextWriter& text(std::string_view s) {
    buffer_.append(s);
    return *this;
  }
  TextWriter& number(float value) {
    std::array<char, 32> digits{};
    const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value);
    buffer_.append(digits.data(), result.ptr);
    return *this;
  }
  TextWriter& number(std::uint64_t value) {
    std::array<char, 24> digits{};
    const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value);
    buffer_.append(digits.data(), result.ptr);
    return *this;
  }
  void endLine() {
    buffer_.push_back('\n');
    if (buffer_.size() >= kBlock) flush();
  }
  void flush() {
    out_.write(buffer_);
    buffer_.clear();
  }

private:
  static constexpr std::size_t kBlock = std::size_t{1} << 22;
  ByteSink& out_;
  std::string buffer_;
};

void writeFace(TextWriter& w, const ObjMesh& mesh, std::size_t t,
               std::span<const std::array<std::uint32_t, 3>> uvTriangles) {
  const bool uvs = !mesh.texcoords.empty(), normals = !mesh.normals.empty();
  w.text("f");
  for (std::size_t c = 0; c < 3; ++c) {
    const std::uint64_t v = std::uint64_t{mesh.triangles[t][c]} + 1; // OBJ counts from 1
    w.text(" ").number(v);
    if (uvs) w.text("/").number(std::uint64_t{uvTriangles[t][c]} + 1);
    if (normals) w.text(uvs ? "/" : "//").number(v);
  }
  w.endLine();
}

// One `o` per group: its vertices, then its faces.
void writeGroupedObjText(const ObjMesh& mesh, const ObjHeader& header, ByteSink& out) {
  TextWriter w(out);
  w.text("# ").text(header.comment).endLine();
  for (std::size_t g = 0; g < mesh.groups.size(); ++g) {
    const ObjGroup& group = mesh.groups[g];
    const bool last = g + 1 == mesh.groups.size();
    const std::size_t positionEnd = last ? mesh.positions.size() : mesh.groups[g + 1].firstPosition;
    const std::size_t triangleEnd = last ? mesh.triangles.size() : mesh.groups[g + 1].firstTriangle;
    w.text("o ").text(group.name).endLine();
    for (std::size_t k = group.firstPosition; k < positionEnd; ++k) {
      const Vec3f p = mesh.positions[k];
      w.text("v ").number(p.x).text(" ").number(p.y).text(" ").number(p.z).endLine();
    }
    if (!mesh.normals.empty())
      for (std::size_t k = group.firstPosition; k < positionEnd; ++k) {
        const Vec3f n = mesh.normals[k];
        w.text("vn ").number(n.x).text(" ").number(n.y).text(" ").number(n.z).endLine();
      }
    for (std::size_t t = group.firstTriangle; t < triangleEnd; ++t)
      writeFace(w, mesh, t, mesh.triangles);
  }
  w.flush();
}

void writeObjText(const ObjMesh& mesh, const ObjHeader& header, ByteSink& out) {
  if (!mesh.groups.empty()) return writeGroupedObjText(mesh, header, out);
  const auto& uvTriangles =
      mesh.texcoordTriangles.empty() ? mesh.triangles : mesh.texcoordTriangles;
  const bool uvs = !mesh.texcoords.empty(), normals = !mesh.normals.empty();
  const bool material = !header.materialLibrary.empty();
  TextWriter w(out);
  w.text("# ").text(header.comment).endLine();
  if (material) w.text("mtllib ").text(header.materialLibrary).endLine();
  for (const Vec3f& p : mesh.positions)
    w.text("v ").number(p.x).text(" ").number(p.y).text(" ").number(p.z).endLine();
  for (const Vec2f& uv : mesh.texcoords)
    w.text("vt ").number(uv.x).text(" ").number(uv.y).endLine();
  for (const Vec3f& n : mesh.normals)
    w.text("vn ").number(n.x).text(" ").number(n.y).text(" ").number(n.z).endLine();
  if (material) w.text("usemtl ").text(header.material).endLine();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    w.text("f");
    for (std::size_t c = 0; c < 3; ++c) {
      const std::uint64_t v = std::uint64_t{mesh.triangles[t][c]} + 1; // OBJ counts from 1
      w.text(" ").number(v);
      if (uvs) w.text("/").number(std::uint64_t{uvTriangles[t][c]} + 1);
      if (normals) w.text(uvs ? "/" : "//").number(v);
    }
    w.endLine();
  }
  w.flush();
}

bool indicesBelow(std::span<const std::array<std::uint32_t, 3>> triangles, std::size_t count) {
  for (const auto& t : triangles)
    if (t[0] >= count || t[1] >= count || t[2] >= count) return false;
  return true;
}

void requireConsistent(const ObjMesh& mesh, const fs::path& objPath) {
  const bool uvTriangles = !mesh.texcoordTriangles.empty();
  for (std::size_t g = 0; g < mesh.groups.size(); ++g)
    if ((g == 0 && (mesh.groups[0].firstPosition != 0 || mesh.groups[0].firstTriangle != 0)) ||
        (g > 0 && (mesh.groups[g].firstPosition < mesh.groups[g - 1].firstPosition ||
                   mesh.groups[g].firstTriangle < mesh.groups[g - 1].firstTriangle)) ||
        mesh.groups[g].firstPosition > mesh.positions.size() ||
        mesh.groups[g].firstTriangle > mesh.triangles.size() || !mesh.texcoords.empty())
      throw Error(ErrorKind::InvalidArgument,
                  "cannot write " + objPath.string() + ": the OBJ's objects are out of order");
  if ((uvTriangles && mesh.texcoordTriangles.size() != mesh.triangles.size()) ||
      (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) ||
      (!uvTriangles && !mesh.texcoords.empty() && mesh.texcoords.size() != mesh.positions.size()))
    throw Error(ErrorKind::InvalidArgument,
                "cannot write " + objPath.string() +
                    ": the OBJ's triangles, normals or texture coordinates disagree in count");
  if (!indicesBelow(mesh.triangles, mesh.positions.size()) ||
      (uvTriangles && !indicesBelow(mesh.texcoordTriangles, mesh.texcoords.size())))
    throw Error(ErrorKind::InvalidArgument, "cannot write " + objPath.string() +
                                                ": a triangle names a vertex that is not there");
}

} // namespace

void stageObj(const ObjMesh& mesh, const ObjHeader& header, const fs::path& objPath,
              OutputSet& set) {
  requireConsistent(mesh, objPath);
  set.stage(objPath, [&](ByteSink& out) { writeObjText(mesh, header, out); });
}

void writeObjWithMaterial(const ObjMesh& mesh, const ObjHeader& header,
                          std::span<const ObjMap> maps, const std::string& mtl,
                          const fs::path& mtlPath, const fs::path& objPath, OutputSet& set) {
  requireConsistent(mesh, objPath); // before any file is staged
  for (const ObjMap& map : maps)
    set.stageBytes(map.path, map.bytes);
  set.stageText(mtlPath, mtl);
  set.stage(objPath, [&](ByteSink& out) { writeObjText(mesh, header, out); });
}

} // namespace octaclay::core::detail
