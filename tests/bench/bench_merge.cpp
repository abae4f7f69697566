// Issue 33's creature from parts (tests/merge_creature.h: a ball body, four capsule legs, a capsule
// neck and a sphere head, placed with transforms) merged into one document (core::mergeParts) at
// N = 1024 (--size=N for another N; --parts=N the parts' own N, 256; --level-set=M the level
// set's resolution, MergeOptions' default unless given). Prints the voxel size, the union's mesh,
// each stage's time, the whole merge's wall-clock and CPU time (target: ≤ 15 s wall), each
// part's fair share of samples (its share of the samples ÷ its share of the area, a sample
// belonging to the part whose analytic surface is nearest; target ≥ 0.5), the samples' distance
// to the analytic union and the stretch summary. --paint paints every part's diffuse layer (a
// colour per part, the body's red following x) so that the layers are carried, which a merge of
// unpainted parts skips. --out=FILE writes the merged document.
// Other arguments are ignored (scripts/bench passes benchmark filters).
#include "../merge_creature.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/merge/merge.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

using namespace octaclay;

namespace {

double cpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

} // namespace

int main(int argc, char** argv) {
  core::MergeOptions options;
  options.size = 1024;
  int partSize = 256;
  std::string out;
  bool paint = false;
  for (int a = 1; a < argc; ++a) {
    if (std::strncmp(argv[a], "--size=", 7) == 0)
      options.size = std::atoi(argv[a] + 7);
    else if (std::strncmp(argv[a], "--parts=", 8) == 0)
      partSize = std::atoi(argv[a] + 8);
    else if (std::strncmp(argv[a], "--level-set=", 12) == 0)
      options.levelSetSize = std::atoi(argv[a] + 12);
    else if (std::strcmp(argv[a], "--no-snap") == 0)
      options.snapToParts = false;
    else if (std::strcmp(argv[a], "--paint") == 0)
      paint = true;
    else if (std::strncmp(argv[a], "--out=", 6) == 0)
      out = argv[a] + 6;
  }
  const std::vector<testing::CreaturePiece> pieces = testing::mergeCreature(partSize);
  if (paint)
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      core::Document& d = *pieces[k].document;
      const std::size_t side = std::size_t(d.size() + 1);
      d.diffuse.texels.resize(side * side * 4);
      for (std::size_t t = 0; t < side * side; ++t) {
        const float x = d.positions.texels()[t].x;
        const float rgba[4] = {k == 0 ? 0.5f + 0.5f * x : 0.1f * float(k), 0.5f, 0.5f, 1.0f};
        std::copy(rgba, rgba + 4, d.diffuse.texels.begin() + std::ptrdiff_t(4 * t));
      }
    }
  const std::vector<core::MergePart> parts = testing::creatureMergeParts(pieces);

  const auto wallStart = std::chrono::steady_clock::now();
  const double cpuStart = cpuMs();
  core::MergeResult merged;
  try {
    merged = core::mergeParts(parts, options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_merge: %s\n", e.what());
    return 1;
  }
  const double wallMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wallStart)
          .count();
  const double cpu = cpuMs() - cpuStart;

  std::printf("creature from %zu parts of N = %d%s merged at N = %d (level set %d)\n", parts.size(),
              partSize, paint ? ", painted," : "", options.size,
              std::min(options.size, options.levelSetSize));
  std::printf("voxel %.4f; union's mesh %zu vertices, %zu triangles, Euler %lld\n",
              merged.voxelSize, merged.levelSetVertices, merged.levelSetTriangles, merged.euler);
  std::printf("least fair share estimated from the map: %.2f, turned %.2f\n",
              merged.leastShareUnturned, merged.leastShareTurned);
  std::printf("level set %.0f ms, map + resample %.0f ms, snap and layers %.0f ms (%.1f %% of the "
              "samples moved onto their part)\n",
              merged.levelSetMs, merged.parameterizeMs, merged.partsMs,
              100.0 * double(merged.snapped) / double(merged.document.positions.texelCount()));
  std::printf("merge: %.1f s wall, %.1f s CPU (target <= 15 s wall) %s\n", wallMs / 1e3, cpu / 1e3,
              wallMs <= 15e3 ? "PASS" : "MISS");

  const core::GeometryImage& image = merged.document.positions;
  double least = 1e9;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const core::RegionSampling s = core::regionSampling(
        image, [&](const core::Vec3f& p) { return testing::nearestPiece(pieces, p) == int(k); });
    least = std::min(least, s.fairShare);
    std::printf("  %-16s area %.3f  samples %.3f  fair share %.2f\n", pieces[k].name.c_str(),
                s.areaShare, s.sampleShare, s.fairShare);
  }
  std::printf("least fair share %.2f (target >= 0.5) %s\n", least, least >= 0.5 ? "PASS" : "MISS");
  double worst = 0, sum = 0;
  for (const core::Vec4f& t : image.texels()) {
    const double d = std::abs(double(testing::unionDistance(pieces, t.xyz())));
    worst = std::max(worst, d);
    sum += d;
  }
  std::printf("distance to the analytic union: mean %.5f, worst %.5f (%.2f voxels)\n",
              sum / double(image.texels().size()), worst, worst / merged.voxelSize);
  const core::StretchSummary stretch = core::summarizeStretch(image);
  std::printf("longest edge / median %.2f, p99 / median %.2f\n", stretch.longestOverMedian,
              stretch.p99OverMedian);
  if (!out.empty()) core::writeDocument(merged.document, out);
  return 0;
}
