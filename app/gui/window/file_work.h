#pragma once

#include "background_task.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/scene.h"
#include "octaclay/core/geometry/vec.h"
#include "octaclay/core/lod/lod.h"

#include <QString>

#include <functional>
#include <memory>

namespace octaclay::app {

/// Every object of an .exr scene, or the one document of an .ocz, balls, tori and planes alike.
/// Throws core::Error for what cannot be read.
core::Scene readSceneFile(const QString& path);

/// What File ▸ Import Mesh made: the document, the side it faces, and a line for the status bar
/// (the map's stretch, flipped triangles, where the colour came from, what could not be used).
struct ImportedMesh {
  core::Document document;
  core::Vec3f facing;
  QString report;
};
/// File ▸ Import Mesh's work at size n, to run off the GUI thread: the mesh validated, mapped on
/// the sphere (control's fraction, cancel) and resampled into result.
std::function<void()> importWork(const QString& path, int n, std::shared_ptr<TaskControl> control,
                                 std::shared_ptr<ImportedMesh> result);

/// File ▸ Export Mesh's work on a copy of document, to run off the GUI thread: OBJ (with maps)
/// and GLB carry the painted layers, PLY / STL / OFF the mesh at level N/divisor. Empty when the
/// path's extension names no format it writes.
std::function<void()> meshExportWork(const core::Document& document, const QString& path,
                                     int divisor);

/// The Level of detail dock's export (OBJ + MTL or GLB, with a tangent-space normal map baked
/// from the full resolution) of snapshot, computing its saliency first when asked; reports its
/// fraction through control and stops between steps (nothing written) when it is cancelled.
std::function<void()> lodExportWork(std::shared_ptr<core::Document> snapshot,
                                    core::LodOptions options, const QString& path,
                                    std::shared_ptr<TaskControl> control, bool computeSaliency);

} // namespace octaclay::app
