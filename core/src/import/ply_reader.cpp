// Based on: Paul Bourke's PLY description (Turk's format), ASCII and binary of either byte order.

#include "import/mesh_reader_common.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

std::string formatNumber(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e18) return std::to_string(static_cast<long long>(v));
  return std::to_string(v);
}

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

} // namespace

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
  // Every vertex element must give positions, or faces could index vertices that never come.
  for (const PlyElement& e : elements) {
    if (e.name != "vertex") continue;
    bool axes[3] = {false, false, false};
    for (const PlyProperty& property : e.properties)
      for (int k = 0; k < 3; ++k)
        if (!property.isList && property.name == std::string(1, char('x' + k))) axes[k] = true;
    if (!(axes[0] && axes[1] && axes[2]))
      fail(path, "the vertex element has no x, y and z properties");
  }
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
} // namespace octaclay::core::detail
