// Strict, bounds-checked readers for the four mesh formats validation accepts.
// Based on: the OBJ vertex/face subset of Wavefront's "Object Files (.obj)" appendix, Paul
// Bourke's PLY description (Turk's format), the STL section of 3D Systems' "SLC/StereoLithography
// Interface Specification" (1988) and Geomview's OFF manual page.

#include "import/mesh_readers.h"

#include "octaclay/core/error.h"
#include "octaclay/core/export/mesh_io.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

using Tri = std::array<std::uint32_t, 3>;

// Files larger than this are refused before allocating: nothing the modeller imports is near
// it, and a corrupt size field must not allocate gigabytes.
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(2) << 30;

[[noreturn]] void fail(const fs::path& path, const std::string& what) {
  throw Error(ErrorKind::InvalidInput, path.string() + ": " + what);
}

std::string readAll(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw Error(ErrorKind::Io, "cannot open " + path.string() + ": no such file");
  if (!fs::is_regular_file(path, ec))
    throw Error(ErrorKind::Io, "cannot open " + path.string() + ": not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw Error(ErrorKind::Io, "cannot read " + path.string() + ": " + ec.message());
  if (size > kMaxFileBytes)
    fail(path, "the file is larger than 2 GiB; decimate the mesh before importing it");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorKind::Io, "cannot open " + path.string() + ": permission denied?");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size))
    throw Error(ErrorKind::Io, "cannot read " + path.string() + ": the read stopped early");
  return text;
}

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// Whitespace-separated tokens of one line.
struct Tokens {
  std::string_view rest;
  bool next(std::string_view& token) {
    std::size_t i = 0;
    while (i < rest.size() && isSpace(rest[i]))
      ++i;
    if (i == rest.size()) return false;
    std::size_t j = i;
    while (j < rest.size() && !isSpace(rest[j]))
      ++j;
    token = rest.substr(i, j - i);
    rest.remove_prefix(j);
    return true;
  }
};

// Walks a text by lines or by tokens, counting lines for messages.
class TextCursor {
public:
  /// linesBefore: how many lines precede pos, so numbers in messages match the file.
  explicit TextCursor(std::string_view text, std::size_t pos = 0, std::size_t linesBefore = 0)
      : text_(text), pos_(pos), newlines_(linesBefore) {}

  /// The next line without its terminator; false at the end of the text.
  bool line(std::string_view& out) {
    if (pos_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    out = text_.substr(pos_, end - pos_);
    if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
    pos_ = end + 1;
    ++line_;
    return true;
  }

  /// The next whitespace-separated token, across lines; false at the end of the text.
  bool token(std::string_view& out) {
    while (pos_ < text_.size() && isSpace(text_[pos_])) {
      if (text_[pos_] == '\n') ++newlines_;
      ++pos_;
    }
    if (pos_ >= text_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_]))
      ++pos_;
    out = text_.substr(start, pos_ - start);
    return true;
  }

  /// Skips to the start of the next line (token mode).
  void skipLine() {
    const std::size_t end = text_.find('\n', pos_);
    pos_ = end == std::string_view::npos ? text_.size() : end;
  }

  /// The 1-based line of the last line() call, or of the last token.
  std::size_t lineNumber() const { return line_ + newlines_ + 1 - (line_ > 0 ? 1 : 0); }
  std::size_t remaining() const { return pos_ < text_.size() ? text_.size() - pos_ : 0; }

private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
  std::size_t newlines_ = 0;
};

std::string quoted(std::string_view token) {
  // Binary garbage in a message would corrupt the terminal; show at most 20 printable bytes.
  std::string out = "'";
  for (char c : token.substr(0, 20))
    out += (c >= 32 && c < 127) ? c : '?';
  if (token.size() > 20) out += "...";
  return out + "'";
}

bool parseDouble(std::string_view token, double& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto r = std::from_chars(token.data(), token.data() + token.size(), out);
  return r.ec == std::errc() && r.ptr == token.data() + token.size();
}

bool parseInt(std::string_view token, long long& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto r = std::from_chars(token.data(), token.data() + token.size(), out);
  return r.ec == std::errc() && r.ptr == token.data() + token.size();
}

std::string formatNumber(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e18) return std::to_string(static_cast<long long>(v));
  return std::to_string(v);
}

