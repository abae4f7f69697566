// The material splat brush on the GPU: one dab writes relief, colour, specular and reflectivity
// inside its radius and nothing outside; every layer stays continuous over seams; projected
// material texels keep their object-space size where the image is stretched, the uv mode's not;
// the one-pass splat (brushLayers) writes what per-layer passes of the same body would.
#include "brush_test_support.h"
#include "path_stroke.h"

#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/document/image_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/material_catalog.h"
#include "octaclay/gpu/stroke.h"

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;

namespace {

// A black-and-white checker material, 8 × 8 cells a tile, flat: only its colour matters.
void writeCheckerMaterial(const std::filesystem::path& folder, const std::string& id,
                          float tileSize) {
  std::filesystem::create_directories(folder);
  const int side = 64;
  core::RasterImage colour{side, side, 3, {}}, flat{side, side, 1, {}}, zero{side, side, 1, {}};
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const float v = ((x / 8 + y / 8) % 2) ? 1.0f : 0.0f;
      colour.pixels.insert(colour.pixels.end(), {v, v, v});
      flat.pixels.push_back(0.5f);
      zero.pixels.push_back(0.0f);
    }
  core::writePng(colour, folder / "colour.png");
  core::writePng(flat, folder / "height.png");
  core::writePng(zero, folder / "specular.png");
  core::writePng(zero, folder / "reflectivity.png");
  std::ofstream(folder / "material.json")
      << R"({"id": ")" << id << R"(", "name": "Checker", "source": "test", "license": "CC0-1.0",
            "tileSize": )"
      << tileSize << R"(, "heightScale": 0.0,
            "maps": {"height": "height.png", "colour": "colour.png",
                     "specular": "specular.png", "reflectivity": "reflectivity.png"}})";
}

std::vector<float> layerTexels(const GpuDocument& d, core::EditLayer layer) {
  const int side = d.size() + 1;
  return d.mirrorTexels(layer, {0, 0, side, side});
}

// The splat as per-layer passes (brush() branching on OCTACLAY_LAYER), the reference for the
// one-pass brushLayers() body: the same arithmetic, one layer a pass.
const char* const kPerLayerSplat = R"(
vec2 splatCoordinates(BrushInput b) {
  if (u_projection == 1) return vec2(b.texel - u_centreTexel) / u_tileSamples;
  vec3 d = b.position - u_centre;
  return vec2(dot(d, u_projectionRight), dot(d, u_projectionUp)) / u_tileSize;
}

vec4 brush(vec4 value, BrushInput b) {
  vec2 c = splatCoordinates(b);
  float w = clamp(b.weight, 0.0, 1.0);
  vec4 surface = textureLod(u_materialSurface, c, u_projection == 1 ? u_materialLodUv : u_materialLod);
  float height = (surface.r - 0.5) * u_relief;
#if OCTACLAY_LAYER == LAYER_POSITIONS
  float before = texelFetch(u_featureLayer, b.texel, 0).r;
  float after = mix(before, height, w);
  return vec4(value.xyz - u_projectionDir * ((after - before) * u_heightScale), value.w);
#elif OCTACLAY_LAYER == LAYER_DIFFUSE
  vec4 colour = textureLod(u_materialColour, c, u_projection == 1 ? u_materialLodUv : u_materialLod);
  return vec4(mix(value.rgb, colour.rgb, w * colour.a), value.a);
#else
  return vec4(mix(value.r, height, w), mix(value.g, surface.g, w), mix(value.b, surface.b, w),
              value.a);
#endif
}
)";

float luminanceAt(const GpuDocument& d, core::Sample s) {
  const std::vector<float> t = d.mirrorTexels(core::EditLayer::Diffuse, {s.i, s.j, 1, 1});
  return (t[0] + t[1] + t[2]) / 3;
}

} // namespace

class SplatTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void oneDabWritesAllFourAttributesInsideItsRadiusOnly();
  void everyLayerStaysContinuousOverSeams();
  void projectedTexelsKeepTheirSizeWhereTheImageStretches();
  void onePassWritesWhatPerLayerPassesWrite();
  void brushLayersMustNotWriteTheMask();
  void aStrokeReadsItsPaintBackOnceAtItsEnd();
  void mapsAreReadAtTheNearestTexelUnlessMagnified();
  void aMixedLayerTakesTheBodysColourByItsAmount();
  void aMixedLayerNeedsBrushLayersAndIsNotSampled();
  void enumParametersAreConstantsPerValue();

private:
  Dab splatDab(const GpuDocument& d, core::Sample s, float radius, const std::string& material,
               int projection);
  /// Median object-space distance between colour changes along the surface line through the
  /// sample's position in direction axis (a checker cell's extent along it).
  float cellSize(const GpuDocument& d, core::Sample centre, core::Vec3f axis, core::Vec3f offset,
                 float reach);
  /// The message load() throws for a brush, or "loaded"; "kept despite: …" if it threw but the
  /// brush stayed loaded.
  std::string loadError(const BrushManifest& m, const std::string& body);

  float edgeTileSize_ = 0;
  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
  BrushManifest splat_;
  QTemporaryDir dir_;
};

void SplatTest::initTestCase() {
  try {
    context_.emplace(GlContext::createHeadless());
    engine_.emplace();
    splat_ = builtInManifest("splat");
    engine_->load(splat_, readFile(splat_.shaderPath()));
    const std::filesystem::path folder = dir_.path().toStdString();
    writeCheckerMaterial(folder / "checker", "checker", 0.07f);
    // 2 diagonals a tile: at N = 128 a map texel spans about four samples.
    writeCheckerMaterial(folder / "checker-large", "checker-large", 2.0f);
    // A tile whose level-0 texels span 2^0.56 samples of the view projection at the test's dab
    // centre (bilinear) and fewer of the uv projection (nearest): both read level 0.
    const GpuDocument sphere(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 128)));
    const core::GeometryImage& p = sphere.document().positions;
    const float spacing = core::length(p.at({81, 64}).xyz() - p.at({80, 64}).xyz());
    edgeTileSize_ = spacing * 64.0f / (sphere.bounds().diagonal() * std::exp2(-0.56f));
    writeCheckerMaterial(folder / "checker-edge", "checker-edge", edgeTileSize_);
    MaterialCatalog catalog;
    catalog.scan({std::filesystem::path(OCTACLAY_SOURCE_DIR) / "resources/materials",
                  dir_.path().toStdString()});
    QVERIFY2(catalog.errors().empty(), catalog.errors().empty() ? "" : catalog.errors()[0].c_str());
    engine_->setMaterials(catalog);
    QVERIFY(engine_->materialIndex("stone") >= 0);
    QVERIFY(engine_->materialIndex("checker") >= 0);
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
}

Dab SplatTest::splatDab(const GpuDocument& d, core::Sample s, float radius,
                        const std::string& material, int projection) {
  Dab dab = dabAt(d.document().positions, s, radius, 1.0f);
  dab.parameters["material"] = {static_cast<float>(engine_->materialIndex(material)), 0, 0, 0};
  dab.parameters["projection"] = {static_cast<float>(projection), 0, 0, 0};
  return dab;
}

