#include "octaclay/gpu/stroke.h"

#include "octaclay/core/error.h"
#include "octaclay/core/normals.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <set>

namespace octaclay::gpu {
namespace {

core::EditLayer editLayer(BrushLayer layer) {
  return static_cast<core::EditLayer>(static_cast<int>(layer));
}

// Captures each undo tile of the written layers the first time a dab may touch it.
class UndoCapture {
public:
  UndoCapture(const GpuDocument& document, std::vector<BrushLayer> layers)
      : document_(document), layers_(std::move(layers)), side_(document.size() + 1),
        tiles_(core::StrokeRecorder::tilesPerSide(side_)) {}

  void cover(core::TexelRect rect) {
    const int size = core::StrokeRecorder::kTileSize;
    for (int ty = rect.y / size; ty <= (rect.y + rect.height - 1) / size; ++ty)
      for (int tx = rect.x / size; tx <= (rect.x + rect.width - 1) / size; ++tx)
        if (seen_.insert(ty * tiles_ + tx).second)
          for (BrushLayer layer : layers_)
            before_.push_back({layer, tx, ty, texels(layer, tx, ty)});
  }

  void coverBorder() {
    for (int k = 0; k < tiles_; ++k)
      for (core::TexelRect r :
           {core::TexelRect{k * core::StrokeRecorder::kTileSize, 0, 1, 1},
            core::TexelRect{k * core::StrokeRecorder::kTileSize, side_ - 1, 1, 1},
            core::TexelRect{0, k * core::StrokeRecorder::kTileSize, 1, 1},
            core::TexelRect{side_ - 1, k * core::StrokeRecorder::kTileSize, 1, 1}})
        cover(r);
  }

  core::Stroke finish(const std::string& label) {
    core::StrokeRecorder recorder(side_);
    for (const Tile& t : before_)
      recorder.addTile(editLayer(t.layer), t.x, t.y, GpuDocument::channels(t.layer), t.texels,
                       texels(t.layer, t.x, t.y));
    return recorder.finish(label);
  }

private:
  struct Tile {
    BrushLayer layer;
    int x, y;
    std::vector<float> texels;
  };

  std::vector<float> texels(BrushLayer layer, int tx, int ty) const {
    const core::Region r = core::StrokeRecorder::tileRegion(side_, tx, ty);
    return document_.mirrorTexels(layer, {r.x, r.y, r.width, r.height});
  }

