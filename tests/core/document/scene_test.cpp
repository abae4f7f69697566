// The scene model: unique names, the transform's maths (against an independent composition of
// axis rotations), its validation, world positions and bounds, and the mirror duplicate's
// geometry (mirrored, closed, facing outward).

#include "octaclay/core/document/document_mirror.h"
#include "octaclay/core/document/scene.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/capsule.h"
#include "octaclay/core/geometry/mesh_extraction.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace octaclay::core;

namespace {

// Rotation about one axis by degrees applied to p: the textbook matrices, one at a time.
Vec3f rotateAbout(int axis, double degrees, Vec3f p) {
  const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);
  const double x = p.x, y = p.y, z = p.z;
  if (axis == 0) return {float(x), float(c * y - s * z), float(s * y + c * z)};
  if (axis == 1) return {float(c * x + s * z), float(y), float(-s * x + c * z)};
  return {float(c * x - s * y), float(s * x + c * y), float(z)};
}

// Rotates p by quaternion q = {x, y, z, w}: p' = q p q*.
Vec3f rotateByQuaternion(const std::array<double, 4>& q, Vec3f p) {
  const double qx = q[0], qy = q[1], qz = q[2], qw = q[3];
  // t = 2 q.xyz × p; p' = p + w t + q.xyz × t
  const double tx = 2 * (qy * p.z - qz * p.y), ty = 2 * (qz * p.x - qx * p.z),
               tz = 2 * (qx * p.y - qy * p.x);
  return {float(p.x + qw * tx + (qy * tz - qz * ty)), float(p.y + qw * ty + (qz * tx - qx * tz)),
          float(p.z + qw * tz + (qx * ty - qy * tx))};
}

float distance(Vec3f a, Vec3f b) {
  return length(a - b);
}

SceneObject ballAt(std::string name, int n, ObjectTransform transform) {
  return {std::move(name), makeDocument(makeBaseShape(BaseShape::Sphere, n)), transform, true,
          false};
}

} // namespace

class SceneTest : public QObject {
  Q_OBJECT
private slots:
  void uniqueNamesFollowBlender();
  void requireNamesEveryObject();
  void objectNames_data();
  void objectNames();
  void transformMatchesAxisRotationsInOrder();
  void quaternionMatchesMatrix();
  void transformProblems_data();
  void transformProblems();
  void sceneProblems();
  void worldBoundsOfAPlacedBall();
  void mirroredDuplicateIsTheWorldMirrorAndFacesOutward_data();
  void mirroredDuplicateIsTheWorldMirrorAndFacesOutward();
};

void SceneTest::uniqueNamesFollowBlender() {
  Scene scene;
  QCOMPARE(scene.uniqueName("Sphere"), std::string("Sphere"));
  scene.objects.push_back(ballAt("Sphere", 2, {}));
  QCOMPARE(scene.uniqueName("Sphere"), std::string("Sphere.001"));
  scene.objects.push_back(ballAt("Sphere.001", 2, {}));
  QCOMPARE(scene.uniqueName("Sphere"), std::string("Sphere.002"));
  QCOMPARE(scene.uniqueName("Sphere.001"), std::string("Sphere.002"));
  // Not a Blender suffix: kept whole as the stem.
  scene.objects.push_back(ballAt("Leg.1", 2, {}));
  QCOMPARE(scene.uniqueName("Leg.1"), std::string("Leg.1.001"));
  QCOMPARE(scene.uniqueName("Head"), std::string("Head"));
}

void SceneTest::requireNamesEveryObject() {
  Scene scene;
  scene.objects.push_back(ballAt("Body", 2, {}));
  scene.objects.push_back(ballAt("Head", 2, {}));
  QCOMPARE(&scene.require("Head"), &scene.objects[1]);
  try {
    scene.require("Tail");
    QFAIL("an unknown name was found");
  } catch (const Error& e) {
    QCOMPARE(e.kind(), ErrorKind::InvalidArgument);
    QVERIFY2(std::string(e.what()).find("Tail") != std::string::npos, e.what());
    QVERIFY2(std::string(e.what()).find("Body, Head") != std::string::npos, e.what());
  }
}

void SceneTest::objectNames_data() {
  QTest::addColumn<QByteArray>("name");
  QTest::addColumn<bool>("good");
  QTest::newRow("plain") << QByteArray("Sphere.001") << true;
  QTest::newRow("utf8") << QByteArray("Ohr links \xc3\xa4") << true;
  QTest::newRow("empty") << QByteArray("") << false;
  QTest::newRow("comma") << QByteArray("a,b") << false;
  QTest::newRow("newline") << QByteArray("a\nb") << false;
  QTest::newRow("256 bytes") << QByteArray(256, 'x') << false;
  QTest::newRow("255 bytes") << QByteArray(255, 'x') << true;
}

