#pragma once

#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/material_catalog.h"

#include <filesystem>

namespace octaclay::app {

/// The built-in brushes' folder: $OCTACLAY_BUILTIN_BRUSHES, else the installed or source tree's
/// (data_folders.h).
std::filesystem::path builtInBrushFolder();

/// Every brush on the search path (built-in, OCTACLAY_PLUGIN_PATH, the user's data folder).
gpu::BrushCatalog scanBrushes();

/// The built-in materials' folder: $OCTACLAY_BUILTIN_MATERIALS, else the installed or source
/// tree's (data_folders.h).
std::filesystem::path builtInMaterialFolder();
/// Every material on the search path (built-in, OCTACLAY_MATERIAL_PATH, the user's folder).
gpu::MaterialCatalog scanMaterials();

} // namespace octaclay::app
