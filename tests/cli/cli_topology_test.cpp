// octaclay-cli on torus and plane documents (issue 33): `new --shape torus|plane|disc` writes
// them, `info` describes them (Euler 0 closed, Euler 1 open), `export` writes PLY and OFF and
// refuses the ball-only textured OBJ and GLB of the full image, `lod` makes their LODs (and the
// textured files through them), `resize` resamples them, `relax` evens them out, `stroke` sculpts
// a square torus
// across its wrap and a plane to its edge; bad arguments exit 2 and write nothing.

#include "cli_support.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>

class CliTopologyTest : public QObject {
  Q_OBJECT

private slots:
  void newTorusChoosesItsHeightFromTheRadii() {
    RUN_JSON(made, "new", "--shape", "torus", "--size", "64", "-o", file("torus.exr"), "--json");
    QCOMPARE(made["topology"].toString(), QString("torus"));
    QCOMPARE(made["width"].toInt(), 64);
    QCOMPARE(made["height"].toInt(), 32); // 64 x 0.3 / 0.7 = 27
    QCOMPARE(made["vertices"].toInt(), 64 * 32);
    RUN_JSON(info, "info", file("torus.exr"), "--json");
    QCOMPARE(info["topology"].toString(), QString("torus"));
    QCOMPARE(info["euler"].toInt(), 0);
    QVERIFY(info["closed"].toBool());
    QVERIFY(info["manifold"].toBool());
    QCOMPARE(info["seam_gap"].toDouble(), 0.0);
    QCOMPARE(info["vertices"].toInt(), 64 * 32);
    QCOMPARE(info["samples"].toInt(), 65 * 33);
    // Its own grid's edges: the ring's outer edges (2π·1.0/64) over the tube's (2π·0.3/32).
    const double longest = info["stretch"].toObject()["longest_over_median"].toDouble();
    QVERIFY2(longest > 1.5 && longest < 1.8, qPrintable(QString::number(longest)));
    RUN_JSON(thin, "new", "--shape", "torus", "--size", "256", "--major", "0.9", "--minor", "0.1",
             "-o", file("thin.exr"), "--json");
    QCOMPARE(thin["height"].toInt(), 32);
    const Result text = runCli({"info", file("thin.exr")});
    QCOMPARE(text.exitCode, kOk);
    QVERIFY(text.out.contains("256x32 cells (257x33 samples)"));
    QVERIFY(text.out.contains("topology   torus"));
  }

  void planeAndDiscHaveOneBoundary() {
    for (const char* shape : {"plane", "disc"}) {
      const QString path = file(QString(shape) + ".exr");
      RUN_JSON(made, "new", "--shape", shape, "--size", "32", "-o", path, "--json");
      QCOMPARE(made["topology"].toString(), QString("plane"));
      QCOMPARE(made["vertices"].toInt(), 33 * 33);
      RUN_JSON(info, "info", path, "--json");
      QCOMPARE(info["euler"].toInt(), 1);
      QVERIFY(!info["closed"].toBool());
      QVERIFY(info["manifold"].toBool());
      QCOMPARE(info["triangles"].toInt(), 2 * 32 * 32);
    }
  }

