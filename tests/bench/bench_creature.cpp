// Issue 23's creature: four legs and a neck pulled out of a ball with snake-hook, each one stroke
// along a 3-point path (where it starts on the ball, then two points in object space the drag
// moves through, as `octaclay-cli stroke --path u,v --drag x,y,z;x,y,z` makes it), keep-detail off
// and on, at N = 256 (--sizes=a,b for others), in three layouts: the animal (legs down -y, two
// on each half of the octahedral image, neck up and to the front), and all four legs along -z or
// +z. A table of each part's (the samples farther than 1.15 from the centre, by the start they
// are nearest to) fair share of samples (its share of the samples ÷ its share of the area; the
// target: at least 0.3 with keep-detail on), its length and the time per stroke, and the least
// fair share of each creature. --out=FILE writes the animal made with keep-detail on.
// Arguments other than --sizes and --out are ignored (scripts/bench passes benchmark filters).
#include "../creature_layout.h"
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

struct Row {
  std::vector<core::RegionSampling> sampling; ///< per part
  std::vector<float> length;                  ///< farthest sample of the part from the centre
  double msPerStroke = 0;
  core::Document document;
};

Row makeCreature(gpu::BrushEngine& engine, const gpu::BrushCatalog& catalog, int n, bool keepDetail,
                 testing::CreatureLayout layout) {
  const gpu::BrushManifest& hook = *catalog.find("snake-hook");
  app::SculptSession session;
  session.setBrushes(engine, catalog);
  const core::GeometryImage ball = core::makeBaseShape(core::BaseShape::Sphere, n);
  session.setDocument(core::makeDocument(ball));
  const std::vector<testing::CreaturePart> all = testing::creatureParts(layout);
  double ms = 0;
  for (const testing::CreaturePart& part : all) {
    const auto start = Clock::now();
    app::StrokeScript stroke = testing::creatureStroke(part, ball, hook.id, session.diagonal());
    stroke.start.settings.keepDetail = keepDetail;
    app::playStroke(session, stroke);
    glFinish();
    ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }
  Row row;
  row.msPerStroke = ms / double(all.size());
  row.document = session.document();
  const core::GeometryImage& image = row.document.positions;
  row.sampling = testing::creatureSampling(image, all);
  for (std::size_t k = 0; k < all.size(); ++k) {
    float farthest = 0;
    for (const core::Vec4f& t : image.texels())
      if (testing::creaturePartOf(all, t.xyz()) == int(k))
        farthest = std::max(farthest, core::length(t.xyz()));
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
      "| layout | N | keep-detail | part | samples | sample share | area share | fair share "
      "| reach from centre | ms per stroke |\n|---|---|---|---|---|---|---|---|---|---|\n");
  using testing::CreatureLayout;
  for (CreatureLayout layout :
       {CreatureLayout::Animal, CreatureLayout::LegsMinusZ, CreatureLayout::LegsPlusZ})
    for (int n : sizes)
      for (bool keepDetail : {false, true}) {
        const std::vector<testing::CreaturePart> all = testing::creatureParts(layout);
        const Row row = makeCreature(engine, catalog, n, keepDetail, layout);
        double least = 1e30;
        for (std::size_t k = 0; k < all.size(); ++k) {
          const core::RegionSampling& r = row.sampling[k];
          least = std::min(least, r.fairShare);
          std::printf("| %s | %d | %s | %s | %zu | %.4f %% | %.4f %% | %.3f | %.3f | %.0f |\n",
                      testing::layoutName(layout), n, keepDetail ? "on" : "off", all[k].name,
                      r.samples, 100 * r.sampleShare, 100 * r.areaShare, r.fairShare, row.length[k],
                      row.msPerStroke);
        }
        std::printf("| %s | %d | %s | least fair share | | | | **%.3f** | | |\n",
                    testing::layoutName(layout), n, keepDetail ? "on" : "off", least);
        if (keepDetail && layout == CreatureLayout::Animal && !out.empty())
          core::writeDocument(row.document, out);
      }
  return 0;
}