void SplatTest::oneDabWritesAllFourAttributesInsideItsRadiusOnly() {
  GpuDocument d(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 128)));
  const core::Sample centre{80, 64}; // away from every seam
  const float radius = 0.35f;
  const core::Vec3f c = d.document().positions.at(centre).xyz();
  const std::vector<float> positions = layerTexels(d, core::EditLayer::Positions);
  const std::vector<float> diffuse = layerTexels(d, core::EditLayer::Diffuse);
  const std::vector<float> feature = layerTexels(d, core::EditLayer::Feature);
  engine_->dab(d, "splat", splatDab(d, centre, radius, "stone", 0));
  const std::vector<float> positions2 = layerTexels(d, core::EditLayer::Positions);
  const std::vector<float> diffuse2 = layerTexels(d, core::EditLayer::Diffuse);
  const std::vector<float> feature2 = layerTexels(d, core::EditLayer::Feature);

  const int side = d.size() + 1;
  int inside = 0, movedIn = 0, colouredIn = 0, shinyIn = 0, reflectiveIn = 0;
  for (int k = 0; k < side * side; ++k) {
    const std::size_t p = static_cast<std::size_t>(k) * 4, f = static_cast<std::size_t>(k) * 3;
    const core::Vec3f q{positions[p], positions[p + 1], positions[p + 2]};
    const float distance = core::length(q - c);
    const bool moved = positions[p] != positions2[p] || positions[p + 1] != positions2[p + 1] ||
                       positions[p + 2] != positions2[p + 2];
    const bool coloured = diffuse[p] != diffuse2[p] || diffuse[p + 1] != diffuse2[p + 1] ||
                          diffuse[p + 2] != diffuse2[p + 2];
    const bool shiny = feature[f + 1] != feature2[f + 1];
    const bool reflective = feature[f + 2] != feature2[f + 2];
    if (distance >= radius) {
      QVERIFY2(!moved && !coloured && !shiny && !reflective && feature[f] == feature2[f],
               qPrintable(QString("texel %1 outside the radius changed").arg(k)));
      continue;
    }
    if (distance > 0.8f * radius) continue; // the falloff's tail: tiny changes may round away
    ++inside;
    movedIn += moved;
    colouredIn += coloured;
    shinyIn += shiny;
    reflectiveIn += reflective;
  }
  QVERIFY(inside > 200);
  // Stone's height, colour, specular and reflectivity all differ from the clay's defaults.
  QVERIFY2(movedIn > inside * 9 / 10, qPrintable(QString("%1 of %2").arg(movedIn).arg(inside)));
  QVERIFY2(colouredIn > inside * 9 / 10, qPrintable(QString::number(colouredIn)));
  QVERIFY2(shinyIn > inside * 9 / 10, qPrintable(QString::number(shinyIn)));
  // (stone's grout is not reflective at all, like the clay: three quarters is the cobbles)
  QVERIFY2(reflectiveIn > inside * 3 / 4, qPrintable(QString::number(reflectiveIn)));
  // Relief is a displacement of the stone's height: small against the radius, never a tear.
  float largest = 0;
  for (std::size_t p = 0; p < positions.size(); p += 4)
    largest = std::max(largest, core::length(core::Vec3f{positions2[p] - positions[p],
                                                         positions2[p + 1] - positions[p + 1],
                                                         positions2[p + 2] - positions[p + 2]}));
  QVERIFY(largest > 1e-4f && largest < 0.1f * radius);
}

void SplatTest::everyLayerStaysContinuousOverSeams() {
  GpuDocument d(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 128)));
  const int n = d.size();
  // On the left seam and on a corner pole: the dab covers both sides of each.
  for (core::Sample centre : {core::Sample{0, n / 3}, core::Sample{0, 0}}) {
    engine_->dab(d, "splat", splatDab(d, centre, 0.4f, "brick", 0));
    QCOMPARE(core::maxSeamGap(d.document().positions), 0.0f);
    for (core::EditLayer layer : {core::EditLayer::Diffuse, core::EditLayer::Feature}) {
      const int channels = GpuDocument::channels(layer);
      int compared = 0;
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          if (i != 0 && j != 0 && i != n && j != n) continue;
          std::array<core::Sample, 4> same{};
          const int count = core::identifiedSamples(n, {i, j}, same);
          const std::vector<float> a = d.mirrorTexels(layer, {i, j, 1, 1});
          for (int k = 0; k < count; ++k) {
            const std::vector<float> b = d.mirrorTexels(layer, {same[k].i, same[k].j, 1, 1});
            for (int ch = 0; ch < channels; ++ch)
              QVERIFY2(a[ch] == b[ch], qPrintable(QString("layer %1 (%2,%3)/(%4,%5)")
                                                      .arg(int(layer))
                                                      .arg(i)
                                                      .arg(j)
                                                      .arg(same[k].i)
                                                      .arg(same[k].j)));
            ++compared;
          }
        }
      QVERIFY(compared > 4 * n);
    }
  }
  // And something was painted on both sides of the seam.
  QVERIFY(luminanceAt(d, {1, n / 3}) != luminanceAt(d, {n / 2, n / 2}));
}

