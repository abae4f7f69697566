// The relax brush (plugins/brushes/relax, a "reparameterize" pass): on a limb pulled out of a
// sphere by push, relax dabs give the limb more samples and shorten its longest edges, while
// every new vertex lies on the old surface, the seams stay exact, no cell folds, paint stays on
// the same surface points, undo/redo is bit-exact, and a broken shader of the kind is reported
// with its file and line.

#include "brush_test_support.h"
#include "path_stroke.h"

#include "octaclay/core/document/document_info.h"
#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/stroke.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <unordered_map>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;

namespace {

constexpr int kN = 128;
constexpr float kLimb = 1.5f; // a vertex farther than this from the centre is on the limb

// How the image samples the limb: its share of the vertices and the grid's edge lengths.
struct Sampling {
  double limbShare = 0;   // vertices with |p| > kLimb ÷ all vertices (N² + 2)
  double longest = 0;     // longest grid edge
  double median = 0;      // median grid edge
  double limbLongest = 0; // longest edge with an end on the limb
};

Sampling measure(const core::GeometryImage& image) {
  const int n = image.size();
  Sampling s;
  std::size_t limb = 0, vertices = 0;
  core::forEachCanonicalRun(n, [&](int j, int begin, int end) {
    for (int i = begin; i < end; ++i, ++vertices)
      limb += core::length(image.at(i, j).xyz()) > kLimb;
  });
  s.limbShare = double(limb) / double(vertices);
  std::vector<double> edges;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      for (core::Sample d : {core::Sample{1, 0}, core::Sample{0, 1}}) {
        if (i + d.i > n || j + d.j > n) continue;
        const core::Vec3f a = image.at(i, j).xyz(), b = image.at(i + d.i, j + d.j).xyz();
        const double l = core::length(a - b);
        edges.push_back(l);
        if (core::length(a) > kLimb || core::length(b) > kLimb)
          s.limbLongest = std::max(s.limbLongest, l);
      }
  std::nth_element(edges.begin(), edges.begin() + std::ptrdiff_t(edges.size() / 2), edges.end());
  s.median = edges[edges.size() / 2];
  s.longest = *std::max_element(edges.begin(), edges.end());
  return s;
}

// Double precision: a long, thin triangle of a stretched limb loses float's digits.
struct V3 {
  double x, y, z;
  V3(core::Vec3f v) : x(v.x), y(v.y), z(v.z) {}
  V3(double a, double b, double c) : x(a), y(b), z(c) {}
  friend V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
};

// The closest point on triangle abc to p, as barycentric weights of a, b, c (Ericson,
// Real-Time Collision Detection 5.1.5).
std::array<double, 3> closestOnTriangle(V3 p, V3 a, V3 b, V3 c) {
  const V3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const V3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const V3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

// The old surface: the grid's triangles (core's cellTriangles) in a uniform grid of buckets.
class OldSurface {
public:
  explicit OldSurface(const core::GeometryImage& image) : image_(image), n_(image.size()) {
    core::BoundingBox box;
    for (int j = 0; j <= n_; ++j)
      for (int i = 0; i <= n_; ++i)
        box.extend(image.at(i, j).xyz());
    origin_ = box.min;
    cell_ = box.diagonal() / 64;
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i < n_; ++i)
        for (const auto& t : core::cellTriangles(n_, i, j)) {
          triangles_.push_back(t);
          core::BoundingBox b;
          for (core::Sample s : t)
            b.extend(image.at(s).xyz());
          const auto lo = key(b.min), hi = key(b.max);
          for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
              for (int x = lo[0]; x <= hi[0]; ++x)
                buckets_[pack({x, y, z})].push_back(triangles_.size() - 1);
        }
  }

  struct Hit {
    float distance = std::numeric_limits<float>::max();
    std::size_t triangle = 0;
    std::array<double, 3> weights{};
  };

  // The closest point of the old surface within `reach` buckets of p.
  Hit closest(core::Vec3f p, int reach = 1) const {
    Hit best;
    const auto k = key(p);
    for (int z = k[2] - reach; z <= k[2] + reach; ++z)
      for (int y = k[1] - reach; y <= k[1] + reach; ++y)
        for (int x = k[0] - reach; x <= k[0] + reach; ++x) {
          const auto found = buckets_.find(pack({x, y, z}));
          if (found == buckets_.end()) continue;
          for (std::size_t t : found->second) {
            const auto& tri = triangles_[t];
            const core::Vec3f a = image_.at(tri[0]).xyz(), b = image_.at(tri[1]).xyz(),
                              c = image_.at(tri[2]).xyz();
            const std::array<double, 3> w = closestOnTriangle(p, a, b, c);
            const V3 q{a.x * w[0] + b.x * w[1] + c.x * w[2], a.y * w[0] + b.y * w[1] + c.y * w[2],
                       a.z * w[0] + b.z * w[1] + c.z * w[2]};
            const float d = float(std::sqrt(dot(q - V3(p), q - V3(p))));
            if (d < best.distance) best = {d, t, w};
          }
        }
    return best;
  }

  const std::array<core::Sample, 3>& triangle(std::size_t t) const { return triangles_[t]; }
  core::Vec3f normal(std::size_t t) const {
    const auto& tri = triangles_[t];
    const core::Vec3f a = image_.at(tri[0]).xyz();
    return core::cross(image_.at(tri[1]).xyz() - a, image_.at(tri[2]).xyz() - a);
  }
  float cell() const { return cell_; }

private:
  std::array<int, 3> key(core::Vec3f p) const {
    return {int(std::floor((p.x - origin_.x) / cell_)), int(std::floor((p.y - origin_.y) / cell_)),
            int(std::floor((p.z - origin_.z) / cell_))};
  }
  static long long pack(std::array<int, 3> k) {
    return (static_cast<long long>(k[0] + 1024) << 40) |
           (static_cast<long long>(k[1] + 1024) << 20) | static_cast<long long>(k[2] + 1024);
  }
  const core::GeometryImage& image_;
  int n_;
  core::Vec3f origin_;
  float cell_ = 1;
  std::vector<std::array<core::Sample, 3>> triangles_;
  std::unordered_map<long long, std::vector<std::size_t>> buckets_;
};

std::array<float, 4> diffuseAt(const core::Layer& diffuse, int n, core::Sample s) {
  if (diffuse.uniform()) return diffuse.fill;
  const std::size_t at = (std::size_t(s.j) * std::size_t(n + 1) + std::size_t(s.i)) * 4;
  return {diffuse.texels[at], diffuse.texels[at + 1], diffuse.texels[at + 2],
          diffuse.texels[at + 3]};
}

} // namespace

class RelaxBrushTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void manifestIsAReparameterizePass();
  void relaxGivesTheLimbSamplesAndKeepsTheSurface();
  void undoRedoIsBitExact();
  void brokenShaderIsReportedWithFileAndLine();
  void bodyWithoutBrushOffsetIsRefused();

private:
  // A sphere with a limb pulled out at the pole sample (N/2, N/2): 15 one-dab push strokes.
  GpuDocument limb();
  // Relax strokes along the limb, base to tip; returns the last one's undo record.
  core::EditStep relax(GpuDocument& document, int strokes);

  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
  std::map<std::string, BrushManifest> manifests_;
};

void RelaxBrushTest::initTestCase() {
  try {
    context_.emplace(GlContext::createHeadless());
    engine_.emplace();
    for (const char* id : {"push", "paint", "relax"}) {
      const BrushManifest manifest = builtInManifest(id);
      engine_->load(manifest, readFile(manifest.shaderPath()));
      manifests_.emplace(id, manifest);
    }
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
}

void RelaxBrushTest::manifestIsAReparameterizePass() {
  const BrushManifest& relax = manifests_.at("relax");
  QCOMPARE(relax.pass, PassKind::Reparameterize);
  QCOMPARE(relax.api, 2);
  QVERIFY(relax.iterations > 1);
  QCOMPARE(relax.writes.size(), std::size_t(4));
}

GpuDocument RelaxBrushTest::limb() {
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, kN)));
  PathStroke push;
  push.brush = "push";
  push.path = {{0.5f, 0.5f}};
  push.radius = 0.06f * document.bounds().diagonal();
  push.strength = 1.0f;
  push.spacing = 1.0f;
  for (int k = 0; k < 15; ++k)
    strokeAlongPath(*engine_, document, manifests_.at("push"), push);
  return document;
}

core::EditStep RelaxBrushTest::relax(GpuDocument& document, int strokes) {
  PathStroke settings;
  settings.brush = "relax";
  settings.radius = 1.0f;
  settings.strength = 1.0f;
  core::EditStep last;
  for (int k = 0; k < strokes; ++k) {
    // Along the limb from its base to its tip: the samples on the ray i > N/2 from the pole.
    const core::GeometryImage& image = document.document().positions;
    int base = kN / 2, tip = kN / 2;
    float far = 0;
    for (int i = kN / 2; i <= kN; ++i) {
      const float r = core::length(image.at(i, kN / 2).xyz());
      if (r > 1.2f) base = i;
      if (r > far) far = r, tip = i;
    }
    settings.path = {{float(base) / kN, 0.5f}, {float(tip) / kN, 0.5f}};
    last = strokeAlongPath(*engine_, document, manifests_.at("relax"), settings).undo;
  }
  return last;
}

