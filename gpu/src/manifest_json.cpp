#include "manifest_json.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace octaclay::gpu::detail {
namespace {

namespace fs = std::filesystem;

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::string(value) : std::string();
}

// Tracks the JSON path while nlohmann parses, to name a key that appears twice in one object
// (nlohmann silently keeps the last one, which would hide a copy-paste mistake).
class DuplicateKeyCheck {
public:
  explicit DuplicateKeyCheck(const fs::path& file) : file_(file) {}

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
    case json::parse_event_t::object_start:
      stack_.push_back({true, {}, {}, 0});
      break;
    case json::parse_event_t::array_start:
      stack_.push_back({false, {}, {}, 0});
      break;
    case json::parse_event_t::key: {
      Frame& top = stack_.back();
      top.key = parsed.get<std::string>();
      if (!top.keys.insert(top.key).second)
        throw ManifestError(file_.string() + ": " + path() +
                            ": appears twice in the same object (remove one)");
      break;
    }
    case json::parse_event_t::value:
      advanceArray();
      break;
    case json::parse_event_t::object_end:
    case json::parse_event_t::array_end:
      stack_.pop_back();
      advanceArray();
      break;
    }
    return true;
  }

private:
  struct Frame {
    bool isObject;
    std::set<std::string> keys;
    std::string key;
    std::size_t index;
  };

  void advanceArray() {
    if (!stack_.empty() && !stack_.back().isObject) ++stack_.back().index;
  }

  std::string path() const {
    std::string out;
    for (const Frame& frame : stack_) {
      if (frame.isObject)
        out += (out.empty() ? "" : ".") + frame.key;
      else
        out += "[" + std::to_string(frame.index) + "]";
    }
    return out;
  }

  fs::path file_;
  std::vector<Frame> stack_;
};

} // namespace

std::string quote(std::string_view s) {
  return json(std::string(s)).dump();
}

std::string formatNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string shortDump(const json& value) {
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

std::string describe(const json& value) {
  if (value.is_object()) return "an object";
  if (value.is_array()) return "an array";
  return shortDump(value);
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

bool isValidId(std::string_view id, bool strictHyphens) {
  if (id.empty()) return false;
  for (std::size_t k = 0; k < id.size(); ++k) {
    const char c = id[k];
    const bool alnum = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    if (alnum) continue;
    if (c != '-') return false;
    if (strictHyphens && (k == 0 || k + 1 == id.size() || id[k + 1] == '-')) return false;
  }
  return true;
}

std::vector<fs::path> pluginSearchPath(const fs::path& builtInFolder, const char* pathVariable,
                                       const char* userFolder) {
  std::vector<fs::path> folders{builtInFolder};
  const std::string list = environment(pathVariable);
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t end = list.find(':', start);
    if (end == std::string::npos) end = list.size();
    if (end > start) folders.emplace_back(list.substr(start, end - start));
    start = end + 1;
  }
  // XDG Base Directory spec: a relative XDG_DATA_HOME is invalid and must be ignored.
  const fs::path dataHome = environment("XDG_DATA_HOME");
  if (dataHome.is_absolute())
    folders.push_back(dataHome / "octaclay" / userFolder);
  else if (const std::string home = environment("HOME"); !home.empty())
    folders.push_back(fs::path(home) / ".local" / "share" / "octaclay" / userFolder);
  return folders;
}

void ManifestReader::failFile(const std::string& reason) const {
  throw ManifestError(file_.string() + ": " + reason);
}

void ManifestReader::fail(const std::string& field, const std::string& reason) const {
  throw ManifestError(file_.string() + ": " + field + ": " + reason);
}

json ManifestReader::readJson() const {
  std::error_code ec;
  const fs::file_status status = fs::status(file_, ec);
  if (!fs::exists(status)) failFile("file not found");
  if (fs::is_directory(status)) failFile("is a folder, not a " + kind_);
  std::ifstream in(file_, std::ios::binary);
  if (!in) failFile(std::string("cannot be read (") + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) failFile("cannot be read (read error)");
  try {
    return json::parse(text.str(), DuplicateKeyCheck(file_));
  } catch (const json::parse_error& e) {
    // nlohmann: "[json.exception.parse_error.101] parse error at line 3, column 5: …".
    std::string detail = e.what();
    const std::string marker = "parse error at ";
    if (const auto at = detail.find(marker); at != std::string::npos)
      detail = detail.substr(at + marker.size());
    failFile("invalid JSON at byte " + std::to_string(e.byte) + ", " + detail);
  }
}

void ManifestReader::unknownField(const std::string& prefix, const std::string& key,
                                  const std::vector<const char*>& known) const {
  std::string hint;
  for (const char* k : known)
    if (editDistance(key, k) <= 2) {
      hint = " (did you mean " + quote(k) + "?)";
      break;
    }
  if (hint.empty()) hint = " (prefix your own fields with x-)";
  fail(prefix + key, "unknown field" + hint);
}

const json& ManifestReader::required(const json& object, const char* key,
                                     const std::string& field) const {
  if (!object.contains(key)) fail(field, "missing required field");
  return object[key];
}

std::string ManifestReader::string(const json& value, const std::string& field) const {
  if (!value.is_string()) fail(field, "expected a string, got " + describe(value));
  return value.get<std::string>();
}

std::string ManifestReader::requiredString(const json& object, const char* key,
                                           const std::string& field) const {
  return string(required(object, key, field), field);
}

std::optional<std::string> ManifestReader::optionalString(const json& object, const char* key,
                                                          const std::string& field) const {
  if (!object.contains(key)) return std::nullopt;
  return string(object[key], field);
}

double ManifestReader::number(const json& value, const std::string& field) const {
  if (!value.is_number()) fail(field, "expected a number, got " + describe(value));
  const double v = value.get<double>();
  if (!std::isfinite(static_cast<float>(v)))
    fail(field, formatNumber(v) + " is too large for a float");
  return v;
}

int ManifestReader::integer(const json& value, const std::string& field) const {
  if (!value.is_number()) fail(field, "expected an integer, got " + describe(value));
  const double v = value.get<double>();
  if (v != std::floor(v) || v < std::numeric_limits<int>::min() ||
      v > std::numeric_limits<int>::max())
    fail(field, "expected an integer, got " + describe(value));
  return static_cast<int>(v);
}

} // namespace octaclay::gpu::detail
