#include "brush_shortcuts.h"

#include <array>
#include <utility>

namespace octaclay::app {

QKeySequence brushShortcut(const QString& brushId) {
  // Letters as in Blender's sculpt mode where it has the brush (X draw, S smooth, I inflate,
  // G grab, K snake hook, C clay strips, L layer, Shift+C crease, Shift+T scrape).
  static constexpr std::array<std::pair<const char*, const char*>, 14> kKeys{{
      {"push", "X"},
      {"smooth", "S"},
      {"inflate", "I"},
      {"flatten", "T"},
      {"relax", "R"},
      {"paint", "P"},
      {"mask", "M"},
      {"grab", "G"},
      {"snake-hook", "K"},
      {"clay-strips", "C"},
      {"layer", "L"},
      {"crease", "Shift+C"},
      {"scrape", "Shift+T"},
      {"pinch", "Shift+P"},
  }};
  for (const auto& [id, key] : kKeys)
    if (brushId == QLatin1String(id)) return QKeySequence(QString::fromLatin1(key));
  return {};
}

} // namespace octaclay::app
