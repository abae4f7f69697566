// Issue 21's limb: 15 push dabs at one spot of a sphere (radius 0.06 of the diagonal, strength 1,
// each dab its own stroke as `octaclay-cli stroke --path "0.5,0.5;0.5,0.5"` makes it) at
// N = 256 and 1024, with keep-detail off and on, then the global even-out of the limb made with
// it off. A table of the limb's (|p| > 1.5) share of samples against its share of area,
// limb / body mean spacing, longest ÷ median grid edge, limb length, surface distance to the
// un-relaxed limb (keep-detail: the largest of its relaxations against the surface its stroke
// left) and times; beside it push's per-dab cost with keep-detail off and on.
// Arguments other than --sizes=a,b are ignored (scripts/bench passes benchmark filters to all).
#include "../keep_detail_clicks.h"
#include "sculpt_session.h"
#include "stroke_script.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"
#include "octaclay/core/relax/relax.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gpu_document.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace octaclay;

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

bool inLimb(const core::Vec3f& p) {
  return core::length(p) > 1.5f;
}

struct Figures {
  core::RegionSampling limb;
  core::StretchSummary stretch;
  float limbLength = 0; ///< farthest sample from the centre, minus the sphere's radius
};

Figures measure(const core::GeometryImage& image) {
  Figures f;
  f.limb = core::regionSampling(image, inLimb);
  f.stretch = core::summarizeStretch(image);
  for (const core::Vec4f& p : image.texels())
    f.limbLength = std::max(f.limbLength, core::length(p.xyz()) - 1.0f);
  return f;
}

struct Brushes {
  gpu::GlContext context = gpu::GlContext::createHeadless();
  gpu::BrushCatalog catalog;
  gpu::BrushEngine engine;
  const gpu::BrushManifest* push = nullptr;
  Brushes() {
    catalog.scan({std::filesystem::path(OCTACLAY_SOURCE_DIR) / "plugins/brushes"});
    push = catalog.find("push");
    if (!push) throw std::runtime_error("no push brush in plugins/brushes");
    engine.load(*push, gpu::BrushCatalog::shaderSource(*push));
  }
};

struct Limb {
  core::Document document;
  double msPerStroke = 0;
  core::SurfaceDistance
      worstRelaxation; ///< keep-detail's largest step, against the stroke's surface
};

// The 15 one-dab strokes, the radius taken from the diagonal before each as the CLI does.
Limb pullLimb(Brushes& b, int n, bool keepDetail) {
  app::SculptSession session;
  session.setBrushes(b.engine, b.catalog);
  session.setDocument(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n)));
  double ms = 0;
  core::SurfaceDistance worst;
  for (int i = 0; i < 15; ++i) {
    const app::StrokeScript s = testing::pushClick(0.5f, 0.5f, keepDetail);
    const auto start = Clock::now();
    app::playStroke(session, s);
    glFinish();
    ms += msSince(start);
    if (session.lastRelaxation().tiles.empty()) continue;
    // How far the relaxation moved the surface the stroke left.
    const core::SurfaceDistance d = testing::lastRelaxationMove(session).moved;
    worst.rms = std::max(worst.rms, d.rms);
    worst.hausdorff = std::max(worst.hausdorff, d.hausdorff);
  }
  return {session.document(), ms / 15, worst};
}

// Milliseconds per dab of a push stroke across the sphere (N = n), median of five strokes:
// radius 0.1 and strength 0.5 (nothing stretched: keep-detail only checks), or radius 0.06 and
// strength 4 (a ridge pulled out: keep-detail relaxes it).
double pushPerDab(Brushes& b, int n, bool keepDetail, bool pull) {
  std::vector<double> perDab;
  for (int run = 0; run < 5; ++run) {
    app::SculptSession session;
    session.setBrushes(b.engine, b.catalog);
    session.setDocument(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n)));
    app::StrokeScript s;
    s.start.brushId = s.start.settings.brushId = "push";
    s.start.settings.radius = pull ? 0.06f : 0.1f;
    s.start.settings.strength = pull ? 4.0f : 0.5f;
    s.start.settings.keepDetail = keepDetail;
    s.path = {{0.35f, 0.5f}, {0.65f, 0.5f}};
    const auto start = Clock::now();
    const app::StrokeEnd r = app::playStroke(session, s);
    glFinish();
    perDab.push_back(msSince(start) / std::max(1, r.dabs));
  }
  std::sort(perDab.begin(), perDab.end());
  return perDab[perDab.size() / 2];
}

void row(const char* what, int n, const Figures& f, double ms, const core::SurfaceDistance* d) {
  std::printf("| %-22s | %5d | %8zu | %6.3f %% | %6.3f %% | %6.3f | %6.2f | %7.1f | %6.2f | ", what,
              n, f.limb.samples, 100 * f.limb.sampleShare, 100 * f.limb.areaShare, f.limb.fairShare,
              f.limb.spacingRatio, f.stretch.longestOverMedian, f.limbLength);
  if (d)
    std::printf("%.4f %% / %.3f %% | ", 100 * d->rms, 100 * d->hausdorff);
  else
    std::printf("— | ");
  std::printf("%9.1f |\n", ms);
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes{256, 1024};
  for (int a = 1; a < argc; ++a)
    if (std::strncmp(argv[a], "--sizes=", 8) == 0) {
      sizes.clear();
      for (const char* p = argv[a] + 8; *p;) {
        sizes.push_back(std::atoi(p));
        while (*p && *p != ',')
          ++p;
        if (*p) ++p;
      }
    }
  Brushes brushes;
  std::printf("GL renderer: %s\n\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  std::printf("| scenario | N | limb samples | limb sample share | limb area share | fair share | "
              "limb/body spacing | longest/median edge | limb length | moved RMS / Hausdorff "
              "(of diagonal) | ms |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int n : sizes) {
    const Limb off = pullLimb(brushes, n, false);
    const Figures offFigures = measure(off.document.positions);
    row("limb, keep-detail off", n, offFigures, off.msPerStroke, nullptr);

    const Limb on = pullLimb(brushes, n, true);
    const Figures onFigures = measure(on.document.positions);
    row("limb, keep-detail on", n, onFigures, on.msPerStroke, &on.worstRelaxation);
    std::printf("|   keep-detail limb length ÷ off | %d | %.3f |\n", n,
                onFigures.limbLength / offFigures.limbLength);

    const auto start = Clock::now();
    const core::Document even = core::evenOutSamples(off.document);
    const double evenMs = msSince(start);
    const core::SurfaceDistance d = core::compareSurfaces(core::extractMesh(off.document.positions),
                                                          core::extractMesh(even.positions));
    row("even-out of the limb", n, measure(even.positions), evenMs, &d);
  }
  std::printf("\n| push per dab, stroke across the sphere | N | keep-detail off ms | on ms | "
              "on ÷ off |\n|---|---|---|---|---|\n");
  for (bool pull : {false, true})
    for (int n : sizes) {
      const double off = pushPerDab(brushes, n, false, pull);
      const double on = pushPerDab(brushes, n, true, pull);
      std::printf("| %s | %d | %.3f | %.3f | %.2f |\n",
                  pull ? "radius 0.06, strength 4 (pulls a ridge)" : "radius 0.1, strength 0.5", n,
                  off, on, on / off);
    }
  return 0;
}
