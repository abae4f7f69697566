#include "data_folders.h"

#include <system_error>

namespace octaclay::app {
namespace fs = std::filesystem;

fs::path installedDataFolder() {
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  if (ec || executable.empty()) return {};
  const fs::path data = executable.parent_path().parent_path() / "share" / "octaclay";
  return fs::is_directory(data / "brushes", ec) ? data : fs::path();
}

fs::path builtInBrushes() {
  const fs::path installed = installedDataFolder();
  return installed.empty() ? fs::path(OCTACLAY_SOURCE_BRUSHES) : installed / "brushes";
}

fs::path resourceFolder() {
  const fs::path installed = installedDataFolder();
  return installed.empty() ? fs::path(OCTACLAY_SOURCE_RESOURCES) : installed;
}

} // namespace octaclay::app
