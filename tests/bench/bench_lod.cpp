// Automatic LOD (issues 7 and 24): our LOD (generateLod: salient-point on a grid, the adaptive
// method, the full-resolution collapse and auto, which picks one of the last two per image) side
// by side with meshoptimizer's meshopt_simplify and OpenMesh's Decimater (quadric module alone),
// both run on the full-resolution mesh (extractMesh), at 1 %, 5 % and 25 % of its 2N² triangles,
// on a sculpted N = 1024 sphere and on every genus-0 mesh of ../shared/data/meshes/genus0
// imported at N = 512. A plain program printing one markdown table (with a line per input giving
// the stretch summary auto decides by) and PASS/MISS lines for the targets:
//   - auto at most 0.3 dB below meshopt_simplify (two-sided PSNR) and at most 1.5x its time, on
//     every input and fraction (issue 24);
//   - on the sculpted sphere, ours ≥ 2 dB above meshopt_simplify and ≥ 20× faster (issue 7);
//   - the dock's live LOD (auto kept to salient-point) at N = 1024 with a 20 k-triangle target
//     in ≤ 16 ms.
//
//   bench_lod [--mesh SUBSTRING] [--samples COUNT] [--no-openmesh] [--methods] [--sphere-size N]
//             [--max-aspect R] [--auto-only] [--document FILE.exr|FOLDER] [--no-saliency]
//
// --auto-only: only auto beside meshopt. --document: documents instead of the sphere and the
// meshes (the same images when made by octaclay-cli import --size 512, without importing again).
// --no-saliency: skip the CPU saliency (only the salient rows and the live line read it).
//
// "ours ms" is the whole path from a full-resolution image whose saliency is already in its
// alpha (the GPU keeps it up to date) to the final LOD mesh with its corner coordinates: the
// best of 5 runs, as meshopt's; OpenMesh is timed once (it takes 10³–10⁴ ms). Both
// are given the triangle count ours ended with, so every row compares equal counts. Distances are
// compareSurfaces against the full-resolution mesh (fractions of its bounding-box diagonal).
// --methods adds rows for the other resampling methods and for salient-point without refit.
// Always exits 0 once the table is printed; misses are read from the PASS/MISS lines.
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/octahedral_resampling.h"
#include "octaclay/core/import/spherical_parameterization.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/saliency.h"
#include "octaclay/core/measure/surface_distance.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

constexpr double kDecibelsAboveMeshopt = 2;
constexpr double kSpeedupOverMeshopt = 20;
constexpr double kLiveMilliseconds = 16;
constexpr double kAutoDecibelsBelowMeshopt = 0.3;
constexpr double kAutoSlowdown = 1.5;
constexpr std::size_t kLiveTriangles = 20'000;
constexpr std::array kFractions = {0.01, 0.05, 0.25};
// meshopt_simplify's best of 5, as ours: its time swung by ±25 % between runs of the benchmark
// (206-251 ms for one mesh at best of 3), and every speed-up is divided by it.
constexpr int kMeshoptRuns = 5;

using Clock = std::chrono::steady_clock;
double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of the whole process (all threads), in ms: on a machine shared with other jobs the
// wall clock counts their time too, the CPU time only ours.
double processCpuMilliseconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

struct Options {
  std::string meshFilter;
  std::size_t samples = 100'000;
  bool openmesh = true;
  bool methods = false;
  // A document (.exr), or a folder of them, instead of the meshes: the same images without
  // importing them again (octaclay-cli import --size 512 makes the bench's own).
  std::string document;
  bool noSaliency = false;
  bool autoOnly = false; // only the auto rows beside meshopt
  int sphereSize = 1024;
  float maxAspect = 10; // LodOptions::maxAspectRatio of every row of ours
};