float SplatTest::cellSize(const GpuDocument& d, core::Sample centre, core::Vec3f axis,
                          core::Vec3f offset, float reach) {
  // Off the centre by `offset`: the line through it would run along a cell edge.
  const core::Vec3f c = d.document().positions.at(centre).xyz() + offset;
  std::vector<float> changes;
  std::optional<bool> previous;
  const int steps = 400;
  for (int k = 0; k <= steps; ++k) {
    const float t = -reach + 2 * reach * static_cast<float>(k) / steps;
    const core::Sample s = nearestSample(d, c + axis * t);
    const bool light = luminanceAt(d, s) > 0.5f;
    if (previous && light != *previous) changes.push_back(t);
    previous = light;
  }
  std::vector<float> gaps;
  for (std::size_t k = 1; k < changes.size(); ++k)
    gaps.push_back(changes[k] - changes[k - 1]);
  if (gaps.size() < 3) return 0;
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<long>(gaps.size() / 2), gaps.end());
  return gaps[gaps.size() / 2];
}

void SplatTest::projectedTexelsKeepTheirSizeWhereTheImageStretches() {
  // An ellipsoid three times as long in x: around its +z pole the image's samples are three
  // times as far apart along x as along y.
  core::Document document = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 512));
  for (core::Vec4f& p : document.positions.texels())
    p.x *= 3;
  core::Sample pole{0, 0};
  float top = -1e9f;
  const int n = document.size();
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (document.positions.at(i, j).z > top) top = document.positions.at(i, j).z, pole = {i, j};
  const core::Vec3f x{1, 0, 0}, y{0, 1, 0};

  float view[2] = {0, 0}, uv[2] = {0, 0};
  for (int projection : {0, 1}) {
    GpuDocument d(document);
    Dab dab = splatDab(d, pole, 0.6f, "checker", projection);
    dab.centreNormal = {0, 0, 1}; // the pole's: keeps the projection frame on x and y
    engine_->dab(d, "splat", dab);
    float* out = projection == 0 ? view : uv;
    const float quarter = 0.3f * 0.07f * GpuDocument(document).bounds().diagonal() / 8;
    out[0] = cellSize(d, pole, x, y * quarter, 0.25f);
    out[1] = cellSize(d, pole, y, x * quarter, 0.25f);
    QVERIFY2(out[0] > 0 && out[1] > 0,
             qPrintable(QString("no checker found (%1, %2)").arg(out[0]).arg(out[1])));
  }
  qInfo("checker cells along x and y on a 3:1 stretched region: view %.4f x %.4f, uv %.4f x %.4f",
        double(view[0]), double(view[1]), double(uv[0]), double(uv[1]));
  // Projected: square cells, 1/8 of a tile (0.07 of the diagonal) on each axis.
  const float diagonal = GpuDocument(document).bounds().diagonal();
  const float expected = 0.07f * diagonal / 8;
  QVERIFY2(std::abs(view[0] / view[1] - 1) < 0.15f,
           qPrintable(QString("view cells %1 x %2").arg(view[0]).arg(view[1])));
  QVERIFY2(std::abs(view[0] / expected - 1) < 0.2f,
           qPrintable(QString("view cell %1, expected %2").arg(view[0]).arg(expected)));
  // uv: the cells follow the image, stretched about 3x along x.
  QVERIFY2(uv[0] / uv[1] > 2.2f, qPrintable(QString("uv cells %1 x %2").arg(uv[0]).arg(uv[1])));
}

