// The paint brushes (colour, specular, reflectivity, mask) run as GPU passes on a sphere whose
// layers hold seam-consistent noise: each moves only its channels toward its value inside the
// radius (checked against a CPU computation of the weight), keeps the other channels and the
// texels outside the radius bit-identical, keeps identified seam samples equal, erases back to
// the layer's base value, and the colour, specular and reflectivity brushes stop where the mask
// is 0. Everything is read back from the GpuDocument's mirror. A seamed dab that reaches every
// tile leaves the border unpainted (an engine bug): that case is an expected failure below.

#include "brush_test_support.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/gpu/gl_context.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <vector>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;

namespace {

constexpr int kSize = 64;
constexpr float kPaint = 0.0f, kErase = 1.0f; // indices of the "mode" enum's options

struct PaintBrush {
  std::string id;
  core::EditLayer layer;
  std::vector<int> channels;                              ///< mirror channels it writes
  std::map<std::string, std::array<float, 4>> parameters; ///< for paint mode
  std::array<float, 4> target;                            ///< paint mode's value, per channel
};

// The specular and reflectivity brushes run with their manifest defaults (0.9, 0.8), so these
// also pin the defaults; the colour moves every diffuse channel away from the base.
PaintBrush paintBrush(const QString& id) {
  if (id == "paint")
    return {"paint",
            core::EditLayer::Diffuse,
            {0, 1, 2, 3},
            {{"color", {0.1f, 0.3f, 0.9f, 0.5f}}},
            {0.1f, 0.3f, 0.9f, 0.5f}};
  if (id == "paint-specular")
    return {"paint-specular", core::EditLayer::Feature, {1}, {}, {0.0f, 0.9f, 0.0f, 0.0f}};
  if (id == "paint-reflectivity")
    return {"paint-reflectivity", core::EditLayer::Feature, {2}, {}, {0.0f, 0.0f, 0.8f, 0.0f}};
  return {"mask", core::EditLayer::Mask, {0}, {}, {0.0f, 0.0f, 0.0f, 0.0f}};
}

bool writes(const PaintBrush& brush, int channel) {
  return std::find(brush.channels.begin(), brush.channels.end(), channel) != brush.channels.end();
}

// Diffuse and feature are RGBA16F textures: a value written there comes back rounded to a half
// float (a relative step of 2^-11, under 5e-4 in [0, 1]), and the CPU's weight differs from the
// GPU's by float rounding only. The mask is R32F.
float tolerance(core::EditLayer layer) {
  return layer == core::EditLayer::Mask ? 1e-5f : 1e-3f;
}

// A value in [0, 1] that a half float holds exactly (k / 1024), the same for every sample
// identified with s so that the layer starts seamed.
float noiseAt(int n, core::Sample s, int channel) {
  const core::Sample c = core::canonical(n, s);
  unsigned h =
      unsigned(c.i) * 73856093u ^ unsigned(c.j) * 19349663u ^ unsigned(channel) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return float(h % 1025u) / 1024.0f;
}

void fillWithNoise(core::Layer& layer, int n) {
  const int side = n + 1;
  layer.texels.resize(std::size_t(side) * side * layer.channels);
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i)
      for (int c = 0; c < layer.channels; ++c)
        layer.texels[(std::size_t(j) * side + i) * layer.channels + c] = noiseAt(n, {i, j}, c);
}

// A sphere whose diffuse and feature layers hold noise (the mask stays unpainted, 1).
core::Document noisyDocument(int n) {
  core::Document doc = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n));
  fillWithNoise(doc.diffuse, n);
  fillWithNoise(doc.feature, n);
  return doc;
}

std::vector<float> texelsOf(const GpuDocument& document, core::EditLayer layer) {
  const int side = document.size() + 1;
  return document.mirrorTexels(layer, {0, 0, side, side});
}

float baseOf(const GpuDocument& document, core::EditLayer layer, int channel) {
  const core::Document& d = document.document();
  const core::Layer& l = layer == core::EditLayer::Diffuse   ? d.diffuse
                         : layer == core::EditLayer::Feature ? d.feature
                                                             : d.mask;
  return l.fill[channel];
}

// Distance of sample (i, j) from the dab's centre, in radii, as the volume area measures it.
float distanceAt(const GpuDocument& document, const Dab& dab, int i, int j) {
  return core::length(document.document().positions.at(i, j).xyz() - dab.centre) / dab.radius;
}