// A sphere sculpted the way a user would: a few soft bumps and dents, two sharp ridges
// (creases along great circles) and a crater rim, all radial displacements of the samples.
GeometryImage sculptedSphere(int n) {
  GeometryImage image = makeBaseShape(BaseShape::Sphere, n);
  struct Bump {
    Vec3f centre;
    float height, width;
  };
  const Bump bumps[] = {{{0.6f, 0.5f, 0.62f}, 0.25f, 0.25f},  {{-0.7f, 0.2f, 0.68f}, -0.12f, 0.2f},
                        {{0.1f, -0.9f, 0.4f}, 0.18f, 0.12f},  {{-0.3f, -0.4f, -0.86f}, 0.3f, 0.35f},
                        {{0.8f, -0.3f, -0.5f}, -0.1f, 0.15f}, {{0.0f, 0.95f, -0.3f}, 0.08f, 0.05f}};
  for (auto& t : image.texels()) {
    const Vec3f d = normalize(t.xyz());
    float r = 1;
    for (const Bump& b : bumps) {
      const Vec3f c = normalize(b.centre);
      const float a = std::acos(std::clamp(dot(d, c), -1.0f, 1.0f));
      r += b.height * std::exp(-(a * a) / (b.width * b.width));
    }
    // Sharp ridges: a tent profile across two great circles, as a crease brush leaves them.
    const float ridge1 = std::abs(dot(d, normalize(Vec3f{1, 1, 0.2f})));
    const float ridge2 = std::abs(dot(d, normalize(Vec3f{-0.3f, 0.4f, 1})));
    r += 0.06f * std::max(0.0f, 1 - ridge1 / 0.08f) + 0.04f * std::max(0.0f, 1 - ridge2 / 0.05f);
    // A crater: a sharp rim ring around one direction, its floor sunk smoothly.
    const float a =
        std::acos(std::clamp(dot(d, normalize(Vec3f{-0.5f, -0.7f, 0.5f})), -1.0f, 1.0f));
    r += 0.05f * std::max(0.0f, 1 - std::abs(a - 0.35f) / 0.04f) -
         0.04f * std::exp(-(a * a) / (0.2f * 0.2f));
    const Vec3f p = d * r;
    t = {p.x, p.y, p.z, 0};
  }
  return image;
}

TriangleMesh compacted(const std::vector<Vec3f>& positions, const std::vector<unsigned>& indices) {
  TriangleMesh mesh;
  std::vector<std::uint32_t> remap(positions.size(), UINT32_MAX);
  for (std::size_t k = 0; k + 2 < indices.size(); k += 3) {
    std::array<std::uint32_t, 3> t{};
    for (int c = 0; c < 3; ++c) {
      std::uint32_t& r = remap[indices[k + c]];
      if (r == UINT32_MAX) {
        r = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(positions[indices[k + c]]);
      }
      t[c] = r;
    }
    mesh.triangles.push_back(t);
  }
  return mesh;
}

struct Timed {
  TriangleMesh mesh;
  double ms = 0;    // wall clock
  double cpuMs = 0; // process CPU time
};

// The best of `runs` calls of make() (wall and CPU time each their own best) and the fastest
// call's result.
template <class Make> auto bestOf(int runs, Make&& make) {
  struct Best {
    std::invoke_result_t<Make&> result{};
    double ms = 1e30, cpuMs = 1e30;
  } best;
  for (int r = 0; r < runs; ++r) {
    const auto start = Clock::now();
    const double cpu = processCpuMilliseconds();
    auto result = make();
    const double ms = millisecondsSince(start);
    best.cpuMs = std::min(best.cpuMs, processCpuMilliseconds() - cpu);
    if (ms < best.ms) {
      best.ms = ms;
      best.result = std::move(result);
    }
  }
  return best;
}

