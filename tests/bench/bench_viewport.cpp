// Frame rates of the modeller's viewport in a 1280 x 800 window (the targets): frames/s
// while a scripted push stroke runs at N = 1024 (with View ▸ Wireframe off and on) and N = 4096
// shown at level 256, and on one object of a scene of 1, 4 and 16 objects of N = 512 (issue 33:
// >= 30 frames/s at 16; `bench_viewport --scenes` runs these alone), and the frame
// time of our level-256 model beside VTK drawing the same sphere as plain vtkPolyData (full
// resolution and level 256), all measured in one run. A plain program printing a table: every
// frame is a synchronous paint of the widget followed by glFinish, so the GL work (llvmpipe
// without a GPU) is counted. Needs an X display with GLX (scripts/bench runs it under Xvfb).
#include "model_prop.h"
#include "modeller.h"
#include "viewport_widget.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/scene.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/gpu/brush_library.h"
#include "octaclay/gpu/stroke_rules.h"

#include <QApplication>
#include <QImage>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QStandardPaths>
#include <QWindow>
#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

using namespace octaclay;

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kWidth = 1280, kHeight = 800;
constexpr int kShownSide = 256;                                      // the displayed level
constexpr long long kShownTriangles = 2LL * kShownSide * kShownSide; // 131072
constexpr double kCircleRadius = 150;                                // px, the stroke's path
constexpr double kStepPixels = 5;                                    // cursor move per frame
constexpr double kStrokeSeconds = 6, kDrawSeconds = 2.5;             // time budget per case
constexpr double kPi = std::numbers::pi;
constexpr int kMaxStrokeFrames = 600, kMaxDrawFrames = 300;

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "bench_viewport: %s\n", message.c_str());
  std::fflush(stdout);
  std::exit(1);
}

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

int swaps = 0; // ViewportWidget::frameSwapped() count: every frame must reach the window

// One frame: Qt paints the widget (paintGL runs the queued dabs, then VTK renders, then Qt
// composes the window), then glFinish so the frame's GL work is done when the clock is read.
// update() and the event loop rather than repaint(): Qt turns a repaint() of a window with a GL
// widget into a posted update when the last composition is under 1/refresh-rate old.
void frame(app::ViewportWidget& widget) {
  const int before = swaps;
  const auto t = Clock::now();
  widget.update();
  while (swaps == before && since(t) < 30)
    QCoreApplication::processEvents(QEventLoop::AllEvents);
  widget.makeCurrent();
  widget.context()->functions()->glFinish();
  widget.doneCurrent();
  if (swaps == before) fail("no frame reached the window in 30 s (no frameSwapped)");
}

void load(app::ViewportWidget& widget, const core::GeometryImage& image, int divisor) {
  if (!widget.modeller().setDocument(core::makeDocument(image)))
    fail("setDocument failed: " + widget.error().toStdString());
  widget.setLevelDivisor(divisor);
  QCoreApplication::processEvents();
  const app::ViewportStats s = widget.stats();
  if (s.n != image.size() || widget.levelDivisor() != divisor)
    fail("the document or level did not take (N " + std::to_string(s.n) + ", divisor " +
         std::to_string(widget.levelDivisor()) + ")");
}

void checkShownTriangles(const app::ViewportWidget& widget) {
  const long long shown = widget.stats().displayedTriangles;
  if (shown != kShownTriangles)
    fail("displayedTriangles is " + std::to_string(shown) + ", expected " +
         std::to_string(kShownTriangles) + " at level 256");
}

// The model must be on screen: the pixel at the model's centre differs from the background at
// the left edge of the same row (the background gradient is vertical).
void checkDrawn(app::ViewportWidget& widget, const char* what) {
  const QImage image = widget.grabFramebuffer();
  const QPoint centre = widget.project({0, 0, 0}).toPoint();
  const QColor model = image.pixelColor(centre), background = image.pixelColor(2, centre.y());
  const int difference = std::abs(model.red() - background.red()) +
                         std::abs(model.green() - background.green()) +
                         std::abs(model.blue() - background.blue());
  if (difference < 30)
    fail(std::string(what) + ": the centre pixel looks like background (" +
         model.name().toStdString() + " vs " + background.name().toStdString() + ")");
}

