// Based on: Geomview's OFF manual page.

#include "import/mesh_reader_common.h"

#include "octaclay/core/error.h"

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

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
} // namespace octaclay::core::detail