  void exportWritesEveryFormatAndRefusesTheRest() {
    RUN_JSON(made, "new", "--shape", "torus", "--size", "32", "-o", file("t.exr"), "--json");
    RUN_JSON(ply, "export", file("t.exr"), "-o", file("t.ply"), "--json");
    QCOMPARE(ply["vertices"].toInt(), 32 * 16);
    QCOMPARE(ply["triangles"].toInt(), 2 * 32 * 16);
    RUN_JSON(plane, "new", "--shape", "plane", "--size", "16", "-o", file("p.exr"), "--json");
    RUN_JSON(off, "export", file("p.exr"), "-o", file("p.off"), "--json");
    QCOMPARE(off["vertices"].toInt(), 17 * 17);
    // Textured OBJ and GLB of the full image and of a level: the torus's own vertex count.
    RUN_JSON(obj, "export", file("t.exr"), "-o", file("t.obj"), "--json");
    QCOMPARE(obj["vertices"].toInt(), 32 * 16);
    QCOMPARE(obj["files"].toArray().size(), 6);
    RUN_JSON(glb, "export", file("t.exr"), "--lod", "16", "-o", file("t.glb"), "--json");
    QCOMPARE(glb["vertices"].toInt(), 16 * 8);
    QCOMPARE(glb["file_vertices"].toInt(), 17 * 9);
    RUN_JSON(planeObj, "export", file("p.exr"), "-o", file("p.obj"), "--json");
    QCOMPARE(planeObj["vertices"].toInt(), 17 * 17);
    // A level leaving fewer than 4 cells around the tube is refused by name, nothing written.
    const Result coarse = runCli({"export", file("t.exr"), "--lod", "4", "-o", file("t4.obj")});
    QVERIFY2(coarse.exitCode == kUsage && coarse.err.contains("--lod 4"), qPrintable(coarse.err));
    QVERIFY(!QFileInfo::exists(file("t4.obj")));
    // A scene of a ball and the torus exports as two GLB nodes (this crashed before).
    RUN_JSON(scene, "add", file("t.exr"), "--shape", "sphere", "--size", "16", "--translate",
             "2,0,0", "-o", file("scene.exr"), "--json");
    RUN_JSON(sceneGlb, "export", file("scene.exr"), "-o", file("scene.glb"), "--json");
    QCOMPARE(sceneGlb["objects"].toInt(), 2);
    QVERIFY(QFileInfo(file("scene.glb")).size() > 1000);
    // The torus alone, named with --object, into a lossy .ocz: one torus object back.
    RUN_JSON(alone, "compress", file("scene.exr"), "--object", "t", "--codec", "wavelet", "-o",
             file("t-alone.ocz"), "--json");
    RUN_JSON(aloneBack, "decompress", file("t-alone.ocz"), "-o", file("t-alone.exr"), "--json");
    QCOMPARE(aloneBack["objects"].toInt(), 1);
    RUN_JSON(aloneInfo, "info", file("t-alone.exr"), "--json");
    QCOMPARE(aloneInfo["topology"].toString(), QString("torus"));
    // Commands still written for the ball alone say so by name (exit 2), and write nothing.
    for (const QStringList& args : {QStringList{"remesh", file("t.exr"), "-o", file("t3.exr")}}) {
      const Result r = runCli(args);
      QVERIFY2(r.exitCode == kUsage && r.err.contains("works on octahedral documents only"),
               qPrintable(describe(args, r)));
      QVERIFY(!QFileInfo::exists(args.last()));
    }
    // relax evens a torus's samples out; an evenly made one is written unchanged with the reason.
    RUN_JSON(relaxed, "relax", file("t.exr"), "-o", file("t2.exr"), "--json");
    QVERIFY(!relaxed["changed"].toBool());
    QVERIFY2(relaxed["reason"].toString().contains("already as even"),
             qPrintable(relaxed["reason"].toString()));
    QVERIFY(QFileInfo::exists(file("t2.exr")));
    // compress codes a torus with an exact codec (its W × H image padded to the square) and
    // with a lossy one (one sample in on a square twice its side), its wrap exact either way.
    RUN_JSON(exact, "compress", file("t.exr"), "--codec", "lossless", "-o", file("t.ocz"),
             "--json");
    QVERIFY(exact["exact"].toBool());
    QCOMPARE(exact["objects"].toArray()[0].toObject()["height"].toInt(), 16);
    RUN_JSON(lossy, "compress", file("t.exr"), "--codec", "dct", "-o", file("t-dct.ocz"), "--json");
    QVERIFY(!lossy["exact"].toBool());
    RUN_JSON(back, "decompress", file("t-dct.ocz"), "-o", file("t-dct.exr"), "--json");
    RUN_JSON(backInfo, "info", file("t-dct.exr"), "--json");
    QCOMPARE(backInfo["euler"].toInt(), 0);
    QVERIFY(backInfo["closed"].toBool());
  }

