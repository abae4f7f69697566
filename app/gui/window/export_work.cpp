#include "export_work.h"

#include "octaclay/core/export/lod_export.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/export/textured_export.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/lod/normal_map.h"
#include "octaclay/core/lod/saliency.h"

#include <QFileInfo>

#include <algorithm>
#include <filesystem>

namespace octaclay::app {
namespace {

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(path.toStdString());
}

} // namespace

std::function<void()> meshExportWork(const core::Document& document, const QString& path,
                                     int divisor) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == "obj" || suffix == "glb") {
    auto snapshot = std::make_shared<core::Document>(document);
    return [snapshot, path, divisor, obj = suffix == "obj"] {
      if (obj)
        core::writeTexturedObj(*snapshot, divisor, toPath(path));
      else
        core::writeGlb(*snapshot, divisor, toPath(path));
    };
  }
  if (!core::meshFormatFromPath(toPath(path))) return {};
  auto snapshot = std::make_shared<core::GeometryImage>(document.positions);
  return [snapshot, path, divisor] {
    core::writeMesh(core::extractMesh(*snapshot, divisor), toPath(path));
  };
}

std::function<void()> lodExportWork(std::shared_ptr<core::Document> snapshot,
                                    core::LodOptions options, const QString& path,
                                    std::shared_ptr<TaskControl> control, bool computeSaliency) {
  return [snapshot, options, path, control, computeSaliency] {
    core::GeometryImage& full = snapshot->positions;
    if (computeSaliency) core::computeSaliency(full);
    const core::LodMesh lod = core::generateLod(full, options);
    control->fraction = 0.3f;
    if (control->cancel) return; // between steps: nothing written yet
    // One map texel per full-resolution sample (up to 4096²): the map carries all the detail
    // the LOD's triangles dropped. Tangent space is what glTF's normalTexture and the OBJ
    // readers' `norm` / `map_Bump` expect.
    const int resolution = std::clamp(full.size(), 2, 4096);
    const core::NormalMap map =
        core::bakeNormalMap(full, lod, core::NormalMapSpace::Tangent, resolution);
    control->fraction = 0.8f;
    if (control->cancel) return;
    core::writeLodMesh(lod, map, *snapshot, toPath(path));
    control->fraction = 1.0f;
  };
}

} // namespace octaclay::app
