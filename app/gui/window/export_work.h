#pragma once

#include "background_task.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/lod/lod.h"

#include <QString>

#include <functional>
#include <memory>

namespace octaclay::app {

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