void SplatTest::onePassWritesWhatPerLayerPassesWrite() {
  // The reference runs the per-layer body in two brushes, each on its own copy of the document,
  // so that every pass reads the layers from before the dab as the one pass does: the relief
  // alone (it reads the old feature), then colour and feature (they read the old positions);
  // after each dab the copies exchange what the other wrote.
  BrushManifest relief = splat_, paint = splat_;
  relief.id = "splat-reference-relief";
  relief.writes = {core::EditLayer::Positions};
  relief.reads = {core::EditLayer::Feature}; // its body samples u_featureLayer
  paint.id = "splat-reference-paint";
  paint.writes = {core::EditLayer::Diffuse, core::EditLayer::Feature};
  paint.reads = {};
  relief.mix = paint.mix = {}; // brush() bodies return the layer's value
  relief.pass = paint.pass = PassKind::Layers;
  try {
    engine_->load(relief, kPerLayerSplat);
    engine_->load(paint, kPerLayerSplat);
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }

  core::Document start = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 128));
  const int n = start.size(), side = n + 1;
  for (bool masked : {false, true}) {
    core::Document document = start;
    if (masked) { // a painted mask: the BRUSH_MASK_TEXTURE variants
      document.mask.texels.assign(static_cast<std::size_t>(side) * side, 1.0f);
      for (int k = 0; k < side * side; k += 3)
        document.mask.texels[static_cast<std::size_t>(k)] = 0.25f;
      document.hasMask = true;
    }
    GpuDocument one(document), reliefOnly(document), paintOnly(document);
    // Overlapping dabs (the later ones see the earlier ones' feature and relief), one across
    // the left seam, in both projections.
    int changed = 0;
    for (const auto& [centre, projection] :
         {std::pair{core::Sample{80, 64}, 0}, std::pair{core::Sample{86, 60}, 0},
          std::pair{core::Sample{0, n / 3}, 1}, std::pair{core::Sample{76, 70}, 1}}) {
      const Dab dab = splatDab(one, centre, 0.35f, "stone", projection);
      const std::vector<float> before = layerTexels(one, core::EditLayer::Diffuse);
      engine_->dab(one, "splat", dab);
      engine_->dab(reliefOnly, relief.id, dab);
      engine_->dab(paintOnly, paint.id, dab);
      const std::vector<float> after = layerTexels(one, core::EditLayer::Diffuse);
      for (std::size_t k = 0; k < after.size(); ++k)
        changed += after[k] != before[k];

      // Positions: float32 and the same arithmetic, up to the compiler's choice of fused
      // multiply-adds: a couple of ulps (llvmpipe: the same bits, here and below).
      const std::vector<float> p = layerTexels(one, core::EditLayer::Positions);
      const std::vector<float> pRef = layerTexels(reliefOnly, core::EditLayer::Positions);
      for (std::size_t k = 0; k < p.size(); ++k)
        QVERIFY2(std::abs(p[k] - pRef[k]) <= 4e-7f * std::max(std::abs(p[k]), 1.0f),
                 qPrintable(QString("masked %1, positions[%2]: %3 vs %4")
                                .arg(masked)
                                .arg(k)
                                .arg(double(p[k]), 0, 'g', 9)
                                .arg(double(pRef[k]), 0, 'g', 9)));
      // Diffuse and feature are half floats: at most one rounding step apart (2^-11 relative).
      for (core::EditLayer layer : {core::EditLayer::Diffuse, core::EditLayer::Feature}) {
        const std::vector<float> a = layerTexels(one, layer);
        const std::vector<float> b = layerTexels(paintOnly, layer);
        for (std::size_t k = 0; k < a.size(); ++k) {
          const float step = std::max(std::abs(a[k]), std::abs(b[k])) * (1.0f / 1024) + 6e-8f;
          QVERIFY2(std::abs(a[k] - b[k]) <= step,
                   qPrintable(QString("masked %1, layer %2 [%3]: %4 vs %5")
                                  .arg(masked)
                                  .arg(int(layer))
                                  .arg(k)
                                  .arg(a[k])
                                  .arg(b[k])));
        }
      }
      const core::TexelRect all{0, 0, side, side};
      // The mirror (pulled rect by rect, halves widened by GpuDocument) equals the textures.
      for (core::EditLayer layer :
           {core::EditLayer::Positions, core::EditLayer::Diffuse, core::EditLayer::Feature}) {
        const int c = GpuDocument::channels(layer);
        const std::vector<float> mirror = layerTexels(one, layer);
        const std::vector<float> texture = one.texture(layer).read({0, 0, side, side});
        for (std::size_t t = 0; t < mirror.size() / static_cast<std::size_t>(c); ++t)
          for (int k = 0; k < c; ++k)
            QVERIFY2(mirror[t * c + k] == texture[t * 4 + k],
                     qPrintable(QString("layer %1 texel %2").arg(int(layer)).arg(t)));
      }
      reliefOnly.restore(core::EditLayer::Diffuse, all,
                         layerTexels(paintOnly, core::EditLayer::Diffuse));
      reliefOnly.restore(core::EditLayer::Feature, all,
                         layerTexels(paintOnly, core::EditLayer::Feature));
      paintOnly.restore(core::EditLayer::Positions, all, pRef);
    }
    QVERIFY(changed > 1000);
    QCOMPARE(core::maxSeamGap(one.document().positions), 0.0f);
  }
}

