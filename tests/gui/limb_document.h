#pragma once

// What the Even Out and Remesh window tests share: a sphere with one long thin limb (few samples
// spread over it, as a far push leaves them) and a document's every bit, to tell "unchanged".

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace octaclay::testing {

/// A unit sphere with a thin limb 3 long pulled out of the pole that sample (N/2, N/2) sits on
/// (+z), smoothstep-shaped and pinched to 0.3 of the radius.
inline core::Document limbDocument(int n) {
  core::GeometryImage image = core::makeBaseShape(core::BaseShape::Sphere, n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      core::Vec4f& p = image.at(i, j);
      const float angle = std::acos(std::clamp(p.z / core::length(p.xyz()), -1.0f, 1.0f));
      const float t = 1.0f - angle / 0.3f;
      if (t <= 0) continue;
      p.z += 3.0f * t * t * (3 - 2 * t);
      const float pinch = 1.0f - 0.7f * std::min(1.0f, 4 * t);
      p.x *= pinch, p.y *= pinch;
    }
  return core::makeDocument(std::move(image));
}

/// Every texel of every layer, as bytes: "unchanged" means bit for bit (a different N gives a
/// different length).
inline std::vector<unsigned char> bitsOf(const core::Document& d) {
  std::vector<unsigned char> out;
  const auto append = [&out](const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    out.insert(out.end(), b, b + bytes);
  };
  const int side = d.size() + 1;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i)
      append(&d.positions.at(i, j), sizeof(core::Vec4f));
  for (const core::Layer* layer : {&d.diffuse, &d.feature, &d.mask}) {
    append(layer->fill.data(), sizeof(layer->fill));
    append(layer->texels.data(), layer->texels.size() * sizeof(float));
  }
  return out;
}

} // namespace octaclay::testing