  // The LOD of a torus and a disc: M counts the longer side's cells, the mesh keeps the
  // topology (closed with Euler 0; one boundary), the textured OBJ and GLB come through it.
  void lodAndCollapsedExportOfTorusAndDisc() {
    RUN_JSON(made, "new", "--shape", "torus", "--size", "64", "-o", file("t.exr"), "--json");
    RUN_JSON(lod, "lod", file("t.exr"), "--size", "16", "--method", "point", "-o",
             file("t.lod.obj"), "--json");
    QCOMPARE(lod["topology"].toString(), QString("torus"));
    QCOMPARE(lod["size"].toInt(), 16);
    QCOMPARE(lod["triangles"].toInt(), 2 * 16 * 8); // 64 x 32 cells, every fourth
    QCOMPARE(lod["full_triangles"].toInt(), 2 * 64 * 32);
    QVERIFY(lod["hausdorff"].toDouble() < 0.02);
    EXPECT_FAILURE(kUsage, file("t.big.obj"), "lod", file("t.exr"), "--size", "64", "-o",
                   file("t.big.obj"));
    RUN_JSON(collapsed, "export", file("t.exr"), "--triangles", "500", "-o", file("t.glb"),
             "--normal-map", file("t.normals.png"), "--json");
    QVERIFY(collapsed["triangles"].toInt() <= 502);
    QVERIFY(QFileInfo(file("t.glb")).size() > 1000);
    QVERIFY(QFileInfo(file("t.normals.png")).size() > 100);
    RUN_JSON(disc, "new", "--shape", "disc", "--size", "64", "-o", file("d.exr"), "--json");
    RUN_JSON(discLod, "lod", file("d.exr"), "--triangles", "1500", "-o", file("d.lod.obj"),
             "--json");
    QCOMPARE(discLod["topology"].toString(), QString("plane"));
    QCOMPARE(discLod["method_used"].toString(), QString("collapse"));
    QVERIFY(discLod["triangles"].toInt() <= 1502);
    QVERIFY(discLod["hausdorff"].toDouble() < 0.001); // a flat sheet, its circle kept
  }

  // resize: a 64 × 32 torus to width 256 is 256 × 128, closed, its wrap exact; down to 4 would
  // leave 2 cells around the tube: refused by name, nothing written.
  void resizeATorus() {
    RUN_JSON(made, "new", "--shape", "torus", "--size", "64", "-o", file("r.exr"), "--json");
    RUN_JSON(up, "resize", file("r.exr"), "--size", "256", "-o", file("r128.exr"), "--json");
    QVERIFY2(up["changed"].toBool(), qPrintable(up["reason"].toString()));
    QCOMPARE(up["size"].toInt(), 256);
    QCOMPARE(up["height"].toInt(), 128);
    QCOMPARE(up["topology"].toString(), QString("torus"));
    // The ring's own edge figures (its grid's edges along i and j), before and after.
    QVERIFY(up["before"].toObject()["longest_over_median"].toDouble() > 1);
    QVERIFY(up["after"].toObject()["median_edge"].toDouble() <
            0.6 * up["before"].toObject()["median_edge"].toDouble());
    QVERIFY(up["hausdorff"].toDouble() < 0.01);
    RUN_JSON(info, "info", file("r128.exr"), "--json");
    QCOMPARE(info["width"].toInt(), 256);
    QCOMPARE(info["seam_gap"].toDouble(), 0.0);
    QCOMPARE(info["euler"].toInt(), 0);
    const Result small = runCli({"resize", file("r.exr"), "--size", "4", "-o", file("r4.exr")});
    QVERIFY2(small.exitCode == kUsage && small.err.contains("at least 4"), qPrintable(small.err));
    QVERIFY(!QFileInfo::exists(file("r4.exr")));
  }

