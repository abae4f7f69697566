#include "scene_actors.h"

#include "modeller.h"
#include "object_placement.h"

#include "octaclay/core/geometry/mesh_extraction.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace octaclay::app {
namespace {

vtkSmartPointer<vtkActor> objectActor(const core::SceneObject& object) {
  const core::GeometryImage& image = object.document.positions;
  // At most kMaxSide cells along the longer side; a torus's or plane's W × H keeps at least
  // the cells extractMesh needs along the shorter one.
  int step = std::max(1, std::max(image.width(), image.height()) / SceneActors::kMaxSide);
  while (step > 1 && (image.width() % step != 0 || image.height() % step != 0 ||
                      std::min(image.width(), image.height()) / step < 4))
    step /= 2;
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
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.78, 0.76, 0.72);
  actor->GetProperty()->SetSpecular(0.1);
  actor->GetProperty()->BackfaceCullingOn(); // a closed surface, as the model is drawn
  vtkNew<vtkMatrix4x4> matrix;
  matrix->DeepCopy(ObjectPlacement(object.transform).objectToWorld().data()); // row-major
  actor->SetUserMatrix(matrix);
  return actor;
}

} // namespace

void SceneActors::rebuild(vtkRenderer& renderer, const Modeller& modeller) {
  clear(renderer);
  for (int k = 0; k < modeller.objectCount(); ++k) {
    const core::SceneObject& object = modeller.objectAt(k);
    if (k == modeller.activeObject() || !object.visible || object.document.size() < 2) continue;
    actors_.push_back(objectActor(object));
    renderer.AddActor(actors_.back());
  }
}

void SceneActors::clear(vtkRenderer& renderer) {
  for (const auto& actor : actors_)
    renderer.RemoveActor(actor);
  actors_.clear();
}

} // namespace octaclay::app