void RelaxBrushTest::relaxGivesTheLimbSamplesAndKeepsTheSurface() {
  GpuDocument document = limb();
  // A stripe round the limb's middle.
  PathStroke paint;
  paint.brush = "paint";
  paint.radius = 0.4f;
  paint.strength = 1.0f;
  paint.parameters["color"] = {1.0f, 0.0f, 0.0f, 1.0f};
  {
    const core::GeometryImage& image = document.document().positions;
    int middle = kN / 2;
    for (int i = kN / 2; i <= kN; ++i)
      if (core::length(image.at(i, kN / 2).xyz()) > 2.5f) middle = i;
    paint.path = {{float(middle) / kN, 0.5f}};
  }
  strokeAlongPath(*engine_, document, manifests_.at("paint"), paint);

  const core::Document start = document.document();
  const Sampling old = measure(start.positions);
  const float diagonal = document.bounds().diagonal();
  float limbLength = 0;
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i)
      limbLength = std::max(limbLength, core::length(start.positions.at(i, j).xyz()));

  // Strokes along the limb. (b) every vertex a stroke moves lies on the surface from before the
  // stroke (it resamples once, from the layers at its start); (d) with the colour there.
  const int strokes = 6;
  float worst = 0, worstColour = 0;
  double leastArea = 1;
  int moved = 0, redMoved = 0, folded = 0;
  for (int k = 0; k < strokes; ++k) {
    const core::Document before = document.document();
    QVERIFY(!relax(document, 1).tiles.empty());
    const core::Document& now = document.document();
    const OldSurface surface(before.positions);
    // Where each vertex now stands in the image before the stroke (the barycentric point of the
    // old triangle it lies on): the offset map, read back.
    std::vector<std::array<double, 2>> at(std::size_t((kN + 1) * (kN + 1)));
    for (int j = 0; j <= kN; ++j)
      for (int i = 0; i <= kN; ++i) {
        at[std::size_t(j * (kN + 1) + i)] = {double(i), double(j)};
        const core::Vec3f p = now.positions.at(i, j).xyz();
        if (p == before.positions.at(i, j).xyz()) continue;
        ++moved;
        const OldSurface::Hit hit = surface.closest(p);
        std::array<double, 2> q{};
        for (int v = 0; v < 3; ++v) {
          q[0] += hit.weights[v] * surface.triangle(hit.triangle)[v].i;
          q[1] += hit.weights[v] * surface.triangle(hit.triangle)[v].j;
        }
        at[std::size_t(j * (kN + 1) + i)] = q;
        worst = std::max(worst, hit.distance);
        std::array<float, 4> colour{};
        for (int v = 0; v < 3; ++v) {
          const auto c = diffuseAt(before.diffuse, kN, surface.triangle(hit.triangle)[v]);
          for (int ch = 0; ch < 4; ++ch)
            colour[ch] += float(c[ch] * hit.weights[v]);
        }
        const std::array<float, 4> here = diffuseAt(now.diffuse, kN, {i, j});
        for (int ch = 0; ch < 4; ++ch)
          worstColour = std::max(worstColour, std::abs(colour[ch] - here[ch]));
        redMoved += here[0] > 0.5f && here[1] < 0.5f;
      }
    // (c) no cell folded: each triangle keeps its orientation in the image. Triangles whose
    // corners stand on both sides of a seam are left out (their points are in different tiles).
    // Checked on the first stroke, whose old surface is push's (the closest point then names
    // the old triangle without ambiguity; later strokes' old surfaces hold slivers near the tip).
    for (int j = 0; j < kN && k == 0; ++j)
      for (int i = 0; i < kN; ++i)
        for (const auto& t : core::cellTriangles(kN, i, j)) {
          std::array<std::array<double, 2>, 3> p{};
          for (int v = 0; v < 3; ++v)
            p[v] = at[std::size_t(t[v].j * (kN + 1) + t[v].i)];
          const double e1x = p[1][0] - p[0][0], e1y = p[1][1] - p[0][1];
          const double e2x = p[2][0] - p[0][0], e2y = p[2][1] - p[0][1];
          if (std::max({std::abs(e1x), std::abs(e1y), std::abs(e2x), std::abs(e2y)}) > kN / 4)
            continue;
          const double r1x = t[1].i - t[0].i, r1y = t[1].j - t[0].j;
          const double r2x = t[2].i - t[0].i, r2y = t[2].j - t[0].j;
          const double area = (e1x * e2y - e1y * e2x) * (r1x * r2y - r1y * r2x);
          leastArea = std::min(leastArea, area);
          folded += area <= 0;
        }
  }
  const core::Document& after = document.document();
  const Sampling now = measure(after.positions);
  qInfo("limb reaches %.2f from the centre; after %d relax strokes: limb share of vertices %.4f "
        "-> %.4f; longest edge / median %.1f -> %.1f (longest %.3f -> %.3f, median %.4f -> "
        "%.4f)",
        limbLength, strokes, old.limbShare, now.limbShare, old.longest / old.median,
        now.longest / now.median, old.longest, now.longest, old.median, now.median);
  qInfo("%d vertex moves, %d of them red; farthest from the surface before the stroke %.3g "
        "(%.3g of the diagonal); colour off by at most %.4f",
        moved, redMoved, worst, worst / diagonal, worstColour);
  // (a) the limb gains samples and its longest edges shrink.
  QVERIFY2(now.limbShare > 3 * old.limbShare, "the limb's share of samples did not go up");
  QVERIFY2(now.longest / now.median < 0.6 * (old.longest / old.median),
           "the longest edge did not shrink against the median");
  QVERIFY(moved > 1000);
  QVERIFY(redMoved > 20);
  QVERIFY2(worst <= 1e-4f * diagonal, "a vertex left the old surface");
  // Half floats hold the colour: 2^-11 relative, plus the interpolation's rounding.
  QVERIFY2(worstColour < 2e-3f, "the paint did not move with the surface");
  // Over all the strokes: one interpolation each.
  const OldSurface surface(start.positions);
  float drift = 0;
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i)
      drift = std::max(drift, surface.closest(after.positions.at(i, j).xyz()).distance);
  qInfo("after all %d strokes, farthest from the surface before them: %.3g of the diagonal",
        strokes, drift / diagonal);

  // (c) seams exact, closed, genus 0, no cell folded: every triangle faces the way the old
  // surface does where it lies.
  QCOMPARE(core::maxSeamGap(after.positions), 0.0f);
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i) {
      std::array<core::Sample, 4> same{};
      const int count = core::identifiedSamples(kN, {i, j}, same);
      for (int k = 1; k < count; ++k)
        QVERIFY(std::memcmp(&after.positions.at(same[0]), &after.positions.at(same[k]),
                            sizeof(core::Vec4f)) == 0);
    }
  const core::DocumentInfo info = core::describeDocument(after);
  QVERIFY(info.closed);
  QVERIFY(info.manifold);
  QCOMPARE(info.euler, 2LL);
  qInfo("least doubled area of a triangle in the image after a stroke: %.3g (1 unmoved)",
        leastArea);
  QCOMPARE(folded, 0);
}