std::string SplatTest::loadError(const BrushManifest& m, const std::string& body) {
  try {
    engine_->load(m, body);
  } catch (const GlError& e) {
    return engine_->has(m.id) ? "kept despite: " + std::string(e.what()) : e.what();
  }
  return "loaded";
}

void SplatTest::brushLayersMustNotWriteTheMask() {
  BrushManifest m = splat_;
  m.id = "splat-with-mask";
  m.writes = {core::EditLayer::Positions, core::EditLayer::Mask};
  const std::string error = loadError(m, readFile(splat_.shaderPath()));
  QVERIFY2(error.find("brushLayers") != std::string::npos, error.c_str());
  QVERIFY(!engine_->has(m.id));
}

// A stroke defers the paint layers' read-back to its end: while it runs the mirror's paint lags
// (positions never do); after finish() the mirror equals the textures texel for texel, and the
// stroke's undo step restores the paint from before it.
void SplatTest::aStrokeReadsItsPaintBackOnceAtItsEnd() {
  GpuDocument d(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 128)));
  const int n = d.size(), side = n + 1;
  const std::vector<float> diffuse = layerTexels(d, core::EditLayer::Diffuse);
  const std::vector<float> feature = layerTexels(d, core::EditLayer::Feature);
  PathStroke settings;
  settings.brush = "splat";
  settings.radius = 0.3f;
  settings.strength = 1.0f;
  settings.parameters["material"] = {static_cast<float>(engine_->materialIndex("stone")), 0, 0, 0};
  const core::Sample start{n / 2, n / 2}, end{n, n / 2}; // ends on the right seam
  StrokeSession session(*engine_, d, splat_, settings);
  session.moveTo(start, settings.radius, settings.strength, 1.0f);
  QVERIFY(d.mirrorStale());
  // The texture holds the paint already, the mirror not yet: nothing read back per dab.
  QVERIFY(d.texture(core::EditLayer::Diffuse).read({start.i, start.j, 1, 1})[0] !=
          diffuse[(static_cast<std::size_t>(start.j) * side + start.i) * 4]);
  QCOMPARE(layerTexels(d, core::EditLayer::Diffuse), diffuse);
  // Positions are read back after every dab (the stroke walks on them).
  const std::vector<float> texture = d.texture(core::EditLayer::Positions).read({0, 0, side, side});
  QCOMPARE(layerTexels(d, core::EditLayer::Positions), texture);
  session.moveTo(end, settings.radius, settings.strength, 1.0f);
  QVERIFY(session.dabs() > 3);
  core::EditStep undo = session.finish("splat");
  QVERIFY(!d.mirrorStale());

  const std::vector<float> paint = d.texture(core::EditLayer::Diffuse).read({0, 0, side, side});
  QCOMPARE(layerTexels(d, core::EditLayer::Diffuse), paint);
  const std::vector<float> rgba = d.texture(core::EditLayer::Feature).read({0, 0, side, side});
  const std::vector<float> mirrored = layerTexels(d, core::EditLayer::Feature);
  for (std::size_t t = 0; t < mirrored.size() / 3; ++t)
    for (std::size_t c = 0; c < 3; ++c)
      QCOMPARE(mirrored[t * 3 + c], rgba[t * 4 + c]);
  QVERIFY(paint != diffuse); // the stroke painted

  core::EditHistory history;
  history.record(std::move(undo));
  QVERIFY(history.undo(undoApplier(d)));
  QCOMPARE(layerTexels(d, core::EditLayer::Diffuse), diffuse);
  QCOMPARE(layerTexels(d, core::EditLayer::Feature), feature);
  QCOMPARE(d.texture(core::EditLayer::Diffuse).read({0, 0, side, side}), diffuse);
}

