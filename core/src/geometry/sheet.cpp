#include "octaclay/core/geometry/sheet.h"

#include <cmath>

namespace octaclay::core {

GeometryImage makeSheet(Sheet sheet, int n) {
  GeometryImage image(Topology::Plane, n, n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = 2.0 * i / n - 1.0, y = 2.0 * j / n - 1.0;
      double px = x, py = y;
      if (sheet == Sheet::Disc) {
        px = x * std::sqrt(1.0 - y * y / 2.0);
        py = y * std::sqrt(1.0 - x * x / 2.0);
      }
      image.at(i, j) = {float(px), float(py), 0.0f, 0.0f};
    }
  return image;
}

} // namespace octaclay::core