struct StrokeFigures {
  int n = 0, divisor = 0, frames = 0;
  double wall = 0, dabsEstimate = 0, lastDabMs = 0, beginMs = 0, endMs = 0, statFps = 0;
  std::size_t changedTexels = 0, recordTexels = 0;
  float maxMove = 0, radiusEnd = 0;
  double circle = 0; // px
};

// A scene of `objects` objects of N = n: the sphere at the origin, the one sculpted (object 0),
// and the others, blobs at a third of its size, on a ring of radius 1.6 around it in the view's
// plane, clear of the stroke's circle (issue 33: stroking one object of a 16-object scene).
void loadScene(app::ViewportWidget& widget, const core::GeometryImage& image, int objects,
               int divisor) {
  core::Scene scene = core::sceneOf(core::makeDocument(image), "Sphere");
  const core::Document blob =
      core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, image.size()));
  for (int k = 1; k < objects; ++k) {
    const double angle = 2 * kPi * (k - 1) / (objects - 1);
    scene.objects.push_back({scene.uniqueName("Blob"),
                             blob,
                             {{1.6f * float(std::cos(angle)), 1.6f * float(std::sin(angle)), 0},
                              {0, 0, float(20 * k)},
                              {0.33f, 0.33f, 0.33f}},
                             true,
                             false});
  }
  if (!widget.modeller().setScene(std::move(scene)))
    fail("setScene failed: " + widget.error().toStdString());
  widget.setLevelDivisor(divisor);
  QCoreApplication::processEvents();
  if (widget.stats().n != image.size() || widget.modeller().objectCount() != objects)
    fail("the scene did not take (N " + std::to_string(widget.stats().n) + ", " +
         std::to_string(widget.modeller().objectCount()) + " objects)");
}

