// Based on: the OBJ vertex/face subset of Wavefront's "Object Files (.obj)" appendix and its
// material library (.mtl) map_Kd statement.

#include "import/mesh_reader_common.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

std::string lowercase(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
  });
  return out;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && isSpace(text.front()))
    text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back()))
    text.remove_suffix(1);
  return text;
}

// A file name as an exporter wrote it: Windows separators become '/'.
fs::path fileName(std::string_view name) {
  std::string out(name);
  std::replace(out.begin(), out.end(), '\\', '/');
  return fs::path(out);
}

bool isFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

// Where a file named by another file is: as written (absolute or relative to `dir`), else
// beside the naming file under its own name (exporters often write the artist's absolute path).
std::optional<fs::path> locate(const fs::path& dir, const fs::path& name) {
  const fs::path direct = name.is_absolute() ? name : dir / name;
  if (isFile(direct)) return direct;
  if (!name.filename().empty() && isFile(dir / name.filename())) return dir / name.filename();
  return std::nullopt;
}

// The image file of a `map_Kd [options] file` line: options (-o 0 0 0, -clamp on, …) skipped,
// the rest of the line is the name, spaces included.
std::string_view mapFileName(Tokens tokens) {
  while (true) {
    Tokens probe = tokens;
    std::string_view option;
    if (!probe.next(option) || option.size() < 2 || option.front() != '-') break;
    tokens = probe;
    const std::string name = lowercase(option.substr(1));
    std::string_view argument;
    if (name == "o" || name == "s" || name == "t") { // one to three numbers
      for (int k = 0; k < 3; ++k) {
        probe = tokens;
        double ignored = 0;
        if (!probe.next(argument) || !parseDouble(argument, ignored)) break;
        tokens = probe;
      }
    } else {
      const int arguments = name == "mm" ? 2 : 1; // -blendu on, -bm 1, -imfchan r, -type sphere …
      for (int k = 0; k < arguments; ++k)
        tokens.next(argument);
    }
  }
  return trimmed(tokens.rest);
}

// The first map_Kd of the material libraries an OBJ names, resolved; a note for each library
// or texture that is missing or unreadable.
std::optional<fs::path> diffuseMap(const fs::path& objPath,
                                   const std::vector<std::string>& libraries,
                                   std::vector<std::string>& notes) {
  const fs::path dir = objPath.parent_path();
  for (const std::string& library : libraries) {
    const auto mtl = locate(dir, fileName(library));
    if (!mtl) {
      notes.push_back("material library " + library + " not found: no texture");
      continue;
    }
    std::string text;
    try {
      text = readAll(*mtl);
    } catch (const Error& e) {
      notes.push_back("material library " + library + " could not be read (" + e.what() + ")");
      continue;
    }
    TextCursor cursor(text);
    std::string_view line;
    while (cursor.line(line)) {
      Tokens tokens{line};
      std::string_view keyword;
      if (!tokens.next(keyword) || lowercase(keyword) != "map_kd") continue;
      const std::string_view name = mapFileName(tokens);
      if (name.empty()) continue;
      if (const auto texture = locate(mtl->parent_path(), fileName(name))) return texture;
      notes.push_back("texture " + std::string(name) + " (map_Kd of " + library +
                      ") not found: no texture");
      return std::nullopt;
    }
    notes.push_back("material library " + library + " has no diffuse texture (map_Kd)");
  }
  return std::nullopt;
}

} // namespace

