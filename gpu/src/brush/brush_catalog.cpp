// Scans brush folders and polls their files for changes. Polling (a few stat calls per brush
// from the modeller's timer) needs no watcher thread and behaves the same on every file system.

#include "octaclay/gpu/brush_catalog.h"

#include "bounded_file.h"
#include "brush_program.h"
#include "manifest_json.h"

#include <algorithm>

namespace octaclay::gpu {

namespace {

namespace fs = std::filesystem;

constexpr const char* kManifestName = "manifest.json";

fs::path manifestOf(const BrushManifest& brush) {
  return brush.folder / kManifestName;
}

} // namespace

std::vector<fs::path> BrushCatalog::defaultSearchPath(const fs::path& builtInFolder) {
  return detail::pluginSearchPath(builtInFolder, "OCTACLAY_PLUGIN_PATH", "brushes");
}

void BrushCatalog::scan(const std::vector<fs::path>& folders) {
  brushes_.clear();
  errors_.clear();
  notes_.clear();
  stamps_.clear();
  searchPath_ = folders; // copied first: folders may be searchPath_ itself (rescan)
  listings_.clear();
  failedFolders_.clear();

  for (const fs::path& folder : searchPath_) {
    listings_.push_back(listBrushFolders(folder));
    const Listing& listing = listings_.back();
    if (!listing.listed) {
      recordError(folder, folder.string() + ": cannot list the brush folder (" +
                              listing.error.message() + ")");
      continue;
    }

    for (const fs::path& candidate : listing.brushFolders) {
      const fs::path manifestFile = candidate / kManifestName;
      try {
        BrushManifest brush = parseBrushManifest(manifestFile);
        detail::resolveShaderContract(brush, shaderSource(brush));
        const auto same = std::find_if(brushes_.begin(), brushes_.end(),
                                       [&](const BrushManifest& b) { return b.id == brush.id; });
        if (same != brushes_.end()) {
          notes_.push_back(manifestFile.string() + ": brush \"" + brush.id + "\" overrides " +
                           manifestOf(*same).string());
          *same = std::move(brush);
        } else {
          brushes_.push_back(std::move(brush));
        }
      } catch (const BrushLoadError& e) {
        recordError(manifestFile, e.what());
        failedFolders_.push_back(failedFolderOf(candidate));
      }
    }
  }

  std::sort(brushes_.begin(), brushes_.end(),
            [](const BrushManifest& a, const BrushManifest& b) { return a.id < b.id; });
  for (const BrushManifest& brush : brushes_)
    stamps_[brush.id] = stampsOf(brush);
}

void BrushCatalog::rescan() {
  scan(searchPath_);
}

bool BrushCatalog::brushFoldersChanged() const {
  for (std::size_t k = 0; k < searchPath_.size(); ++k)
    if (!(listBrushFolders(searchPath_[k]) == listings_[k])) return true;
  for (const FailedFolder& failed : failedFolders_) {
    const FailedFolder now = failedFolderOf(failed.folder);
    if (now.manifest != failed.manifest || now.directory != failed.directory) return true;
  }
  return false;
}

BrushCatalog::Listing BrushCatalog::listBrushFolders(const fs::path& folder) {
  Listing listing;
  std::error_code ec;
  if (!fs::exists(folder, ec)) return listing; // missing (usually the user folder): no brushes
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (detail::holdsManifest(*it, kManifestName)) listing.brushFolders.push_back(it->path());
  }
  if (ec) {
    listing.listed = false;
    listing.error = ec;
    listing.brushFolders.clear();
    return listing;
  }
  std::sort(listing.brushFolders.begin(), listing.brushFolders.end());
  return listing;
}

const BrushManifest* BrushCatalog::find(std::string_view id) const {
  const auto it =
      std::lower_bound(brushes_.begin(), brushes_.end(), id,
                       [](const BrushManifest& b, std::string_view key) { return b.id < key; });
  return it != brushes_.end() && it->id == id ? &*it : nullptr;
}

std::string BrushCatalog::shaderSource(const BrushManifest& brush) {
  try {
    return detail::readBoundedFile(brush.shaderPath(), detail::kMaxShaderBytes, "shader");
  } catch (const detail::BoundedFileError& e) {
    throw BrushLoadError(e.what());
  }
}

std::vector<std::string> BrushCatalog::changedBrushes() {
  std::vector<std::string> changed;
  for (const BrushManifest& brush : brushes_) {
    const Stamps now = stampsOf(brush);
    Stamps& seen = stamps_[brush.id];
    if (now != seen) {
      changed.push_back(brush.id);
      seen = now;
    }
  }
  return changed;
}

bool BrushCatalog::reload(std::string_view id) {
  const auto it = std::find_if(brushes_.begin(), brushes_.end(),
                               [&](const BrushManifest& b) { return b.id == id; });
  if (it == brushes_.end()) return false;
  const fs::path manifestFile = manifestOf(*it);
  // Whatever the outcome, the files as they are now have been looked at: a broken edit is
  // reported once, not on every poll.
  stamps_[it->id] = stampsOf(*it);
  try {
    BrushManifest fresh = parseBrushManifest(manifestFile);
    detail::resolveShaderContract(fresh, shaderSource(fresh));
    if (fresh.id != it->id)
      throw BrushLoadError(manifestFile.string() + ": id: changed from \"" + it->id + "\" to \"" +
                           fresh.id + "\" while loaded (rescan the brush folders to rename)");
    *it = std::move(fresh);
    stamps_[it->id] = stampsOf(*it);
    clearError(manifestFile);
    return true;
  } catch (const BrushLoadError& e) {
    recordError(manifestFile, e.what());
    return false;
  }
}

BrushCatalog::FileStamp BrushCatalog::stampOf(const fs::path& path) {
  FileStamp s;
  std::error_code ec;
  const auto time = fs::last_write_time(path, ec);
  if (ec) return s;
  // A directory has no file size; its time alone says entries were added or removed.
  const auto size = fs::is_directory(path, ec) ? 0 : fs::file_size(path, ec);
  if (ec) return s;
  s.exists = true;
  s.time = time;
  s.size = size;
  return s;
}

BrushCatalog::Stamps BrushCatalog::stampsOf(const BrushManifest& brush) {
  return {stampOf(manifestOf(brush)), stampOf(brush.shaderPath())};
}

BrushCatalog::FailedFolder BrushCatalog::failedFolderOf(const fs::path& folder) {
  return {folder, stampOf(folder / kManifestName), stampOf(folder)};
}

void BrushCatalog::recordError(const fs::path& path, std::string message) {
  clearError(path);
  errors_.push_back({path, std::move(message)});
}

void BrushCatalog::clearError(const fs::path& path) {
  std::erase_if(errors_, [&](const BrushCatalogError& e) { return e.path == path; });
}

} // namespace octaclay::gpu