// A push stroke along a circle of kCircleRadius px around the model's centre on screen, the
// cursor moving kStepPixels per frame; objects > 0: the model is object 0 of such a scene.
StrokeFigures strokeCase(app::ViewportWidget& widget, int n, int divisor, int objects = 0) {
  StrokeFigures f;
  f.n = n;
  f.divisor = divisor;
  const core::GeometryImage start = core::makeBaseShape(core::BaseShape::Sphere, n);
  if (objects > 0)
    loadScene(widget, start, objects, divisor);
  else
    load(widget, start, divisor);
  checkShownTriangles(widget);
  const QPointF centre = widget.project({0, 0, 0});
  // A scene frames all its objects: the sphere is smaller on screen, so the circle is at most
  // 0.6 of its radius there (the same kStepPixels a frame).
  const double circle =
      objects > 0
          ? std::min(kCircleRadius, 0.6 * std::hypot(widget.project({1, 0, 0}).x() - centre.x(),
                                                     widget.project({1, 0, 0}).y() - centre.y()))
          : kCircleRadius;
  f.circle = circle;
  const auto at = [&](double angle) {
    return centre + QPointF(circle * std::cos(angle), circle * std::sin(angle));
  };
  const double step = kStepPixels / circle;
  if (!widget.pickAt(at(0)) || !widget.pickAt(at(kPi)))
    fail("the stroke's circle leaves the model");

  // Warm-up (brush variant compiled, first dabs, first frames), then undone.
  widget.beginStrokeAt(at(kPi));
  if (!widget.stroking()) fail("the warm-up stroke did not start: " + widget.error().toStdString());
  for (int k = 1; k <= 8; ++k) {
    widget.continueStrokeTo(at(kPi + k * step));
    frame(widget);
  }
  widget.endStroke();
  if (!widget.modeller().undoStroke()) fail("the warm-up stroke left nothing to undo");
  frame(widget);

  // The timed stroke. Between frames, off the clock, the dabs are counted by replaying the
  // stroke rules (gpu/stroke_rules.h) with the (u, v) the widget picks (ViewportWidget exposes
  // no dab count): walk the straight (u, v) segment from the previous point over the surface as
  // the stroke began (the sphere: the warm-up was undone), one dab per spacing x radius, the
  // remainder carried, the radius a fraction of the bounding box when the stroke began.
  const float spacingFraction =
      gpu::dabSpacing(*widget.modeller().library()->catalog().find("push"), 0);
  const auto radius = [&] {
    core::BoundingBox box;
    for (const core::Vec4f& texel : widget.modeller().document().positions.texels())
      box.extend(texel.xyz());
    return widget.modeller().brushState().settings().radius * box.diagonal();
  };
  const double spacing = double(spacingFraction * radius());
  const auto startAt = [&](double u, double v) {
    return core::interpolatePosition(start, gpu::surfacePointAt(n, u * n, v * n));
  };
  std::optional<core::PickHit> hit = widget.pickAt(at(0));
  double previousU = hit->u, previousV = hit->v;
  double travelled = 0;
  int dabs = 1;
  auto t = Clock::now();
  widget.beginStrokeAt(at(0));
  f.beginMs = since(t) * 1e3;
  if (!widget.stroking()) fail("the stroke did not start: " + widget.error().toStdString());
  double angle = 0;
  while (f.frames < kMaxStrokeFrames && f.wall < kStrokeSeconds) {
    angle += step;
    hit = widget.pickAt(at(angle)); // what continueStrokeTo will pick
    if (hit) {
      // Fine steps: the surface is linear on each triangle, so this is the arc length to far
      // better than a dab.
      const double du = hit->u - previousU, dv = hit->v - previousV;
      const int steps = 1 + int(std::ceil(8.0 * n * std::max(std::abs(du), std::abs(dv))));
      core::Vec3f last = startAt(previousU, previousV);
      for (int k = 1; k <= steps; ++k) {
        const double s = double(k) / steps;
        const core::Vec3f here = startAt(previousU + s * du, previousV + s * dv);
        travelled += double(core::length(here - last));
        last = here;
        for (; travelled >= spacing; travelled -= spacing)
          ++dabs;
      }
      previousU = hit->u;
      previousV = hit->v;
    }
    t = Clock::now();
    widget.continueStrokeTo(at(angle));
    frame(widget);
    f.wall += since(t);
    ++f.frames;
  }
  f.dabsEstimate = dabs;
  const app::ViewportStats s = widget.stats();
  f.lastDabMs = s.lastDabMs;
  f.statFps = s.framesPerSecond;
  t = Clock::now();
  widget.endStroke();
  f.endMs = since(t) * 1e3;
  if (!widget.error().isEmpty()) fail("the viewport reported: " + widget.error().toStdString());
  checkShownTriangles(widget);

  // The stroke must have changed the model; no texel moves more than strength x radius a dab.
  const core::EditStep* record = widget.modeller().history().nextUndo();
  f.recordTexels = record ? record->changedTexels : 0;
  const core::GeometryImage& now = widget.modeller().document().positions;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float move = core::length(now.at(i, j).xyz() - start.at(i, j).xyz());
      f.changedTexels += move > 0;
      f.maxMove = std::max(f.maxMove, move);
    }
  if (f.changedTexels == 0 || f.recordTexels == 0)
    fail("the stroke at N = " + std::to_string(n) + " did not change the model");
  f.radiusEnd = radius();
  return f;
}

struct DrawFigures {
  int frames = 0;
  double wall = 0;
  double msPerFrame() const { return wall / frames * 1e3; }
};

DrawFigures drawCase(app::ViewportWidget& widget) {
  for (int k = 0; k < 3; ++k) // first frames upload VTK's buffers or build state
    frame(widget);
  DrawFigures d;
  const auto t = Clock::now();
  while (d.frames < kMaxDrawFrames && since(t) < kDrawSeconds) {
    frame(widget);
    ++d.frames;
  }
  d.wall = since(t);
  return d;
}

