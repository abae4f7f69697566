#include "manifest_json.h"

#include "bounded_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <unordered_set>

namespace octaclay::gpu::detail {
namespace {

namespace fs = std::filesystem;

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::string(value) : std::string();
}

// Names a key that appears twice in one object (nlohmann silently keeps the last one, which
// would hide a copy-paste mistake): a SAX pass over text already known to be valid JSON. Not
// nlohmann's parser callback: its end_object rescans the enclosing array, quadratic in the
// array's length (10^5 parameters took seconds).
class DuplicateKeyCheck : public nlohmann::json_sax<json> {
public:
  explicit DuplicateKeyCheck(const fs::path& file) : file_(file) {}

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    stack_.push_back({true, {}, {}, 0});
    return true;
  }
  bool key(string_t& key) override {
    Frame& top = stack_.back();
    top.key = key;
    if (!top.keys.insert(key).second)
      throw ManifestError(file_.string() + ": " + path() +
                          ": appears twice in the same object (remove one)");
    return true;
  }
  bool end_object() override { return end(); }
  bool start_array(std::size_t) override {
    stack_.push_back({false, {}, {}, 0});
    return true;
  }
  bool end_array() override { return end(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false; // the text was parsed once already: cannot happen
  }

private:
  struct Frame {
    bool isObject;
    std::unordered_set<std::string> keys;
    std::string key;
    std::size_t index;
  };

  bool value() {
    if (!stack_.empty() && !stack_.back().isObject) ++stack_.back().index;
    return true;
  }
  bool end() {
    stack_.pop_back();
    return value();
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
  if (!fs::exists(fs::symlink_status(file_, ec))) failFile("file not found");
  try {
    return parseJson(readBoundedFile(file_, kMaxManifestBytes, kind_));
  } catch (const BoundedFileError& e) {
    throw ManifestError(e.what());
  }
}

json ManifestReader::parseJson(std::string_view text) const {
  try {
    json parsed = json::parse(text);
    DuplicateKeyCheck check(file_);
    json::sax_parse(text, &check);
    return parsed;
  } catch (const json::parse_error& e) {
    // nlohmann: "[json.exception.parse_error.101] parse error at line 3, column 5: …".
    std::string detail = e.what();
    const std::string marker = "parse error at ";
    if (const auto at = detail.find(marker); at != std::string::npos)
      detail = detail.substr(at + marker.size());
    // nlohmann quotes the bytes it last read: a stray byte (ill-formed UTF-8) is shown as \xFF,
    // so the message itself stays UTF-8 (brushes --json prints it).
    std::string shown;
    for (const unsigned char c : detail) {
      if (c >= 0x20 && c < 0x7f) {
        shown += static_cast<char>(c);
      } else {
        static constexpr char kHex[] = "0123456789ABCDEF";
        shown += {'\\', 'x', kHex[c >> 4], kHex[c & 15]};
      }
    }
    detail = std::move(shown);
    failFile("invalid JSON at byte " + std::to_string(e.byte) + ", " + detail);
  } catch (const json::out_of_range&) {
    // nlohmann refuses a number too large for any of its types (error 406) this way.
    failFile("invalid JSON: a number is too large to read");
  }
}

bool holdsManifest(const fs::directory_entry& entry, const char* manifestName) {
  std::error_code ec;
  if (!entry.is_directory(ec)) return false;
  // The name's own status: a manifest that is a broken link or a link loop is still a brush
  // folder, one whose load fails and is listed as broken.
  return fs::exists(fs::symlink_status(entry.path() / manifestName, ec));
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
  if (v != 0.0 && static_cast<float>(v) == 0.0f)
    fail(field, formatNumber(v) + " is too small for a float (it would be 0)");
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