void SceneTest::objectNames() {
  QFETCH(QByteArray, name);
  QFETCH(bool, good);
  QCOMPARE(!objectNameProblem(std::string_view(name.constData(), name.size())), good);
}

void SceneTest::transformMatchesAxisRotationsInOrder() {
  const ObjectTransform t{{1.5f, -2.0f, 0.25f}, {30.0f, -45.0f, 120.0f}, {2.0f, 0.5f, -3.0f}};
  for (const Vec3f p : {Vec3f{1, 0, 0}, Vec3f{0, 1, 0}, Vec3f{0.3f, -0.7f, 0.9f}}) {
    // Scale, then X, then Y, then Z, then move.
    Vec3f expected{p.x * t.scale.x, p.y * t.scale.y, p.z * t.scale.z};
    expected = rotateAbout(0, t.rotationDegrees.x, expected);
    expected = rotateAbout(1, t.rotationDegrees.y, expected);
    expected = rotateAbout(2, t.rotationDegrees.z, expected);
    expected = expected + t.translation;
    const Vec3f got = applyTransform(t, p);
    QVERIFY2(distance(got, expected) < 1e-5f, qPrintable(QString("(%1 %2 %3) against (%4 %5 %6)")
                                                             .arg(got.x)
                                                             .arg(got.y)
                                                             .arg(got.z)
                                                             .arg(expected.x)
                                                             .arg(expected.y)
                                                             .arg(expected.z)));
  }
  // The identity leaves points bit for bit.
  const Vec3f p{0.1f, -0.2f, 0.3f};
  QCOMPARE(applyTransform({}, p), p);
}

void SceneTest::quaternionMatchesMatrix() {
  for (const Vec3f angles :
       {Vec3f{0, 0, 0}, Vec3f{90, 0, 0}, Vec3f{10, 20, 30}, Vec3f{-170, 85, 400}}) {
    const ObjectTransform t{{}, angles, {1, 1, 1}};
    const auto q = rotationQuaternion(t);
    QVERIFY(std::abs(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] - 1) < 1e-12);
    for (const Vec3f p : {Vec3f{1, 0, 0}, Vec3f{0, 1, 0}, Vec3f{0, 0, 1}})
      QVERIFY(distance(rotateByQuaternion(q, p), applyTransform(t, p)) < 1e-5f);
  }
}

void SceneTest::transformProblems_data() {
  QTest::addColumn<int>("field"); // 0 translation, 1 rotation, 2 scale
  QTest::addColumn<float>("value");
  QTest::addColumn<QString>("needle");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  QTest::newRow("NaN translation") << 0 << nan << "not a finite number";
  QTest::newRow("inf rotation") << 1 << inf << "not a finite number";
  QTest::newRow("NaN scale") << 2 << nan << "not a finite number";
  QTest::newRow("far") << 0 << 2.0e6f << "translation y";
  QTest::newRow("many turns") << 1 << 4000.0f << "rotation y";
  QTest::newRow("zero scale") << 2 << 0.0f << "scale y";
  QTest::newRow("tiny scale") << 2 << 1e-5f << "scale y";
  QTest::newRow("huge scale") << 2 << -2e4f << "scale y";
}

void SceneTest::transformProblems() {
  QFETCH(int, field);
  QFETCH(float, value);
  QFETCH(QString, needle);
  ObjectTransform t;
  (field == 0 ? t.translation : field == 1 ? t.rotationDegrees : t.scale).y = value;
  const auto problem = transformProblem(t);
  QVERIFY(problem.has_value());
  QVERIFY2(QString::fromStdString(*problem).contains(needle), problem->c_str());
  // Within the bounds: no problem, either sign.
  QVERIFY(!transformProblem({{-1e6f, 0, 1e6f}, {3600, -3600, 0}, {-1e4f, 1e-4f, -1}}));
}

void SceneTest::sceneProblems() {
  Scene scene;
  QVERIFY(sceneProblem(scene).has_value());
  scene.objects.push_back(ballAt("A", 2, {}));
  QVERIFY(!sceneProblem(scene));
  scene.objects.push_back(ballAt("A", 2, {}));
  QVERIFY(sceneProblem(scene)->find("two objects") != std::string::npos);
  scene.objects.back().name = "B";
  scene.objects.back().transform.scale.z = 0;
  QVERIFY(sceneProblem(scene)->find("object 'B'") != std::string::npos);
}

