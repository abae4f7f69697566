// Which tiles a dab can touch.
#include "loaded_brush.h"

#include "octaclay/core/error.h"
#include "octaclay/gpu/brush_engine.h"

#include <algorithm>
#include <array>

namespace octaclay::gpu {

std::vector<core::TexelRect> BrushEngine::reach(const GpuDocument& document,
                                                const std::string& brushId, const Dab& dab) const {
  const auto found = brushes_.find(brushId);
  if (found == brushes_.end())
    throw core::Error(core::ErrorKind::UnknownId, "no brush named '" + brushId + "' is loaded");
  const core::TileBounds& bounds = document.bounds();
  std::vector<core::TexelRect> rects;
  if (found->second->manifest.area == AreaMode::Uv) {
    // Samples within the radius (in samples) of the centre sample or of one of its images over
    // the tiling (prelude.glsl's uvDistance), so uv brushes continue across seams.
    const float r = dab.radius / std::max(1e-20f, bounds.diagonal()) * document.samplesAcross();
    const float n = float(document.size()), h = float(document.grid().height);
    const float ci = float(dab.centreTexel.i), cj = float(dab.centreTexel.j);
    // The torus's images are the translates by W in i, H in j or both; a plane has none.
    const core::Topology topology = document.topology();
    const std::array<std::array<float, 2>, 9> images =
        topology == core::Topology::Torus ? std::array<std::array<float, 2>, 9>{{{ci, cj},
                                                                                 {ci + n, cj},
                                                                                 {ci - n, cj},
                                                                                 {ci, cj + h},
                                                                                 {ci, cj - h},
                                                                                 {ci + n, cj + h},
                                                                                 {ci - n, cj - h},
                                                                                 {ci + n, cj - h},
                                                                                 {ci - n, cj + h}}}
        : topology == core::Topology::Plane
            ? std::array<std::array<float, 2>, 9>{{{ci, cj},
                                                   {ci, cj},
                                                   {ci, cj},
                                                   {ci, cj},
                                                   {ci, cj},
                                                   {ci, cj},
                                                   {ci, cj},
                                                   {ci, cj},
                                                   {ci, cj}}}
            : std::array<std::array<float, 2>, 9>{{{ci, cj},
                                                   {-ci, n - cj},
                                                   {2 * n - ci, n - cj},
                                                   {n - ci, -cj},
                                                   {n - ci, 2 * n - cj},
                                                   {ci + n, cj + n},
                                                   {ci - n, cj - n},
                                                   {ci + n, cj - n},
                                                   {ci - n, cj + n}}};
    for (int ty = 0; ty < bounds.tilesY(); ++ty)
      for (int tx = 0; tx < bounds.tilesX(); ++tx) {
        const core::TexelRect t = bounds.tileRect(tx, ty);
        for (const auto& c : images) {
          const float dx = std::max({float(t.x) - c[0], 0.0f, c[0] - float(t.x + t.width - 1)});
          const float dy = std::max({float(t.y) - c[1], 0.0f, c[1] - float(t.y + t.height - 1)});
          if (dx * dx + dy * dy <= r * r) {
            rects.push_back(t);
            break;
          }
        }
      }
    return rects;
  }
  // Quarters of tiles: the pass, its copies and the read-back run over fewer samples.
  return bounds.rectsNearSphere(dab.centre, dab.radius);
}

} // namespace octaclay::gpu
