// Based on: the STL section of 3D Systems' "SLC/StereoLithography Interface Specification"
// (1988), ASCII and binary.

#include "import/mesh_reader_common.h"

#include "octaclay/core/error.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

std::uint32_t swapBytes(std::uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

} // namespace

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
} // namespace octaclay::core::detail
