// Issue 30's cases, made through the sculpting session as `octaclay-cli stroke` makes them, then
// evened out (core::evenOut, what `relax` and Mesh ▸ Even Out Samples run) and remeshed
// (core::remeshDocument, `remesh`): one table row per case and operation with the worst stretch
// (longest edge ÷ median), the least fair share of the pulled parts (the limb: samples farther
// than 1.6 from the centre; the creature: each leg and the neck), how far the surface moved
// (RMS, Hausdorff, fractions of the diagonal), whether the operation changed the document, and
// the time. Cases: the snake-hook limb off the image's centre at N = 256, fourteen push clicks
// at strength 13.3 at N = 256, the four-legged creature (keep-detail on) at N = 1024
// (--creature=N for another N, 0 to leave it out). --file=doc.exr (repeatable) runs documents
// from files instead, the pulled part being what lies farther than 1.6 from the centre, as
// `octaclay-cli stroke` makes the limb. Other arguments are ignored (scripts/bench passes
// benchmark filters).
#include "../creature_layout.h"
#include "sculpt_session.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/import/remesh.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/relax/relax.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace octaclay;

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Case {
  std::string name;
  core::Document document;
  std::function<double(const core::GeometryImage&)> leastFairShare;
};

double limbShare(const core::GeometryImage& image) {
  return core::regionSampling(image, [](const core::Vec3f& p) { return core::length(p) > 1.6f; })
      .fairShare;
}

void printRow(const Case& c, const char* operation, const core::GeometryImage& image, bool changed,
              double rms, double hausdorff, double ms, const std::string& note) {
  const core::StretchSummary s = core::summarizeStretch(image);
  std::printf("| %s | %s | %s | %.1f | %.3f | %.4f %% | %.4f %% | %.0f | %s |\n", c.name.c_str(),
              operation, changed ? "yes" : "no", s.longestOverMedian, c.leastFairShare(image),
              100 * rms, 100 * hausdorff, ms, note.c_str());
  std::fflush(stdout);
}

void runCase(const Case& c) {
  printRow(c, "before", c.document.positions, false, 0, 0, 0, "");
  auto start = Clock::now();
  const core::EvenOutResult even = core::evenOut(c.document);
  double ms = msSince(start);
  printRow(c, "even out", even.document.positions, even.changed, even.moved.rms,
           even.moved.hausdorff, ms,
           even.changed ? "step " + std::to_string(even.step).substr(0, 5) : even.reason);
  if (even.changed) {
    start = Clock::now();
    const core::EvenOutResult again = core::evenOut(even.document);
    ms = msSince(start);
    printRow(c, "even out twice", again.document.positions, again.changed, again.moved.rms,
             again.moved.hausdorff, ms, again.changed ? "" : again.reason);
  }
  start = Clock::now();
  const core::RemeshResult remeshed = core::remeshDocument(c.document);
  ms = msSince(start);
  char note[160];
  std::snprintf(note, sizeof note, "parameterize %.0f ms, resample %.0f ms, measure %.0f ms%s%s",
                remeshed.parameterizeMs, remeshed.resampleMs, remeshed.measureMs,
                remeshed.changed ? "" : "; ", remeshed.reason.c_str());
  printRow(c, "remesh", remeshed.changed ? remeshed.document.positions : c.document.positions,
           remeshed.changed, remeshed.moved.rms, remeshed.moved.hausdorff, ms, note);
}

} // namespace

int main(int argc, char** argv) {
  int creatureSize = 1024;
  std::vector<std::string> files;
  for (int a = 1; a < argc; ++a) {
    if (std::strncmp(argv[a], "--creature=", 11) == 0) creatureSize = std::atoi(argv[a] + 11);
    if (std::strncmp(argv[a], "--file=", 7) == 0) files.emplace_back(argv[a] + 7);
  }
  if (!files.empty()) {
    std::printf("| case | operation | changed | longest ÷ median | least fair share | RMS moved | "
                "Hausdorff moved | ms | note |\n|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& f : files)
      runCase({f, core::readDocument(f), limbShare});
    return 0;
  }
  gpu::GlContext context = gpu::GlContext::createHeadless();
  gpu::BrushCatalog catalog;
  catalog.scan({std::filesystem::path(OCTACLAY_SOURCE_DIR) / "plugins/brushes"});
  gpu::BrushEngine engine;
  for (const char* id : {"snake-hook", "push", "relax"})
    engine.load(*catalog.find(id), gpu::BrushCatalog::shaderSource(*catalog.find(id)));

  const auto session = [&](int n) {
    auto s = std::make_unique<app::SculptSession>();
    s->setBrushes(engine, catalog);
    s->setDocument(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n)));
    return s;
  };
  // A stroke as octaclay-cli makes it; radius a fraction of the diagonal.
  const auto script = [](const char* id, float radius, float strength, bool keepDetail) {
    app::StrokeScript s;
    s.start.brushId = s.start.settings.brushId = id;
    s.start.settings.radius = radius;
    s.start.settings.strength = strength;
    s.start.settings.keepDetail = keepDetail;
    return s;
  };
  std::printf("| case | operation | changed | longest ÷ median | least fair share | RMS moved | "
              "Hausdorff moved | ms | note |\n|---|---|---|---|---|---|---|---|---|\n");
  {
    auto s = session(256);
    app::StrokeScript hook = script("snake-hook", 0.05f / s->diagonal(), 1, false);
    hook.path = {{0.70f, 0.40f}};
    hook.dragPoints = {
        {0.9f, -0.35f, 0.55f}, {1.3f, -0.55f, 0.8f}, {1.7f, -0.75f, 1.05f}, {2.0f, -0.9f, 1.25f}};
    app::playStroke(*s, hook);
    glFinish();
    runCase({"snake-hook limb, N 256", s->document(), limbShare});
  }
  {
    auto s = session(256);
    app::StrokeScript push = script("push", 0.05f / s->diagonal(), 13.3f, true);
    push.path = {{0.70f, 0.40f}};
    for (int i = 0; i < 14; ++i)
      app::playStroke(*s, push);
    glFinish();
    runCase({"push spike, N 256", s->document(), limbShare});
  }
  if (creatureSize > 0) {
    auto s = session(creatureSize);
    const std::vector<testing::CreaturePart> parts =
        testing::creatureParts(testing::CreatureLayout::Animal);
    const core::GeometryImage ball = s->document().positions;
    for (const testing::CreaturePart& part : parts)
      app::playStroke(*s, testing::creatureStroke(part, ball, "snake-hook", s->diagonal()));
    glFinish();
    runCase({"creature, N " + std::to_string(creatureSize), s->document(),
             [parts](const core::GeometryImage& image) {
               double least = 1e30;
               for (const core::RegionSampling& r : testing::creatureSampling(image, parts))
                 least = std::min(least, r.fairShare);
               return least;
             }});
  }
  return 0;
}