  void strokesAcrossTheWrapAndToTheEdge() {
    RUN_JSON(made, "new", "--shape", "torus", "--size", "64", "--height", "64", "-o",
             file("sq.exr"), "--json");
    RUN_JSON(stroke, "stroke", file("sq.exr"), "--brush", "inflate", "--path", "0.95,0.5;1,0.5",
             "--radius", "0.1", "-o", file("sq2.exr"), "--json");
    QVERIFY(stroke["dabs"].toInt() >= 1);
    RUN_JSON(info, "info", file("sq2.exr"), "--json");
    QCOMPARE(info["seam_gap"].toDouble(), 0.0);
    QCOMPARE(info["euler"].toInt(), 0);
    QVERIFY(info["closed"].toBool());
    RUN_JSON(plane, "new", "--shape", "disc", "--size", "64", "-o", file("d.exr"), "--json");
    RUN_JSON(pushed, "stroke", file("d.exr"), "--brush", "push", "--path", "0.8,0.5;1,0.5",
             "--radius", "0.1", "-o", file("d2.exr"), "--json");
    RUN_JSON(planeInfo, "info", file("d2.exr"), "--json");
    QCOMPARE(planeInfo["euler"].toInt(), 1);
    QVERIFY(planeInfo["bbox"].toObject()["max"].toArray()[2].toDouble() > 0.01); // pushed up
    // A thin ring sampled evenly (W ≠ H, chosen from the radii) sculpts across both wraps: its
    // seams stay exact, it stays closed with Euler characteristic 0, and the stroke moved it.
    RUN_JSON(wide, "new", "--shape", "torus", "--size", "128", "--major", "0.8", "--minor", "0.2",
             "-o", file("w.exr"), "--json");
    QCOMPARE(wide["width"].toInt(), 128);
    QCOMPARE(wide["height"].toInt(), 32);
    RUN_JSON(wideStroke, "stroke", file("w.exr"), "--brush", "inflate", "--path", "0,0;0.05,0.1",
             "--radius", "0.1", "-o", file("w2.exr"), "--json");
    QVERIFY(wideStroke["dabs"].toInt() >= 2);
    RUN_JSON(wideInfo, "info", file("w2.exr"), "--json");
    QCOMPARE(wideInfo["seam_gap"].toDouble(), 0.0);
    QCOMPARE(wideInfo["euler"].toInt(), 0);
    QVERIFY(wideInfo["closed"].toBool());
    QVERIFY(wideInfo["bbox"].toObject()["max"].toArray()[2].toDouble() > 0.201); // inflated
    // A plane of its own W × H through a scene's --object: the stroke reaches its edge.
    RUN_JSON(scene, "add", file("w.exr"), "--shape", "plane", "--size", "32", "--name", "ground",
             "-o", file("scene.exr"), "--json");
    RUN_JSON(ground, "stroke", file("scene.exr"), "--object", "ground", "--brush", "push", "--path",
             "0.9,0.5;1,0.5", "--radius", "0.1", "-o", file("scene2.exr"), "--json");
    QVERIFY(ground["dabs"].toInt() >= 1);
  }

  void badShapesAreUsageErrors() {
    EXPECT_FAILURE(kUsage, file("x.exr"), "new", "--shape", "sphere", "--major", "1", "-o",
                   file("x.exr"));
    EXPECT_FAILURE(kUsage, file("x.exr"), "new", "--shape", "torus", "--major", "0.2", "--minor",
                   "0.3", "-o", file("x.exr"));
    EXPECT_FAILURE(kUsage, file("x.exr"), "new", "--shape", "torus", "--size", "2", "-o",
                   file("x.exr"));
    EXPECT_FAILURE(kUsage, file("x.exr"), "new", "--shape", "torus", "--size", "64", "--height",
                   "48", "-o", file("x.exr"));
    EXPECT_FAILURE(kUsage, file("x.exr"), "new", "--shape", "klein", "-o", file("x.exr"));
  }

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
};

QTEST_GUILESS_MAIN(CliTopologyTest)
#include "cli_topology_test.moc"
