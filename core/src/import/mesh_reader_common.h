// What the mesh readers (one file per format) share: the file read, line and token walks, and
// number parsing that reports malformed input as Error(InvalidInput) naming the file.
#pragma once

#include "import/mesh_readers.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core::detail {

using Tri = std::array<std::uint32_t, 3>;

/// Throws Error(InvalidInput) with the message "<path>: <what>".
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what);

/// The whole file, refused (Error(InvalidInput)) when larger than 2 GiB; Error(Io) when it
/// cannot be opened or read.
std::string readAll(const std::filesystem::path& path);

inline bool isSpace(char c) {
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

/// The token in single quotes, for messages: at most 20 bytes, unprintable ones as '?'.
std::string quoted(std::string_view token);

/// The whole token as a number (a leading '+' allowed); false when it is not one.
bool parseDouble(std::string_view token, double& out);
bool parseInt(std::string_view token, long long& out);

// Doubles beyond float's range become ±infinity, which validation reports as non-finite.
float toFloat(double v);

/// Appends polygon `poly` fan-triangulated; one with fewer than three corners is counted in
/// shortFaces instead.
void addPolygon(std::vector<Tri>& triangles, const std::vector<std::uint32_t>& poly,
                std::size_t& shortFaces);

/// The format readers behind parseRawMesh, one file each.
RawMesh readObj(const std::filesystem::path& path, std::string_view text);
RawMesh readOff(const std::filesystem::path& path, std::string_view text);
RawMesh readPly(const std::filesystem::path& path, std::string_view text);
RawMesh readStl(const std::filesystem::path& path, std::string_view text);

} // namespace octaclay::core::detail