std::uint32_t swapBytes(std::uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

// Doubles beyond float's range become ±infinity, which validation reports as non-finite.
float toFloat(double v) {
  // Converting an out-of-range double to float is undefined behaviour, so saturate explicitly.
  constexpr double kMax = std::numeric_limits<float>::max();
  if (v > kMax) return std::numeric_limits<float>::infinity();
  if (v < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(v);
}

void addPolygon(std::vector<Tri>& triangles, const std::vector<std::uint32_t>& poly,
                std::size_t& shortFaces) {
  if (poly.size() < 3) {
    ++shortFaces;
    return;
  }
  // A fan keeps the polygon's winding; polygons in these files are small and convex enough.
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    triangles.push_back({poly[0], poly[k], poly[k + 1]});
}

// ---------------------------------------------------------------------------------------- OBJ

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

// ---------------------------------------------------------------------------------------- OFF

RawMesh readOff(const fs::path& path, std::string_view text) {
  RawMesh raw;
  TextCursor cursor(text);
  // Next line with content, comments stripped.
  auto contentLine = [&](std::string_view& out) {
    std::string_view line;
    while (cursor.line(line)) {
      line = line.substr(0, line.find('#'));
      Tokens probe{line};
      std::string_view token;
      if (probe.next(token)) {
        out = line;
        return true;
      }
    }
    return false;
  };
  auto where = [&] { return "line " + std::to_string(cursor.lineNumber()); };

  std::string_view line;
  if (!contentLine(line)) fail(path, "the file is empty");
  Tokens header{line};
  std::string_view keyword;
  header.next(keyword);
  const bool isOff = keyword.size() >= 3 && keyword.substr(keyword.size() - 3) == "OFF" &&
                     keyword.find_first_not_of("STCN") == keyword.size() - 3;
  if (!isOff) {
    if (keyword.ends_with("OFF"))
      fail(path, "only 3-D OFF is supported (" + quoted(keyword) + " is not)");
    fail(path, "not an OFF file: the first line must be OFF, not " + quoted(keyword));
  }
  Tokens counts = header;
  std::string_view token;
  if (!Tokens{counts}.next(token)) {
    if (!contentLine(line)) fail(path, "truncated: the vertex and face counts are missing");
    counts = Tokens{line};
  } else if (token == "BINARY") {
    fail(path, "binary OFF is not supported; save it as ASCII OFF, PLY or OBJ");
  }
  long long vertexCount = 0, faceCount = 0;
  if (!counts.next(token) || !parseInt(token, vertexCount) || !counts.next(token) ||
      !parseInt(token, faceCount) || vertexCount < 0 || faceCount < 0)
    fail(path, where() + ": expected the vertex, face and edge counts");
  // Each vertex or face needs at least two bytes of text; larger counts are a lie.
  if (static_cast<unsigned long long>(vertexCount) + static_cast<unsigned long long>(faceCount) >
      cursor.remaining())
    fail(path, "truncated: the header promises " + std::to_string(vertexCount) + " vertices and " +
                   std::to_string(faceCount) + " faces, more than the file can hold");

  raw.mesh.positions.reserve(static_cast<std::size_t>(vertexCount));
  for (long long i = 0; i < vertexCount; ++i) {
    if (!contentLine(line))
      fail(path, "truncated: the header promises " + std::to_string(vertexCount) +
                     " vertices, the file ends after " + std::to_string(i));
    Tokens tokens{line};
    double xyz[3];
    for (double& c : xyz) {
      if (!tokens.next(token)) fail(path, where() + ": a vertex needs three coordinates");
      if (!parseDouble(token, c)) fail(path, where() + ": " + quoted(token) + " is not a number");
    }
    raw.mesh.positions.push_back({toFloat(xyz[0]), toFloat(xyz[1]), toFloat(xyz[2])});
  }
  std::vector<std::uint32_t> poly;
  for (long long i = 0; i < faceCount; ++i) {
    if (!contentLine(line))
      fail(path, "truncated: the header promises " + std::to_string(faceCount) +
                     " faces, the file ends after " + std::to_string(i));
    Tokens tokens{line};
    long long n = 0;
    if (!tokens.next(token) || !parseInt(token, n) || n < 0)
      fail(path, where() + ": a face must start with its vertex count");
    poly.clear();
    for (long long k = 0; k < n; ++k) {
      long long index = 0;
      if (!tokens.next(token))
        fail(path, where() + ": the face lists " + std::to_string(n) + " vertices but has " +
                       std::to_string(k));
      if (!parseInt(token, index)) fail(path, where() + ": " + quoted(token) + " is not an index");
      if (index < 0 || index >= vertexCount)
        fail(path, where() + ": face " + std::to_string(i + 1) + " refers to vertex index " +
                       std::to_string(index) + ", but the file has " + std::to_string(vertexCount) +
                       " vertices (OFF counts from 0)");
      poly.push_back(static_cast<std::uint32_t>(index));
    }
    addPolygon(raw.mesh.triangles, poly, raw.shortFaces);
  }
  return raw;
}

// ---------------------------------------------------------------------------------------- PLY

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

std::optional<PlyType> plyType(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::I8;
  if (name == "uchar" || name == "uint8") return PlyType::U8;
  if (name == "short" || name == "int16") return PlyType::I16;
  if (name == "ushort" || name == "uint16") return PlyType::U16;
  if (name == "int" || name == "int32") return PlyType::I32;
  if (name == "uint" || name == "uint32") return PlyType::U32;
  if (name == "float" || name == "float32") return PlyType::F32;
  if (name == "double" || name == "float64") return PlyType::F64;
  return std::nullopt;
}

std::size_t plySize(PlyType t) {
  switch (t) {
  case PlyType::I8:
  case PlyType::U8:
    return 1;
  case PlyType::I16:
  case PlyType::U16:
    return 2;
  case PlyType::I32:
  case PlyType::U32:
  case PlyType::F32:
    return 4;
  case PlyType::F64:
    return 8;
  }
  return 1;
}

// A colour channel in [0, 1]: integers are scaled by their type's largest value (uchar 255),
// floats are taken as they are.
float plyColour(PlyType type, double v) {
  double scale = 1;
  switch (type) {
  case PlyType::I8:
    scale = 127;
    break;
  case PlyType::U8:
    scale = 255;
    break;
  case PlyType::I16:
    scale = 32767;
    break;
  case PlyType::U16:
    scale = 65535;
    break;
  case PlyType::I32:
    scale = 2147483647.0;
    break;
  case PlyType::U32:
    scale = 4294967295.0;
    break;
  case PlyType::F32:
  case PlyType::F64:
    break;
  }
  const double c = v / scale;
  return std::isfinite(c) ? static_cast<float>(std::clamp(c, 0.0, 1.0)) : 0.0f;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::F32;
  bool isList = false;
  PlyType countType = PlyType::U8;
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, LittleEndian, BigEndian };

// Reads PLY scalars from ASCII tokens or binary bytes, with bounds checks either way.
class PlyScalars {
public:
  PlyScalars(const fs::path& path, std::string_view text, std::size_t dataStart,
             std::size_t headerLines, PlyFormat format)
      : path_(path), data_(text.substr(dataStart)), format_(format),
        text_(text, dataStart, headerLines) {}

  double read(PlyType type, const std::string& where) {
    if (format_ == PlyFormat::Ascii) {
      std::string_view token;
      if (!text_.token(token)) fail(path_, "truncated: the file ends inside " + where);
      double v = 0;
      if (!parseDouble(token, v))
        fail(path_, "line " + std::to_string(text_.lineNumber()) + ": " + quoted(token) +
                        " is not a number (in " + where + ")");
      return v;
    }
    const std::size_t size = plySize(type);
    if (data_.size() - pos_ < size) fail(path_, "truncated: the file ends inside " + where);
    unsigned char bytes[8];
    std::memcpy(bytes, data_.data() + pos_, size);
    pos_ += size;
    const bool fileIsBig = format_ == PlyFormat::BigEndian;
    if (fileIsBig != (std::endian::native == std::endian::big)) std::reverse(bytes, bytes + size);
    switch (type) {
    case PlyType::I8:
      return static_cast<double>(static_cast<std::int8_t>(bytes[0]));
    case PlyType::U8:
      return static_cast<double>(bytes[0]);
    case PlyType::I16:
      return static_cast<double>(load<std::int16_t>(bytes));
    case PlyType::U16:
      return static_cast<double>(load<std::uint16_t>(bytes));
    case PlyType::I32:
      return static_cast<double>(load<std::int32_t>(bytes));
    case PlyType::U32:
      return static_cast<double>(load<std::uint32_t>(bytes));
    case PlyType::F32:
      return static_cast<double>(load<float>(bytes));
    case PlyType::F64:
      return load<double>(bytes);
    }
    return 0;
  }

  /// Upper bound on how many more scalars the data can hold (one byte or two characters each).
  std::size_t capacity() const {
    return format_ == PlyFormat::Ascii ? text_.remaining() / 2 + 1 : data_.size() - pos_;
  }

private:
  template <class T> static T load(const unsigned char* bytes) {
    T v;
    std::memcpy(&v, bytes, sizeof v);
    return v;
  }

  const fs::path& path_;
  std::string_view data_;
  PlyFormat format_;
  std::size_t pos_ = 0;
  TextCursor text_;
};

RawMesh readPly(const fs::path& path, std::string_view text) {
  TextCursor header(text);
  std::string_view line;
  if (!header.line(line) || line != "ply") fail(path, "not a PLY file: it must start with 'ply'");
  std::optional<PlyFormat> format;
  std::vector<PlyElement> elements;
  bool ended = false;
  std::size_t dataStart = 0;
  while (!ended && header.line(line)) {
    const std::string where = "header line " + std::to_string(header.lineNumber());
    Tokens tokens{line};
    std::string_view keyword, a, b, c, d;
    if (!tokens.next(keyword)) continue;
    if (keyword == "format") {
      tokens.next(a);
      if (a == "ascii")
        format = PlyFormat::Ascii;
      else if (a == "binary_little_endian")
        format = PlyFormat::LittleEndian;
      else if (a == "binary_big_endian")
        format = PlyFormat::BigEndian;
      else
        fail(path, where + ": unknown format " + quoted(a));
    } else if (keyword == "element") {
      unsigned long long count = 0;
      if (!tokens.next(a) || !tokens.next(b) ||
          std::from_chars(b.data(), b.data() + b.size(), count).ptr != b.data() + b.size())
        fail(path, where + ": expected 'element <name> <count>'");
      elements.push_back({std::string(a), count, {}});
    } else if (keyword == "property") {
      if (elements.empty()) fail(path, where + ": a property before any element");
      PlyProperty property;
      if (!tokens.next(a)) fail(path, where + ": incomplete property");
      if (a == "list") {
        if (!tokens.next(b) || !tokens.next(c) || !tokens.next(d))
          fail(path, where + ": expected 'property list <count type> <type> <name>'");
        const auto countType = plyType(b), type = plyType(c);
        if (!countType || !type || *countType == PlyType::F32 || *countType == PlyType::F64)
          fail(path, where + ": bad list types " + quoted(b) + " " + quoted(c));
        property = {std::string(d), *type, true, *countType};
      } else {
        const auto type = plyType(a);
        if (!type || !tokens.next(b)) fail(path, where + ": bad property type " + quoted(a));
        property = {std::string(b), *type, false, PlyType::U8};
      }
      elements.back().properties.push_back(property);
    } else if (keyword == "end_header") {
      ended = true;
      // The data starts after this line's '\n', whatever the line ending.
      dataStart = static_cast<std::size_t>(line.data() - text.data()) + line.size();
      if (dataStart < text.size() && text[dataStart] == '\r') ++dataStart;
      if (dataStart < text.size() && text[dataStart] == '\n') ++dataStart;
    } else if (keyword != "comment" && keyword != "obj_info") {
      fail(path, where + ": unknown header keyword " + quoted(keyword));
    }
  }
  if (!ended) fail(path, "truncated: the header has no end_header line");
  if (!format) fail(path, "the header has no format line");

  const PlyElement* vertexElement = nullptr;
  for (const PlyElement& e : elements)
    if (e.name == "vertex") vertexElement = &e;
  if (!vertexElement) fail(path, "the file has no vertex element");
  const unsigned long long vertexCount = vertexElement->count;
  if (vertexCount >= std::numeric_limits<std::uint32_t>::max())
    fail(path, "more than 4 billion vertices");

  RawMesh raw;
  PlyScalars scalars(path, text, dataStart, header.lineNumber(), *format);
  std::vector<std::uint32_t> poly;
  std::vector<double> list;
  for (const PlyElement& element : elements) {
    if (element.properties.empty()) continue;
    // Every element takes at least one scalar per property: a larger count is a lie.
    if (element.count > scalars.capacity() / element.properties.size() + 1)
      fail(path, "truncated: the header promises " + std::to_string(element.count) + " '" +
                     element.name + "' elements, more than the file can hold");
    const bool isVertex = element.name == "vertex";
    const bool isFace = element.name == "face";
    const bool isStrip = element.name == "tristrips";
    int xyz[3] = {-1, -1, -1};
    int rgba[4] = {-1, -1, -1, -1};
    int indices = -1;
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (isVertex && !property.isList) {
        if (property.name == "x") xyz[0] = int(p);
        if (property.name == "y") xyz[1] = int(p);
        if (property.name == "z") xyz[2] = int(p);
        // red green blue [alpha], as most writers name them; some prefix diffuse_.
        const std::string_view colour = std::string_view(property.name).starts_with("diffuse_")
                                            ? std::string_view(property.name).substr(8)
                                            : std::string_view(property.name);
        if (colour == "red") rgba[0] = int(p);
        if (colour == "green") rgba[1] = int(p);
        if (colour == "blue") rgba[2] = int(p);
        if (colour == "alpha") rgba[3] = int(p);
      }
      if ((isFace || isStrip) && property.isList &&
          (indices < 0 || property.name == "vertex_indices" || property.name == "vertex_index"))
        indices = int(p);
    }
    if (isVertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
      fail(path, "the vertex element has no x, y and z properties");
    if (isVertex) raw.mesh.positions.reserve(static_cast<std::size_t>(element.count));
    const bool coloured = isVertex && rgba[0] >= 0 && rgba[1] >= 0 && rgba[2] >= 0;
    if (isVertex && !coloured && (rgba[0] >= 0 || rgba[1] >= 0 || rgba[2] >= 0))
      raw.notes.push_back("the vertices have only some of red, green and blue: colours ignored");
    if (coloured) raw.vertexColours.reserve(static_cast<std::size_t>(element.count));

    for (unsigned long long i = 0; i < element.count; ++i) {
      const std::string where = element.name + " " + std::to_string(i + 1);
      double position[3] = {0, 0, 0};
      float colour[4] = {0, 0, 0, 1};
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (!property.isList) {
          const double v = scalars.read(property.type, where);
          for (int k = 0; k < 3; ++k)
            if (xyz[k] == int(p)) position[k] = v;
          for (int k = 0; k < 4; ++k)
            if (rgba[k] == int(p)) colour[k] = plyColour(property.type, v);
          continue;
        }
        const double n = scalars.read(property.countType, where);
        if (n < 0 || n != std::floor(n) || n > double(scalars.capacity()))
          fail(path, where + ": bad list length " + formatNumber(n));
        const bool keep = int(p) == indices;
        if (keep) list.clear();
        for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {
          const double v = scalars.read(property.type, where);
          if (keep) list.push_back(v);
        }
        if (!keep) continue;
        poly.clear();
        for (double v : list) {
          if (isStrip && v == -1) {
            poly.push_back(std::numeric_limits<std::uint32_t>::max());
            continue;
          }
          if (v != std::floor(v) || v < 0 || v >= double(vertexCount))
            fail(path, where + " refers to vertex index " + formatNumber(v) +
                           ", but the file has " + std::to_string(vertexCount) +
                           " vertices (PLY counts from 0)");
          poly.push_back(static_cast<std::uint32_t>(v));
        }
        if (isFace) {
          addPolygon(raw.mesh.triangles, poly, raw.shortFaces);
        } else {
          // A strip k0 k1 k2 k3 … is triangles (k0 k1 k2), (k2 k1 k3), … ; -1 restarts it.
          const std::uint32_t restart = std::numeric_limits<std::uint32_t>::max();
          std::size_t start = 0;
          for (std::size_t k = 0; k + 2 < poly.size(); ++k) {
            if (poly[k] == restart) start = k + 1;
            if (poly[k] == restart || poly[k + 1] == restart || poly[k + 2] == restart) continue;
            const bool odd = (k - start) % 2 == 1;
            raw.mesh.triangles.push_back(odd ? Tri{poly[k + 1], poly[k], poly[k + 2]}
                                             : Tri{poly[k], poly[k + 1], poly[k + 2]});
          }
        }
      }
      if (isVertex)
        raw.mesh.positions.push_back(
            {toFloat(position[0]), toFloat(position[1]), toFloat(position[2])});
      if (coloured) raw.vertexColours.push_back({colour[0], colour[1], colour[2], colour[3]});
    }
  }
  return raw;
}

// ---------------------------------------------------------------------------------------- STL

RawMesh readStl(const fs::path& path, std::string_view text) {
  RawMesh raw;
  raw.cornersPerFace = true;
  std::uint32_t binaryCount = 0;
  if (text.size() >= 84) {
    std::memcpy(&binaryCount, text.data() + 80, 4);
    if constexpr (std::endian::native == std::endian::big) binaryCount = swapBytes(binaryCount);
  }
  const bool sizeMatches =
      text.size() >= 84 && std::uint64_t(text.size()) == 84 + 50 * std::uint64_t(binaryCount);
  const std::size_t firstToken = text.find_first_not_of(" \t\r\n");
  const bool saysSolid =
      firstToken != std::string_view::npos && text.substr(firstToken, 5) == "solid";
  // Binary files may also start with "solid"; the size check tells them apart. A truncated
  // binary file that starts with "solid" has no "facet" keyword near its start.
  const bool looksAscii = saysSolid && text.substr(0, 1024).find("facet") != std::string_view::npos;

  const bool hasNul = text.substr(0, 1024).find('\0') != std::string_view::npos;
  if (sizeMatches && (!looksAscii || hasNul)) {
    raw.mesh.positions.reserve(std::size_t(binaryCount) * 3);
    raw.mesh.triangles.reserve(binaryCount);
    for (std::uint32_t f = 0; f < binaryCount; ++f) {
      const char* facet = text.data() + 84 + std::size_t(f) * 50;
      for (int k = 0; k < 3; ++k) {
        float xyz[3];
        std::memcpy(xyz, facet + 12 + 12 * k, 12);
        if constexpr (std::endian::native == std::endian::big)
          for (float& c : xyz)
            c = std::bit_cast<float>(swapBytes(std::bit_cast<std::uint32_t>(c)));
        raw.mesh.positions.push_back({xyz[0], xyz[1], xyz[2]});
      }
      raw.mesh.triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
    }
    return raw;
  }
  if (!looksAscii) {
    if (text.size() >= 84)
      fail(path, "not a readable STL file: as binary STL its header promises " +
                     std::to_string(binaryCount) + " triangles (" +
                     std::to_string(84 + 50 * std::uint64_t(binaryCount)) +
                     " bytes) but the file has " + std::to_string(text.size()) +
                     " bytes (truncated?), and it is not ASCII STL either");
    fail(path, "not an STL file: too short for binary STL and it does not start with 'solid'");
  }

  TextCursor cursor(text);
  std::string_view token;
  auto where = [&] { return "line " + std::to_string(cursor.lineNumber()); };
  auto expect = [&](std::string_view word) {
    if (!cursor.token(token))
      fail(path, "truncated: the file ends before '" + std::string(word) + "'");
    if (token != word)
      fail(path, where() + ": expected '" + std::string(word) + "', found " + quoted(token));
  };
  auto readVector = [&](double(&xyz)[3]) {
    for (double& c : xyz) {
      if (!cursor.token(token)) fail(path, "truncated: the file ends inside a facet");
      if (!parseDouble(token, c)) fail(path, where() + ": " + quoted(token) + " is not a number");
    }
  };
  expect("solid");
  cursor.skipLine(); // the solid's name
  bool ended = false;
  while (cursor.token(token)) {
    if (token == "endsolid") {
      cursor.skipLine();
      ended = true;
      continue;
    }
    if (ended && token == "solid") {
      // Some exporters write several solids into one file.
      cursor.skipLine();
      ended = false;
      continue;
    }
    if (ended || token != "facet")
      fail(path, where() + ": expected 'facet' or 'endsolid', found " + quoted(token));
    double xyz[3];
    expect("normal");
    readVector(xyz);
    expect("outer");
    expect("loop");
    const auto first = static_cast<std::uint32_t>(raw.mesh.positions.size());
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      readVector(xyz);
      raw.mesh.positions.push_back({toFloat(xyz[0]), toFloat(xyz[1]), toFloat(xyz[2])});
    }
    expect("endloop");
    expect("endfacet");
    raw.mesh.triangles.push_back({first, first + 1, first + 2});
    if (raw.mesh.positions.size() >= std::numeric_limits<std::uint32_t>::max() - 3)
      fail(path, "more than 4 billion vertices");
  }
  if (!ended) fail(path, "truncated: the file ends without 'endsolid'");
  return raw;
}

} // namespace

RawMesh readRawMesh(const fs::path& path) {
  const auto format = meshFormatFromPath(path);
  if (!format)
    throw Error(ErrorKind::InvalidArgument,
                "cannot read " + path.string() +
                    ": unknown mesh format; use .obj, .ply, .stl or .off");
  const std::string text = readAll(path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) fail(path, "the file is empty");
  switch (*format) {
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
