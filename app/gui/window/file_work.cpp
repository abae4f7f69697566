#include "file_work.h"

#include "save_compressed_dialog.h"

#include "octaclay/core/codec/compressed_scene.h"
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/export/lod_export.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/export/textured_export.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/import/import.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/spherical_parameterization.h"
#include "octaclay/core/lod/facing.h"
#include "octaclay/core/lod/normal_map.h"
#include "octaclay/core/lod/saliency.h"

#include <QFileInfo>
#include <QObject>

#include <algorithm>
#include <filesystem>

namespace octaclay::app {
namespace {

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(path.toStdString());
}

} // namespace

core::Scene readSceneFile(const QString& path) {
  core::Scene scene = QFileInfo(path).suffix().compare("ocz", Qt::CaseInsensitive) == 0
                          ? core::readCompressedScene(toPath(path))
                          : core::readScene(toPath(path));
  return scene; // balls, tori and planes alike: the GPU sculpts every topology
}

std::function<void()> importWork(const QString& path, int n, std::shared_ptr<TaskControl> control,
                                 std::shared_ptr<ImportedMesh> result) {
  return [path, n, control, result] {
    const core::ValidatedMesh mesh = core::loadGenus0Mesh(toPath(path));
    const core::SphericalMap map = core::parameterizeOnSphere(mesh.mesh, [control](float f) {
      control->fraction = 0.9f * f;
      return !control->cancel.load();
    });
    if (map.flipped > 0)
      throw core::Error(core::ErrorKind::InvalidInput,
                        "the spherical map folds over itself (" + std::to_string(map.flipped) +
                            " flipped triangles): this mesh is not supported yet");
    core::ImportedDiffuse diffuse;
    result->document = core::importValidatedMesh(mesh, map, n, &diffuse);
    result->facing = core::guessFacing(result->document.positions);
    control->fraction = 1.0f;
    QString colour = QObject::tr("no colour");
    if (diffuse.source == core::DiffuseSource::VertexColours)
      colour = QObject::tr("vertex colours");
    else if (diffuse.source == core::DiffuseSource::Texture)
      colour = QObject::tr("texture %1")
                   .arg(QString::fromStdString(diffuse.texture.filename().string()));
    result->report = QObject::tr("stretch %1, %2 flipped triangles, %3")
                         .arg(static_cast<double>(map.stretchL2), 0, 'f', 2)
                         .arg(map.flipped)
                         .arg(colour);
    // Attributes the file names but the import could not use (a missing .mtl or texture).
    for (const std::string& note : diffuse.notes)
      result->report += QStringLiteral("; ") + QString::fromStdString(note);
  };
}

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
