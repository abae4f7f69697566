#include "octaclay/core/document/document.h"

namespace octaclay::core {

std::vector<std::string> Layer::channelNames() const {
  if (channels == 1) return {"Y"};
  if (channels == 3) return {"R", "G", "B"};
  return {"R", "G", "B", "A"};
}

Document makeDocument(GeometryImage image) {
  Document document;
  document.topology = image.topology();
  document.positions = std::move(image);
  return document;
}

} // namespace octaclay::core
