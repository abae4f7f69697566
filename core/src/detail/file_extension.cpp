// One place for the extension test that the exports, the normal-map writer and the CLI share.

#include "octaclay/core/file_extension.h"

#include <algorithm>
#include <cctype>

namespace octaclay::core {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

} // namespace octaclay::core
