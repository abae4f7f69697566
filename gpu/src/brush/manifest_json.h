#pragma once

// The JSON reading that brush manifests and material manifests share: every message starts with
// the manifest's path and names the field ("parameters[2].type: …"), unknown fields are refused
// with a did-you-mean hint, a key given twice is an error.

#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::gpu::detail {

using json = nlohmann::json;

/// A manifest problem; parsers rethrow it as their public error type (BrushLoadError, …).
class ManifestError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

std::string quote(std::string_view s);
std::string formatNumber(double value);
/// What a wrong value was, for "expected …, got …".
std::string describe(const json& value);
std::string shortDump(const json& value);
std::size_t editDistance(std::string_view a, std::string_view b);
/// Lowercase words of [a-z0-9] joined by single '-' when strictHyphens, else [a-z0-9-]+.
bool isValidId(std::string_view id, bool strictHyphens);

/// "float, int, bool, color or enum".
template <std::size_t N> std::string listChoices(const std::array<const char*, N>& names) {
  std::string out;
  for (std::size_t k = 0; k < N; ++k) {
    if (k > 0) out += k + 1 == N ? " or " : ", ";
    out += names[k];
  }
  return out;
}

/// builtInFolder, then each folder of the ':'-separated $pathVariable (empty entries skipped),
/// then the user's $XDG_DATA_HOME/octaclay/<userFolder> (or ~/.local/share/octaclay/…; left out
/// when neither is usable).
std::vector<std::filesystem::path> pluginSearchPath(const std::filesystem::path& builtInFolder,
                                                    const char* pathVariable,
                                                    const char* userFolder);

/// Whether a listed folder entry is a plugin folder: a folder holding an entry named
/// manifestName, whatever that entry is (a link loop or a FIFO is a folder to report as broken).
/// Only stats: never opens the manifest.
bool holdsManifest(const std::filesystem::directory_entry& entry, const char* manifestName);

/// Field readers over one manifest file; each failure throws ManifestError.
class ManifestReader {
public:
  /// kind names the file in "is a folder, not a <kind>".
  ManifestReader(std::filesystem::path file, std::string kind)
      : file_(std::move(file)), kind_(std::move(kind)) {}

  const std::filesystem::path& file() const { return file_; }

  [[noreturn]] void failFile(const std::string& reason) const;
  [[noreturn]] void fail(const std::string& field, const std::string& reason) const;

  /// The file parsed, duplicate keys refused. Only a regular file of at most kMaxManifestBytes
  /// is read (a FIFO, device or link loop is refused without blocking).
  json readJson() const;
  /// text parsed as the file's contents, duplicate keys refused.
  json parseJson(std::string_view text) const;

  /// Refuses keys of object not in known, except those starting with "x-".
  template <std::size_t N>
  void rejectUnknownFields(const json& object, const std::string& prefix,
                           const std::array<const char*, N>& known) const {
    for (const auto& [key, value] : object.items()) {
      if (key.starts_with("x-")) continue;
      bool isKnown = false;
      for (const char* k : known)
        isKnown = isKnown || key == k;
      if (!isKnown) unknownField(prefix, key, std::vector<const char*>(known.begin(), known.end()));
    }
  }

  const json& required(const json& object, const char* key, const std::string& field) const;
  std::string string(const json& value, const std::string& field) const;
  std::string requiredString(const json& object, const char* key, const std::string& field) const;
  std::optional<std::string> optionalString(const json& object, const char* key,
                                            const std::string& field) const;
  /// A number that fits a float.
  double number(const json& value, const std::string& field) const;
  int integer(const json& value, const std::string& field) const;

  /// The index of value in names as an Enum.
  template <typename Enum, std::size_t N>
  Enum choose(const std::string& value, const std::array<const char*, N>& names,
              const std::string& field, const char* what) const {
    for (std::size_t k = 0; k < N; ++k)
      if (value == names[k]) return static_cast<Enum>(k);
    fail(field,
         "unknown " + std::string(what) + " " + quote(value) + " (use " + listChoices(names) + ")");
  }

private:
  [[noreturn]] void unknownField(const std::string& prefix, const std::string& key,
                                 const std::vector<const char*>& known) const;

  std::filesystem::path file_;
  std::string kind_;
};

} // namespace octaclay::gpu::detail
