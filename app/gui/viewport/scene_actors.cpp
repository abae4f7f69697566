#include "scene_actors.h"

#include "modeller.h"
#include "object_placement.h"

#include "octaclay/core/document/scene.h"
#include "octaclay/core/geometry/mesh_extraction.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace octaclay::app {
namespace {

// The object's surface every step-th sample, smooth-shaded, as a mapper.
vtkSmartPointer<vtkPolyDataMapper> levelMapper(const core::GeometryImage& image, int step) {
  const core::TriangleMesh mesh = core::extractMesh(image, step);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.positions.size()));
  for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
    const core::Vec3f& p = mesh.positions[k];
    points->SetPoint(static_cast<vtkIdType>(k), p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size()),
                           static_cast<vtkIdType>(mesh.triangles.size()) * 3);
  for (const auto& t : mesh.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    triangles->InsertNextCell(3, ids);
  }
  // Smooth shading: per-vertex normals, the area-weighted sum of the (outward,
  // counter-clockwise) triangles' around each vertex.
  std::vector<core::Vec3f> sums(mesh.positions.size());
  for (const auto& t : mesh.triangles) {
    const core::Vec3f a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const core::Vec3f n = core::cross(b - a, c - a);
    for (const std::uint32_t v : t)
      sums[v] = sums[v] + n;
  }
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(sums.size()));
  for (std::size_t k = 0; k < sums.size(); ++k) {
    const core::Vec3f n = core::length(sums[k]) > 0 ? core::normalize(sums[k]) : core::Vec3f{};
    normals->SetTuple3(static_cast<vtkIdType>(k), n.x, n.y, n.z);
  }
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  surface->GetPointData()->SetNormals(normals);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(surface);
  mapper->ScalarVisibilityOff();
  mapper->StaticOn(); // its input never changes: no pipeline check each frame
  return mapper;
}

void renderStarts(vtkObject* caller, unsigned long, void* clientData, void*) {
  static_cast<SceneActors*>(clientData)->chooseLevels(*static_cast<vtkRenderer*>(caller));
}

} // namespace

SceneActors::~SceneActors() {
  if (observed_) observed_->RemoveObserver(observer_);
}

void SceneActors::rebuild(vtkRenderer& renderer, const Modeller& modeller) {
  clear(renderer);
  for (int k = 0; k < modeller.objectCount(); ++k) {
    const core::SceneObject& object = modeller.objectAt(k);
    if (k == modeller.activeObject() || !object.visible || object.document.size() < 2) continue;
    const core::GeometryImage& image = object.document.positions;
    Object drawn;
    // Steps that divide both W and H (a torus's or plane's W × H) and keep at least four cells
    // along the shorter side: at most kMaxSide cells along the longer one, then coarser.
    const int longer = std::max(image.width(), image.height());
    const int shorter = std::min(image.width(), image.height());
    const auto fits = [&](int step) {
      return image.width() % step == 0 && image.height() % step == 0 && shorter / step >= 4;
    };
    int step = std::max(1, longer / kMaxSide);
    while (step > 1 && !fits(step))
      step /= 2;
    for (;; step *= 2) {
      drawn.levels.push_back(levelMapper(image, step));
      drawn.sides.push_back(longer / step);
      if (longer / (step * 2) < kMinSide || !fits(step * 2)) break;
    }
    const core::BoundingBox box = core::worldBounds(object);
    for (int c = 0; c < 3; ++c)
      drawn.centre[c] = 0.5 * (double((&box.min.x)[c]) + double((&box.max.x)[c]));
    drawn.radius = 0.5 * double(box.diagonal());
    const core::Vec3f extent = box.extent();
    drawn.breadth = double(std::max({extent.x, extent.y, extent.z}));
    drawn.actor = vtkSmartPointer<vtkActor>::New();
    drawn.actor->SetMapper(drawn.levels.front());
    drawn.actor->GetProperty()->SetColor(0.78, 0.76, 0.72);
    drawn.actor->GetProperty()->SetSpecular(0.1);
    // A closed surface's back faces are hidden, as the model is drawn; a plane shows both sides.
    drawn.actor->GetProperty()->SetBackfaceCulling(image.topology() != core::Topology::Plane);
    vtkNew<vtkMatrix4x4> matrix;
    matrix->DeepCopy(ObjectPlacement(object.transform).objectToWorld().data()); // row-major
    drawn.actor->SetUserMatrix(matrix);
    renderer.AddActor(drawn.actor);
    objects_.push_back(std::move(drawn));
  }
  if (objects_.empty()) return;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(renderStarts);
  callback->SetClientData(this);
  observed_ = &renderer;
  observer_ = renderer.AddObserver(vtkCommand::StartEvent, callback);
}

void SceneActors::clear(vtkRenderer& renderer) {
  for (const Object& object : objects_)
    renderer.RemoveActor(object.actor);
  objects_.clear();
  if (observed_) observed_->RemoveObserver(observer_);
  observed_ = nullptr;
}

int SceneActors::shownSide(int k) const {
  const Object& object = objects_.at(static_cast<std::size_t>(k));
  return object.sides[static_cast<std::size_t>(object.shown)];
}

void SceneActors::chooseLevels(vtkRenderer& renderer) {
  vtkCamera* camera = renderer.GetActiveCamera();
  const int* size = renderer.GetSize();
  if (!camera || size[1] <= 0) return;
  double eye[3];
  camera->GetPosition(eye);
  const double halfView = std::tan(camera->GetViewAngle() * 0.5 * vtkMath::Pi() / 180.0);
  for (Object& object : objects_) {
    // Pixels a world unit spans at the object's distance (or in the parallel view).
    const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(eye, object.centre));
    double pixelsPerUnit = 0;
    if (camera->GetParallelProjection())
      pixelsPerUnit = 0.5 * size[1] / std::max(camera->GetParallelScale(), 1e-12);
    else if (distance > object.radius)
      pixelsPerUnit = 0.5 * size[1] / (distance * halfView);
    // A ball of side N shows about 2N edges around its outline, π·d pixels long: the coarsest
    // level that keeps them within kOutlineSegmentPixels, the finest when the eye is inside
    // the object's sphere.
    const bool outside = distance > object.radius || camera->GetParallelProjection();
    const double wanted =
        outside ? vtkMath::Pi() * 2 * object.radius * pixelsPerUnit / (2 * kOutlineSegmentPixels)
                : double(kMaxSide);
    std::size_t level = 0;
    while (level + 1 < object.sides.size() && double(object.sides[level + 1]) >= wanted)
      ++level;
    if (static_cast<int>(level) != object.shown) {
      object.shown = static_cast<int>(level);
      object.actor->SetMapper(object.levels[level]);
    }
  }
}

} // namespace octaclay::app