RawMesh readObj(const fs::path& path, std::string_view text) {
  RawMesh raw;
  auto& positions = raw.mesh.positions;
  constexpr std::uint32_t kNoUv = std::numeric_limits<std::uint32_t>::max();
  // Absolute indices may point at vertices defined later in the file; those are checked at the
  // end against the final count.
  struct Forward {
    std::size_t line;
    long long index;
  };
  std::vector<Forward> forward;
  std::vector<std::uint32_t> poly, polyUv;
  // Attributes, kept aside until it is known whether every vertex or face has them: a file
  // that colours or maps only part of the surface is imported without them.
  std::vector<std::array<double, 3>> colours; ///< per vertex; NaN when it has none
  std::size_t colouredVertices = 0;
  std::vector<std::array<float, 2>> uvs;
  std::vector<std::uint32_t> triangleUv; ///< three vt indices per triangle, kNoUv when absent
  long long farthestUv = 0;              ///< the largest vt index a face used
  std::size_t farthestUvLine = 0;
  std::string badUv; ///< why the texture coordinates are unusable
  std::vector<std::string> libraries;

  TextCursor cursor(text);
  std::string_view line;
  while (cursor.line(line)) {
    Tokens tokens{line};
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    auto where = [&] { return "line " + std::to_string(cursor.lineNumber()); };
    if (keyword == "v") {
      double xyz[3];
      for (double& c : xyz) {
        std::string_view token;
        if (!tokens.next(token)) fail(path, where() + ": a vertex needs three coordinates");
        if (!parseDouble(token, c)) fail(path, where() + ": " + quoted(token) + " is not a number");
      }
      if (positions.size() >= std::numeric_limits<std::uint32_t>::max())
        fail(path, "more than 4 billion vertices");
      positions.push_back({toFloat(xyz[0]), toFloat(xyz[1]), toFloat(xyz[2])});
      // The common `v x y z r g b` extension; anything else after x y z (a w, comments) is
      // not a colour.
      std::array<double, 3> rgb{};
      std::string_view token;
      int extra = 0;
      bool numbers = true;
      while (tokens.next(token)) {
        if (extra < 3 && !parseDouble(token, rgb[extra])) numbers = false;
        ++extra;
      }
      const bool coloured = numbers && extra == 3 && std::isfinite(rgb[0]) &&
                            std::isfinite(rgb[1]) && std::isfinite(rgb[2]);
      if (!coloured) rgb.fill(std::numeric_limits<double>::quiet_NaN());
      colouredVertices += coloured ? 1 : 0;
      colours.push_back(rgb);
    } else if (keyword == "vt") {
      double uv[2] = {0, 0};
      std::string_view token;
      for (int k = 0; k < 2 && tokens.next(token); ++k)
        if (!parseDouble(token, uv[k]) || !std::isfinite(uv[k])) {
          if (badUv.empty())
            badUv = where() + ": " + quoted(token) + " is not a texture coordinate";
          uv[k] = 0;
        }
      uvs.push_back({static_cast<float>(uv[0]), static_cast<float>(uv[1])});
    } else if (keyword == "f" || keyword == "fo") {
      poly.clear();
      polyUv.clear();
      std::string_view token;
      while (tokens.next(token)) {
        // v, v/vt, v//vn or v/vt/vn.
        const std::size_t slash = token.find('/');
        const std::string_view first = token.substr(0, slash);
        long long index = 0;
        if (!parseInt(first, index))
          fail(path, where() + ": " + quoted(token) + " is not a face index");
        if (index == 0) fail(path, where() + ": face index 0 (OBJ counts vertices from 1)");
        const long long count = static_cast<long long>(positions.size());
        if (index < 0) {
          if (index < -count)
            fail(path, where() + ": relative index " + std::to_string(index) + " points before " +
                           "the first vertex (only " + std::to_string(count) + " vertices so far)");
          index = count + index + 1;
        }
        if (index > std::numeric_limits<std::uint32_t>::max())
          fail(path, where() + ": face index " + std::to_string(index) + " is out of range");
        if (index > count) forward.push_back({cursor.lineNumber(), index});
        poly.push_back(static_cast<std::uint32_t>(index - 1));

        // Texture coordinates are an attribute: a bad index drops them, not the mesh.
        std::uint32_t uv = kNoUv;
        if (slash != std::string_view::npos) {
          std::string_view second = token.substr(slash + 1);
          second = second.substr(0, second.find('/'));
          long long t = 0;
          const long long uvCount = static_cast<long long>(uvs.size());
          if (second.empty()) {
            // v//vn: no texture coordinate
          } else if (!parseInt(second, t) || t == 0 || t < -uvCount ||
                     t > std::numeric_limits<std::uint32_t>::max()) {
            if (badUv.empty())
              badUv = where() + ": " + quoted(token) + " has a bad texture coordinate index";
          } else {
            if (t < 0) t = uvCount + t + 1;
            if (t > farthestUv) {
              farthestUv = t;
              farthestUvLine = cursor.lineNumber();
            }
            uv = static_cast<std::uint32_t>(t - 1);
          }
        }
        polyUv.push_back(uv);
      }
      const std::size_t before = raw.mesh.triangles.size();
      addPolygon(raw.mesh.triangles, poly, raw.shortFaces);
      // addPolygon fans around corner 0.
      for (std::size_t k = 1; k <= raw.mesh.triangles.size() - before; ++k)
        triangleUv.insert(triangleUv.end(), {polyUv[0], polyUv[k], polyUv[k + 1]});
    } else if (keyword == "mtllib") {
      // Names are separated by spaces, but exporters also write one name with spaces in it.
      const std::string_view all = trimmed(tokens.rest);
      if (locate(path.parent_path(), fileName(all))) {
        libraries.emplace_back(all);
      } else {
        std::string_view name;
        while (tokens.next(name))
          libraries.emplace_back(name);
      }
    }
    // vn, vp, o, g, s, l, usemtl, comments: nothing the import needs.
  }
  for (const Forward& f : forward)
    if (f.index > static_cast<long long>(positions.size()))
      fail(path, "line " + std::to_string(f.line) + ": a face refers to vertex " +
                     std::to_string(f.index) + ", but the file has only " +
                     std::to_string(positions.size()) + " vertices");

  if (colouredVertices == positions.size() && !positions.empty()) {
    // Colours are written in [0, 1]; some exporters write bytes instead.
    double largest = 0;
    for (const auto& rgb : colours)
      largest = std::max({largest, rgb[0], rgb[1], rgb[2]});
    const double scale = largest > 1 ? 1.0 / 255.0 : 1.0;
    raw.vertexColours.reserve(colours.size());
    for (const auto& rgb : colours) {
      auto channel = [&](double c) { return static_cast<float>(std::clamp(c * scale, 0.0, 1.0)); };
      raw.vertexColours.push_back({channel(rgb[0]), channel(rgb[1]), channel(rgb[2]), 1.0f});
    }
  } else if (colouredVertices > 0) {
    raw.notes.push_back("only " + std::to_string(colouredVertices) + " of " +
                        std::to_string(positions.size()) +
                        " vertices have colours: colours ignored");
  }

  const std::size_t mappedCorners = static_cast<std::size_t>(std::count_if(
      triangleUv.begin(), triangleUv.end(), [](std::uint32_t t) { return t != kNoUv; }));
  if (mappedCorners > 0 && badUv.empty() && farthestUv > static_cast<long long>(uvs.size()))
    badUv = "line " + std::to_string(farthestUvLine) + ": a face refers to texture coordinate " +
            std::to_string(farthestUv) + ", but the file has only " + std::to_string(uvs.size());
  if (mappedCorners > 0 && badUv.empty() && mappedCorners < triangleUv.size()) {
    std::size_t unmapped = 0;
    for (std::size_t t = 0; t < triangleUv.size(); t += 3)
      if (triangleUv[t] == kNoUv || triangleUv[t + 1] == kNoUv || triangleUv[t + 2] == kNoUv)
        ++unmapped;
    badUv = std::to_string(unmapped) + " of " + std::to_string(triangleUv.size() / 3) +
            " triangles have none";
  }
  if (mappedCorners > 0 && !badUv.empty()) {
    raw.notes.push_back("texture coordinates ignored (" + badUv + ")");
  } else if (mappedCorners > 0) {
    raw.cornerUv.resize(raw.mesh.triangles.size());
    for (std::size_t t = 0; t < raw.cornerUv.size(); ++t)
      for (std::size_t k = 0; k < 3; ++k)
        raw.cornerUv[t][k] = uvs[triangleUv[3 * t + k]];
  }

  std::vector<std::string> mapNotes;
  const auto texture = libraries.empty() ? std::nullopt : diffuseMap(path, libraries, mapNotes);
  raw.notes.insert(raw.notes.end(), mapNotes.begin(), mapNotes.end());
  if (texture && raw.cornerUv.empty()) {
    raw.notes.push_back("texture " + texture->filename().string() +
                        " ignored: the faces have no texture coordinates");
  } else if (texture) {
    raw.diffuseTexture = *texture;
  } else if (!raw.cornerUv.empty() && libraries.empty()) {
    raw.notes.push_back("texture coordinates but no material library (mtllib): no texture");
  }
  return raw;
}
} // namespace octaclay::core::detail