Timed meshopt(const TriangleMesh& full, std::size_t triangles) {
  std::vector<unsigned> indices(full.triangles.size() * 3);
  for (std::size_t t = 0; t < full.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      indices[3 * t + c] = full.triangles[t][c];
  std::vector<unsigned> out(indices.size());
  const auto best = bestOf(kMeshoptRuns, [&] {
    return meshopt_simplify(out.data(), indices.data(), indices.size(), &full.positions[0].x,
                            full.positions.size(), sizeof(Vec3f), 3 * triangles, 1.0f, 0, nullptr);
  });
  out.resize(best.result);
  return {compacted(full.positions, out), best.ms, best.cpuMs};
}

// OpenMesh 9's TriConnectivity::is_collapse_ok looks a property up by name on every call and
// made the Decimater take minutes on 2N² triangles; the Decimater calls is_collapse_ok on its
// mesh type, so this mesh answers it with the link condition for closed manifold meshes (as
// core/src/lod/vertex_collapse.cpp does). The priorities and collapses are OpenMesh's own.
class DecimaterMesh : public OpenMesh::TriMesh_ArrayKernelT<> {
public:
  bool is_collapse_ok(HalfedgeHandle v0v1) {
    const HalfedgeHandle v1v0 = opposite_halfedge_handle(v0v1);
    const VertexHandle v0 = to_vertex_handle(v1v0), v1 = to_vertex_handle(v0v1);
    if (status(edge_handle(v0v1)).deleted() || status(v0).deleted() || status(v1).deleted())
      return false;
    if (is_boundary(v0v1) || is_boundary(v1v0)) return false;
    const VertexHandle vl = to_vertex_handle(next_halfedge_handle(v0v1));
    const VertexHandle vr = to_vertex_handle(next_halfedge_handle(v1v0));
    if (vl == vr) return false;
    if (stamp_.size() < n_vertices()) stamp_.resize(n_vertices(), 0);
    ++current_;
    for (const VertexHandle v : vv_range(v0))
      stamp_[v.idx()] = current_;
    int shared = 0;
    for (const VertexHandle v : vv_range(v1))
      if (stamp_[v.idx()] == current_) {
        if (v != vl && v != vr) return false;
        ++shared;
      }
    return shared == 2;
  }

private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_ = 0;
};

Timed openmeshDecimater(const TriangleMesh& full, std::size_t triangles) {
  using Mesh = DecimaterMesh;
  Mesh mesh; // built and decimated in the timed call, read after it
  const auto best = bestOf(1, [&] {
    mesh.reserve(full.positions.size(), full.triangles.size() * 3 / 2, full.triangles.size());
    for (const Vec3f& p : full.positions)
      mesh.add_vertex(Mesh::Point(p.x, p.y, p.z));
    for (const auto& t : full.triangles)
      mesh.add_face(Mesh::VertexHandle(int(t[0])), Mesh::VertexHandle(int(t[1])),
                    Mesh::VertexHandle(int(t[2])));
    OpenMesh::Decimater::DecimaterT<Mesh> decimater(mesh);
    OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
    decimater.add(quadric);
    decimater.module(quadric).unset_max_err();
    decimater.initialize();
    decimater.decimate_to_faces(0, triangles);
    mesh.garbage_collection(); // while the Decimater lives: after it is gone this throws bad_alloc
    return mesh.n_faces();
  });
  std::vector<Vec3f> positions;
  for (const auto v : mesh.vertices())
    positions.push_back(
        {float(mesh.point(v)[0]), float(mesh.point(v)[1]), float(mesh.point(v)[2])});
  std::vector<unsigned> indices;
  for (const auto f : mesh.faces())
    for (const auto v : mesh.fv_range(f))
      indices.push_back(unsigned(v.idx()));
  return {compacted(positions, indices), best.ms, best.cpuMs};
}

Timed ours(const GeometryImage& image, const LodOptions& options, int runs) {
  auto best = bestOf(runs, [&] { return generateLod(image, options).mesh; });
  return {std::move(best.result), best.ms, best.cpuMs};
}

// Mean saliency at the corners of a LOD (each corner's image sample).
double meanCornerSaliency(const GeometryImage& image, const LodMesh& lod) {
  const int n = image.size();
  double sum = 0;
  for (const auto& corners : lod.cornerUv)
    for (const Vec2f uv : corners)
      sum += image.at(int(std::lround(uv.x * float(n))), int(std::lround(uv.y * float(n)))).w;
  return lod.cornerUv.empty() ? 0 : sum / (3.0 * double(lod.cornerUv.size()));
}

// The collapse's saliency weighting (LodOptions::collapseSaliencyWeight) against none: where
// the vertices go (mean saliency at the corners) and what it costs in PSNR.
template <class Input>
void saliencyWeightLine(const GeometryImage& image, const TriangleMesh& full, LodOptions options,
                        double fraction, const Input& input,
                        const SurfaceDistanceOptions& distance) {
  options.method = ResampleMethod::Collapse;
  const LodMesh weighted = generateLod(image, options);
  options.collapseSaliencyWeight = 0;
  const LodMesh plain = generateLod(image, options);
  std::printf("| %s | %d | %g %% | collapse saliency weight | mean saliency at the corners %.3f "
              "(unweighted %.3f), PSNR %.2f dB (unweighted %.2f dB) |\n",
              input.name.c_str(), input.n, 100 * fraction, meanCornerSaliency(image, weighted),
              meanCornerSaliency(image, plain), compareSurfaces(full, weighted.mesh, distance).psnr,
              compareSurfaces(full, plain.mesh, distance).psnr);
  std::fflush(stdout);
}

struct Verdict {
  std::string mesh, variant;
  double fraction = 0, decibels = 0, speedup = 0, cpuSpeedup = 0;
};

int run(const Options& options) {
  const fs::path data = (fs::path(OCTACLAY_SHARED_DATA) / "meshes" / "genus0").lexically_normal();
  struct Input {
    std::string name;
    int n;
  };
  std::vector<Input> inputs = {{"sculpted_sphere", options.sphereSize}};
  if (!options.document.empty()) {
    inputs.clear();
    std::vector<fs::path> documents{options.document};
    if (fs::is_directory(options.document)) {
      documents.clear();
      for (const auto& entry : fs::directory_iterator(options.document))
        if (entry.path().extension() == ".exr") documents.push_back(entry.path());
      std::sort(documents.begin(), documents.end());
    }
    for (const fs::path& d : documents)
      inputs.push_back({d.string(), 0});
  }
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(data))
    if (entry.path().extension() == ".obj" || entry.path().extension() == ".ply")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (options.document.empty())
    for (const fs::path& f : files)
      inputs.push_back({f.filename().string(), 512});
  const SurfaceDistanceOptions distance{options.samples, 1};
  std::vector<Verdict> verdicts;
  if (std::FILE* load = std::fopen("/proc/loadavg", "r")) {
    char line[128] = {};
    if (std::fgets(line, sizeof line, load)) std::printf("load average at start: %s\n", line);
    std::fclose(load);
  }
  std::printf("| mesh | N | fraction | method | triangles | ms | CPU ms | RMS %% | Hausdorff %% | "
              "PSNR dB | x meshopt | x meshopt (CPU) | dB over meshopt |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  double liveMs = -1, liveCpuMs = -1;
  for (const Input& input : inputs) {
    if (!options.meshFilter.empty() && input.name.find(options.meshFilter) == std::string::npos)
      continue;
    GeometryImage image;
    try {
      if (input.n == 0) {
        image = readDocument(input.name, {.layers = false}).positions;
      } else if (input.name == "sculpted_sphere") {
        image = sculptedSphere(input.n);
      } else {
        const TriangleMesh mesh = loadGenus0Mesh(data / input.name).mesh;
        image = resampleOctahedral(mesh, parameterizeOnSphere(mesh), input.n);
      }
    } catch (const std::exception& e) {
      std::printf("| %s | %d | FAIL: %s |\n", input.name.c_str(), input.n, e.what());
      continue;
    }
    const auto saliencyStart = Clock::now();
    if (!options.noSaliency)
      computeSaliency(image); // the GPU pass's job in the modeller: timed here for the record only
    const double saliencyMs = millisecondsSince(saliencyStart);
    const StretchSummary stretch = coarseStretch(image);
    std::printf("| %s | %d | stretch | coarse longest/median %.2f, p99/median %.2f, over 4x %.4f, "
                "roughness %.2f: auto picks %s | CPU saliency %.0f ms |\n",
                input.name.c_str(), input.n, stretch.longestOverMedian, stretch.p99OverMedian,
                stretch.shareOver4x, imageRoughness(image),
                std::string(methodName(chooseLodMethod(image, {}))).c_str(), saliencyMs);
    std::fflush(stdout);
    const TriangleMesh full = extractMesh(image);
    const std::size_t fullTriangles = full.triangles.size();
    for (const double fraction : kFractions) {
      const auto target = static_cast<std::size_t>(std::llround(fraction * double(fullTriangles)));
      LodOptions lodOptions;
      lodOptions.targetTriangles = target;
      lodOptions.method = ResampleMethod::SalientPoint;
      lodOptions.maxAspectRatio = options.maxAspect;
      // Ours, each row and verdict: the grid and the adaptive method, plain and oversampled.
      struct Variant {
        const char *row, *verdict;
        ResampleMethod method;
        int oversample;
        Timed timed;
        SurfaceDistance distance;
      };
      std::vector<Variant> variants{
          {{"ours (salient-point)", "oversample 1", ResampleMethod::SalientPoint, 1, {}, {}},
           {"ours (salient-point, oversample 2)",
            "oversample 2",
            ResampleMethod::SalientPoint,
            2,
            {},
            {}},
           {"ours (adaptive)", "adaptive", ResampleMethod::Adaptive, 1, {}, {}},
           {"ours (adaptive, oversample 2)",
            "adaptive, oversample 2",
            ResampleMethod::Adaptive,
            2,
            {},
            {}},
           {"ours (collapse)", "collapse", ResampleMethod::Collapse, 1, {}, {}},
           {"ours (auto)", "auto", ResampleMethod::Auto, 1, {}, {}}}};
      if (options.autoOnly) variants.erase(variants.begin(), variants.begin() + 5);
      const ResampleMethod autoChoice = chooseLodMethod(image, lodOptions);
      for (Variant& v : variants) {
        LodOptions variant = lodOptions;
        variant.method = v.method;
        variant.oversample = v.oversample;
        v.timed = ours(image, variant, 5);
        v.distance = compareSurfaces(full, v.timed.mesh, distance);
      }
      const Timed& our = variants.back().timed; // auto's count: its rows compare equal counts
      const std::size_t triangles = our.mesh.triangles.size();
      const Timed opt = meshopt(full, triangles);
      const SurfaceDistance optDistance = compareSurfaces(full, opt.mesh, distance);
      const auto row = [&](const char* method, const Timed& t, const SurfaceDistance& d) {
        std::printf(
            "| %s | %d | %g %% | %s | %zu | %.1f | %.1f | %.4f | %.3f | %.1f | %.1f | %.1f | %+.1f "
            "|\n",
            input.name.c_str(), input.n, 100 * fraction, method, t.mesh.triangles.size(), t.ms,
            t.cpuMs, 100 * d.rms, 100 * d.hausdorff, d.psnr, opt.ms / t.ms, opt.cpuMs / t.cpuMs,
            d.psnr - optDistance.psnr);
        std::fflush(stdout);
      };
      for (const Variant& v : variants)
        row(v.method == ResampleMethod::Auto
                ? ("ours (auto: " + std::string(methodName(autoChoice)) + ")").c_str()
                : v.row,
            v.timed, v.distance);
      if (options.methods) {
        for (const ResampleMethod m :
             {ResampleMethod::Point, ResampleMethod::Average, ResampleMethod::SalientAverage}) {
          LodOptions other = lodOptions;
          other.method = m;
          const Timed t = ours(image, other, 3);
          row(std::string(methodName(m)).c_str(), t, compareSurfaces(full, t.mesh, distance));
        }
        LodOptions noRefit = lodOptions;
        noRefit.refitToSurface = false;
        const Timed t = ours(image, noRefit, 3);
        row("salient-point, no refit", t, compareSurfaces(full, t.mesh, distance));
        LodOptions decimater = lodOptions;
        decimater.collapseEngine = CollapseEngine::Decimater;
        const Timed d = ours(image, decimater, 3);
        row("salient-point, Decimater engine", d, compareSurfaces(full, d.mesh, distance));
      }
      row("meshopt_simplify", opt, optDistance);
      if (autoChoice == ResampleMethod::Collapse && !options.noSaliency)
        saliencyWeightLine(image, full, lodOptions, fraction, input, distance);
      if (options.openmesh && !options.autoOnly) {
        const Timed om = openmeshDecimater(full, triangles);
        row("OpenMesh Decimater", om, compareSurfaces(full, om.mesh, distance));
      }
      for (const Variant& v : variants)
        if (v.method == ResampleMethod::Auto || input.name == "sculpted_sphere")
          verdicts.push_back({input.name, v.verdict, fraction, v.distance.psnr - optDistance.psnr,
                              opt.ms / v.timed.ms, opt.cpuMs / v.timed.cpuMs});
    }
    if (input.n == 1024) {
      LodOptions live; // the dock's: auto, kept to the image methods
      live.method = ResampleMethod::Auto;
      live.autoMayCollapse = false;
      live.targetTriangles = kLiveTriangles;
      const Timed t = ours(image, live, 9);
      liveMs = t.ms;
      liveCpuMs = t.cpuMs;
    }
  }
  std::printf("\n");
  // Issue 24's targets for auto on every mesh: never more than 0.3 dB below meshopt_simplify
  // and at most 1.5x its time.
  for (const Verdict& v : verdicts) {
    if (v.variant != "auto") continue;
    const bool pass = v.decibels >= -kAutoDecibelsBelowMeshopt && v.speedup >= 1 / kAutoSlowdown;
    std::printf("%s %s %g %% (auto): %+.2f dB over meshopt_simplify (target >= %+.1f), %.2fx its "
                "time (target <= %.1fx; %.2fx in CPU time)\n",
                pass ? "PASS" : "MISS", v.mesh.c_str(), 100 * v.fraction, v.decibels,
                -kAutoDecibelsBelowMeshopt, 1 / v.speedup, kAutoSlowdown, 1 / v.cpuSpeedup);
  }
  // Issue 7's targets, on the sculpted sphere only (issue 24 withdrew them for imported meshes).
  for (const Verdict& v : verdicts) {
    if (v.mesh != "sculpted_sphere") continue;
    const bool pass = v.decibels >= kDecibelsAboveMeshopt && v.speedup >= kSpeedupOverMeshopt;
    std::printf("%s %s %g %% (%s): %+.1f dB over meshopt_simplify (target >= %+.0f), %.1fx "
                "faster (target >= %.0fx; %.1fx in CPU time)\n",
                pass ? "PASS" : "MISS", v.mesh.c_str(), 100 * v.fraction, v.variant.c_str(),
                v.decibels, kDecibelsAboveMeshopt, v.speedup, kSpeedupOverMeshopt, v.cpuSpeedup);
  }
  if (liveMs >= 0)
    std::printf("%s live LOD: generateLod N = 1024, %zu-triangle target: %.1f ms wall, %.1f ms CPU "
                "over its threads (target <= %.0f ms)\n",
                liveMs <= kLiveMilliseconds ? "PASS" : "MISS", kLiveTriangles, liveMs, liveCpuMs,
                kLiveMilliseconds);
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--mesh" && i + 1 < argc) {
      options.meshFilter = argv[++i];
    } else if (arg == "--samples" && i + 1 < argc) {
      options.samples = std::strtoull(argv[++i], nullptr, 10);
    } else if (arg == "--sphere-size" && i + 1 < argc) {
      options.sphereSize = std::atoi(argv[++i]);
    } else if (arg == "--max-aspect" && i + 1 < argc) {
      options.maxAspect = std::strtof(argv[++i], nullptr);
    } else if (arg == "--no-openmesh") {
      options.openmesh = false;
    } else if (arg == "--document" && i + 1 < argc) {
      options.document = argv[++i];
    } else if (arg == "--no-saliency") {
      options.noSaliency = true;
    } else if (arg == "--auto-only") {
      options.autoOnly = true;
    } else if (arg == "--methods") {
      options.methods = true;
    } else {
      std::fprintf(stderr, "bench_lod: unknown option %s\n", argv[i]);
      return 2;
    }
  }
  return run(options);
}
