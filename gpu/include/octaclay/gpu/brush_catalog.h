#pragma once

#include "octaclay/gpu/brush_manifest.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace octaclay::gpu {

/// A brush that could not be loaded (or reloaded): its manifest path and BrushLoadError's
/// message (which starts with that path).
struct BrushCatalogError {
  std::filesystem::path path;
  std::string message;
};

/// The brushes found in a search path of folders, each brush a sub-folder holding manifest.json
/// and its shader. A bad brush is recorded in errors() and never stops the others. Not
/// thread-safe: the modeller owns one on the GUI thread and hands shader sources to the GL
/// thread, which compiles them.
class BrushCatalog {
public:
  /// builtInFolder, then each folder of $OCTACLAY_PLUGIN_PATH (':'-separated, empty entries
  /// skipped), then the user's folder: $XDG_DATA_HOME/octaclay/brushes when XDG_DATA_HOME is an
  /// absolute path, else $HOME/.local/share/octaclay/brushes (left out when HOME is unset).
  static std::vector<std::filesystem::path>
  defaultSearchPath(const std::filesystem::path& builtInFolder);

  /// Forgets what was loaded, then parses every immediate sub-folder of each folder that holds a
  /// manifest.json, folders in order and sub-folders by name. A brush whose id was already
  /// found replaces the earlier one, and notes() says so. Missing folders are skipped silently
  /// (the user folder usually does not exist); one that exists but cannot be listed is an
  /// error. Remembers the files' times and sizes for changedBrushes(), and the folders and
  /// the brush folders found in each for brushFoldersChanged() and rescan().
  void scan(const std::vector<std::filesystem::path>& folders);
  /// scan() again over the folders the last scan() searched (none before the first scan).
  void rescan();
  /// The folders the last scan() searched, in order.
  const std::vector<std::filesystem::path>& searchPath() const { return searchPath_; }

  /// Whether a rescan() would find other brush folders than the last scan() did: an immediate
  /// sub-folder holding a manifest.json appeared in or vanished from a searched folder (a
  /// plugin dropped in or deleted while the modeller runs), a searched folder appeared,
  /// vanished or became (un)listable, or a brush folder whose manifest failed to load at the
  /// scan was edited (a folder caught half-copied loads once the copy completes). Lists each
  /// searched folder once and stats a file per brush folder: cheap enough for a GUI-thread
  /// timer. Stays true until the next scan().
  bool brushFoldersChanged() const;

  /// Loaded brushes, sorted by id. Pointers and references into it stay valid until the next
  /// scan() or reload().
  const std::vector<BrushManifest>& brushes() const { return brushes_; }
  /// Brushes that failed to load, in search order, plus failed reloads (whose brush keeps its
  /// previous manifest). A later successful reload removes that brush's entry.
  const std::vector<BrushCatalogError>& errors() const { return errors_; }
  /// Things worth a log line that are not errors: "<manifest>: brush "x" overrides <manifest>".
  const std::vector<std::string>& notes() const { return notes_; }
  /// The loaded brush with this id, or nullptr.
  const BrushManifest* find(std::string_view id) const;

  /// The text of the brush's shader file. Throws BrushLoadError naming the file when it cannot
  /// be read.
  static std::string shaderSource(const BrushManifest& brush);

  /// Ids of loaded brushes whose manifest.json or shader changed (last-write time or size,
  /// including appearing or disappearing) since the last scan(), reload() or call; each change
  /// is reported once. Only stats a few files: cheap enough for a GUI-thread timer.
  std::vector<std::string> changedBrushes();

  /// Re-parses the brush with this id from its folder. On success the new manifest replaces the
  /// old one (and any error of this brush is cleared); on failure the old manifest stays and the
  /// error is recorded in errors(). A manifest whose id changed is refused (rescan to rename).
  /// Returns whether the new manifest was taken; false also when no brush has this id.
  bool reload(std::string_view id);

private:
  // What changedBrushes() compares: size and time of the manifest and of the shader.
  struct FileStamp {
    bool exists = false;
    std::uintmax_t size = 0;
    std::filesystem::file_time_type time{};
    bool operator==(const FileStamp&) const = default;
  };
  struct Stamps {
    FileStamp manifest, shader;
    bool operator==(const Stamps&) const = default;
  };

  // What brushFoldersChanged() compares for one searched folder: whether it could be listed
  // and its sub-folders holding a manifest.json, sorted.
  struct Listing {
    bool listed = true; // false: it exists but listing failed (error says why)
    std::error_code error;
    std::vector<std::filesystem::path> brushFolders;
    bool operator==(const Listing& o) const {
      return listed == o.listed && brushFolders == o.brushFolders;
    }
  };
  // A folder whose manifest failed to load at the scan: its manifest and the folder's own time
  // (which moves when a file such as the shader is created in it).
  struct FailedFolder {
    std::filesystem::path folder;
    FileStamp manifest, directory;
  };

  static Stamps stampsOf(const BrushManifest& brush);
  static FileStamp stampOf(const std::filesystem::path& path);
  static FailedFolder failedFolderOf(const std::filesystem::path& folder);
  static Listing listBrushFolders(const std::filesystem::path& folder);
  void recordError(const std::filesystem::path& path, std::string message);
  void clearError(const std::filesystem::path& path);

  std::vector<BrushManifest> brushes_;
  std::vector<BrushCatalogError> errors_;
  std::vector<std::string> notes_;
  std::map<std::string, Stamps, std::less<>> stamps_;
  std::vector<std::filesystem::path> searchPath_;
  std::vector<Listing> listings_;           // one per searchPath_ folder
  std::vector<FailedFolder> failedFolders_; // brush folders whose manifest failed at the scan
};

} // namespace octaclay::gpu