app::ModelProp* modelProp(app::ViewportWidget& widget) {
  vtkPropCollection* props = widget.renderer()->GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp())
    if (auto* model = app::ModelProp::SafeDownCast(prop)) return model;
  fail("the viewport's renderer has no ModelProp");
}

vtkSmartPointer<vtkPolyData> toPolyData(const core::TriangleMesh& mesh, bool normals) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.positions.size()));
  for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
    const core::Vec3f& p = mesh.positions[k];
    points->SetPoint(static_cast<vtkIdType>(k), p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size()),
                           static_cast<vtkIdType>(mesh.triangles.size() * 3));
  for (const auto& tri : mesh.triangles) {
    const vtkIdType ids[3] = {tri[0], tri[1], tri[2]};
    triangles->InsertNextCell(3, ids);
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(triangles);
  if (!normals) return polyData;
  vtkNew<vtkPolyDataNormals> filter;
  filter->SetInputData(polyData);
  filter->ComputePointNormalsOn();
  filter->ComputeCellNormalsOff();
  filter->SplittingOff();   // smooth shading everywhere, as our model is shaded
  filter->ConsistencyOff(); // the mesh is already consistently oriented
  filter->AutoOrientNormalsOff();
  filter->Update();
  return filter->GetOutput();
}

// VTK draws `mesh` through a vtkPolyDataMapper actor in the viewport's renderer, our model
// hidden.
DrawFigures vtkCase(app::ViewportWidget& widget, const core::TriangleMesh& mesh, bool normals,
                    const char* what) {
  vtkSmartPointer<vtkPolyData> polyData = toPolyData(mesh, normals);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(polyData);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  app::ModelProp* model = modelProp(widget);
  model->VisibilityOff();
  widget.renderer()->AddActor(actor);
  const DrawFigures d = drawCase(widget);
  checkDrawn(widget, what);
  if (std::string(mapper->GetClassName()) == "vtkPolyDataMapper")
    fail("vtkPolyDataMapper::New() gave the abstract mapper (VTK's OpenGL2 factory is not set)");
  widget.renderer()->RemoveActor(actor);
  model->VisibilityOn();
  return d;
}

} // namespace

