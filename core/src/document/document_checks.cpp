#include "octaclay/core/document/document_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace octaclay::core {

std::optional<std::string> positionsProblem(const GeometryImage& positions) {
  const int side = positions.size() + 1;
  float largest = 0;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const Vec4f& t = positions.at(i, j);
      if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z))
        return "position at sample (" + std::to_string(i) + ", " + std::to_string(j) +
               ") is not a finite number";
      largest = std::max({largest, std::abs(t.x), std::abs(t.y), std::abs(t.z)});
    }
  if (largest > kMaxCoordinate) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", static_cast<double>(largest));
    return std::string("a coordinate of magnitude ") + text +
           " is too large: the bounding-box diagonal overflows (coordinates must stay below "
           "1e18; scale the model down)";
  }
  return std::nullopt;
}

std::optional<std::string> layerChannelsProblem(const std::vector<std::string>& channels) {
  const Document defaults;
  for (const Layer* layer : {&defaults.diffuse, &defaults.feature, &defaults.mask}) {
    const auto names = layer->channelNames();
    int present = 0;
    for (const std::string& n : names)
      present += std::count(channels.begin(), channels.end(), layer->name + "." + n) > 0;
    if (present != 0 && present != layer->channels)
      return "layer " + layer->name + " has " + std::to_string(present) + " of its " +
             std::to_string(layer->channels) + " channels";
  }
  return std::nullopt;
}

} // namespace octaclay::core