// The smooth falloff's weight at distance d (radii), times strength.
float smoothWeight(float d, float strength) {
  if (d >= 1) return 0;
  const float s = 1 - d * d;
  return s * s * strength;
}

bool sameBits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

Dab dabOf(const GpuDocument& document, core::Sample s, float radius, float strength,
          const PaintBrush& brush, float mode) {
  Dab dab = dabAt(document.document().positions, s, radius, strength);
  dab.parameters = brush.parameters;
  dab.parameters["mode"] = {mode, 0.0f, 0.0f, 0.0f};
  return dab;
}

} // namespace

class PaintBrushesTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void dabMovesItsChannelsInsideTheRadiusOnly_data() { brushes(); }
  void dabMovesItsChannelsInsideTheRadiusOnly();
  void seamDabsKeepIdentifiedSamplesEqual_data() { brushes(); }
  void seamDabsKeepIdentifiedSamplesEqual();
  void seamedDabOverTheWholeImage_data() { brushes(); }
  void seamedDabOverTheWholeImage();
  void fullWeightEraseRestoresTheBase_data() { brushes(); }
  void fullWeightEraseRestoresTheBase();
  void smoothEraseIsPartialTowardsTheRim_data() { brushes(); }
  void smoothEraseIsPartialTowardsTheRim();
  void maskBlocksPaint_data();
  void maskBlocksPaint();

private:
  static void brushes();
  /// What is wrong after a paint-mode dab of b centred on sample s of a noisy N = n sphere
  /// (identified samples unequal, the centre not painted, nothing painted beside a copy of the
  /// centre), or an empty string.
  QString seamDabProblem(const PaintBrush& b, int n, core::Sample s);
  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
};

void PaintBrushesTest::brushes() {
  QTest::addColumn<QString>("brush");
  for (const char* id : {"paint", "paint-specular", "paint-reflectivity", "mask"})
    QTest::newRow(id) << QString(id);
}