int main(int argc, char** argv) {
  QApplication application(argc, argv);
  // The brush values it sets are persisted as a user's are: into Qt's test folder, not theirs.
  QStandardPaths::setTestModeEnabled(true);
  const auto total = Clock::now();

  app::Modeller modeller;
  app::ViewportWidget widget(modeller);
  QObject::connect(&widget, &app::ViewportWidget::frameSwapped, [] { ++swaps; });
  widget.resize(kWidth, kHeight);
  widget.show();
  for (const auto t = Clock::now(); !widget.glReady() && since(t) < 20;)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  if (!widget.glReady()) fail("GL did not start: " + widget.error().toStdString());
  if (widget.width() != kWidth || widget.height() != kHeight)
    fail("the viewport is " + std::to_string(widget.width()) + " x " +
         std::to_string(widget.height()) + ", not 1280 x 800 (screen too small?)");
  const gpu::BrushManifest* push =
      widget.modeller().library() ? widget.modeller().library()->catalog().find("push") : nullptr;
  if (!push) fail("the push brush is not in the library");

  // Diagnosis only: OCTACLAY_BENCH_MULTISAMPLES=0 measures the viewport without VTK's MSAA.
  if (const char* samples = std::getenv("OCTACLAY_BENCH_MULTISAMPLES"))
    widget.renderWindow()->SetMultiSamples(std::atoi(samples));
  // Whatever values a user of this machine stored: the benchmark's own, the manifest's area and
  // falloff as a brush starts with, the stroke options' defaults.
  app::BrushState& brush = widget.modeller().brushState();
  if (!brush.selectBrush("push")) fail("the push brush is not in the brush state");
  brush.setRadiusUnit(app::RadiusUnit::Scene);
  brush.setRadius(0.05f);
  brush.setStrength(0.3f);
  brush.setArea(push->area);
  brush.setFalloff(push->falloff);
  brush.setPressureTarget(app::BrushSettings{}.pressureTarget);
  brush.setStabilizer(0.0f);
  brush.setSymmetry(0);
  brush.setKeepDetail(app::BrushSettings{}.keepDetail);

  widget.makeCurrent();
  const auto* glRenderer =
      reinterpret_cast<const char*>(widget.context()->functions()->glGetString(GL_RENDERER));
  widget.doneCurrent();
  std::printf("bench_viewport: %d x %d viewport, GL renderer %s, Qt platform %s, VTK "
              "multisamples %d\n",
              kWidth, kHeight, glRenderer ? glRenderer : "?",
              QGuiApplication::platformName().toStdString().c_str(),
              widget.renderWindow()->GetMultiSamples());
  std::printf("push brush: radius %.2f of the diagonal, strength %.2f, spacing %.2f x radius; "
              "cursor on a %.0f px circle, %.0f px per frame\n\n",
              static_cast<double>(brush.radius()), static_cast<double>(brush.strength()),
              static_cast<double>(push->spacing), kCircleRadius, kStepPixels);
  std::fflush(stdout);

  // (a), (b): stroking; (s1) to (s16): stroking one object of a scene of 1, 4 and 16 objects of
  // N = 512 (level 256), the others drawn beside it. --scenes runs those alone.
  const bool scenesOnly = argc > 1 && std::string(argv[1]) == "--scenes";
  std::printf("%-36s %7s %8s %9s %9s %11s %11s %9s %9s\n", "stroke case", "frames", "wall s",
              "frames/s", "ms/frame", "dabs (est.)", "dabs/s", "dab ms", "target");
  std::vector<StrokeFigures> strokes;
  struct StrokeCase {
    int n, divisor;
    double target;
    bool wireframe;
    int objects;
  };
  std::vector<StrokeCase> cases;
  if (!scenesOnly)
    cases = {{1024, 4, 30.0, false, 0}, {1024, 4, 20.0, true, 0}, {4096, 16, 15.0, false, 0}};
  for (int objects : {1, 4, 16})
    cases.push_back({512, 2, 30.0, false, objects});
  for (const StrokeCase& c : cases) {
    app::ViewLooks looks = widget.looks();
    looks.wireframe = c.wireframe;
    widget.setLooks(looks);
    const StrokeFigures f = strokeCase(widget, c.n, c.divisor, c.objects);
    const double fps = f.frames / f.wall;
    const std::string name =
        c.objects > 0 ? "(s" + std::to_string(c.objects) + ") stroke 1 of " +
                            std::to_string(c.objects) + " objects N=512 (/2)"
                      : std::string(c.n == 1024 ? (c.wireframe ? "(a')" : "(a)") : "(b)") +
                            " stroke N=" + std::to_string(c.n) + " level 256 (/" +
                            std::to_string(c.divisor) + ")" + (c.wireframe ? " wireframe" : "");
    std::printf("%-36s %7d %8.2f %9.1f %9.2f %11.0f %11.1f %9.3f %6.0f %s\n", name.c_str(),
                f.frames, f.wall, fps, f.wall / f.frames * 1e3, f.dabsEstimate,
                f.dabsEstimate / f.wall, f.lastDabMs, c.target, fps >= c.target ? "met" : "MISSED");
    std::fflush(stdout);
    strokes.push_back(f);
  }
  widget.setLooks({});
  for (const StrokeFigures& f : strokes)
    std::printf(
        "  N=%d: circle %.0f px, %zu texels moved (max %.3f), undo record %zu texels, brush "
        "radius at the end %.3f, beginStroke %.1f ms, endStroke %.1f ms, "
        "stats().framesPerSecond %.0f\n",
        f.n, f.circle, f.changedTexels, static_cast<double>(f.maxMove), f.recordTexels,
        static_cast<double>(f.radiusEnd), f.beginMs, f.endMs, f.statFps);
  if (scenesOnly) {
    std::printf("total run time %.1f s\n", since(total));
    return 0;
  }

  // (c) to (e): drawing only, N = 1024.
  std::printf("\n%-60s %7s %9s %9s %12s\n", "draw case (no stroke)", "frames", "ms/frame",
              "frames/s", "triangles");
  const auto row = [](const std::string& what, const DrawFigures& d, long long triangles) {
    std::printf("%-60s %7d %9.2f %9.1f %12lld\n", what.c_str(), d.frames, d.msPerFrame(),
                d.frames / d.wall, triangles);
    std::fflush(stdout);
  };
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, 1024);
  load(widget, sphere, 4);
  checkShownTriangles(widget);
  app::ModelProp* model = modelProp(widget);
  model->VisibilityOff();
  const DrawFigures empty = drawCase(widget);
  model->VisibilityOn();
  row("(0) background only (model hidden): the frame's fixed cost", empty, 0);
  const DrawFigures ours = drawCase(widget);
  checkDrawn(widget, "(c) our level-256 model");
  row("(c) ours, N=1024 at level 256 (/4)", ours, widget.stats().displayedTriangles);

  const core::TriangleMesh full = core::extractMesh(widget.modeller().document().positions, 1);
  const DrawFigures vtkFull = vtkCase(widget, full, true, "(d) VTK full resolution");
  row("(d) VTK polydata, N=1024 full res, vtkPolyDataNormals on", vtkFull,
      static_cast<long long>(full.triangles.size()));
  const DrawFigures vtkFullFlat = vtkCase(widget, full, false, "(d') VTK full, no normals");
  row("(d') VTK polydata, N=1024 full res, normals off", vtkFullFlat,
      static_cast<long long>(full.triangles.size()));
  const core::TriangleMesh level = core::extractMesh(widget.modeller().document().positions, 4);
  const DrawFigures vtkLevel = vtkCase(widget, level, true, "(e) VTK level 256");
  row("(e) VTK polydata, level-256 mesh, vtkPolyDataNormals on", vtkLevel,
      static_cast<long long>(level.triangles.size()));
  checkShownTriangles(widget);

  // The target compares the cost of drawing the two models; every frame also pays a fixed
  // cost (clear, VTK's and Qt's framebuffer copies, the swap) measured by (0) in this run.
  const double oursDraw = ours.msPerFrame() - empty.msPerFrame();
  const double vtkDraw = vtkFull.msPerFrame() - empty.msPerFrame();
  const double drawRatio = oursDraw / vtkDraw;
  std::printf("\nmodel draw cost (frame minus (0)): ours %.2f ms, VTK full-res %.2f ms = %.3f "
              "(1/%.1f); target <= 1/8 = 0.125: %s\n",
              oursDraw, vtkDraw, drawRatio, 1 / drawRatio, drawRatio <= 0.125 ? "met" : "MISSED");
  const double ratio = ours.msPerFrame() / vtkFull.msPerFrame();
  std::printf("whole frames (c)/(d): ours %.2f ms / VTK full-res %.2f ms = %.3f (1/%.1f)\n",
              ours.msPerFrame(), vtkFull.msPerFrame(), ratio, 1 / ratio);
  std::printf("ratio (c)/(d'): %.3f (1/%.1f) against VTK without normals\n",
              ours.msPerFrame() / vtkFullFlat.msPerFrame(),
              vtkFullFlat.msPerFrame() / ours.msPerFrame());
  std::printf("ratio (c)/(e): %.3f against VTK drawing the same level-256 mesh\n",
              ours.msPerFrame() / vtkLevel.msPerFrame());
  std::printf("total run time %.1f s\n", since(total));
  return 0;
}