// Where the bound level's texels are about a sample wide, a dab reads the nearest texel (the
// checker's cells stay pure black and white); where the maps are magnified past level 0 it
// reads them bilinearly, so samples near a cell edge take grey values between the two.
void SplatTest::mapsAreReadAtTheNearestTexelUnlessMagnified() {
  const auto greys = [&](const std::string& material, int& black, int& white) {
    GpuDocument d(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 128)));
    Dab dab = splatDab(d, {80, 64}, 0.35f, material, 0);
    dab.strength = 100; // the weight clamps to 1 over nearly all the dab: diffuse = map colour
    const std::vector<float> positions = layerTexels(d, core::EditLayer::Positions);
    engine_->dab(d, "splat", dab);
    const std::vector<float> after = layerTexels(d, core::EditLayer::Diffuse);
    int grey = 0;
    black = white = 0;
    for (std::size_t k = 0; k < after.size(); k += 4) {
      // Within 0.9 radii (1 − d²)² ≥ 0.036: the weight is 1 there.
      const core::Vec3f p{positions[k], positions[k + 1], positions[k + 2]};
      if (core::length(p - dab.centre) > 0.9f * dab.radius) continue;
      const float v = after[k];
      if (v <= 0.02f)
        ++black;
      else if (v >= 0.98f)
        ++white;
      else
        ++grey;
    }
    return grey;
  };
  int black = 0, white = 0;
  // N = 128, a tile of 0.07 diagonals: about 6.6 texels a sample at level 0, level 3 bound.
  QCOMPARE(greys("checker", black, white), 0);
  QVERIFY2(black > 100 && white > 100,
           qPrintable(QString("%1 black, %2 white").arg(black).arg(white)));
  // A tile of 2 diagonals: a texel spans about 4 samples.
  const int grey = greys("checker-large", black, white);
  QVERIFY2(grey > 10 && black > 100 && white > 100,
           qPrintable(QString("%1 grey, %2 black, %3 white").arg(grey).arg(black).arg(white)));
  // The view projection magnified, the uv one not, both at level 0 (one texture on two units):
  // the view projection still reads bilinearly.
  QVERIFY2(std::log2(64.0f / (edgeTileSize_ * 128.0f)) > -0.5f, "the uv projection magnifies");
  const int edgeGrey = greys("checker-edge", black, white);
  QVERIFY2(edgeGrey > 0,
           qPrintable(QString("%1 grey, %2 black, %3 white").arg(edgeGrey).arg(black).arg(white)));
}