void RelaxBrushTest::undoRedoIsBitExact() {
  GpuDocument document = limb();
  PathStroke paint;
  paint.brush = "paint";
  paint.path = {{0.55f, 0.5f}};
  paint.radius = 0.5f;
  paint.strength = 1.0f;
  strokeAlongPath(*engine_, document, manifests_.at("paint"), paint);
  const auto start = snapshot(document);
  core::EditHistory history;
  history.record(relax(document, 1));
  const auto relaxed = snapshot(document);
  QVERIFY(!sameBits(start, relaxed));
  const core::TileApplier apply = undoApplier(document);
  QVERIFY(history.undo(apply));
  QVERIFY(sameBits(snapshot(document), start));
  QVERIFY(history.redo(apply));
  QVERIFY(sameBits(snapshot(document), relaxed));
}

void RelaxBrushTest::brokenShaderIsReportedWithFileAndLine() {
  BrushManifest broken = manifests_.at("relax");
  broken.id = "relax-broken";
  try {
    engine_->load(broken, "vec2 brushOffset(BrushInput b) {\n  return vec3(b.weight);\n}\n");
    QFAIL("a broken shader loaded");
  } catch (const GlError& e) {
    const std::string message = e.what();
    QVERIFY2(message.find(broken.shaderPath().string() + ":2") != std::string::npos,
             message.c_str());
  }
  QVERIFY(!engine_->has("relax-broken"));
}

void RelaxBrushTest::bodyWithoutBrushOffsetIsRefused() {
  BrushManifest wrong = manifests_.at("relax");
  wrong.id = "relax-without-offset";
  try {
    engine_->load(wrong, "vec4 brush(vec4 value, BrushInput b) { return value; }\n");
    QFAIL("a reparameterize brush without brushOffset() loaded");
  } catch (const GlError& e) {
    const std::string message = e.what();
    QVERIFY2(message.find("brushOffset") != std::string::npos, message.c_str());
    QVERIFY2(message.find(wrong.shaderPath().string()) != std::string::npos, message.c_str());
  }
}

QTEST_GUILESS_MAIN(RelaxBrushTest)
#include "relax_brush_gltest.moc"
