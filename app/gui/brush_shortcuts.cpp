#include "brush_shortcuts.h"

#include <array>
#include <utility>

namespace octaclay::app {

QKeySequence brushShortcut(const QString& brushId) {
  // Letters as in Blender's sculpt mode where it has the brush (X draw, S smooth, I inflate).
  static constexpr std::array<std::pair<const char*, const char*>, 7> kKeys{{
      {"push", "X"},
      {"smooth", "S"},
      {"inflate", "I"},
      {"flatten", "T"},
      {"relax", "R"},
      {"paint", "P"},
      {"mask", "M"},
  }};
  for (const auto& [id, key] : kKeys)
    if (brushId == QLatin1String(id)) return QKeySequence(QString::fromLatin1(key));
  return {};
}

} // namespace octaclay::app