// A layer in "mix": the body's (colour, amount) is blended in by the GPU: rgb moves toward the
// colour by the amount, alpha stays, texels of weight 0 keep their bits, and the body sees the
// layer as zeros (it never reads it).
void SplatTest::aMixedLayerTakesTheBodysColourByItsAmount() {
  BrushManifest m = splat_;
  m.id = "mix-test";
  m.writes = {core::EditLayer::Diffuse};
  m.mix = {core::EditLayer::Diffuse};
  m.falloff = Falloff::Constant; // weight 1 over the whole radius
  m.parameters.clear();
  try {
    // 1 + diffuse.r is 1 only if the layer comes in as zeros.
    engine_->load(m, "void brushLayers(inout vec4 positions, inout vec4 diffuse, inout vec4 "
                     "feature, BrushInput b) { diffuse = vec4(1.0 + diffuse.r, 0.0, 0.5, 0.25); }");
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
  core::Document document = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 256));
  const int side = document.size() + 1;
  document.diffuse.texels.resize(static_cast<std::size_t>(side) * side * 4);
  for (std::size_t k = 0; k < document.diffuse.texels.size(); ++k)
    // Varied, in [0, 1], and exact in half floats (the mirror then equals the texture).
    document.diffuse.texels[k] = static_cast<float>((k * 37) % 65) / 64.0f;
  GpuDocument d(document);
  const std::vector<float> before = layerTexels(d, core::EditLayer::Diffuse);
  // Around the pole, tiles away from the seams: the varied paint is not seamed, and a seam pass
  // would average it.
  const core::Sample centre{128, 128};
  const float radius = 0.4f;
  const core::Vec3f c = d.document().positions.at(centre).xyz();
  engine_->dab(d, m.id, dabAt(d.document().positions, centre, radius, 1.0f));
  const std::vector<float> after = layerTexels(d, core::EditLayer::Diffuse);
  const std::array<float, 3> colour{1.0f, 0.0f, 0.5f};
  int inside = 0;
  for (int k = 0; k < side * side; ++k) {
    const std::size_t t = static_cast<std::size_t>(k) * 4;
    const core::Vec3f q = d.document().positions.texels()[static_cast<std::size_t>(k)].xyz();
    if (core::length(q - c) >= radius) {
      for (int ch = 0; ch < 4; ++ch)
        QCOMPARE(after[t + ch], before[t + ch]);
      continue;
    }
    ++inside;
    for (int ch = 0; ch < 3; ++ch) {
      const float expected = 0.75f * before[t + ch] + 0.25f * colour[ch];
      QVERIFY2(std::abs(after[t + ch] - expected) <= expected / 1024 + 1e-6f,
               qPrintable(QString("texel %1 channel %2: %3, expected %4")
                              .arg(k)
                              .arg(ch)
                              .arg(after[t + ch])
                              .arg(expected)));
    }
    QCOMPARE(after[t + 3], before[t + 3]);
  }
  QVERIFY(inside > 100);
}

void SplatTest::aMixedLayerNeedsBrushLayersAndIsNotSampled() {
  BrushManifest m = splat_;
  m.parameters.clear();
  m.writes = {core::EditLayer::Diffuse};
  m.mix = {core::EditLayer::Diffuse};
  m.id = "mix-with-brush";
  const std::string perLayer = loadError(m, "vec4 brush(vec4 v, BrushInput b) { return v; }");
  QVERIFY2(perLayer.find("\"mix\" needs a brushLayers() body") != std::string::npos,
           perLayer.c_str());
  m.id = "mix-sampling";
  m.reads = {core::EditLayer::Diffuse};
  const std::string sampling =
      loadError(m, "void brushLayers(inout vec4 positions, inout vec4 diffuse, inout vec4 feature, "
                   "BrushInput b) { diffuse = texelFetch(u_diffuseLayer, b.texel, 0); }");
  QVERIFY2(sampling.find("cannot read u_diffuseLayer") != std::string::npos, sampling.c_str());
}

// An enum is a constant of the program (usable where GLSL wants one: an array size) and each
// value gets its own program: dabs alternating between values each get theirs.
void SplatTest::enumParametersAreConstantsPerValue() {
  BrushManifest m = splat_;
  m.id = "enum-test";
  m.writes = {core::EditLayer::Diffuse};
  m.mix = {};
  m.pass = PassKind::Layers; // a brush() body
  m.falloff = Falloff::Constant;
  BrushParameter tone;
  tone.id = "tone";
  tone.type = ParameterType::Enum;
  tone.options = {"dark", "mid", "light"};
  tone.max = 2;
  m.parameters = {tone};
  try {
    engine_->load(m, "vec4 brush(vec4 v, BrushInput b) { float steps[u_tone + 1]; "
                     "return vec4(vec3(float(steps.length() - 1) / 2.0), v.a); }");
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
  GpuDocument d(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64)));
  const core::Sample centre{32, 32};
  for (int value : {2, 0, 1, 2, 0}) {
    Dab dab = dabAt(d.document().positions, centre, 0.3f, 1.0f);
    dab.parameters["tone"] = {static_cast<float>(value), 0, 0, 0};
    engine_->dab(d, m.id, dab);
    QCOMPARE(d.mirrorTexels(core::EditLayer::Diffuse, {centre.i, centre.j, 1, 1})[0],
             static_cast<float>(value) / 2.0f);
  }
}

QTEST_APPLESS_MAIN(SplatTest)
#include "splat_gltest.moc"