void PaintBrushesTest::initTestCase() {
  try {
    context_.emplace(GlContext::createHeadless());
    engine_.emplace();
    for (const char* id : {"paint", "paint-specular", "paint-reflectivity", "mask"}) {
      const BrushManifest manifest = builtInManifest(id);
      QCOMPARE(manifest.category, Category::Paint);
      engine_->load(manifest, readFile(manifest.shaderPath()));
      // The same brush with weight 1 over its whole disc, as a user sets falloff constant.
      BrushManifest constant = manifest;
      constant.id += "-constant";
      constant.falloff = Falloff::Constant;
      engine_->load(constant, readFile(constant.shaderPath()));
    }
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
}

void PaintBrushesTest::dabMovesItsChannelsInsideTheRadiusOnly() {
  QFETCH(QString, brush);
  const PaintBrush b = paintBrush(brush);
  core::Document doc = noisyDocument(kSize);
  if (b.layer == core::EditLayer::Mask) {
    fillWithNoise(doc.mask, kSize);
    doc.hasMask = true;
  }
  GpuDocument document(std::move(doc));
  std::map<core::EditLayer, std::vector<float>> layers;
  for (core::EditLayer l :
       {core::EditLayer::Diffuse, core::EditLayer::Feature, core::EditLayer::Mask})
    layers[l] = texelsOf(document, l);
  const std::vector<float> before = layers[b.layer];
  const int channels = GpuDocument::channels(b.layer);
  const Dab dab = dabOf(document, {kSize / 3, kSize / 2}, 0.6f, 1.0f, b, kPaint);
  engine_->dab(document, b.id, dab);
  const std::vector<float> after = texelsOf(document, b.layer);

  const float tol = tolerance(b.layer);
  int inside = 0, moved = 0;
  for (int j = 0; j <= kSize; ++j)
    for (int i = 0; i <= kSize; ++i) {
      const float d = distanceAt(document, dab, i, j);
      const float w = smoothWeight(d, dab.strength);
      inside += d < 1;
      for (int c = 0; c < channels; ++c) {
        const std::size_t k = (std::size_t(j) * (kSize + 1) + i) * channels + c;
        const QString where = QString("(%1,%2).%3: %4 -> %5, weight %6")
                                  .arg(i)
                                  .arg(j)
                                  .arg(c)
                                  .arg(before[k])
                                  .arg(after[k])
                                  .arg(w);
        if (d >= 1 || !writes(b, c)) { // outside the radius, or a channel the brush leaves
          QVERIFY2(sameBits(before[k], after[k]), qPrintable(where));
          continue;
        }
        const float want = before[k] + (b.target[c] - before[k]) * w;
        QVERIFY2(std::abs(after[k] - want) <= tol, qPrintable(where));
        QVERIFY2(std::abs(after[k] - b.target[c]) <= std::abs(before[k] - b.target[c]) + tol,
                 qPrintable(where)); // never away from the value
        moved += w > 0.1f && std::abs(before[k] - b.target[c]) > 0.05f &&
                 std::abs(after[k] - before[k]) > 10 * tol;
      }
    }
  QVERIFY2(inside > 50, qPrintable(QString::number(inside)));
  QVERIFY2(moved > 20, qPrintable(QString::number(moved)));
  // The centre gets the value itself (weight 1).
  const std::size_t centre = (std::size_t(kSize / 2) * (kSize + 1) + kSize / 3) * channels;
  for (int c : b.channels)
    QVERIFY(std::abs(after[centre + c] - b.target[c]) <= tol);
  // The brush touched its own layer only.
  for (const auto& [layer, texels] : layers)
    if (layer != b.layer) {
      const std::vector<float> now = texelsOf(document, layer);
      QVERIFY(std::memcmp(texels.data(), now.data(), now.size() * sizeof(float)) == 0);
    }
}

void PaintBrushesTest::seamDabsKeepIdentifiedSamplesEqual() {
  QFETCH(QString, brush);
  const int n = 2 * kSize; // 4 × 4 tiles: no dab below reaches them all (see the test below)
  // The left fold, the bottom fold, the right fold, the top fold, the side's fold point, a corner.
  for (core::Sample s : {core::Sample{0, n / 4}, core::Sample{n / 3, 0}, core::Sample{n, 3 * n / 4},
                         core::Sample{n / 3, n}, core::Sample{0, n / 2}, core::Sample{0, 0}}) {
    const QString problem = seamDabProblem(paintBrush(brush), n, s);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }
}

void PaintBrushesTest::seamedDabOverTheWholeImage() {
  QFETCH(QString, brush);
  // At N = 64 the image is 2 × 2 tiles and a dab on the corner pole reaches all four: the engine
  // swaps the pass's scratch texture in, and its seaming pass must then render into the new
  // scratch (it once kept rendering into the swapped-in texture and restored the old border).
  const QString problem = seamDabProblem(paintBrush(brush), kSize, {0, 0});
  QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

QString PaintBrushesTest::seamDabProblem(const PaintBrush& b, int n, core::Sample s) {
  const int channels = GpuDocument::channels(b.layer);
  core::Document doc = noisyDocument(n);
  if (b.layer == core::EditLayer::Mask) {
    fillWithNoise(doc.mask, n);
    doc.hasMask = true;
  }
  GpuDocument document(std::move(doc));
  const std::vector<float> before = texelsOf(document, b.layer);
  engine_->dab(document, b.id, dabOf(document, s, 0.3f, 1.0f, b, kPaint));
  const std::vector<float> after = texelsOf(document, b.layer);
  const auto at = [&](const std::vector<float>& texels, core::Sample t, int c) {
    return texels[(std::size_t(t.j) * (n + 1) + t.i) * channels + c];
  };
  const auto changed = [&](core::Sample t) {
    for (int c = 0; c < channels; ++c)
      if (!sameBits(at(before, t, c), at(after, t, c))) return true;
    return false;
  };
  const QString dab = QString("dab at (%1,%2), N = %3: ").arg(s.i).arg(s.j).arg(n);
  std::array<core::Sample, 4> copies{};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int count = core::identifiedSamples(n, {i, j}, copies);
      for (int k = 1; k < count; ++k)
        for (int c = 0; c < channels; ++c)
          if (!sameBits(at(after, copies[0], c), at(after, copies[k], c)))
            return dab + QString("(%1,%2) and (%3,%4) differ in channel %5")
                             .arg(copies[0].i)
                             .arg(copies[0].j)
                             .arg(copies[k].i)
                             .arg(copies[k].j)
                             .arg(c);
    }
  // Every copy of the centre holds the value (weight 1 there), and the dab reached both sides of
  // the seam: beside every copy something changed.
  const int count = core::identifiedSamples(n, s, copies);
  for (int k = 0; k < count; ++k) {
    for (int c : b.channels)
      if (std::abs(at(after, copies[k], c) - b.target[c]) > tolerance(b.layer))
        return dab + QString("the centre's copy (%1,%2) holds %3 in channel %4, not %5")
                         .arg(copies[k].i)
                         .arg(copies[k].j)
                         .arg(at(after, copies[k], c))
                         .arg(c)
                         .arg(b.target[c]);
    bool near = false;
    for (core::Sample d :
         {core::Sample{1, 0}, core::Sample{-1, 0}, core::Sample{0, 1}, core::Sample{0, -1}}) {
      const core::Sample t{copies[k].i + d.i, copies[k].j + d.j};
      near = near || (t.i >= 0 && t.j >= 0 && t.i <= n && t.j <= n && changed(t));
    }
    if (!near)
      return dab + QString("nothing changed beside (%1,%2)").arg(copies[k].i).arg(copies[k].j);
  }
  return {};
}

void PaintBrushesTest::fullWeightEraseRestoresTheBase() {
  QFETCH(QString, brush);
  const PaintBrush b = paintBrush(brush);
  GpuDocument document(noisyDocument(kSize)); // the mask starts unpainted: 1
  const std::vector<float> start = texelsOf(document, b.layer);
  const int channels = GpuDocument::channels(b.layer);
  const core::Sample centre{kSize / 2, kSize / 3};
  engine_->dab(document, b.id, dabOf(document, centre, 0.5f, 1.0f, b, kPaint));
  const std::vector<float> painted = texelsOf(document, b.layer);
  // Weight 1 over the whole disc of radius 0.4, inside the painted one.
  const Dab erase = dabOf(document, centre, 0.4f, 1.0f, b, kErase);
  engine_->dab(document, b.id + "-constant", erase);
  const std::vector<float> after = texelsOf(document, b.layer);

  const float tol = tolerance(b.layer);
  int erased = 0;
  for (int j = 0; j <= kSize; ++j)
    for (int i = 0; i <= kSize; ++i) {
      const float d = distanceAt(document, erase, i, j);
      for (int c = 0; c < channels; ++c) {
        const std::size_t k = (std::size_t(j) * (kSize + 1) + i) * channels + c;
        const QString where =
            QString("(%1,%2).%3: %4 -> %5").arg(i).arg(j).arg(c).arg(painted[k]).arg(after[k]);
        if (d >= 1 || !writes(b, c)) {
          QVERIFY2(sameBits(painted[k], after[k]), qPrintable(where));
          if (!writes(b, c)) QVERIFY2(sameBits(start[k], after[k]), qPrintable(where));
          continue;
        }
        const float base = baseOf(document, b.layer, c);
        if (b.layer == core::EditLayer::Mask)
          QVERIFY2(after[k] == base, qPrintable(where)); // R32F: exactly
        else
          QVERIFY2(std::abs(after[k] - base) <= tol, qPrintable(where));
        erased += std::abs(painted[k] - base) > 0.05f;
      }
    }
  QVERIFY2(erased > 20, qPrintable(QString::number(erased)));
}

void PaintBrushesTest::smoothEraseIsPartialTowardsTheRim() {
  QFETCH(QString, brush);
  const PaintBrush b = paintBrush(brush);
  GpuDocument document(noisyDocument(kSize));
  const int channels = GpuDocument::channels(b.layer);
  const core::Sample centre{kSize / 3, kSize / 3};
  // Paint the whole disc to the value, then erase it with the smooth falloff.
  engine_->dab(document, b.id + "-constant", dabOf(document, centre, 0.5f, 1.0f, b, kPaint));
  const std::vector<float> painted = texelsOf(document, b.layer);
  const Dab erase = dabOf(document, centre, 0.5f, 1.0f, b, kErase);
  engine_->dab(document, b.id, erase);
  const std::vector<float> after = texelsOf(document, b.layer);

  const float tol = tolerance(b.layer);
  int full = 0, partway = 0;
  for (int j = 0; j <= kSize; ++j)
    for (int i = 0; i <= kSize; ++i) {
      const float w = smoothWeight(distanceAt(document, erase, i, j), erase.strength);
      for (int c : b.channels) {
        const std::size_t k = (std::size_t(j) * (kSize + 1) + i) * channels + c;
        const float base = baseOf(document, b.layer, c);
        const QString where = QString("(%1,%2).%3: %4 -> %5, weight %6, base %7")
                                  .arg(i)
                                  .arg(j)
                                  .arg(c)
                                  .arg(painted[k])
                                  .arg(after[k])
                                  .arg(w)
                                  .arg(base);
        QVERIFY2(std::abs(after[k] - (painted[k] + (base - painted[k]) * w)) <= tol,
                 qPrintable(where));
        if (w == 1.0f) { // the centre region
          if (b.layer == core::EditLayer::Mask)
            QVERIFY2(after[k] == base, qPrintable(where));
          else
            QVERIFY2(std::abs(after[k] - base) <= tol, qPrintable(where));
          ++full;
        } else if (w > 0.1f && w < 0.9f && std::abs(painted[k] - base) > 0.2f) {
          // Strictly between the painted value and the base.
          QVERIFY2(std::abs(after[k] - base) < std::abs(painted[k] - base) - 10 * tol,
                   qPrintable(where));
          QVERIFY2(std::abs(after[k] - painted[k]) > 10 * tol, qPrintable(where));
          ++partway;
        }
      }
    }
  QVERIFY(full >= 1);
  QVERIFY2(partway > 20, qPrintable(QString::number(partway)));
}

void PaintBrushesTest::maskBlocksPaint_data() {
  QTest::addColumn<QString>("brush");
  for (const char* id : {"paint", "paint-specular", "paint-reflectivity"})
    QTest::newRow(id) << QString(id);
}

void PaintBrushesTest::maskBlocksPaint() {
  QFETCH(QString, brush);
  const PaintBrush b = paintBrush(brush);
  const int channels = GpuDocument::channels(b.layer);
  {
    // A mask that is 0 everywhere (unpainted, no mask texture): nothing changes.
    core::Document doc = noisyDocument(kSize);
    doc.mask.fill[0] = 0.0f;
    doc.hasMask = true;
    GpuDocument document(std::move(doc));
    const std::vector<float> before = texelsOf(document, b.layer);
    engine_->dab(document, b.id, dabOf(document, {kSize / 2, kSize / 2}, 0.8f, 1.0f, b, kPaint));
    const std::vector<float> after = texelsOf(document, b.layer);
    QVERIFY(std::memcmp(before.data(), after.data(), after.size() * sizeof(float)) == 0);
  }
  // A painted mask: 0 over a disc (the mask brush at weight 1), then a wider paint dab.
  GpuDocument document(noisyDocument(kSize));
  const core::Sample centre{kSize / 2, kSize / 2};
  const Dab protect = dabOf(document, centre, 0.3f, 1.0f, paintBrush("mask"), kPaint);
  engine_->dab(document, "mask-constant", protect);
  const std::vector<float> mask = texelsOf(document, core::EditLayer::Mask);
  const std::vector<float> before = texelsOf(document, b.layer);
  const Dab dab = dabOf(document, centre, 0.6f, 1.0f, b, kPaint);
  engine_->dab(document, b.id, dab);
  const std::vector<float> after = texelsOf(document, b.layer);
  int blocked = 0, painted = 0;
  for (int j = 0; j <= kSize; ++j)
    for (int i = 0; i <= kSize; ++i) {
      const std::size_t t = std::size_t(j) * (kSize + 1) + i;
      const float w = smoothWeight(distanceAt(document, dab, i, j), dab.strength);
      for (int c = 0; c < channels; ++c) {
        const std::size_t k = t * channels + c;
        const QString where = QString("(%1,%2).%3: mask %4, %5 -> %6")
                                  .arg(i)
                                  .arg(j)
                                  .arg(c)
                                  .arg(mask[t])
                                  .arg(before[k])
                                  .arg(after[k]);
        if (mask[t] == 0.0f) {
          QVERIFY2(sameBits(before[k], after[k]), qPrintable(where));
          blocked += writes(b, c);
        } else if (mask[t] == 1.0f && writes(b, c)) {
          const float want = before[k] + (b.target[c] - before[k]) * w;
          QVERIFY2(std::abs(after[k] - want) <= tolerance(b.layer), qPrintable(where));
          painted += std::abs(want - before[k]) > 10 * tolerance(b.layer);
        }
      }
    }
  QVERIFY2(blocked > 20, qPrintable(QString::number(blocked)));
  QVERIFY2(painted > 20, qPrintable(QString::number(painted)));
}

QTEST_APPLESS_MAIN(PaintBrushesTest)
#include "paint_brushes_gltest.moc"
