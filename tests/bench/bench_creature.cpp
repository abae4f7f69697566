// Issue 23's creature: four legs and a neck pulled out of a ball with snake-hook, each one stroke
// along a 3-point path (where it starts on the ball, then two points in object space the drag
// moves through, as `octaclay-cli stroke --path u,v --drag x,y,z;x,y,z` makes it), keep-detail off
// and on, at N = 256 (--sizes=a,b for others). A table of each part's (the samples farther than
// 1.15 from the centre, by the start they are nearest to) fair share of samples (its share of
// the samples ÷ its share of the area; the target: at least 0.3 with keep-detail on), its length
// and the time per stroke. --out=FILE writes the last creature made with keep-detail on.
// Arguments other than --sizes and --out are ignored (scripts/bench passes benchmark filters).
#include "sculpt_session.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gpu_document.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace octaclay;

namespace {

using Clock = std::chrono::steady_clock;

struct Part {
  const char* name;
  core::Vec3f start;               ///< direction from the ball's centre to where it starts
  std::array<core::Vec3f, 2> drag; ///< the two points the drag moves through
  float radius;                    ///< object units
};

// down: -1 puts the legs on the ball's -z half (the image's corner triangles, across seams), 1 on
// its +z half (the image's middle).
std::vector<Part> parts(float down) {
  std::vector<Part> out;
  for (const float x : {-1.0f, 1.0f})
    for (const float y : {-1.0f, 1.0f}) {
      const core::Vec3f s = core::normalize(core::Vec3f{0.45f * x, 0.45f * y, 0.77f * down});
      const core::Vec3f out1 = core::Vec3f{0.05f * x, 0.05f * y, 0.45f * down};
      out.push_back({x < 0 ? (y < 0 ? "leg back left" : "leg back right")
                           : (y < 0 ? "leg front left" : "leg front right"),
                     s,
                     {s + out1, s + core::Vec3f{0.08f * x, 0.08f * y, 0.9f * down}},
                     0.2f});
    }
  const core::Vec3f neck = core::normalize(core::Vec3f{0.7f, 0.0f, -0.7f * down});
  out.push_back({"neck",
                 neck,
                 {core::Vec3f{0.95f, 0.0f, -1.15f * down}, core::Vec3f{1.25f, 0.0f, -1.55f * down}},
                 0.25f});
  return out;
}

// The image point (u, v) of the sample of image nearest to p.
std::array<float, 2> uvNearest(const core::GeometryImage& image, core::Vec3f p) {
  const int n = image.size();
  float best = 1e30f;
  std::array<float, 2> uv{};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (const float d = core::length(image.at(i, j).xyz() - p); d < best)
        best = d, uv = {float(i) / float(n), float(j) / float(n)};
  return uv;
}

struct Row {
  std::vector<core::RegionSampling> sampling; ///< per part
  std::vector<float> length;                  ///< farthest sample of the part from the centre
  double msPerStroke = 0;
  core::Document document;
};

Row makeCreature(gpu::BrushEngine& engine, const gpu::BrushCatalog& catalog, int n, bool keepDetail,
                 float down) {
  const gpu::BrushManifest& hook = *catalog.find("snake-hook");
  app::SculptSession session;
  session.setBrushes(engine, catalog);
  session.setKeepDetail(keepDetail);
  const core::GeometryImage ball = core::makeBaseShape(core::BaseShape::Sphere, n);
  session.setDocument(core::makeDocument(ball));
  const std::vector<Part> all = parts(down);
  double ms = 0;
  for (const Part& part : all) {
    gpu::StrokeSettings s;
    s.brush = hook.id;
    s.path = {uvNearest(ball, part.start)};
    s.dragPoints = {part.drag[0], part.drag[1]};
    s.radius = part.radius;
    s.strength = 1.0f;
    const auto start = Clock::now();
    session.strokeAlongPath(hook, s);
    glFinish();
    ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }
  Row row;
  row.msPerStroke = ms / double(all.size());
  row.document = session.document();
  const core::GeometryImage& image = row.document.positions;
  // A sample belongs to the part whose start it is nearest to, once it is out of the ball.
  const auto partOf = [&](const core::Vec3f& p) {
    if (core::length(p) <= 1.15f) return -1;
    int best = 0;
    for (std::size_t k = 1; k < all.size(); ++k)
      if (core::length(p - all[k].start) < core::length(p - all[best].start)) best = int(k);
    return best;
  };
  for (std::size_t k = 0; k < all.size(); ++k) {
    row.sampling.push_back(
        core::regionSampling(image, [&](const core::Vec3f& p) { return partOf(p) == int(k); }));
    float farthest = 0;
    for (const core::Vec4f& t : image.texels())
      if (partOf(t.xyz()) == int(k)) farthest = std::max(farthest, core::length(t.xyz()));
    row.length.push_back(farthest);
  }
  return row;
}

} // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes{256};
  std::string out;
  for (int a = 1; a < argc; ++a) {
    if (std::strncmp(argv[a], "--sizes=", 8) == 0) {
      sizes.clear();
      for (const char* p = argv[a] + 8; *p;) {
        sizes.push_back(std::atoi(p));
        while (*p && *p != ',')
          ++p;
        if (*p == ',') ++p;
      }
    } else if (std::strncmp(argv[a], "--out=", 6) == 0) {
      out = argv[a] + 6;
    }
  }
  gpu::GlContext context = gpu::GlContext::createHeadless();
  gpu::BrushCatalog catalog;
  catalog.scan({std::filesystem::path(OCTACLAY_SOURCE_DIR) / "plugins/brushes"});
  gpu::BrushEngine engine;
  for (const char* id : {"snake-hook", "relax"})
    engine.load(*catalog.find(id), gpu::BrushCatalog::shaderSource(*catalog.find(id)));
  std::printf(
      "| legs | N | keep-detail | part | samples | sample share | area share | fair share | "
      "reach from centre | ms per stroke |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (float down : {-1.0f, 1.0f})
    for (int n : sizes)
      for (bool keepDetail : {false, true}) {
        const std::vector<Part> all = parts(down);
        const char* legs = down < 0 ? "-z" : "+z";
        const Row row = makeCreature(engine, catalog, n, keepDetail, down);
        double least = 1e30;
        for (std::size_t k = 0; k < all.size(); ++k) {
          const core::RegionSampling& r = row.sampling[k];
          least = std::min(least, r.fairShare);
          std::printf("| %s | %d | %s | %s | %zu | %.4f %% | %.4f %% | %.3f | %.3f | %.0f |\n",
                      legs, n, keepDetail ? "on" : "off", all[k].name, r.samples,
                      100 * r.sampleShare, 100 * r.areaShare, r.fairShare, row.length[k],
                      row.msPerStroke);
        }
        std::printf("| %s | %d | %s | least fair share | | | | **%.3f** | | |\n", legs, n,
                    keepDetail ? "on" : "off", least);
        if (keepDetail && down > 0 && !out.empty()) core::writeDocument(row.document, out);
      }
  return 0;
}