void SceneTest::worldBoundsOfAPlacedBall() {
  // A unit ball scaled (2, 1, 0.5), turned 90° about z (x → y), moved to (10, 0, -1): its box is
  // [9, 11] in x (the former y), [-2, 2] in y, [-1.5, -0.5] in z.
  Scene scene;
  scene.objects.push_back(ballAt("Ball", 64, {{10, 0, -1}, {0, 0, 90}, {2, 1, 0.5f}}));
  const BoundingBox box = worldBounds(scene.objects[0]);
  QVERIFY(std::abs(box.min.x - 9) < 1e-4f && std::abs(box.max.x - 11) < 1e-4f);
  QVERIFY(std::abs(box.min.y + 2) < 1e-4f && std::abs(box.max.y - 2) < 1e-4f);
  QVERIFY(std::abs(box.min.z + 1.5f) < 1e-4f && std::abs(box.max.z + 0.5f) < 1e-4f);
  // A second, hidden object widens the scene's box unless only the visible ones count.
  scene.objects.push_back(ballAt("Far", 8, {{-100, 0, 0}, {}, {1, 1, 1}}));
  scene.objects.back().visible = false;
  QVERIFY(std::abs(sceneBounds(scene).min.x + 101) < 1e-4f);
  QCOMPARE(sceneBounds(scene, true).min.x, box.min.x);
  // World positions follow the texels' order.
  const auto world = worldPositions(scene.objects[0]);
  QCOMPARE(world.size(), scene.objects[0].document.positions.texelCount());
  QCOMPARE(world[5], applyTransform(scene.objects[0].transform,
                                    scene.objects[0].document.positions.texels()[5].xyz()));
}

void SceneTest::mirroredDuplicateIsTheWorldMirrorAndFacesOutward_data() {
  QTest::addColumn<int>("axis");
  QTest::addColumn<int>("n");
  for (int n : {2, 16, 64})
    for (int axis = 0; axis < 3; ++axis)
      QTest::addRow("axis %d N=%d", axis, n) << axis << n;
}

void SceneTest::mirroredDuplicateIsTheWorldMirrorAndFacesOutward() {
  QFETCH(int, axis);
  QFETCH(int, n);
  // A capsule (not symmetric under the transpose's diagonal) placed off every axis plane, turned
  // and scaled unevenly: the mirrored copy must be every world point mirrored across the plane.
  SceneObject leg{"Leg",
                  makeDocument(makeCapsule(n, Capsule{0.3f, 1.0f})),
                  {{0.7f, 0.4f, -0.9f}, {20, -35, 50}, {1.0f, 2.0f, 0.5f}},
                  true,
                  false};
  // A painted texel follows its sample.
  leg.document.diffuse.texels.assign(leg.document.positions.texelCount() * 4, 0.5f);
  leg.document.diffuse.texels[(1 * (n + 1) + 0) * 4] = 0.25f; // sample (i 0, j 1)
  const SceneObject copy{"Leg.001", mirrorDocument(leg.document, axis),
                         mirroredTransform(leg.transform, axis), true, false};
  QCOMPARE(copy.document.diffuse.texels[(0 * (n + 1) + 1) * 4], 0.25f); // at (i 1, j 0)

  const auto original = worldPositions(leg);
  const auto mirrored = worldPositions(copy);
  const int side = n + 1;
  float worst = 0;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      Vec3f p = original[std::size_t(j) * side + i];
      (axis == 0 ? p.x : axis == 1 ? p.y : p.z) *= -1;
      worst = std::max(worst, distance(p, mirrored[std::size_t(i) * side + j]));
    }
  QVERIFY2(worst < 1e-5f, qPrintable(QString("moved %1 from the mirror image").arg(worst)));

  // Facing outward: the world mesh of each encloses a positive volume, the same one.
  auto worldMesh = [](const SceneObject& object) {
    TriangleMesh mesh = extractMesh(object.document.positions);
    for (Vec3f& p : mesh.positions)
      p = applyTransform(object.transform, p);
    return mesh;
  };
  const double before = signedVolume(worldMesh(leg));
  const double after = signedVolume(worldMesh(copy));
  QVERIFY2(before > 0, qPrintable(QString::number(before)));
  QVERIFY2(std::abs(after - before) < 1e-5 * before,
           qPrintable(QString("volume %1 against %2").arg(after).arg(before)));
  // Every triangle's normal points away from the object's centre, as on the original.
  const TriangleMesh mesh = worldMesh(copy);
  const Vec3f centre = applyTransform(copy.transform, {0, 0, 0});
  int inward = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3f a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    if (dot(cross(b - a, c - a), (a + b + c) * (1.0f / 3) - centre) < 0) ++inward;
  }
  QCOMPARE(inward, 0);
}

QTEST_APPLESS_MAIN(SceneTest)
#include "scene_test.moc"
