// octaclay-cli's scene verbs end to end (objects, add, transform, remove, rename, duplicate) and
// --object on the single-object commands: names, transforms as typed, exit 2 for unknown names
// (listing the objects) and for a multi-object document without --object, exit 3 for a file
// that lies, nothing written on a refusal, the other objects untouched by an edit of one.

#include "cli_support.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/document/scene_io.h"

#include <QJsonArray>
#include <QTemporaryDir>

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

using namespace octaclay;

namespace {

bool samePositions(const core::Document& a, const core::Document& b) {
  return a.size() == b.size() &&
         std::memcmp(a.positions.texels().data(), b.positions.texels().data(),
                     a.positions.byteSize()) == 0;
}

QJsonObject objectNamed(const QJsonObject& listing, const QString& name) {
  for (const auto& o : listing["objects"].toArray())
    if (o.toObject()["name"].toString() == name) return o.toObject();
  return {};
}

float at(const QJsonObject& object, const char* key, int k) {
  return static_cast<float>(object[key].toArray()[k].toDouble());
}

} // namespace

class CliSceneTest : public QObject {
  Q_OBJECT
private slots:
  void initTestCase();
  void buildAScene();
  void unknownObjectsNameTheObjects();
  void multiObjectDocumentsNeedObject();
  void objectEditsLeaveTheOthersAlone();
  void refusalsWriteNothing();
  void lyingFilesExitThree();
  void plainDocumentsStayPlain();
  void mergeMakesOneClosedObject();
  void importOfSeveralPartsMakesObjects();
  void torusAndPlaneObjects();

private:
  QString path(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
  QString scene_; ///< body, Leg, Leg.001 (mirrored), Head
};

void CliSceneTest::initTestCase() {
  QVERIFY(dir_.isValid());
  scene_ = path("creature.exr");
  RUN_JSON(created, "new", "--shape", "sphere", "--size", "16", "-o", path("body.exr"), "--json");
  RUN_JSON(leg, "add", path("body.exr"), "--shape", "capsule", "--name", "Leg", "--size", "8",
           "--translate", "0.6,-0.25,-1", "--rotate", "15,0,30", "--scale", "0.5,0.5,0.75", "-o",
           scene_, "--json");
  QCOMPARE(leg["objects"].toInt(), 2);
  RUN_JSON(mirrored, "duplicate", scene_, "--object", "Leg", "--mirror", "x", "-o", scene_,
           "--json");
  QCOMPARE(mirrored["name"].toString(), QString("Leg.001"));
  RUN_JSON(head, "add", scene_, "--shape", "sphere", "--name", "Head", "--translate", "0,0,1.4",
           "--scale", "0.4", "-o", scene_, "--json");
  QCOMPARE(head["size"].toInt(), 16); // the first object's N
}

void CliSceneTest::buildAScene() {
  RUN_JSON(listing, "objects", scene_, "--json");
  const QJsonArray objects = listing["objects"].toArray();
  QCOMPARE(objects.size(), 4);
  QStringList names;
  for (const auto& o : objects)
    names << o.toObject()["name"].toString();
  QCOMPARE(names, (QStringList{"body", "Leg", "Leg.001", "Head"}));

  // The transforms as typed, to the float.
  const QJsonObject leg = objectNamed(listing, "Leg");
  QCOMPARE(at(leg, "translation", 0), 0.6f);
  QCOMPARE(at(leg, "translation", 1), -0.25f);
  QCOMPARE(at(leg, "rotation", 2), 30.0f);
  QCOMPARE(at(leg, "scale", 2), 0.75f);
  QCOMPARE(leg["size"].toInt(), 8);
  QCOMPARE(leg["width"].toInt(), 8); // cells
  QCOMPARE(leg["topology"].toString(), QString("octahedral"));
  // The mirror across the scene's x plane: x moved, the angles about y and z turned back.
  const QJsonObject copy = objectNamed(listing, "Leg.001");
  QCOMPARE(at(copy, "translation", 0), -0.6f);
  QCOMPARE(at(copy, "translation", 1), -0.25f);
  QCOMPARE(at(copy, "rotation", 0), 15.0f);
  QCOMPARE(at(copy, "rotation", 2), -30.0f);
  QCOMPARE(at(copy, "scale", 2), 0.75f);
  const QJsonObject head = objectNamed(listing, "Head");
  QCOMPARE(at(head, "scale", 1), 0.4f);

  // Placed again, renamed, a plain copy, one removed: each verb in place.
  const QString edited = path("edited.exr");
  RUN_JSON(moved, "transform", scene_, "--object", "Head", "--rotate", "0,0,90", "-o", edited,
           "--json");
  QCOMPARE(static_cast<float>(moved["translation"].toArray()[2].toDouble()), 1.4f); // kept
  RUN_JSON(renamed, "rename", edited, "--object", "Head", "--to", "Kopf", "-o", edited, "--json");
  RUN_JSON(copied, "duplicate", edited, "--object", "Kopf", "-o", edited, "--json");
  QCOMPARE(copied["name"].toString(), QString("Kopf.001"));
  RUN_JSON(removed, "remove", edited, "--object", "body", "-o", edited, "--json");
  QCOMPARE(removed["objects"].toInt(), 4);
  RUN_JSON(after, "objects", edited, "--json");
  QStringList afterNames;
  for (const auto& o : after["objects"].toArray())
    afterNames << o.toObject()["name"].toString();
  QCOMPARE(afterNames, (QStringList{"Leg", "Leg.001", "Kopf", "Kopf.001"}));
  QCOMPARE(at(objectNamed(after, "Kopf.001"), "rotation", 2), 90.0f);

  // The human listing names every object.
  const Result text = runCli({"objects", edited});
  QCOMPARE(text.exitCode, kOk);
  for (const char* name : {"Leg", "Leg.001", "Kopf", "Kopf.001"})
    QVERIFY2(text.out.contains(name), text.out.constData());
}

void CliSceneTest::unknownObjectsNameTheObjects() {
  const QString out = path("never.exr");
  for (const QStringList& args :
       {QStringList{"info", scene_, "--object", "Tail"},
        QStringList{"relax", scene_, "--object", "Tail", "-o", out},
        QStringList{"lod", scene_, "--object", "Tail", "--size", "4", "-o", path("never.obj")},
        QStringList{"export", scene_, "--object", "Tail", "-o", path("never.obj")},
        QStringList{"compress", scene_, "--object", "Tail", "--codec", "lossless", "-o",
                    path("never.ocz")},
        QStringList{"stroke", scene_, "--object", "Tail", "--brush", "inflate", "--path", "0.5,0.5",
                    "-o", out},
        QStringList{"transform", scene_, "--object", "Tail", "--scale", "2", "-o", out},
        QStringList{"remove", scene_, "--object", "Tail", "-o", out},
        QStringList{"rename", scene_, "--object", "Tail", "--to", "X", "-o", out},
        QStringList{"duplicate", scene_, "--object", "Tail", "-o", out}}) {
    const Result r = runCli(args);
    QVERIFY2(r.exitCode == kUsage, qPrintable(describe(args, r)));
    QVERIFY2(r.err.contains("no object 'Tail'") && r.err.contains("body, Leg, Leg.001, Head"),
             qPrintable(describe(args, r)));
    QVERIFY(!QFileInfo::exists(out));
  }
}

void CliSceneTest::multiObjectDocumentsNeedObject() {
  for (const QStringList& args :
       {QStringList{"info", scene_}, QStringList{"relax", scene_, "-o", path("never.exr")},
        QStringList{"export", scene_, "--lod", "4", "-o", path("never.ply")},
        QStringList{"transform", scene_, "--scale", "2", "-o", path("never.exr")},
        QStringList{"resize", scene_, "--size", "8", "-o", path("never.exr")},
        QStringList{"remesh", scene_, "-o", path("never.exr")},
        QStringList{"compare", scene_, scene_}}) {
    const Result r = runCli(args);
    QVERIFY2(r.exitCode == kUsage && r.err.contains("--object NAME") && r.err.contains("4 objects"),
             qPrintable(describe(args, r)));
  }
  // With --object the single-object commands work on that object.
  RUN_JSON(info, "info", scene_, "--object", "Leg", "--json");
  QCOMPARE(info["size"].toInt(), 8);
  QCOMPARE(info["euler"].toInt(), 2);
  RUN_JSON(same, "compare", scene_, scene_, "--object", "Leg.001", "--json");
  QCOMPARE(same["hausdorff"].toDouble(), 0.0);
  RUN_JSON(exported, "export", scene_, "--object", "Head", "-o", path("head.ply"), "--json");
  QVERIFY(QFileInfo::exists(path("head.ply")));
  // Without --object, export writes every visible object, placed: GLB nodes, OBJ groups.
  RUN_JSON(glb, "export", scene_, "-o", path("scene.glb"), "--json");
  QCOMPARE(glb["objects"].toInt(), 4);
  RUN_JSON(obj, "export", scene_, "-o", path("scene.obj"), "--json");
  QFile text(path("scene.obj"));
  QVERIFY(text.open(QIODevice::ReadOnly));
  QCOMPARE(text.readAll().count("\no "), 4);
}

void CliSceneTest::objectEditsLeaveTheOthersAlone() {
  const core::Scene before = core::readScene(scene_.toStdString());
  const QString out = path("stroked.exr");
  RUN_JSON(stroked, "stroke", scene_, "--object", "Leg.001", "--brush", "inflate", "--path",
           "0.5,0.5;0.6,0.5", "--radius", "0.3", "--strength", "0.5", "-o", out, "--json");
  QVERIFY(stroked["dabs"].toInt() > 0);
  const core::Scene after = core::readScene(out.toStdString());
  QCOMPARE(after.objects.size(), before.objects.size());
  for (std::size_t k = 0; k < after.objects.size(); ++k) {
    QCOMPARE(after.objects[k].name, before.objects[k].name);
    QVERIFY(after.objects[k].transform == before.objects[k].transform);
    const bool same = samePositions(after.objects[k].document, before.objects[k].document);
    QVERIFY2(same == (after.objects[k].name != "Leg.001"), after.objects[k].name.c_str());
  }
  RUN_JSON(relaxed, "relax", out, "--object", "Head", "-o", out, "--json");
  const core::Scene again = core::readScene(out.toStdString());
  QVERIFY(samePositions(again.objects[2].document, after.objects[2].document));
  RUN_JSON(resized, "resize", out, "--object", "Leg", "--size", "16", "-o", path("resized.exr"),
           "--json");
  const core::Scene resizedScene = core::readScene(path("resized.exr").toStdString());
  QCOMPARE(resizedScene.objects[1].document.size(), resized["size"].toInt()); // or kept
  QVERIFY(samePositions(resizedScene.objects[0].document, again.objects[0].document));
}

void CliSceneTest::refusalsWriteNothing() {
  const QString out = path("refused.exr");
  EXPECT_FAILURE(kUsage, out, "transform", scene_, "--object", "Leg", "--scale", "0", "-o", out);
  EXPECT_FAILURE(kUsage, out, "transform", scene_, "--object", "Leg", "--translate", "1,nan,0",
                 "-o", out);
  EXPECT_FAILURE(kUsage, out, "transform", scene_, "--object", "Leg", "--rotate", "1,2", "-o", out);
  EXPECT_FAILURE(kUsage, out, "add", scene_, "--shape", "teapot", "-o", out);
  EXPECT_FAILURE(kUsage, out, "add", scene_, "--shape", "sphere", "--name", "Leg", "-o", out);
  EXPECT_FAILURE(kUsage, out, "add", scene_, "--shape", "sphere", "--name", "a,b", "-o", out);
  EXPECT_FAILURE(kUsage, out, "rename", scene_, "--object", "Leg", "--to", "Head", "-o", out);
  EXPECT_FAILURE(kUsage, out, "duplicate", scene_, "--object", "Leg", "--mirror", "w", "-o", out);
  EXPECT_FAILURE(kUsage, out, "remove", path("body.exr"), "--object", "body", "-o", out);
  EXPECT_FAILURE(kUsage, path("refused.obj"), "add", scene_, "--shape", "sphere", "-o",
                 path("refused.obj"));
}

void CliSceneTest::lyingFilesExitThree() {
  // 10^6 declared parts: refused from the headers, for every verb that reads a document.
  std::string bytes = "\x76\x2f\x31\x01";
  const auto u32 = [&](std::uint32_t v) {
    for (int k = 0; k < 4; ++k)
      bytes.push_back(char((v >> (8 * k)) & 0xff));
  };
  u32(2 | 0x1000);
  std::string header = std::string("dataWindow") + '\0' + "box2i" + '\0';
  header +=
      std::string("\x10\0\0\0", 4) + std::string(8, '\0') + std::string("\x02\0\0\0\x02\0\0\0", 8);
  header.push_back('\0');
  for (int k = 0; k < 1000000; ++k)
    bytes += header;
  bytes.push_back('\0');
  const QString lying = path("million.exr");
  std::ofstream(lying.toStdString(), std::ios::binary)
      .write(bytes.data(), std::streamsize(bytes.size()));
  const QString out = path("never.exr");
  for (const QStringList& args : {QStringList{"objects", lying}, QStringList{"info", lying},
                                  QStringList{"add", lying, "--shape", "sphere", "-o", out},
                                  QStringList{"transform", lying, "--scale", "2", "-o", out}}) {
    const Result r = runCli(args);
    QVERIFY2(r.exitCode == kInvalidInput && r.err.contains("more than 1024 objects"),
             qPrintable(describe(args, r)));
    QVERIFY(!QFileInfo::exists(out));
  }
}

void CliSceneTest::plainDocumentsStayPlain() {
  // A stroke or relax of today's one-object file writes today's file: no scene attributes.
  const QString relaxed = path("relaxed.exr");
  RUN_JSON(r, "relax", path("body.exr"), "-o", relaxed, "--json");
  std::ifstream in(relaxed.toStdString(), std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  QVERIFY(bytes.find("octaclay.name") == std::string::npos);
  QVERIFY((static_cast<unsigned char>(bytes[5]) & 0x10) == 0); // no multi-part flag
  // A named one-object scene keeps its name and place through a relax.
  const QString one = path("one.exr");
  RUN_JSON(removed, "remove", path("edited.exr"), "--object", "Leg.001", "-o", one, "--json");
  RUN_JSON(gone, "remove", one, "--object", "Kopf", "-o", one, "--json");
  RUN_JSON(last, "remove", one, "--object", "Kopf.001", "-o", one, "--json");
  RUN_JSON(left, "relax", one, "-o", one, "--json");
  RUN_JSON(listing, "objects", one, "--json");
  QCOMPARE(listing["objects"].toArray().size(), 1);
  QCOMPARE(objectNamed(listing, "Leg")["translation"].toArray()[0].toDouble(), double(0.6f));
}

void CliSceneTest::mergeMakesOneClosedObject() {
  // The body and one leg of the creature merge; the far-off head does not touch the legs.
  const QString merged = path("merged.exr");
  RUN_JSON(m, "merge", scene_, "--objects", "body,Leg", "--name", "Torso", "--size", "32", "-o",
           merged, "--json");
  QCOMPARE(m["objects"].toInt(), 3);
  RUN_JSON(listing, "objects", merged, "--json");
  QStringList names;
  for (const auto& o : listing["objects"].toArray())
    names << o.toObject()["name"].toString();
  QCOMPARE(names, (QStringList{"Torso", "Leg.001", "Head"}));
  RUN_JSON(info, "info", merged, "--object", "Torso", "--json");
  QCOMPARE(info["euler"].toInt(), 2);
  QVERIFY(info["closed"].toBool());
  // The merged surface spans the body and the placed leg (world space, identity transform):
  // the leg reaches below the body's bottom (z = -1).
  QVERIFY2(info["bbox"].toObject()["min"].toArray()[2].toDouble() < -1.2,
           qPrintable(QJsonDocument(info).toJson()));
  // Objects that do not touch: exit 3, nothing written; a name listed twice or once: exit 2.
  EXPECT_FAILURE(kInvalidInput, path("apart.exr"), "merge", scene_, "--objects", "Leg,Leg.001",
                 "-o", path("apart.exr"));
  EXPECT_FAILURE(kUsage, path("apart.exr"), "merge", scene_, "--objects", "Leg,Leg", "-o",
                 path("apart.exr"));
  EXPECT_FAILURE(kUsage, path("apart.exr"), "merge", scene_, "--objects", "Leg", "-o",
                 path("apart.exr"));
  EXPECT_FAILURE(kUsage, path("apart.exr"), "merge", scene_, "--objects", "Leg,Tail", "-o",
                 path("apart.exr"));
  // A ground plane through the body: a sheet encloses nothing, refused by name (exit 3).
  RUN_JSON(ground, "add", scene_, "--shape", "plane", "--name", "Ground", "--size", "16", "--scale",
           "3", "-o", path("grounded.exr"), "--json");
  EXPECT_FAILURE(kInvalidInput, path("apart.exr"), "merge", path("grounded.exr"), "--objects",
                 "body,Ground", "-o", path("apart.exr"));
}

void CliSceneTest::importOfSeveralPartsMakesObjects() {
  // Three lumps apart, exported as one STL (corners welded on reading), come back as three
  // objects where they stood.
  const QString lumps = path("lumps.exr");
  RUN_JSON(a, "new", "--shape", "sphere", "--size", "16", "-o", lumps, "--json");
  RUN_JSON(b, "add", lumps, "--shape", "cube", "--translate", "3,0,0", "-o", lumps, "--json");
  RUN_JSON(c, "add", lumps, "--shape", "capsule", "--translate", "0,0,4", "--rotate", "0,90,0",
           "-o", lumps, "--json");
  RUN_JSON(stl, "export", lumps, "-o", path("lumps.stl"), "--json");
  RUN_JSON(imported, "import", path("lumps.stl"), "--size", "16", "-o", path("parts.exr"),
           "--json");
  QCOMPARE(imported["objects"].toInt(), 3);
  RUN_JSON(listing, "objects", path("parts.exr"), "--json");
  QCOMPARE(listing["objects"].toArray().size(), 3);
  for (const char* name : {"Part", "Part.001", "Part.002"}) {
    RUN_JSON(info, "info", path("parts.exr"), "--object", name, "--json");
    QVERIFY(info["closed"].toBool());
    QCOMPARE(info["euler"].toInt(), 2);
  }
  // The capsule (the last part), turned to lie along x at z = 4: 2 long, 1 thick.
  RUN_JSON(capsule, "info", path("parts.exr"), "--object", "Part.002", "--json");
  const QJsonObject box = capsule["bbox"].toObject();
  const double dx = box["max"].toArray()[0].toDouble() - box["min"].toArray()[0].toDouble();
  const double z = box["max"].toArray()[2].toDouble();
  QVERIFY2(std::abs(dx - 2) < 0.05 && std::abs(z - 4.5) < 0.05,
           qPrintable(QJsonDocument(capsule).toJson()));
  // Lumps that touch at a point (the creature's head sits on the body's pole) stay one
  // refused mesh, with import's own words.
  RUN_JSON(touching, "export", scene_, "-o", path("touching.stl"), "--json");
  const Result refused = runCli({"import", path("touching.stl"), "-o", path("never.exr")});
  QVERIFY2(refused.err.contains("pinch"), refused.err.constData());
  EXPECT_FAILURE(kInvalidInput, path("never.exr"), "import", path("touching.stl"), "-o",
                 path("never.exr"));
}

void CliSceneTest::torusAndPlaneObjects() {
  // A ball, a ring above it, its mirror below, and a disc: each keeps its topology.
  const QString mixed = path("mixed.exr");
  RUN_JSON(a, "new", "--shape", "sphere", "--size", "16", "-o", mixed, "--json");
  RUN_JSON(b, "add", mixed, "--shape", "torus", "--translate", "0,0,2", "-o", mixed, "--json");
  RUN_JSON(c, "duplicate", mixed, "--object", "Torus", "--mirror", "z", "-o", mixed, "--json");
  RUN_JSON(d, "add", mixed, "--shape", "plane", "--translate", "0,0,-3", "-o", mixed, "--json");
  RUN_JSON(listing, "objects", mixed, "--json");
  QCOMPARE(objectNamed(listing, "Torus")["topology"].toString(), QString("torus"));
  QCOMPARE(objectNamed(listing, "Torus.001")["topology"].toString(), QString("torus"));
  QCOMPARE(at(objectNamed(listing, "Torus.001"), "translation", 2), -2.0f);
  QCOMPARE(objectNamed(listing, "Plane")["topology"].toString(), QString("plane"));
  RUN_JSON(ring, "info", mixed, "--object", "Torus.001", "--json");
  QCOMPARE(ring["euler"].toInt(), 0);
  QVERIFY(ring["closed"].toBool());
  RUN_JSON(sheet, "info", mixed, "--object", "Plane", "--json");
  QCOMPARE(sheet["euler"].toInt(), 1);
  QVERIFY(!sheet["closed"].toBool());
}

QTEST_APPLESS_MAIN(CliSceneTest)
#include "cli_scene_test.moc"
