#include "import/mesh_reader_common.h"

#include "octaclay/core/error.h"

#include <charconv>
#include <fstream>
#include <limits>
#include <system_error>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

// Files larger than this are refused before allocating: nothing the modeller imports is near
// it, and a corrupt size field must not allocate gigabytes.
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(2) << 30;

} // namespace

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

} // namespace octaclay::core::detail