  const GpuDocument& document_;
  std::vector<BrushLayer> layers_;
  int side_, tiles_;
  std::set<int> seen_;
  std::vector<Tile> before_;
};

core::Sample sampleAt(int n, std::array<float, 2> uv) {
  return {static_cast<int>(std::lround(uv[0] * static_cast<float>(n))),
          static_cast<int>(std::lround(uv[1] * static_cast<float>(n)))};
}

core::Vec3f mirrored(core::Vec3f p, core::Vec3f centre, unsigned axes) {
  if (axes & kSymmetryX) p.x = 2 * centre.x - p.x;
  if (axes & kSymmetryY) p.y = 2 * centre.y - p.y;
  if (axes & kSymmetryZ) p.z = 2 * centre.z - p.z;
  return p;
}

} // namespace

core::Sample nearestSample(const GpuDocument& document, core::Vec3f p) {
  const core::TileBounds& bounds = document.bounds();
  const core::GeometryImage& image = document.document().positions;
  float radius = 1e-3f * std::max(bounds.diagonal(), 1e-6f);
  for (;;) {
    float best = std::numeric_limits<float>::max();
    core::Sample found{};
    for (int t : bounds.tilesNearSphere(p, radius)) {
      const core::TexelRect r =
          bounds.tileRect(t % bounds.tilesPerSide(), t / bounds.tilesPerSide());
      for (int j = r.y; j < r.y + r.height; ++j)
        for (int i = r.x; i < r.x + r.width; ++i) {
          const core::Vec3f d = image.at(i, j).xyz() - p;
          const float d2 = core::dot(d, d);
          if (d2 < best) best = d2, found = {i, j};
        }
    }
    if (best <= radius * radius) return found;
    radius *= 4; // nothing that close yet: widen the search
  }
}

StrokeResult runStroke(BrushEngine& engine, GpuDocument& document, const BrushManifest& brush,
                       const StrokeSettings& settings) {
  if (settings.path.empty())
    throw core::Error(core::ErrorKind::InvalidArgument, "the stroke's path has no point");
  for (const auto& uv : settings.path)
    if (!(uv[0] >= 0 && uv[0] <= 1 && uv[1] >= 0 && uv[1] <= 1))
      throw core::Error(core::ErrorKind::InvalidArgument, "path point (" + std::to_string(uv[0]) +
                                                              ", " + std::to_string(uv[1]) +
                                                              ") is outside [0, 1]");
  const int n = document.size();
  const float spacing =
      (settings.spacing > 0 ? settings.spacing : brush.spacing) * std::abs(settings.radius);
  const core::BoundingBox box = [&] {
    core::BoundingBox b;
    for (int t = 0; t < document.bounds().tilesPerSide() * document.bounds().tilesPerSide(); ++t) {
      b.extend(document.bounds().box(t).min);
      b.extend(document.bounds().box(t).max);
    }
    return b;
  }();
  const core::Vec3f centre = (box.min + box.max) * 0.5f;

  StrokeResult result;
  UndoCapture undo(document, brush.writes);
  const auto start = std::chrono::steady_clock::now();

  auto dabAt = [&](core::Sample s) {
    std::vector<core::Sample> centres{s};
    const core::Vec3f p = document.document().positions.at(s).xyz();
    for (unsigned axes = 1; axes < 8; ++axes)
      if ((axes & settings.symmetry) == axes)
        centres.push_back(nearestSample(document, mirrored(p, centre, axes)));
    for (core::Sample c : centres) {
      Dab dab;
      dab.centreTexel = c;
      dab.centre = document.document().positions.at(c).xyz();
      dab.centreNormal = core::vertexNormal(document.document().positions, c);
      dab.radius = settings.radius;
      dab.strength = settings.strength;
      dab.pressure = settings.pressure;
      dab.parameters = settings.parameters;
      std::vector<core::TexelRect> reach = engine.reach(document, brush.id, dab);
      bool border = false;
      for (const core::TexelRect& r : reach) {
        undo.cover(r);
        border =
            border || r.x == 0 || r.y == 0 || r.x + r.width == n + 1 || r.y + r.height == n + 1;
      }
      if (border) undo.coverBorder();
      engine.dab(document, brush.id, dab, std::move(reach));
      ++result.dabs;
    }
  };

  // Walk each segment one sample at a time, measuring distance on the current surface.
  core::Sample previous = sampleAt(n, settings.path.front());
  dabAt(previous);
  float travelled = 0;
  for (std::size_t k = 1; k < settings.path.size(); ++k) {
    const core::Sample a = sampleAt(n, settings.path[k - 1]), b = sampleAt(n, settings.path[k]);
    const int steps = std::max(std::abs(b.i - a.i), std::abs(b.j - a.j));
    for (int step = 1; step <= steps; ++step) {
      const float t = static_cast<float>(step) / static_cast<float>(steps);
      const core::Sample s{a.i + static_cast<int>(std::lround(t * static_cast<float>(b.i - a.i))),
                           a.j + static_cast<int>(std::lround(t * static_cast<float>(b.j - a.j)))};
      const core::GeometryImage& image = document.document().positions;
      travelled += core::length(image.at(s).xyz() - image.at(previous).xyz());
      previous = s;
      if (travelled >= spacing) {
        dabAt(s);
        travelled = 0;
      }
    }
  }
  result.engineMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  result.undo = undo.finish(brush.id);
  return result;
}

} // namespace octaclay::gpu
