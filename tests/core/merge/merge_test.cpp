// Merge: the voxel union of placed parts as one octahedral document. The creature from parts
// (tests/merge_creature.h) merged at N = 256 against the analytic union it stands for; its
// layers carried from the parts; every refusal with its message and nothing changed.

#include "../../merge_creature.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/capsule.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/merge/merge.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

using namespace octaclay;
using namespace octaclay::core;

namespace {

// The message of the Error that f throws (with its kind), or "" when it throws none.
template <class F> std::string errorOf(F&& f, ErrorKind* kind = nullptr) {
  try {
    f();
  } catch (const Error& e) {
    if (kind) *kind = e.kind();
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

} // namespace

class MergeTest : public QObject {
  Q_OBJECT

private slots:
  void creatureIsOneClosedBallNearTheUnion();
  void creaseOnALegIsAsDeepAsOnTheBody();
  void layersComeFromTheNearestPart();
  void ringIsRefusedWithItsGenus();
  void apartIsRefused();
  void farFromTheOriginAndLarge();
  void badArgumentsAreRefused();
  void progressAndCancel();
};

void MergeTest::creatureIsOneClosedBallNearTheUnion() {
  const std::vector<testing::CreaturePiece> pieces = testing::mergeCreature(128);
  const std::vector<Document> before = [&] {
    std::vector<Document> docs;
    for (const auto& piece : pieces)
      docs.push_back(*piece.document);
    return docs;
  }();
  const std::vector<MergePart> parts = testing::creatureMergeParts(pieces);
  MergeOptions options;
  options.size = 256;
  const MergeResult merged = mergeParts(parts, options);
  qInfo("voxel %.4f, level set %zu vertices, %zu triangles; %.0f + %.0f + %.0f ms",
        merged.voxelSize, merged.levelSetVertices, merged.levelSetTriangles, merged.levelSetMs,
        merged.parameterizeMs, merged.partsMs);
  for (std::size_t k = 0; k < pieces.size(); ++k) // the parts are only read
    QVERIFY(pieces[k].document->positions.texels().size() == before[k].positions.texels().size() &&
            std::equal(pieces[k].document->positions.texels().begin(),
                       pieces[k].document->positions.texels().end(),
                       before[k].positions.texels().begin()));

  QVERIFY(merged.sourcePart.empty()); // every layer uniform with one fill: nothing searched

  // One closed genus-0 ball at N = 256, seamed.
  const Document& doc = merged.document;
  QCOMPARE(doc.size(), 256);
  QCOMPARE(merged.euler, 2LL);
  QCOMPARE(maxSeamGap(doc.positions), 0.0f);
  const MeshTopology topo = analyzeTopology(extractMesh(doc.positions));
  QCOMPARE(topo.euler, 2LL);
  QVERIFY(topo.closed() && topo.manifold());

  // Every sample near the analytic union: within 0.75 voxel (the mesher rounds the concave
  // creases where parts meet, where the union's distance has a kink, by up to about half a
  // voxel; elsewhere its faces cut the parts' curvature by a small fraction of a voxel), and
  // 0.05 voxel on average.
  double worst = 0, sum = 0;
  for (const Vec4f& t : doc.positions.texels()) {
    const double d = std::abs(double(testing::unionDistance(pieces, t.xyz())));
    worst = std::max(worst, d);
    sum += d;
  }
  const double mean = sum / double(doc.positions.texels().size());
  qInfo("distance to the analytic union: mean %.5f, worst %.5f (%.2f voxels)", mean, worst,
        worst / merged.voxelSize);
  QVERIFY2(worst <= 0.75 * merged.voxelSize, qPrintable(QString::number(worst)));
  QVERIFY2(mean <= 0.05 * merged.voxelSize, qPrintable(QString::number(mean)));
  // Where the surface is one part's alone (its nearest part nearer than the next by 2 voxels)
  // the samples were moved onto that part: on the analytic surface within the part's own chord
  // sag, not the level set's facets. The largest sag is the unit body's: a triangle's
  // circumradius (its longest edge / √3) squared over twice the radius, with half as much again
  // for the longest edge's neighbours (~3·10⁻⁴ at N = 128).
  const double bodyEdge = summarizeStretch(pieces[0].document->positions).longestEdge;
  const double sag = 1.5 * (bodyEdge * bodyEdge / 3.0) / 2.0;
  double worstAlone = 0;
  std::size_t alone = 0;
  for (const Vec4f& t : doc.positions.texels()) {
    float margin = 0;
    const int k = testing::nearestPiece(pieces, t.xyz(), &margin);
    if (margin < 2 * merged.voxelSize) continue;
    ++alone;
    worstAlone = std::max(
        worstAlone, std::abs(double(testing::pieceDistance(pieces[std::size_t(k)], t.xyz()))));
  }
  const double texels = double(doc.positions.texelCount());
  qInfo("%.1f %% of the samples moved onto their part; %.1f %% clear of the junctions, within "
        "%.6f of their part",
        100.0 * double(merged.snapped) / texels, 100.0 * double(alone) / texels, worstAlone);
  QVERIFY(double(merged.snapped) >= 0.85 * texels);
  QVERIFY2(worstAlone <= sag,
           qPrintable(QString::number(worstAlone) + " > " + QString::number(sag)));
  // And the union is covered: every leg's foot and the head's top are reached (the merged
  // bounding box spans the union's within a voxel).
  const BoundingBox box = boundingBox(doc.positions);
  QVERIFY2(std::abs(box.min.y - -1.8f) <= merged.voxelSize, qPrintable(QString::number(box.min.y)));
  const float headTop = std::sqrt(0.5f) * 1.95f + 0.45f;
  QVERIFY2(std::abs(box.max.y - headTop) <= merged.voxelSize,
           qPrintable(QString::number(box.max.y)));

  // Every part holds at least half of its fair share of the samples (issue 33's target), and
  // 0.7 with the map turned for the parts (0.60 unturned at this N; estimated from the map
  // within 0.01 of the measure here).
  double least = 1e9;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const RegionSampling s = regionSampling(
        doc.positions, [&](const Vec3f& p) { return testing::nearestPiece(pieces, p) == int(k); });
    qInfo("%-16s area %.3f, samples %.3f, fair share %.2f", pieces[k].name.c_str(), s.areaShare,
          s.sampleShare, s.fairShare);
    QVERIFY2(s.fairShare >= 0.5, qPrintable(QString::fromStdString(pieces[k].name)));
    least = std::min(least, s.fairShare);
  }
  qInfo("least fair share %.2f; estimated %.2f unturned, %.2f turned", least,
        merged.leastShareUnturned, merged.leastShareTurned);
  QVERIFY(merged.leastShareTurned >= merged.leastShareUnturned);
  QVERIFY2(std::abs(least - merged.leastShareTurned) <= 0.05, qPrintable(QString::number(least)));
  QVERIFY2(least >= 0.7, qPrintable(QString::number(least)));
  const StretchSummary stretch = summarizeStretch(doc.positions);
  qInfo("longest edge / median %.2f, p99 / median %.2f", stretch.longestOverMedian,
        stretch.p99OverMedian);
}

void MergeTest::creaseOnALegIsAsDeepAsOnTheBody() {
  // The same valley sculpted into the body (a ring around x = 0.8) and into a leg (a ring
  // around its middle): 0.03 deep (0.8 voxel), a Gaussian of width 0.04. Its depth: the
  // deepest sample below the part's analytic surface near the ring, in the part and merged.
  constexpr float depth = 0.03f, width = 0.04f;
  std::vector<testing::CreaturePiece> pieces = testing::mergeCreature(128);
  for (Vec4f& t : pieces[0].document->positions.texels()) {
    const float g = std::exp(-((t.x - 0.8f) / width) * ((t.x - 0.8f) / width));
    t.x *= 1 - depth * g, t.y *= 1 - depth * g, t.z *= 1 - depth * g;
  }
  for (Vec4f& t : pieces[1].document->positions.texels()) { // local: the capsule along z
    const float g = std::exp(-(t.z / width) * (t.z / width)), rho = std::hypot(t.x, t.y);
    if (rho > 0) t.x *= 1 - depth * g / rho, t.y *= 1 - depth * g / rho;
  }
  const auto valley = [&](const GeometryImage& image, const PartTransform& placed,
                          std::size_t piece) {
    const testing::CreaturePiece& part = pieces[piece];
    const Vec3f centre = piece == 0 ? Vec3f{0.8f, 0, 0} : (part.a + part.b) * 0.5f;
    const Vec3f axis = piece == 0 ? Vec3f{1, 0, 0} : normalize(part.b - part.a);
    float deepest = 0;
    for (const Vec4f& t : image.texels()) {
      const Vec3f p = placed.apply(t.xyz());
      if (std::abs(dot(p - centre, axis)) > width || testing::nearestPiece(pieces, p) != int(piece))
        continue;
      deepest = std::max(deepest, -testing::pieceDistance(part, p));
    }
    return deepest;
  };
  MergeOptions options;
  options.size = 256;
  const MergeResult merged = mergeParts(testing::creatureMergeParts(pieces), options);
  double ratio[2] = {};
  for (const std::size_t piece : {std::size_t(0), std::size_t(1)}) {
    const float before = valley(pieces[piece].document->positions, pieces[piece].transform, piece);
    const float after = valley(merged.document.positions, PartTransform{}, piece);
    ratio[piece == 0 ? 0 : 1] = double(after) / double(before);
    qInfo("%-16s valley %.4f deep in the part, %.4f merged (%.2f)", pieces[piece].name.c_str(),
          double(before), double(after), ratio[piece == 0 ? 0 : 1]);
    QVERIFY(before > 0.8f * depth);
    QVERIFY2(std::abs(ratio[piece == 0 ? 0 : 1] - 1.0) <= 0.2, qPrintable(QString::number(after)));
  }
  QVERIFY2(std::abs(ratio[1] / ratio[0] - 1.0) <= 0.2, "the leg's valley against the body's");
}

void MergeTest::layersComeFromTheNearestPart() {
  std::vector<testing::CreaturePiece> pieces = testing::mergeCreature(64);
  // Each part a colour of its own; the body's diffuse painted: red follows its x.
  for (std::size_t k = 0; k < pieces.size(); ++k)
    pieces[k].document->diffuse.fill = {float(k) / 8.0f, 0.5f, 1.0f - float(k) / 8.0f, 1.0f};
  Document& body = *pieces[0].document;
  const std::size_t side = std::size_t(body.size() + 1);
  body.diffuse.texels.resize(side * side * 4);
  for (std::size_t t = 0; t < side * side; ++t) {
    const Vec3f p = body.positions.texels()[t].xyz();
    const float rgba[4] = {0.5f + 0.5f * p.x, 0.25f, 0.75f, 1.0f};
    std::copy(rgba, rgba + 4, body.diffuse.texels.begin() + std::ptrdiff_t(4 * t));
  }
  pieces[3].document->hasMask = true;
  // Carried on the way while snapping, and on their own without it.
  for (const bool snap : {true, false}) {
    MergeOptions options;
    options.size = 128;
    options.snapToParts = snap;
    const MergeResult merged = mergeParts(testing::creatureMergeParts(pieces), options);
    const Document& doc = merged.document;
    QVERIFY(!doc.diffuse.uniform());
    QVERIFY(doc.feature.uniform() && doc.mask.uniform()); // the same fill in every part
    QVERIFY(doc.hasMask);
    const std::size_t mergedSide = std::size_t(doc.size() + 1);
    QCOMPARE(merged.sourcePart.size(), mergedSide * mergedSide);

    // Away from the junctions (the nearest part nearer than the next by 0.05), every texel took
    // its layers from the part whose surface it lies on: that part's colour, and on the body the
    // painted red, read at the closest point (within 0.02: the body at N = 64 is 0.04 between
    // samples, and red changes by half of x's change).
    std::size_t clear = 0, fromNearest = 0, colourRight = 0;
    double worstRed = 0;
    for (std::size_t t = 0; t < mergedSide * mergedSide; ++t) {
      const Vec3f p = doc.positions.texels()[t].xyz();
      float margin = 0;
      const int k = testing::nearestPiece(pieces, p, &margin);
      if (margin < 0.05f) continue;
      ++clear;
      if (merged.sourcePart[t] == k) ++fromNearest;
      const float* rgba = doc.diffuse.texels.data() + 4 * t;
      if (k == 0) {
        worstRed = std::max(worstRed, std::abs(double(rgba[0]) - (0.5 + 0.5 * double(p.x))));
        if (std::abs(rgba[0] - (0.5f + 0.5f * p.x)) <= 0.02f && rgba[1] == 0.25f &&
            rgba[2] == 0.75f)
          ++colourRight;
      } else {
        const auto& fill = pieces[std::size_t(k)].document->diffuse.fill;
        bool same = true;
        for (int c = 0; c < 4; ++c)
          same = same && std::abs(rgba[c] - fill[std::size_t(c)]) <= 1e-6f;
        if (same) ++colourRight;
      }
    }
    qInfo("%zu of %zu texels clear of the junctions; from the nearest part %zu, colour right %zu; "
          "body's red off by %.4f at most",
          clear, mergedSide * mergedSide, fromNearest, colourRight, worstRed);
    QVERIFY(clear > mergedSide * mergedSide * 3 / 4);
    QCOMPARE(fromNearest, clear);
    QCOMPARE(colourRight, clear);
  }
}

void MergeTest::ringIsRefusedWithItsGenus() {
  // Four capsules along the sides of a square, overlapping at its corners: a ring, genus 1.
  const Document side = makeDocument(makeCapsule(64, {0.15f, 1.0f}));
  std::vector<MergePart> parts;
  for (int k = 0; k < 4; ++k) {
    const float angle = 90.0f * float(k);
    const float a = angle * std::numbers::pi_v<float> / 180.0f;
    // Rotated to lie along x (about y), then about z to the square's k-th side.
    PartTransform t =
        PartTransform::fromTrs({0.5f * -std::sin(a), 0.5f * std::cos(a), 0}, {0, 90.0f, angle});
    parts.push_back({&side, t});
  }
  MergeOptions options;
  options.size = 64;
  ErrorKind kind{};
  const std::string message = errorOf([&] { mergeParts(parts, options); }, &kind);
  qInfo("%s", message.c_str());
  QVERIFY(kind == ErrorKind::InvalidInput);
  QVERIFY2(contains(message, "genus 1") && contains(message, "Euler characteristic 0"),
           message.c_str());
  // The same sides with one left out (an open U): one ball, merged.
  parts.pop_back();
  QCOMPARE(mergeParts(parts, options).euler, 2LL);
}

void MergeTest::apartIsRefused() {
  const Document ball = makeDocument(makeBaseShape(BaseShape::Sphere, 32));
  const std::vector<MergePart> apart{{&ball, PartTransform::fromTrs({-1.2f, 0, 0})},
                                     {&ball, PartTransform::fromTrs({1.2f, 0, 0})}};
  MergeOptions options;
  options.size = 64;
  ErrorKind kind{};
  const std::string message = errorOf([&] { mergeParts(apart, options); }, &kind);
  QVERIFY(kind == ErrorKind::InvalidInput);
  QVERIFY2(contains(message, "these objects do not touch") && contains(message, "2 separate"),
           message.c_str());
  // Overlapping by 0.2: one piece.
  const std::vector<MergePart> touching{{&ball, PartTransform::fromTrs({-0.9f, 0, 0})},
                                        {&ball, PartTransform::fromTrs({0.9f, 0, 0})}};
  QCOMPARE(mergeParts(touching, options).euler, 2LL);
}

void MergeTest::farFromTheOriginAndLarge() {
  // Two balls of radius 1000 overlapping by 200, a million units from the origin: the merge
  // works in the parts' own scale (the voxel from their area), so the result is the small
  // case's scaled: one ball, every sample within a voxel of the union, most snapped.
  const Document ball = makeDocument(makeBaseShape(BaseShape::Sphere, 32));
  const Vec3f far{1e6f, -2e6f, 5e5f}, s{1000, 1000, 1000};
  const std::vector<MergePart> parts{
      {&ball, PartTransform::fromTrs(far + Vec3f{-900, 0, 0}, {0, 0, 0}, s)},
      {&ball, PartTransform::fromTrs(far + Vec3f{900, 0, 0}, {0, 0, 0}, s)}};
  MergeOptions options;
  options.size = 64;
  const MergeResult merged = mergeParts(parts, options);
  QCOMPARE(merged.euler, 2LL);
  QVERIFY(merged.voxelSize > 10 && merged.voxelSize < 100);
  double worst = 0;
  for (const Vec4f& t : merged.document.positions.texels()) {
    const Vec3f p = t.xyz() - far;
    const double d = std::min(length(p - Vec3f{-900, 0, 0}), length(p - Vec3f{900, 0, 0})) - 1000;
    worst = std::max(worst, std::abs(d));
  }
  qInfo("voxel %.1f, worst %.2f, %zu of %zu snapped", merged.voxelSize, worst, merged.snapped,
        merged.document.positions.texelCount());
  QVERIFY2(worst <= merged.voxelSize, qPrintable(QString::number(worst)));
  QVERIFY(merged.snapped > merged.document.positions.texelCount() / 2);
}

void MergeTest::badArgumentsAreRefused() {
  const Document ball = makeDocument(makeBaseShape(BaseShape::Sphere, 32));
  const auto refused = [&](std::vector<MergePart> parts, MergeOptions options,
                           const std::string& words) {
    ErrorKind kind{};
    const std::string message = errorOf([&] { mergeParts(parts, options); }, &kind);
    QVERIFY2(kind == ErrorKind::InvalidArgument && contains(message, words),
             (message + " (wanted: " + words + ")").c_str());
  };
  MergeOptions ok;
  ok.size = 64;
  refused({}, ok, "at least one part");
  refused({{nullptr, {}}}, ok, "no document");
  refused(std::vector<MergePart>(65536, {&ball, {}}), ok, "at most 65 535 parts");
  for (int n : {0, 3, 100, 16384}) {
    MergeOptions bad = ok;
    bad.size = n;
    refused({{&ball, {}}}, bad, "out of range");
  }
  PartTransform nan;
  nan.m[5] = std::numeric_limits<double>::quiet_NaN();
  refused({{&ball, {}}, {&ball, nan}}, ok, "part 2's transform has a value that is not a finite");
  PartTransform inf = PartTransform::fromTrs({std::numeric_limits<float>::infinity(), 0, 0});
  refused({{&ball, inf}}, ok, "not a finite");
  refused({{&ball, PartTransform::fromTrs({0, 0, 0}, {0, 0, 0}, {1, 0, 1})}}, ok, "flattens");
  PartTransform projective;
  projective.m[12] = 0.5;
  refused({{&ball, projective}}, ok, "last row");
  MergeOptions tiny = ok;
  tiny.voxelSize = 1e-9;
  refused({{&ball, {}}}, tiny, "too small");
  tiny.voxelSize = 1e-4; // 1.3·10⁹ surface voxels on the unit ball: refused before any is made
  refused({{&ball, {}}}, tiny, "more than 8192");
  Document broken = ball;
  broken.positions.at(3, 4).y = std::numeric_limits<float>::quiet_NaN();
  ErrorKind kind{};
  const std::string message = errorOf(
      [&] {
        mergeParts({{{&ball, {}}, {&broken, {}}}}, ok);
      },
      &kind);
  QVERIFY2(kind == ErrorKind::InvalidInput && contains(message, "part 2"), message.c_str());
  // A plane or disc encloses nothing: refused by the object's name, whatever it touches (a sheet
  // through the ball's middle would come out a plate a voxel thick).
  const Document sheet = makeDocument(makeSheet(Sheet::Square, 32));
  for (const MergePart& plane : {MergePart{&sheet, {}, "Ground"}, MergePart{&sheet, {}, ""}}) {
    ErrorKind planeKind{};
    const std::string why = errorOf(
        [&] {
          mergeParts({{{&ball, {}, "Body"}, plane}}, ok);
        },
        &planeKind);
    QVERIFY2(planeKind == ErrorKind::InvalidInput &&
                 contains(why, plane.name.empty() ? "part 2 is a plane" : "'Ground' is a plane"),
             why.c_str());
  }
  // A mirrored part is fine: a mirror duplicate of a leg.
  QCOMPARE(
      mergeParts({{{&ball, PartTransform::fromTrs({0, 0, 0}, {0, 0, 0}, {-1, 1, 1})}}}, ok).euler,
      2LL);
}

void MergeTest::progressAndCancel() {
  const Document ball = makeDocument(makeBaseShape(BaseShape::Sphere, 32));
  const std::vector<MergePart> parts{{&ball, PartTransform::fromTrs({-0.5f, 0, 0})},
                                     {&ball, PartTransform::fromTrs({0.5f, 0, 0})}};
  MergeOptions options;
  options.size = 64;
  std::vector<float> seen;
  mergeParts(parts, options, [&](float f) {
    seen.push_back(f);
    return true;
  });
  QVERIFY(seen.size() >= 5);
  QCOMPARE(seen.front(), 0.0f);
  QCOMPARE(seen.back(), 1.0f);
  for (std::size_t k = 1; k < seen.size(); ++k)
    QVERIFY2(seen[k] >= seen[k - 1], qPrintable(QString::number(k)));
  // Stopped at each stage in turn: Cancelled every time.
  for (float stop : {0.0f, 0.1f, 0.3f, 0.5f, 0.88f, 0.95f}) {
    ErrorKind kind{};
    const std::string message = errorOf(
        [&] { mergeParts(parts, options, [&](float f) { return f < stop || stop < 0; }); }, &kind);
    QVERIFY2(kind == ErrorKind::Cancelled,
             qPrintable(QString::number(stop) + ": " + QString::fromStdString(message)));
  }
}

QTEST_APPLESS_MAIN(MergeTest)
#include "merge_test.moc"
